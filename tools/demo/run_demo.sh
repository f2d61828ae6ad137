#!/usr/bin/env bash
# The demo, Strider's main job on a desk: the real sprawl8 firmware runs on the
# virtual Mega (tools/vbench) and drives the Bullet model of the robot
# (tools/sim) in lock-step: its PCA9685 pulses move the joint motors, its
# HC-SR04 hears a ray cast in the world. The scenario walks forward, turns,
# walks on into a wall and lets obstacle avoidance take it round.
# Writes out/demo/: metrics.json, trace.csv, robot.log (what the robot said),
# run.gif (top and side views) and plots.png; prints a short summary.
set -euo pipefail
BUILD="${1:?usage: run_demo.sh BUILD_DIR [PYTHON]}"
PY="${2:-python3}"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
OUT="$ROOT/out/demo"
ELF="$BUILD/src/strider_firmware_sprawl8.elf"
SIM="$BUILD/tools/sim/strider-sim"
SCENARIO="$ROOT/tools/sim/scenarios/sprawl8_demo.scenario"

for f in "$ELF" "$SIM"; do
  [ -x "$f" ] || [ -f "$f" ] || { echo "demo: $f was not built (needs gcc-avr, arduino-core-avr, simavr, libbullet-dev)" >&2; exit 1; }
done

mkdir -p "$OUT"
echo "== sprawl8 firmware on the virtual Mega, in the Bullet world: $(basename "$SCENARIO")"
"$SIM" "$SCENARIO" --out "$OUT" --firmware "$ELF"

echo
echo "== what the robot said over Bluetooth"
cat "$OUT/robot.log"

echo
echo "== pictures"
if "$PY" -c 'import matplotlib, PIL' 2>/dev/null; then
  "$PY" "$ROOT/tools/sim/render_trace.py" "$OUT"
else
  echo "no matplotlib/pillow for $PY: skipped run.gif and plots.png"
fi

"$PY" - "$OUT/metrics.json" "$OUT/trace.csv" <<'PY'
import csv, json, math, sys
m = json.load(open(sys.argv[1]))
rows = [r for r in csv.DictReader(open(sys.argv[2])) if float(r["t"]) >= m["ready_s"]]
# The path without the body's sway from step to step: the track averaged over
# 1 s (50 rows of 20 ms), then its length.
half = 25
xs, ys = [float(r["x_mm"]) for r in rows], [float(r["y_mm"]) for r in rows]
avg = [(sum(xs[max(0, k - half):k + half + 1]) / len(xs[max(0, k - half):k + half + 1]),
        sum(ys[max(0, k - half):k + half + 1]) / len(ys[max(0, k - half):k + half + 1])) for k in range(len(rows))]
track = sum(math.dist(avg[k - 1], avg[k]) for k in range(1, len(avg)))
steps = round(m["sim_time_s"] / 0.004)  # strider-sim's default physics step
print()
print(f"== summary (from {m['ready_s']:.1f} s, when the robot had stood up, to the end)")
print(f"displacement, start to end:     {m['distance_mm']:.0f} mm (straight line)")
print(f"path walked (forward, turn, round the wall): {track:.0f} mm "
      f"(the body centre's track over 1 s; {m['path_mm']:.0f} mm with the sway of every step)")
print(f"top speed {m['speed_mm_s']:.0f} mm/s (best 2 s), turned {m['heading_change_deg']:+.0f} deg")
if m.get("min_clearance_mm") is not None:
    print(f"closest to the wall: body {m['min_clearance_mm']:.0f} mm, legs {m['min_robot_clearance_mm']:.0f} mm, "
          f"{m['collisions']} contacts with it")
print(f"fell: {'yes' if m['fell'] else 'no'}; max tilt {m['max_tilt_deg']:.1f} deg")
if m.get("odometry_mm") is not None:
    print(f"gait odometry {m['odometry_mm']:.0f} mm, the body {m['odometry_error_pct']:.1f} % short of it")
print(f"speed: {m['sim_time_s']:.0f} s simulated in {m['wall_time_s']:.1f} s of wall clock "
      f"({m['sim_time_s'] / max(1e-9, m['wall_time_s']):.1f}x real time); "
      f"{m['cpu_time_s']:.1f} s of CPU ({m['real_time_factor']:.1f}x per CPU second)")
print(f"physics: {m['solver_fallbacks']} of {steps} steps solved by PGS when the exact solver gave up on them")
PY
echo "files: $OUT"
