#!/usr/bin/env python3
"""Re-measures the speed corrections of lib/strider/gait/speed_correction.h.

For a model and gait: the model's firmware on the virtual Mega (firmware
mode), the gait, then `walk V` (or `turn W`) held 7 s from standing; prints
the commanded and achieved speeds (metrics.json: speed_mm_s, the best 2 s
window; yaw_rate_deg_s), the error, and achieved/commanded x the ratio in
force, the table's new entry. About 2 s of CPU a run.

  tools/sim/measure_speed.py --sim out/build/tools/sim/strider-sim \\
      --elf out/build/src/strider_firmware_sprawl8.elf --robot sprawl8 \\
      --gait trot --walk 155 --turn 60 --ratio 4697 --turn-ratio 8780
"""
import argparse
import json
import os
import subprocess
import tempfile


def run(sim, elf, robot, gait, command):
    with tempfile.TemporaryDirectory() as d:
        sc = os.path.join(d, "run.scenario")
        with open(sc, "w") as f:
            f.write(f"robot {robot}\nduration 12\n"
                    "at 0.2 send $deadman off*cb77\\n\n"
                    f"at 0.4 send gait {gait}\\n\n"
                    f"at 4 send {command}\\n\nat 11 send stop\\n\n")
        args = [sim, sc, "--out", os.path.join(d, "out"), "--quiet"]
        if elf:
            args += ["--firmware", elf]
        subprocess.run(args, check=True)
        with open(os.path.join(d, "out", "metrics.json")) as f:
            return json.load(f)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sim", required=True)
    p.add_argument("--elf", default="", help="firmware ELF (default: library mode)")
    p.add_argument("--robot", required=True)
    p.add_argument("--gait", required=True)
    p.add_argument("--walk", type=float, help="forward speed [mm/s]")
    p.add_argument("--turn", type=float, help="turn rate [deg/s]")
    p.add_argument("--ratio", type=float, default=10000, help="linear ratio in force [1/10000]")
    p.add_argument("--turn-ratio", type=float, default=10000, help="turn ratio in force [1/10000]")
    a = p.parse_args()
    if a.walk:
        m = run(a.sim, a.elf, a.robot, a.gait, f"walk {a.walk:g}")
        got = m["speed_mm_s"]
        drift = 100 * abs(m["lateral_drift_mm"]) / max(m["distance_mm"], 1e-9)
        print(f"{a.robot} {a.gait} walk {a.walk:g} mm/s -> {got:.1f} mm/s ({100 * (got / a.walk - 1):+.1f} %), "
              f"drift {drift:.1f} %, ratio {a.ratio * got / a.walk:.0f}")
    if a.turn:
        m = run(a.sim, a.elf, a.robot, a.gait, f"turn {a.turn:g}")
        got = m["yaw_rate_deg_s"]
        print(f"{a.robot} {a.gait} turn {a.turn:g} deg/s -> {got:.1f} deg/s ({100 * (got / a.turn - 1):+.1f} %), "
              f"360 deg in {360 / got if got else float('inf'):.2f} s, ratio {a.turn_ratio * got / a.turn:.0f}")


if __name__ == "__main__":
    main()
