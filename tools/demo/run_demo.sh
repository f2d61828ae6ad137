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
"$SIM" "$SCENARIO" --out "$OUT" --firmware "$ELF" --quiet   # the summary is at the end

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

echo
"$PY" "$ROOT/tools/demo/summary.py" "$OUT"
echo "files: $OUT"
