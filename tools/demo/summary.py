#!/usr/bin/env python3
"""The demo's end-of-run summary, from what strider-sim wrote in a run folder:
metrics.json, trace.csv and robot.log (what the robot said over Bluetooth).

Each figure says what it measures: displacement (start to end) and path
length (along the track) both; the real-time factor on the wall clock, with
the CPU time beside it; how many physics steps fell back from the exact
solver, and what that means; the gait odometry only when the run has one
(library mode: the firmware's is inside the Mega); and what obstacle
avoidance did, read from the robot's own notices, not assumed.

  python3 tools/demo/summary.py out/demo
"""
import csv
import json
import math
import os
import sys

# The path's length without the body's sway from step to step: the track
# averaged over this many seconds, then measured.
SMOOTH_S = 1.0


def smoothed_path_mm(rows, smooth_s=SMOOTH_S):
    """Length [mm] of the body centre's horizontal track, each point the mean
    of the points within smooth_s / 2 either side of it (nearer the ends, a
    window as wide on both sides: the first and last points stay where they
    are, so a straight walk keeps its length)."""
    if len(rows) < 2:
        return 0.0
    dt = (rows[-1]["t"] - rows[0]["t"]) / (len(rows) - 1) or 1.0
    half = max(0, int(round(smooth_s / dt / 2)))
    xs = [r["x_mm"] for r in rows]
    ys = [r["y_mm"] for r in rows]
    avg = []
    for k in range(len(rows)):
        h = min(half, k, len(rows) - 1 - k)
        a, b = k - h, k + h + 1
        avg.append((sum(xs[a:b]) / (b - a), sum(ys[a:b]) / (b - a)))
    return sum(math.dist(avg[k - 1], avg[k]) for k in range(1, len(avg)))


def avoidance_events(log_lines):
    """[(t_s, state)] from the robot's `info avoid STATE` notices."""
    out = []
    for line in log_lines:
        words = line.split()
        if len(words) >= 3 and words[1:3] == ["info", "avoid"]:
            try:
                out.append((float(words[0]), words[3] if len(words) > 3 else ""))
            except ValueError:
                pass
    return out


def avoidance_line(events, has_obstacles):
    """What obstacle avoidance did, in words; None when there was nothing to avoid and it never acted."""
    acted = [(t, s) for t, s in events if s in ("sidestep", "blocked", "sensor_fault")]
    if not acted:
        if not has_obstacles:
            return None
        return "avoidance: never acted (no `info avoid sidestep`): nothing came within its stop distance ahead"
    parts = []
    for t, s in acted:
        parts.append({"sidestep": f"sidestepped at {t:.1f} s", "blocked": f"blocked (stood) at {t:.1f} s",
                      "sensor_fault": f"sonar fault at {t:.1f} s"}[s])
    forward = [t for t, s in events if s == "forward" and t > acted[0][0]]
    if forward:
        parts.append(f"walking forward again at {forward[0]:.1f} s")
    return "avoidance (the robot's notices): " + ", ".join(parts)


def summary_lines(m, rows, log_lines):
    """The summary as a list of lines. m: metrics.json; rows: trace rows (floats)
    from ready_s on; log_lines: robot.log."""
    out = []
    out.append(f"== summary: {m['robot']} in {m['mode']} mode, from {m['ready_s']:.1f} s (stood up) "
               f"to {m['sim_time_s']:.1f} s")
    out.append(f"displacement (start to end, a straight line): {m['distance_mm']:.0f} mm")
    out.append(f"path length (along the body centre's track, averaged over {SMOOTH_S:g} s): "
               f"{smoothed_path_mm(rows):.0f} mm; {m['path_mm']:.0f} mm with the sway of every step")
    out.append(f"top speed {m['speed_mm_s']:.0f} mm/s (best 2 s of displacement), "
               f"heading changed {m['heading_change_deg']:+.0f} deg")
    line = avoidance_line(avoidance_events(log_lines), m.get("min_clearance_mm") is not None)
    if line:
        out.append(line)
    if m.get("min_clearance_mm") is not None:
        out.append(f"closest to an obstacle: body {m['min_clearance_mm']:.0f} mm, any part "
                   f"{m['min_robot_clearance_mm']:.0f} mm; {m['collisions']} contacts with it")
    out.append(f"fell: {'yes' if m['fell'] else 'no'}; max tilt {m['max_tilt_deg']:.1f} deg")
    if m.get("odometry_mm") is not None:
        out.append(f"gait odometry (library mode: the gait engine's own dead reckoning): {m['odometry_mm']:.0f} mm, "
                   f"the body {m['odometry_error_pct']:.1f} % short of it")
    wall = m.get("real_time_factor_wall")
    if wall is None:
        wall = m["sim_time_s"] / max(1e-9, m["wall_time_s"])
    out.append(f"real-time factor: {wall:.1f}x on the wall clock ({m['sim_time_s']:.1f} s simulated in "
               f"{m['wall_time_s']:.1f} s); CPU {m['cpu_time_s']:.1f} s, {m['real_time_factor']:.1f}x per CPU second")
    if m.get("solver", "mlcp") == "mlcp" and m.get("solver_fallbacks") is not None:
        steps = m.get("physics_steps") or round(m["sim_time_s"] / 0.004)
        share = 100.0 * m["solver_fallbacks"] / max(1, steps)
        out.append(f"physics solver fallbacks: {m['solver_fallbacks']} of {steps} steps ({share:.1f} %): the exact "
                   f"contact solver (MLCP) gave up on them and Bullet's iterative one (PGS) solved them instead")
    return out


def load(run_dir):
    with open(os.path.join(run_dir, "metrics.json"), encoding="utf-8") as f:
        m = json.load(f)
    with open(os.path.join(run_dir, "trace.csv"), encoding="utf-8") as f:
        rows = [{k: float(v) for k, v in r.items() if k in ("t", "x_mm", "y_mm")} for r in csv.DictReader(f)]
    rows = [r for r in rows if r["t"] >= m["ready_s"] - 1e-9]
    log = []
    path = os.path.join(run_dir, "robot.log")
    if os.path.exists(path):
        with open(path, encoding="utf-8", errors="replace") as f:
            log = f.read().splitlines()
    return m, rows, log


def main(argv):
    if len(argv) != 2:
        sys.exit("usage: summary.py RUN_DIR (a folder written by strider-sim --out)")
    print("\n".join(summary_lines(*load(argv[1]))))


if __name__ == "__main__":
    main(sys.argv)
