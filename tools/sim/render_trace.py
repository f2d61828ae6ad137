#!/usr/bin/env python3
"""Pictures of a strider-sim run for people.

Reads DIR/trace.csv and DIR/scene.json (written by strider-sim --out DIR) and writes
  DIR/run.gif        top view and a side view along the robot's heading, animated (Pillow)
  DIR/run.mp4        the same as a video, when ffmpeg is installed (--mp4)
  DIR/plots.png      path, speed, heading and static stability margin over time

Needs matplotlib and Pillow: Debian's python3-matplotlib and python3-pil, or
`pip install matplotlib pillow` in a virtual environment.

  python3 tools/sim/render_trace.py DIR [--fps 10] [--mp4] [--no-gif]
"""

import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch, Polygon, Rectangle
except ImportError:  # pragma: no cover
    sys.exit("render_trace.py needs matplotlib (Debian: python3-matplotlib, or pip install matplotlib)")


def load(run_dir):
    with open(os.path.join(run_dir, "scene.json")) as f:
        scene = json.load(f)
    with open(os.path.join(run_dir, "trace.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    if not rows:
        sys.exit("empty trace")
    return scene, rows


def body_corners(scene, row, z_level=None):
    """Body outline (top view) in world coordinates."""
    length, width, _ = scene["body_mm"]
    yaw = math.radians(row["yaw_deg"])
    c, s = math.cos(yaw), math.sin(yaw)
    pts = []
    for dx, dy in ((length / 2, width / 2), (-length / 2, width / 2), (-length / 2, -width / 2), (length / 2, -width / 2)):
        pts.append((row["x_mm"] + c * dx - s * dy, row["y_mm"] + s * dx + c * dy))
    return pts


def hip_world(scene, row, i):
    hx, hy, hz = scene["hips_mm"][i]
    yaw, pitch, roll = (math.radians(row[k]) for k in ("yaw_deg", "pitch_deg", "roll_deg"))
    # R = Rz(yaw) Ry(pitch) Rx(roll), body -> world
    cy, sy, cp, sp, cr, sr = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch), math.cos(roll), math.sin(roll)
    x = cy * cp * hx + (cy * sp * sr - sy * cr) * hy + (cy * sp * cr + sy * sr) * hz
    y = sy * cp * hx + (sy * sp * sr + cy * cr) * hy + (sy * sp * cr - cy * sr) * hz
    z = -sp * hx + cp * sr * hy + cp * cr * hz
    return row["x_mm"] + x, row["y_mm"] + y, row["z_mm"] + z


def ray_box(px, py, hx, hy, box):
    """The distances [s0, s1] along the ray p + s h (h a unit vector) inside
    the axis-aligned box (x, y, sx, sy, sz) seen from above; None if it misses."""
    x, y, sx, sy, _ = box
    lo, hi = -math.inf, math.inf
    for p, h, c, size in ((px, hx, x, sx), (py, hy, y, sy)):
        a, b = c - size / 2, c + size / 2
        if abs(h) < 1e-12:
            if not a <= p <= b:
                return None
            continue
        t0, t1 = sorted(((a - p) / h, (b - p) / h))
        lo, hi = max(lo, t0), min(hi, t1)
    return (lo, hi) if lo <= hi else None


def side_section(scene, row, box, half_width):
    """Where an obstacle is in the side view: the distances along the heading
    [s0, s1] at which a strip of half_width either side of the body's centre
    line meets it, or None when nothing in the strip (nothing in the way)."""
    yaw = math.radians(row["yaw_deg"])
    hx, hy = math.cos(yaw), math.sin(yaw)
    hits = []
    for off in (-half_width, -half_width / 2, 0.0, half_width / 2, half_width):
        r = ray_box(row["x_mm"] - hy * off, row["y_mm"] + hx * off, hx, hy, box)
        if r is not None:
            hits.append(r)
    if not hits:
        return None
    return min(h[0] for h in hits), max(h[1] for h in hits)


def convex_hull(points):
    pts = sorted(set(points))
    if len(pts) <= 2:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def segment_distance(p, a, b):
    ax, ay = b[0] - a[0], b[1] - a[1]
    L2 = ax * ax + ay * ay
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / L2))
    return math.hypot(p[0] - a[0] - t * ax, p[1] - a[1] - t * ay)


def stability_margin(row, legs):
    """Signed distance [mm] of the CoM's ground projection to the support
    polygon of the feet in contact (positive inside); None with < 3 feet."""
    feet = [(row[f"foot_{i}_x"], row[f"foot_{i}_y"]) for i in range(legs) if row[f"contact_{i}"] > 0.5]
    hull = convex_hull(feet)
    if len(hull) < 3:
        return None
    p = (row["com_x_mm"], row["com_y_mm"])
    d = min(segment_distance(p, hull[k], hull[(k + 1) % len(hull)]) for k in range(len(hull)))
    inside = all(
        (hull[(k + 1) % len(hull)][0] - hull[k][0]) * (p[1] - hull[k][1])
        - (hull[(k + 1) % len(hull)][1] - hull[k][1]) * (p[0] - hull[k][0])
        >= 0
        for k in range(len(hull))
    )
    return d if inside else -d


def side_window(scene, rows):
    """The side view's span along the heading [mm]: behind the body by its legs'
    reach, ahead by the reach and 400 mm (the avoidance stops 200 mm short)."""
    legs = int(scene["legs"])
    reach = max(
        math.hypot(r[f"foot_{i}_x"] - r["x_mm"], r[f"foot_{i}_y"] - r["y_mm"]) for r in rows for i in range(legs)
    )
    reach = max(reach, scene["body_mm"][0] / 2)
    return -(reach + 40), reach + 400, reach


class Scene:
    """Persistent artists of the top and side views; update() moves them to
    one trace row (redrawing axes and ticks per frame would cost 5x more).
    The side view looks at the robot from its right, along its heading: its
    horizontal axis is the distance ahead of the body centre, and it shows an
    obstacle where the strip the robot sweeps (its width with the feet) meets
    it, so a wall is drawn at its distance ahead while it is in the way and
    not at all beside it."""

    def __init__(self, fig, ax_top, ax_side, scene, rows, bounds):
        self.scene, self.rows = scene, rows
        self.legs = int(scene["legs"])
        xmin, xmax, ymin, ymax, zmax = bounds
        ax_top.set_xlim(xmin, xmax)
        ax_top.set_ylim(ymin, ymax)
        ax_top.set_aspect("equal")
        back, front, self.half_width = side_window(scene, rows)
        ax_side.set_xlim(back, front)
        ax_side.set_ylim(-10, zmax)
        ax_side.set_aspect("equal")
        ax_side.set_title("side view along the heading: distance ahead of the body [mm], height [mm]", fontsize=9)
        ax_side.axhline(0, color="0.3", lw=1)
        self.side_obstacles = []
        for ob in scene["obstacles_mm"]:
            x, y, sx, sy, sz = ob
            ax_top.add_patch(Rectangle((x - sx / 2, y - sy / 2), sx, sy, color="0.55"))
            patch = Rectangle((0, 0), 1, sz, color="0.55", visible=False)
            ax_side.add_patch(patch)
            self.side_obstacles.append((ob, patch))
        self.title = ax_top.set_title("")
        (self.path,) = ax_top.plot([], [], color="tab:blue", lw=0.8)
        self.body = Polygon([[0, 0]] * 4, closed=True, fc="tab:orange", ec="k", alpha=0.8)
        ax_top.add_patch(self.body)
        self.top_legs = [ax_top.plot([], [], color="k", lw=1.5)[0] for _ in range(self.legs)]
        self.top_feet = [ax_top.plot([], [], "o", ms=5)[0] for _ in range(self.legs)]
        self.side_legs = [ax_side.plot([], [], color="k", lw=1.5)[0] for _ in range(self.legs)]
        self.side_feet = [ax_side.plot([], [], "o", ms=4)[0] for _ in range(self.legs)]
        (self.com,) = ax_top.plot([], [], "+", color="k", ms=8)
        (self.side_body,) = ax_side.plot([], [], color="tab:orange", lw=max(2.0, scene["body_mm"][2] / 6))
        handles = [
            Line2D([], [], color="tab:blue", lw=0.8, label="path of the body centre"),
            Patch(fc="tab:orange", ec="k", label="body"),
            Line2D([], [], color="k", lw=1.5, label="leg (hip to foot)"),
            Line2D([], [], ls="", marker="o", color="tab:green", label="foot on the ground"),
            Line2D([], [], ls="", marker="o", color="tab:red", label="foot in the air"),
            Line2D([], [], ls="", marker="+", color="k", ms=8, label="centre of mass"),
        ]
        if scene["obstacles_mm"]:
            handles.append(Patch(color="0.55", label="obstacle"))
        fig.legend(handles=handles, loc="lower center", ncol=4, fontsize=7, frameon=False)

    def update(self, k):
        scene, row = self.scene, self.rows[k]
        self.title.set_text(f"{scene['robot']}  t = {row['t']:.2f} s   top view [mm]")
        self.path.set_data([r["x_mm"] for r in self.rows[: k + 1]], [r["y_mm"] for r in self.rows[: k + 1]])
        self.body.set_xy(body_corners(scene, row))
        for i in range(self.legs):
            hx, hy, hz = hip_world(scene, row, i)
            fx, fy, fz = row[f"foot_{i}_x"], row[f"foot_{i}_y"], row[f"foot_{i}_z"]
            colour = "tab:green" if row[f"contact_{i}"] > 0.5 else "tab:red"
            self.top_legs[i].set_data([hx, fx], [hy, fy])
            self.top_feet[i].set_data([fx], [fy])
            self.top_feet[i].set_color(colour)
            self.side_legs[i].set_data([self.ahead(row, hx, hy), self.ahead(row, fx, fy)], [hz, fz])
            self.side_feet[i].set_data([self.ahead(row, fx, fy)], [fz])
            self.side_feet[i].set_color(colour)
        self.com.set_data([row["com_x_mm"]], [row["com_y_mm"]])
        length = scene["body_mm"][0]
        pitch = math.radians(row["pitch_deg"])
        half = length / 2 * math.cos(pitch)
        self.side_body.set_data(
            [-half, half], [row["z_mm"] + length / 2 * math.sin(pitch), row["z_mm"] - length / 2 * math.sin(pitch)]
        )
        for ob, patch in self.side_obstacles:
            hit = side_section(scene, row, ob, self.half_width)
            patch.set_visible(hit is not None)
            if hit is not None:
                patch.set_x(hit[0])
                patch.set_width(hit[1] - hit[0])

    @staticmethod
    def ahead(row, x, y):
        """Distance of a world point ahead of the body centre along the heading [mm]."""
        yaw = math.radians(row["yaw_deg"])
        return (x - row["x_mm"]) * math.cos(yaw) + (y - row["y_mm"]) * math.sin(yaw)


def bounds_of(scene, rows):
    xs = [r["x_mm"] for r in rows] + [r[f"foot_{i}_x"] for r in rows for i in range(int(scene["legs"]))]
    ys = [r["y_mm"] for r in rows] + [r[f"foot_{i}_y"] for r in rows for i in range(int(scene["legs"]))]
    for x, y, sx, sy, sz in scene["obstacles_mm"]:
        xs += [x - sx / 2, x + sx / 2]
        ys += [y - sy / 2, y + sy / 2]
    pad = 60
    xmin, xmax, ymin, ymax = min(xs) - pad, max(xs) + pad, min(ys) - pad, max(ys) + pad
    zmax = max(max(r["z_mm"] for r in rows) + 80, max([o[4] for o in scene["obstacles_mm"]] + [0]) + 20)
    return xmin, xmax, ymin, ymax, zmax


def render_frames(scene, rows, fps):
    from PIL import Image

    dt = rows[1]["t"] - rows[0]["t"] if len(rows) > 1 else 0.02
    step = max(1, int(round(1.0 / (fps * dt))))
    bounds = bounds_of(scene, rows)
    xmin, xmax, ymin, ymax, zmax = bounds
    top_h = (ymax - ymin) / (xmax - xmin)
    back, front, _ = side_window(scene, rows)
    side_h = (zmax + 10) / (front - back)
    width_in = 7.0
    fig = plt.figure(figsize=(width_in, width_in * (top_h + side_h) + 1.5), dpi=80)
    gs = fig.add_gridspec(2, 1, height_ratios=[max(top_h, 0.05), max(side_h, 0.05)])
    ax_top = fig.add_subplot(gs[0])
    ax_side = fig.add_subplot(gs[1])
    frames = []
    view = Scene(fig, ax_top, ax_side, scene, rows, bounds)
    view.update(0)
    fig.tight_layout(rect=(0, 0.07, 1, 1))  # once: the layout does not change between frames; room for the legend
    for k in range(0, len(rows), step):
        view.update(k)
        fig.canvas.draw()
        w, h = fig.canvas.get_width_height()
        frames.append(Image.frombytes("RGBA", (w, h), bytes(fig.canvas.buffer_rgba())).convert("RGB"))
    plt.close(fig)
    return frames


def write_gif(frames, path, fps):
    # One palette for the whole film and no dithering: the drawings are flat
    # colours, so this keeps them crisp and the file small.
    from PIL import Image

    sample = frames[:: max(1, len(frames) // 8)]
    w, h = frames[0].size
    sheet = Image.new("RGB", (w, h * len(sample)))
    for k, f in enumerate(sample):
        sheet.paste(f, (0, h * k))
    palette = sheet.quantize(colors=128, dither=0)
    pal = [f.quantize(palette=palette, dither=0) for f in frames]
    pal[0].save(path, save_all=True, append_images=pal[1:], duration=int(1000 / fps), loop=0, optimize=True)


def write_mp4(frames, path, fps):
    ffmpeg = shutil.which("ffmpeg")
    if ffmpeg is None:
        print("render_trace.py: no ffmpeg, skipping the MP4 (Debian: apt-get install ffmpeg)", file=sys.stderr)
        return False
    w, h = frames[0].size
    w2, h2 = w - w % 2, h - h % 2
    cmd = [ffmpeg, "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{w2}x{h2}", "-r", str(fps),
           "-i", "-", "-pix_fmt", "yuv420p", "-vcodec", "libx264", path]
    proc = subprocess.Popen(cmd, stdin=subprocess.PIPE)
    for f in frames:
        proc.stdin.write(f.crop((0, 0, w2, h2)).tobytes())
    proc.stdin.close()
    return proc.wait() == 0


def has_odometry(run_dir, rows):
    """Library mode records the gait engine's odometry; firmware mode has none
    (metrics.json `odometry_mm` null): no odometry line is drawn then."""
    try:
        with open(os.path.join(run_dir, "metrics.json")) as f:
            return json.load(f).get("odometry_mm") is not None
    except (OSError, ValueError):
        return any(r["odo_x_mm"] or r["odo_y_mm"] or r["odo_yaw_deg"] for r in rows)


def write_plots(scene, rows, path, odometry=True):
    legs = int(scene["legs"])
    t = [r["t"] for r in rows]
    fig, ax = plt.subplots(2, 2, figsize=(10, 7), dpi=90)
    a = ax[0][0]
    for k, (x, y, sx, sy, sz) in enumerate(scene["obstacles_mm"]):
        a.add_patch(Rectangle((x - sx / 2, y - sy / 2), sx, sy, color="0.6", label="obstacle" if k == 0 else None))
    a.plot([r["x_mm"] for r in rows], [r["y_mm"] for r in rows], label="body centre")
    if odometry:
        a.plot([r["odo_x_mm"] + rows[0]["x_mm"] for r in rows], [r["odo_y_mm"] + rows[0]["y_mm"] for r in rows], "--",
               lw=0.8, label="gait odometry")
    a.plot([rows[0]["x_mm"]], [rows[0]["y_mm"]], "go", label="start")
    a.plot([rows[-1]["x_mm"]], [rows[-1]["y_mm"]], "rs", label="end")
    a.set_aspect("equal", adjustable="datalim")
    a.set_title("path [mm]")
    a.legend(fontsize=8)
    a = ax[0][1]
    speed = [math.hypot(r["vx_mm_s"], r["vy_mm_s"]) for r in rows]
    win = max(1, int(round(1.0 / max(1e-6, t[1] - t[0])))) if len(t) > 1 else 1
    # Displacement over the last second: the sway of each step cancels (the
    # metric speed_mm_s is the best 2 s window of the same).
    smooth = [
        math.hypot(rows[k]["x_mm"] - rows[max(0, k - win)]["x_mm"], rows[k]["y_mm"] - rows[max(0, k - win)]["y_mm"])
        / max(1e-9, t[k] - t[max(0, k - win)])
        for k in range(len(rows))
    ]
    a.plot(t, speed, lw=0.5, color="0.7", label="instant")
    a.plot(t, smooth, label="1 s displacement")
    a.set_title("speed [mm/s]")
    a.set_xlabel("t [s]")
    a.legend(fontsize=8)
    a = ax[1][0]
    a.plot(t, [r["yaw_deg"] for r in rows], label="heading")
    if odometry:
        a.plot(t, [r["odo_yaw_deg"] + rows[0]["yaw_deg"] for r in rows], "--", lw=0.8, label="gait odometry")
    a.set_title("heading [deg]")
    a.set_xlabel("t [s]")
    a.legend(fontsize=8)
    a = ax[1][1]
    margins = [stability_margin(r, legs) for r in rows]
    a.plot([ti for ti, m in zip(t, margins) if m is not None], [m for m in margins if m is not None], ".", ms=2,
           label="margin (negative: CoM outside)")
    a.axhline(0, color="r", lw=0.8, label="0: CoM on the polygon's edge")
    a.set_title("static stability margin [mm] (CoM to support polygon)")
    a.legend(fontsize=8, loc="center right")
    a.set_xlabel("t [s]")
    fig.suptitle(f"{scene['robot']}")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir", help="folder written by strider-sim --out")
    ap.add_argument("--fps", type=float, default=10.0, help="frames per second of the animation (default 10)")
    ap.add_argument("--mp4", action="store_true", help="also write run.mp4 (needs ffmpeg)")
    ap.add_argument("--no-gif", action="store_true", help="only the plots")
    args = ap.parse_args()
    scene, rows = load(args.run_dir)
    write_plots(scene, rows, os.path.join(args.run_dir, "plots.png"), has_odometry(args.run_dir, rows))
    written = ["plots.png"]
    if args.mp4 and shutil.which("ffmpeg") is None:
        print("render_trace.py: no ffmpeg, skipping the MP4 (Debian: apt-get install ffmpeg)", file=sys.stderr)
        args.mp4 = False
    if not args.no_gif or args.mp4:
        try:
            frames = render_frames(scene, rows, args.fps)
        except ImportError:
            sys.exit("render_trace.py needs Pillow for the animation (Debian: python3-pil, or pip install pillow)")
        if not args.no_gif:
            write_gif(frames, os.path.join(args.run_dir, "run.gif"), args.fps)
            written.append("run.gif")
        if args.mp4 and write_mp4(frames, os.path.join(args.run_dir, "run.mp4"), args.fps):
            written.append("run.mp4")
    print("wrote " + ", ".join(os.path.join(args.run_dir, w) for w in written))


if __name__ == "__main__":
    main()
