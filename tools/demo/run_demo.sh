#!/usr/bin/env bash
# The demo: one stride of a foot for two robots, every point solved by the
# `strider` CLI in body coordinates, in float and in fixed point side by side.
# - hexapod18 (seed 002), front-left leg: seed 001's rectangular foot path
#   (lift, swing forward, lower, push back) around the model's standing foot.
# - sprawl8 (seed 000), front-left leg: seed 000 fig. 2B's A -> B -> C -> D
#   loop; a 2-DOF foot lives on a torus, so the path is laid on it (lift by
#   the knee, swing by the hip) and IK must find the same point again.
set -euo pipefail
BUILD="${1:?usage: run_demo.sh BUILD_DIR}"
STRIDER="$BUILD/tools/cli/strider"

python3 - "$STRIDER" <<'PY'
import json, math, subprocess, sys

strider = sys.argv[1]

def cli(*args, stdin=None):
    out = subprocess.run([strider, *args], input=stdin, capture_output=True, text=True, check=True).stdout
    return [json.loads(l) for l in out.splitlines()]

def solve(robot, points, scalar):
    text = "".join(f"{x:.4f} {y:.4f} {z:.4f}\n" for x, y, z in points)
    return cli("ik", "--robot", robot, "--leg", "0", "--frame", "body", "--scalar", scalar, "--stdin", stdin=text)

def segment(corners, n):
    pts = []
    for a, b in zip(corners, corners[1:]):
        pts += [tuple(a[k] + (b[k] - a[k]) * i / n for k in range(3)) for i in range(n)]
    return pts

def show(title, robot, path):
    flt, fix = solve(robot, path, "float"), solve(robot, path, "fixed")
    print(title)
    print(f"{'target x':>9} {'y':>8} {'z':>8} | {'status':>8} {'joints (float) [deg]':>26} | {'fixed - float':>13} [mm]")
    worst, statuses = 0.0, {}
    for p, a, b in zip(path, flt, fix):
        statuses[a["status"]] = statuses.get(a["status"], 0) + 1
        if a["joints_deg"] is None:
            print(f"{p[0]:9.2f} {p[1]:8.2f} {p[2]:8.2f} | {a['status']:>8}")
            continue
        d = math.dist(a["foot_mm"], b["foot_mm"])
        worst = max(worst, d)
        q = " ".join(f"{v:8.3f}" for v in a["joints_deg"])
        print(f"{p[0]:9.2f} {p[1]:8.2f} {p[2]:8.2f} | {a['status']:>8} {q:>26} | {d:13.4f}")
    print(f"{len(path)} points: {statuses}; worst fixed-vs-float foot difference {worst:.4f} mm\n")

# hexapod18: rectangle step, stride 40 mm along body x, lift 30 mm.
leg = cli("legs", "--robot", "hexapod18")[0]
x0, y0, z0 = leg["stand_mm"]
s, h = 20.0, 30.0
show("hexapod18 front-left foot, rectangular step (seed 001 fig. 8), body frame [mm]", "hexapod18",
     segment([(x0 - s, y0, z0), (x0 - s, y0, z0 + h), (x0 + s, y0, z0 + h), (x0 + s, y0, z0), (x0 - s, y0, z0)], 6))

# sprawl8: A (stand) -> B (lifted) -> C (lifted, swung) -> D (down, swung) -> A.
leg = cli("legs", "--robot", "sprawl8")[0]
t1s, t2s = leg["stand_joints_deg"][:2]
corners = [(t1s - 12, t2s), (t1s - 12, t2s + 20), (t1s + 12, t2s + 20), (t1s + 12, t2s), (t1s - 12, t2s)]
path = []
for (a1, a2), (b1, b2) in zip(corners, corners[1:]):
    for i in range(6):
        j = f"{a1 + (b1 - a1) * i / 6:.4f},{a2 + (b2 - a2) * i / 6:.4f}"
        path.append(tuple(cli("fk", "--robot", "sprawl8", "--leg", "0", "--frame", "body", "--joints", j)[0]["foot_mm"]))
show("sprawl8 front-left foot, seed 000 fig. 2B loop A-B-C-D, body frame [mm]", "sprawl8", path)
PY
