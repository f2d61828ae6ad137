"""The AVR section of docs/results.md: cycles and sizes from tools/bench
(avr_cycles, firmware_figures.py), else out/bench/avr.json."""
import json
import shutil
import subprocess
import sys

from results_common import RESULTS, ROOT, NotMeasured, fmt, not_measured, table


def firmware_figures(d):
    """[(model, figures)] of the firmware ELFs in avr.json, wherever the
    bench put them: a dict or list of objects with flash_bytes (not the
    bench firmware's own bench_elf)."""
    out = []
    for key, v in d.items():
        if key in ("bench_elf", "entries"):
            continue
        if isinstance(v, dict) and "flash_bytes" in v:
            out.append((key, v))
        elif isinstance(v, dict):
            out += [(k, f) for k, f in v.items() if isinstance(f, dict) and "flash_bytes" in f]
        elif isinstance(v, list):
            out += [(f.get("model") or f.get("robot") or f.get("name") or "?", f) for f in v
                    if isinstance(f, dict) and "flash_bytes" in f]
    return out


def firmware_budgets(fw):
    """The budgets each model misses (strings), or None when the bench's
    budget table is not available."""
    try:
        import firmware_figures as ff  # tools/bench
        budget = ff.BUDGET
    except (ImportError, AttributeError):
        return None
    missed = []
    for name, f in fw:
        for key, limit in budget.items():
            if f.get(key) is not None and f[key] > limit:
                missed.append(f"{name} {key.replace('_', ' ')} {f[key]:,} > {limit:,}")
    return missed


def avr_data(build, reuse):
    """AVR figures measured now with the build's bench (avr_cycles on the
    bench firmware, then tools/bench/firmware_figures.py on every model's
    firmware) into out/results/avr.json; else out/bench/avr.json from an
    earlier `tools/dev bench`. Returns (data, where it came from)."""
    out = RESULTS / "avr.json"
    if reuse and out.is_file():
        return json.loads(out.read_text()), "out/results/avr.json, an earlier run of this script"
    cycles = build / "tools" / "bench" / "avr_cycles"
    elf = build / "tools" / "bench" / "strider_bench_firmware.elf"
    size = shutil.which("avr-size")
    if cycles.is_file() and elf.is_file() and size:
        p = subprocess.run([str(cycles), "--elf", str(elf), "--size-tool", size, "--json", str(out)],
                           capture_output=True, text=True, timeout=600)
        if p.returncode == 0 and out.is_file():
            vbench, fw = build / "tools" / "vbench" / "vbench", build / "src"
            if vbench.is_file() and list(fw.glob("strider_firmware_*.elf")):
                subprocess.run([sys.executable, str(ROOT / "tools" / "bench" / "firmware_figures.py"), "--vbench",
                                str(vbench), "--firmware-dir", str(fw), "--size-tool", size, "--json", str(out)],
                               capture_output=True, text=True, timeout=1200)
            return json.loads(out.read_text()), "measured in this run (tools/bench: avr_cycles, firmware_figures.py)"
    legacy = ROOT / "out" / "bench" / "avr.json"
    if legacy.is_file():
        return json.loads(legacy.read_text()), "out/bench/avr.json, written by an earlier `tools/dev bench`"
    raise NotMeasured("the AVR bench is not built (needs gcc-avr, avr-libc, simavr) and out/bench/avr.json is missing")


def avr(data):
    d, where = data
    from bench_report import tables
    md = f"Source: {where}.\n\n" + tables(d) + "\n"
    fw = firmware_figures(d)
    md += "\n### Firmware per robot\n\n"
    if not fw:
        md += not_measured("avr.json has no per-robot firmware figures yet (the firmware ELFs are measured "
                           "by tools/dev bench once src/ builds them)")
    else:
        rows = [[name, fmt(f.get("flash_bytes")), fmt(f.get("ram_static_bytes")), fmt(f.get("stack_peak_bytes")),
                 fmt(f.get("tick_cycles_max")),
                 fmt(f["tick_cycles_max"] / d["f_cpu"] * 1e3) if f.get("tick_cycles_max") else "-",
                 fmt(f.get("overruns")),
                 (f"{fmt(f['i2c_frame_bytes_max'])} B = {fmt(f.get('i2c_frame_us_max_400khz'))} us"
                  if f.get("i2c_frame_bytes_max") is not None else "-")]
                for name, f in fw]
        md += ("Each model's firmware ELF: sizes from avr-size, the rest from a run on the virtual Mega "
               "(tools/bench/firmware_figures.py):\n\n")
        md += table(["model", "flash [B]", "static RAM [B]", "peak stack [B]", "tick max [cycles]", "tick max [ms]",
                     "tick overruns", "largest I2C frame (at 400 kHz)"], rows)
        missed = firmware_budgets(fw)
        if missed is not None:
            md += ("\nBudgets (issue 5, as tools/bench/firmware_figures.py states them): "
                   + ("all met." if not missed else "missed: " + "; ".join(missed) + ".") + "\n")
            summary_fw = ("-", "firmware budgets (flash, RAM, stack, longest tick within the 20 ms period)", "issue 5",
                          "all met" if not missed else f"{len(missed)} missed (AVR section)")
    summary = []
    if fw and firmware_budgets(fw) is not None:
        summary.append(summary_fw)
    for e in d.get("entries", []):
        if e["name"].startswith("coxa_femur_tibia_ik") and e.get("target_cycles"):
            scalar = "fixed" if "fixed" in e["name"] else "float"
            summary.append(("-", f"AVR: hexapod leg IK, {scalar}", f"<= {e['target_cycles']:,} cycles",
                            f"{e['cycles']:,.0f} cycles ({'met' if e['cycles'] <= e['target_cycles'] else 'missed'})"))
    return md, summary
