#!/usr/bin/env python3
"""Per-robot figures of the real firmware, measured on the virtual Mega.

For every model's firmware ELF: flash and static RAM from avr-size; the
longest control tick, the deepest stack (the firmware paints its free RAM at
start-up and reports `stack_peak` in `status`) and the overruns from a run on
tools/vbench that boots, stands, walks forward, turns and strafes, and from a
second run that changes the servos' PWM frequency (400 Hz and back) while
walking; the largest I2C frame of the first run and its time at 400 kHz from the bytes sent (simavr does not time
TWI realistically). Merges them into avr.json under "firmware" and prints a
table against the budgets of the real Mega (256 KB flash, 8 KB SRAM).

    firmware_figures.py --vbench BIN --firmware-dir DIR --json out/bench/avr.json
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

MODELS = ["sprawl8", "mammal8", "dog12", "hexapod18", "spider12"]
F_CPU = 16_000_000
# Budgets for every firmware against the real Mega: half its flash, half its
# SRAM for static data, 1 KB of stack, and the longest tick a firmware takes
# (command changes, step starts and the I2C frame included) within 10 ms of
# the 20 ms period with no overrun. The 28,000-cycle target of hexapod18's
# control tick is a cycles-per-call figure of the benchmark (avr_cycles'
# control_tick_hexapod18_fixed entry, its target_cycles), not a bound on
# this longest tick.
BUDGET = {"flash_bytes": 128 * 1024, "ram_static_bytes": 4 * 1024, "stack_peak_bytes": 1024,
          "tick_cycles_max": 10_000 * F_CPU // 1_000_000, "overruns": 0}
# The servo frame at the bus limit: 0.1 ms per joint at 400 kHz (18 channels
# in 1.8 ms, 8 in 0.8 ms), from the bytes vbench logged.
FRAME_US_PER_JOINT = 100
JOINTS = {"sprawl8": 8, "mammal8": 8, "dog12": 12, "hexapod18": 18, "spider12": 12}

# Boot (the velocity-limit search takes up to ~3 s), stand up, then walk,
# turn and strafe at full speed, asking for status at the end.
SCRIPT = """\
at 0 range 1500
at 8 send speed 100\\n
at 8.2 send walk 80\\n
at 9.0 send walk 80\\n
at 9.8 send turn 40\\n
at 10.6 send turn 40\\n
at 11.4 send strafe 50\\n
at 12.2 send strafe 50\\n
at 12.9 send status\\n
"""
DURATION_S = 13.4
# A second run for the tick around a settings change: the servos' PWM at 400
# Hz (where the tick map cannot hold the built-in servos' longest pulses and
# each frame maps them the slow way) with a walk and a turn, then back to 50
# Hz (the outputs rescaled, the map refitted a leg per frame). Its tick,
# stack and overruns count; its I2C frames, the boards' prescale bursts, are
# not servo frames.
PWM_SCRIPT = """\
at 0 range 1500
at 8 send speed 100\\n
at 8.1 send cal start\\n
at 8.2 send cal pwm 400\\n
at 8.3 send cal save\\n
at 8.5 send walk 80\\n
at 9.3 send turn 40\\n
at 10.1 send cal start\\n
at 10.2 send cal pwm 50\\n
at 10.3 send cal save\\n
at 10.6 send walk 80\\n
at 11.4 send status\\n
"""
PWM_DURATION_S = 11.9


def avr_size(size_tool, elf):
    out = subprocess.run([size_tool, "-A", elf], check=True, capture_output=True, text=True).stdout
    sec = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 2 and parts[0].startswith(".") and parts[1].isdigit():
            sec[parts[0]] = int(parts[1])
    flash = sec.get(".text", 0) + sec.get(".data", 0)
    ram = sec.get(".data", 0) + sec.get(".bss", 0) + sec.get(".noinit", 0)
    return flash, ram


def run_vbench(vbench, elf, script_text=SCRIPT, duration_s=DURATION_S):
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write(script_text)
        script = f.name
    try:
        out = subprocess.run([vbench, "--elf", elf, "--script", script, "--duration", str(duration_s), "--log"],
                             capture_output=True, text=True, timeout=600).stdout
    finally:
        os.unlink(script)
    status = [l for l in out.splitlines() if "ok status" in l]
    if not status:
        raise RuntimeError("no status reply from %s:\n%s" % (elf, out[-2000:]))
    fields = dict(re.findall(r"(\w+)=(\S+)", status[-1]))
    i2c = re.search(r"max (\d+) bytes/frame, max (\d+) us/frame", out)
    resets = re.search(r"resets \d+ unexpected (\d+)", out)
    return {
        "tick_us_max": int(fields.get("tick_max_us", 0)),
        "tick_cycles_max": int(fields.get("tick_max_us", 0)) * (F_CPU // 1_000_000),
        "stack_peak_bytes": int(fields.get("stack_peak", 0)),
        "overruns": int(fields.get("overruns", 0)),
        "mode": fields.get("mode", "?"),
        "i2c_frame_bytes_max": int(i2c.group(1)) if i2c else 0,
        "i2c_frame_us_max_400khz": int(i2c.group(2)) if i2c else 0,
        "unexpected_resets": int(resets.group(1)) if resets else 0,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--vbench", required=True)
    ap.add_argument("--firmware-dir", required=True, help="folder of strider_firmware_<model>.elf")
    ap.add_argument("--size-tool", default="avr-size")
    ap.add_argument("--json", required=True, help="avr.json to merge into (created if missing)")
    ap.add_argument("--models", default=",".join(MODELS))
    args = ap.parse_args()

    figures = {}
    for model in args.models.split(","):
        elf = os.path.join(args.firmware_dir, "strider_firmware_%s.elf" % model)
        if not os.path.exists(elf):
            print("missing %s" % elf, file=sys.stderr)
            return 1
        flash, ram = avr_size(args.size_tool, elf)
        fig = {"flash_bytes": flash, "ram_static_bytes": ram}
        fig.update(run_vbench(args.vbench, elf))
        pwm = run_vbench(args.vbench, elf, PWM_SCRIPT, PWM_DURATION_S)
        for key in ("tick_us_max", "tick_cycles_max", "stack_peak_bytes"):
            fig[key] = max(fig[key], pwm[key])
        fig["overruns"] += pwm["overruns"]
        fig["unexpected_resets"] += pwm["unexpected_resets"]
        figures[model] = fig

    data = {}
    if os.path.exists(args.json):
        with open(args.json) as f:
            data = json.load(f)
    data["firmware"] = figures
    os.makedirs(os.path.dirname(os.path.abspath(args.json)), exist_ok=True)
    with open(args.json, "w") as f:
        json.dump(data, f, indent=1)

    print("budgets: flash <= %s B, static RAM <= %s B, stack <= %s B, tick <= %s cycles (10 ms), "
          "0 overruns, I2C frame <= %d us per joint at 400 kHz" % (
              "{:,}".format(BUDGET["flash_bytes"]), "{:,}".format(BUDGET["ram_static_bytes"]),
              "{:,}".format(BUDGET["stack_peak_bytes"]), "{:,}".format(BUDGET["tick_cycles_max"]), FRAME_US_PER_JOINT))
    print("| model | flash [B] | static RAM [B] | peak stack [B] | tick max [cycles] | overruns | I2C frame max |")
    print("|---|---|---|---|---|---|---|")
    for model, g in figures.items():
        print("| %s | %s | %s | %s | %s | %d | %d B = %d us |" % (
            model, "{:,}".format(g["flash_bytes"]), "{:,}".format(g["ram_static_bytes"]),
            "{:,}".format(g["stack_peak_bytes"]), "{:,}".format(g["tick_cycles_max"]), g["overruns"],
            g["i2c_frame_bytes_max"], g["i2c_frame_us_max_400khz"]))
    missed = []
    for model, g in figures.items():
        for key, limit in BUDGET.items():
            if g[key] > limit:
                missed.append("%s %s %d > %d" % (model, key, g[key], limit))
        frame_limit = FRAME_US_PER_JOINT * JOINTS.get(model, 18)
        if g["i2c_frame_us_max_400khz"] > frame_limit:
            missed.append("%s I2C frame %d us > %d us" % (model, g["i2c_frame_us_max_400khz"], frame_limit))
        if g["unexpected_resets"]:
            missed.append("%s reset %d times" % (model, g["unexpected_resets"]))
    print("budgets: " + ("all met" if not missed else "MISSED: " + "; ".join(missed)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
