#!/usr/bin/env python3
"""Turns out/bench/avr.json (written by `tools/dev bench`) into the Markdown
tables of docs/benchmarks.md, or prints them.

usage: bench_report.py [--json out/bench/avr.json] [--write docs/benchmarks.md]
"""
import argparse
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
BEGIN = "<!-- bench:begin -->"
END = "<!-- bench:end -->"


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
    a = ap.parse_args()
    text = tables(json.load(open(a.json)))
    if not a.write:
        print(text)
        return 0
    path = pathlib.Path(a.write)
    doc = path.read_text()
    if BEGIN not in doc or END not in doc:
        print(f"{path}: no {BEGIN} ... {END} section", file=sys.stderr)
        return 1
    head, rest = doc.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    path.write_text(f"{head}{BEGIN}\n{text}\n{END}{tail}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
