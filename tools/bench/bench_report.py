#!/usr/bin/env python3
"""Turns out/bench/avr.json (written by `tools/dev bench`) into the Markdown
tables of docs/benchmarks.md and the firmware sizes table of docs/firmware.md,
or prints them.

usage: bench_report.py [--json out/bench/avr.json] [--write docs/benchmarks.md]
                       [--firmware-table docs/firmware.md]
"""
import argparse
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
BEGIN = "<!-- bench:begin -->"
END = "<!-- bench:end -->"
FIRMWARE_BEGIN = "<!-- firmware:begin -->"
FIRMWARE_END = "<!-- firmware:end -->"


def firmware_table(d):
    """The per-model firmware figures (avr-size, the virtual Mega's run)."""
    f_mhz = d["f_cpu"] / 1e6
    out = ["| model | flash [B] | static RAM [B] | peak stack [B] | tick max [cycles] | overruns | largest I2C frame |",
           "|---|---|---|---|---|---|---|"]
    for model, f in d.get("firmware", {}).items():
        tick_ms = f["tick_cycles_max"] / f_mhz / 1000.0
        i2c_ms = f["i2c_frame_us_max_400khz"] / 1000.0
        out.append(f"| {model} | {f['flash_bytes']:,} | {f['ram_static_bytes']:,} | {f['stack_peak_bytes']:,} | "
                   f"{f['tick_cycles_max']:,} ({tick_ms:.1f} ms) | {f['overruns']} | "
                   f"{f['i2c_frame_bytes_max']} B = {i2c_ms:.2f} ms at 400 kHz |")
    return "\n".join(out)


def replace_section(path, begin, end, text):
    path = pathlib.Path(path)
    doc = path.read_text()
    if begin not in doc or end not in doc:
        print(f"{path}: no {begin} ... {end} section", file=sys.stderr)
        return False
    head, rest = doc.split(begin, 1)
    tail = rest.split(end, 1)[1]
    path.write_text(f"{head}{begin}\n{text}\n{end}{tail}")
    return True


def tables(d):
    f_mhz = d["f_cpu"] / 1e6
    rows = {}
    for e in d["entries"]:
        name = e["name"]
        for scalar in ("fixed", "float"):
            if name.startswith(scalar + "_"):
                key, col = name[len(scalar) + 1:], scalar
                break
            if name.endswith("_" + scalar):
                key, col = name[: -len(scalar) - 1], scalar
                break
        else:
            key, col = name, "other"
        rows.setdefault(key, {})[col] = e
    out = [f"Simulated {d['mcu']} at {f_mhz:.0f} MHz ({d['compiler']}), average cycles per call "
           f"(min-max), {d['inputs']} input set; marker overhead of {d['overhead_cycles']:.0f} cycles removed.", "",
           "| entry | fixed (Q16.16) | float | target |", "|---|---|---|---|"]

    def cell(e):
        if not e:
            return "-"
        us = e["cycles"] / f_mhz
        return f"{e['cycles']:,.0f} ({e['cycles_min']:,}-{e['cycles_max']:,}) = {us:,.0f} us"

    for key, cols in rows.items():
        targets = [f"{c}: <= {cols[c]['target_cycles']:,} {'met' if cols[c].get('meets_target') else 'MISSED'}"
                   for c in ("fixed", "float") if cols.get(c, {}).get("target_cycles")]
        out.append(f"| {key} | {cell(cols.get('fixed'))} | {cell(cols.get('float'))} | {'; '.join(targets)} |")
    b = d.get("bench_elf", {})
    out += ["", f"Bench firmware: {b.get('flash_bytes', 0):,} B flash, {b.get('ram_static_bytes', 0):,} B static RAM, "
            f"{b.get('stack_peak_bytes', 0):,} B peak stack."]
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default=str(ROOT / "out/bench/avr.json"))
    ap.add_argument("--write", help="Markdown file whose bench section is replaced")
    ap.add_argument("--firmware-table", help="Markdown file whose firmware section is replaced")
    a = ap.parse_args()
    d = json.load(open(a.json))
    if not a.write and not a.firmware_table:
        print(tables(d))
        print()
        print(firmware_table(d))
        return 0
    ok = True
    if a.write:
        ok = replace_section(a.write, BEGIN, END, tables(d)) and ok
    if a.firmware_table:
        ok = replace_section(a.firmware_table, FIRMWARE_BEGIN, FIRMWARE_END, firmware_table(d)) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
