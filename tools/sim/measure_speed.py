#!/usr/bin/env python3
"""Re-measures the speed corrections of lib/strider/gait/speed_correction.h.

For a model and gait: the model's firmware on the virtual Mega (firmware
mode), the gait, then `walk V` (or `turn W`, or an RC pad button at a
slider step) held 7 s from standing (the pad's speed as `status` reports it); prints the commanded and achieved
speeds, the error, and achieved/commanded x the ratio in force, the table's
new entry. About 2 s of CPU a run.

Achieved is the steady speed: the body's displacement (or unwrapped yaw)
from 3 s after the command, once the speed ramp is over, to the stop
(trace.csv), over that time. metrics.json's best 2 s window flatters gaits
that rock the body to and fro; it is printed alongside (best2s).

  tools/sim/measure_speed.py --sim out/build/tools/sim/strider-sim \\
      --elf out/build/src/strider_firmware_sprawl8.elf --robot sprawl8 \\
      --gait trot --walk 155 --turn 60 --ratio 4697 --turn-ratio 8780
  tools/sim/measure_speed.py ... --robot sprawl8 --pad F --slider q
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import tempfile

COMMAND_S = 4.0   # the command (or button) goes out
STEADY_S = 7.0    # the ramp is over: the steady window starts
STOP_S = 11.0     # stop: the window ends


def steady(trace_path, t0=STEADY_S, t1=STOP_S):
    """Mean speed [mm/s], mean yaw rate [deg/s] and lateral drift [mm] from t0 to t1."""
    rows = []
    with open(trace_path) as f:
        for r in csv.DictReader(f):
            t = float(r["t"])
            if t0 <= t <= t1:
                rows.append((t, float(r["x_mm"]), float(r["y_mm"]), float(r["yaw_deg"])))
    (ta, xa, ya, _), (tb, xb, yb, _) = rows[0], rows[-1]
    yaw = 0.0
    for (_, _, _, p), (_, _, _, q) in zip(rows, rows[1:]):
        d = q - p
        yaw += d - 360.0 * round(d / 360.0)
    dt = tb - ta
    dist = math.hypot(xb - xa, yb - ya)
    # Drift: the displacement across the start heading.
    h = math.radians(rows[0][3])
    lateral = -(xb - xa) * math.sin(h) + (yb - ya) * math.cos(h)
    return dist / dt, yaw / dt, lateral, dist


def run(sim, elf, robot, gait, command, slider="", window_s=STOP_S - STEADY_S, shift_s=0.0, imu=False):
    """One run: the command held from COMMAND_S + shift_s; the steady window
    is window_s long from STEADY_S + shift_s (slow speeds take a longer one:
    the body's sway within a step is then a smaller part of the displacement).
    imu: an MPU-6050 fitted (the firmware's heading hold, docs/imu.md)."""
    command_s = COMMAND_S + shift_s
    steady_s = STEADY_S + shift_s
    stop_s = steady_s + window_s
    with tempfile.TemporaryDirectory() as d:
        sc = os.path.join(d, "run.scenario")
        with open(sc, "w") as f:
            f.write(f"robot {robot}\nduration {stop_s + 1:g}\n{'imu on' + chr(10) if imu else ''}"
                    "at 0.2 send $deadman off*cb77\\n\n")
            if gait:
                f.write(f"at 0.4 send gait {gait}\\n\n")
            if slider:
                f.write(f"at 0.6 send {slider}\n")
            end = "S" if slider else "stop\\n"
            f.write(f"at {command_s:g} send {command}\nat {stop_s - 0.5:g} send status\\n\n"
                    f"at {stop_s:g} send {end}\n")
        args = [sim, sc, "--out", os.path.join(d, "out"), "--quiet"]
        if elf:
            args += ["--firmware", elf]
        subprocess.run(args, check=True)
        with open(os.path.join(d, "out", "metrics.json")) as f:
            m = json.load(f)
        with open(os.path.join(d, "out", "robot.log")) as f:
            status = [line for line in f if re.search(r"\bok status\b", line)]
        # The status sent before the stop: the gait walked, the command in force.
        fields = dict(re.findall(r" (\w+)=(\S+)", status[-1])) if status else {}
        m["gait_walked"] = fields.get("gait", "")
        m["commanded_vx"] = float(fields.get("vx", "nan"))
        m["commanded_wz"] = float(fields.get("wz", "nan"))
        return m, steady(os.path.join(d, "out", "trace.csv"), steady_s, stop_s)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sim", required=True)
    p.add_argument("--elf", default="", help="firmware ELF (default: library mode)")
    p.add_argument("--robot", required=True)
    p.add_argument("--gait", default="", help="gait (default: the model's, or the pad's choice)")
    p.add_argument("--walk", type=float, help="forward speed [mm/s]")
    p.add_argument("--turn", type=float, help="turn rate [deg/s]")
    p.add_argument("--pad", help="RC button: F (forward) or G (turn anticlockwise)")
    p.add_argument("--slider", default="q", help="RC slider byte: 0-9, q (100 %%)")
    p.add_argument("--ratio", type=float, default=10000, help="linear ratio in force [1/10000]")
    p.add_argument("--turn-ratio", type=float, default=10000, help="turn ratio in force [1/10000]")
    p.add_argument("--window", type=float, default=STOP_S - STEADY_S, help="steady window [s]")
    a = p.parse_args()
    pct = 100 if a.slider == "q" else 10 * int(a.slider)
    name = f"{a.robot} {a.gait or '(default)'}"
    walk = a.walk or (155 * pct / 100 if a.pad == "F" else None)
    turn = a.turn or (60 * pct / 100 if a.pad == "G" else None)
    if walk:
        cmd = ("F", a.slider) if a.pad else (f"walk {walk:g}\\n", "")
        m, (got, _, lateral, dist) = run(a.sim, a.elf, a.robot, a.gait, *cmd, window_s=a.window)
        walk = m["commanded_vx"] if a.pad else walk  # the pad's speed for this model (status)
        drift = 100 * abs(lateral) / max(dist, 1e-9)
        print(f"{name} walk {walk:g} mm/s -> {got:.1f} mm/s ({100 * (got / walk - 1):+.1f} %), "
              f"drift {drift:.1f} %, best2s {m['speed_mm_s']:.1f}, ratio {a.ratio * got / walk:.0f}")
    if turn:
        cmd = ("G", a.slider) if a.pad else (f"turn {turn:g}\\n", "")
        m, (_, got, _, _) = run(a.sim, a.elf, a.robot, a.gait, *cmd, window_s=a.window)
        turn = m["commanded_wz"] if a.pad else turn
        print(f"{name} turn {turn:g} deg/s -> {got:.1f} deg/s ({100 * (got / turn - 1):+.1f} %), "
              f"360 deg in {360 / got if got else float('inf'):.2f} s, best2s {m['yaw_rate_deg_s']:.1f}, "
              f"ratio {a.turn_ratio * got / turn:.0f}")


if __name__ == "__main__":
    main()
