#!/usr/bin/env python3
"""Draws a gait run of `strider gait` to PNG: the footfall diagram, the foot
paths seen from above and from the side (body frame), and the static
stability margin over time.

    # from a CSV written by `strider gait ... > run.csv`
    python3 tools/plot_gait.py --csv run.csv --out run.png
    # or let the script run the CLI (path of the built binary)
    python3 tools/plot_gait.py --strider out/build/tools/cli/strider \\
        --robot sprawl8 --gait crawl --vx 60 --duration 4 --dt 0.02 --out crawl.png
    # the six swing trajectory shapes (docs/gaits.md)
    python3 tools/plot_gait.py --shapes --out shapes.png

Needs matplotlib (pip install matplotlib); uses the Agg backend, so no
display is needed. The CSV columns are those of ARCHITECTURE.md "Gaits":
t, then per leg i contact_i, foot_i_x, foot_i_y, foot_i_z, q_i_*, status_i,
then margin_mm.
"""
import argparse
import csv
import io
import math
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LEG_NAMES = {
    4: ["0 front left", "1 rear left", "2 rear right", "3 front right"],
    6: ["0 front left", "1 middle left", "2 rear left", "3 rear right", "4 middle right", "5 front right"],
}
STATUS_MARK = {"clamped": "o", "joint_limit": "x", "unreachable": "X"}


def read_csv(text):
    """Returns (t, legs, margin): legs[i] = dict of lists contact/x/y/z/status."""
    rows = list(csv.reader(io.StringIO(text)))
    if not rows or rows[0][0] != "t":
        raise SystemExit("plot_gait: not a strider gait CSV (first column must be t)")
    head = rows[0]
    index = {name: k for k, name in enumerate(head)}
    n = sum(1 for name in head if name.startswith("contact_"))
    t, margin = [], []
    legs = [{"contact": [], "x": [], "y": [], "z": [], "status": []} for _ in range(n)]
    for r in rows[1:]:
        if not r:
            continue
        t.append(float(r[0]))
        margin.append(float(r[index["margin_mm"]]))
        for i in range(n):
            leg = legs[i]
            leg["contact"].append(r[index[f"contact_{i}"]] == "1")
            leg["x"].append(float(r[index[f"foot_{i}_x"]]))
            leg["y"].append(float(r[index[f"foot_{i}_y"]]))
            leg["z"].append(float(r[index[f"foot_{i}_z"]]))
            leg["status"].append(r[index[f"status_{i}"]])
    return t, legs, margin


def stance_spans(t, contact):
    """(start, length) of each run of contact, for broken_barh."""
    spans, start = [], None
    dt = t[1] - t[0] if len(t) > 1 else 0.02
    for k, c in enumerate(contact):
        if c and start is None:
            start = t[k]
        if not c and start is not None:
            spans.append((start, t[k] - start))
            start = None
    if start is not None:
        spans.append((start, t[-1] - start + dt))
    return spans


def plot_run(t, legs, margin, title, out, dpi=110):
    n = len(legs)
    names = LEG_NAMES.get(n, [str(i) for i in range(n)])
    colors = plt.get_cmap("tab10").colors
    fig = plt.figure(figsize=(12, 9), constrained_layout=True)
    grid = fig.add_gridspec(3, 2, height_ratios=[1.0, 1.6, 0.9])
    fig.suptitle(title)

    ax = fig.add_subplot(grid[0, :])
    for i, leg in enumerate(legs):
        ax.broken_barh(stance_spans(t, leg["contact"]), (n - 1 - i - 0.4, 0.8), color=colors[i % 10])
    ax.set_yticks(range(n))
    ax.set_yticklabels(list(reversed(names)))
    ax.set_xlim(t[0], t[-1])
    ax.set_xlabel("t [s]")
    ax.set_title("footfall diagram (bar: foot on the ground)")

    top = fig.add_subplot(grid[1, 0])
    side = fig.add_subplot(grid[1, 1])
    for i, leg in enumerate(legs):
        c = colors[i % 10]
        top.plot(leg["x"], leg["y"], color=c, lw=1.0, label=names[i])
        side.plot(leg["x"], leg["z"], color=c, lw=1.0)
        for status, mark in STATUS_MARK.items():
            pts = [(x, y, z) for x, y, z, s in zip(leg["x"], leg["y"], leg["z"], leg["status"]) if s == status]
            if pts:
                top.plot([p[0] for p in pts], [p[1] for p in pts], mark, color=c, ms=2, alpha=0.5)
                side.plot([p[0] for p in pts], [p[2] for p in pts], mark, color=c, ms=2, alpha=0.5)
    top.set_aspect("equal", adjustable="datalim")
    top.set_xlabel("x [mm] (forward)")
    top.set_ylabel("y [mm] (left)")
    top.set_title("foot paths from above (body frame)")
    top.legend(fontsize=7, loc="center")
    side.set_xlabel("x [mm] (forward)")
    side.set_ylabel("z [mm] (up)")
    side.set_title("foot paths from the side; o clamped, x joint limit")

    ax = fig.add_subplot(grid[2, :])
    ax.plot(t, margin, color="k", lw=1.0)
    ax.axhline(0.0, color="r", lw=0.8, ls="--")
    ax.set_xlim(t[0], t[-1])
    ax.set_xlabel("t [s]")
    ax.set_ylabel("margin [mm]")
    ax.set_title("static stability margin (negative: CoM outside the support polygon)")
    fig.savefig(out, dpi=dpi)
    plt.close(fig)


# ---- swing shapes (lib/strider/gait/swing_trajectory.h) ----------------------

CHAMP_X = [-0.15, -0.2805, -0.3, -0.3, -0.3, 0.0, 0.0, 0.0, 0.3032, 0.3032, 0.2826, 0.15]
CHAMP_Y = [-0.5, -0.5, -0.3611, -0.3611, -0.3611, -0.3611, -0.3611, -0.3214, -0.3214, -0.3214, -0.5, -0.5]


def bezier(s):
    u = [0.0] + [x / 0.4 + 0.5 for x in CHAMP_X[1:-1]] + [1.0]
    w = [(y + 0.5) / 0.15 for y in CHAMP_Y]
    n = len(u) - 1
    bu = sum(math.comb(n, i) * s**i * (1 - s) ** (n - i) * u[i] for i in range(n + 1))
    bw = sum(math.comb(n, i) * s**i * (1 - s) ** (n - i) * w[i] for i in range(n + 1))
    return bu, bw / 1.03339


def shape_point(shape, s):
    if shape == "rectangle":
        if 3 * s < 1:
            return 0.0, 3 * s
        if 3 * s < 2:
            return 3 * s - 1, 1.0
        return 1.0, 3 - 3 * s
    if shape == "cycloid":
        a = 2 * math.pi * s
        return s - math.sin(a) / (2 * math.pi), (1 - math.cos(a)) / 2
    if shape == "parabola":
        return s, 4 * s * (1 - s)
    if shape == "bezier":
        return bezier(s)
    a = math.pi * s  # ellipse, semicircle
    return (1 - math.cos(a)) / 2, math.sin(a)


def plot_shapes(out, stride=36.0, height=20.0, dpi=110):
    shapes = ["rectangle", "semicircle", "ellipse", "cycloid", "parabola", "bezier"]
    fig, axes = plt.subplots(2, 3, figsize=(12, 6), constrained_layout=True)
    fig.suptitle(f"swing trajectories: stride {stride:g} mm, step height {height:g} mm; dots every 1/20 of the swing")
    for ax, shape in zip(axes.flat, shapes):
        apex = min(max(stride / 2, height / 2), height) if shape == "semicircle" else height
        xs, zs = [], []
        for k in range(201):
            u, w = shape_point(shape, k / 200)
            xs.append(-stride / 2 + u * stride)
            zs.append(w * apex)
        ax.plot(xs, zs, "b-", lw=1.2)
        dots = [shape_point(shape, k / 20) for k in range(21)]
        ax.plot([-stride / 2 + u * stride for u, _ in dots], [w * apex for _, w in dots], "b.", ms=4)
        ax.plot([-stride / 2, stride / 2], [0, 0], "k-", lw=2)  # stance
        ax.set_title(shape)
        ax.set_aspect("equal")
        ax.set_xlim(-stride * 0.75, stride * 0.75)
        ax.set_ylim(-3, max(height, stride / 2) * 1.15)
        ax.set_xlabel("along the step [mm]")
        ax.set_ylabel("height [mm]")
    fig.savefig(out, dpi=dpi)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--csv", help="CSV written by strider gait ('-' for stdin)")
    p.add_argument("--strider", help="path of the strider binary, to run it instead of reading a CSV")
    p.add_argument("--robot")
    p.add_argument("--gait")
    p.add_argument("--vx", default="0")
    p.add_argument("--vy", default="0")
    p.add_argument("--wz", default="0")
    p.add_argument("--speed", default="100")
    p.add_argument("--duration", default="4")
    p.add_argument("--dt", default="0.02")
    p.add_argument("--scalar", default="float")
    p.add_argument("--trajectory")
    p.add_argument("--title")
    p.add_argument("--shapes", action="store_true", help="draw the six swing trajectory shapes instead")
    p.add_argument("--out", required=True, help="PNG to write")
    p.add_argument("--dpi", type=int, default=110)
    a = p.parse_args()

    if a.shapes:
        plot_shapes(a.out, dpi=a.dpi)
        return 0
    if a.csv:
        text = sys.stdin.read() if a.csv == "-" else open(a.csv, encoding="utf-8").read()
        title = a.title or a.csv
    elif a.strider and a.robot and a.gait:
        cmd = [a.strider, "gait", "--robot", a.robot, "--gait", a.gait, "--vx", a.vx, "--vy", a.vy, "--wz", a.wz,
               "--speed", a.speed, "--duration", a.duration, "--dt", a.dt, "--scalar", a.scalar]
        if a.trajectory:
            cmd += ["--trajectory", a.trajectory]
        run = subprocess.run(cmd, capture_output=True, text=True, check=False)
        if run.returncode != 0:
            sys.stderr.write(run.stderr)
            return run.returncode
        sys.stderr.write(run.stderr)
        text = run.stdout
        title = a.title or (f"{a.robot} {a.gait}: vx {a.vx} mm/s, vy {a.vy} mm/s, wz {a.wz} deg/s"
                            + (f", {a.trajectory}" if a.trajectory else ""))
    else:
        p.error("give --csv FILE, or --strider PATH with --robot and --gait, or --shapes")
    t, legs, margin = read_csv(text)
    if not t:
        raise SystemExit("plot_gait: the CSV has no rows")
    plot_run(t, legs, margin, title, a.out, a.dpi)
    return 0


if __name__ == "__main__":
    sys.exit(main())
