#!/usr/bin/env python3
"""Regenerates docs/results.md: every figure in it is measured by this run
(or read from a result file a measuring tool wrote) and nothing is typed in
by hand, except the seed papers' own numbers, which are quoted as such.
A section whose source is missing says "not measured: <why>".

Sources:
- the `strider` CLI (seed 001 pose ranges, seed 002 tables 4-9, accuracy);
- tools/pso_bench (pso_bench + pso_compare.py: seed 003 table 4, pyswarms);
- tools/bench (avr_cycles, firmware_figures.py) for AVR cycles and sizes,
  else out/bench/avr.json from an earlier `tools/dev bench`;
- strider-sim and tools/sim/scenarios (seed 000 speed and turning, seed 003
  table 5 distances), when the simulator is built;
- tools/pso_bench/gait_tune (PSO gait tuning over strider-sim rollouts);
- tools/results/sim_crosscheck.py (strider-sim's runs replayed in pybullet
  and MuJoCo), when they are installed.
Intermediate results go to out/results/.

usage: make_results.py [--build DIR] [--out docs/results.md] [--reuse] [--quick] [--no-slow]
                       [--only pso,gait]
  --reuse  take the PSO comparison, gait tuning, simulator metrics and
           cross-check replays from out/results when present instead of
           measuring them again
  --quick  fewer samples (a check of the generator itself, not for docs)
  --no-slow  skip the PSO comparison, the simulator and the gait tuning
           (they then read "not measured"); for the generator's own test
  --only   measure only the named section groups (pso: seed 003 table 4
           and the pyswarms comparison; gait: the gait tuning) and replace
           those sections and their summary rows in the existing page
"""
import argparse
import datetime
import json
import math
import os
import pathlib
import random
import re
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
RESULTS = ROOT / "out" / "results"
sys.path.insert(0, str(ROOT / "tools" / "bench"))
from host_info import cpu_name  # noqa: E402


class NotMeasured(Exception):
    """A section's source is missing; the message says why."""


def not_measured(why):
    return f"not measured: {why}\n"


def fmt(v, digits=3):
    """A number with `digits` significant digits, plain when reasonable."""
    if v is None:
        return "-"
    if isinstance(v, str):
        return v
    if v == 0:
        return "0"
    if float(v).is_integer() and abs(v) < 1e9:
        return f"{int(v):,}"
    a = abs(v)
    if a >= 1e5 or a < 1e-3:
        return f"{v:.{max(digits - 1, 0)}e}"
    return f"{v:,.{max(digits - 1 - int(math.floor(math.log10(a))), 0)}f}"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out) + "\n"


# -- the strider CLI ----------------------------------------------------------

class Cli:
    def __init__(self, path):
        self.path = path
        self.calls = 0

    def run(self, args, stdin=None):
        self.calls += 1
        p = subprocess.run([self.path, *args], input=stdin, capture_output=True, text=True, timeout=120)
        if p.returncode != 0:
            raise RuntimeError(f"strider {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()}")
        return [json.loads(line) for line in p.stdout.splitlines() if line.startswith("{")]

    def ik_many(self, robot, leg, points, scalar="float", frame="leg"):
        text = "".join(f"{x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in points)
        return self.run(["ik", "--robot", robot, "--leg", str(leg), "--stdin", "--scalar", scalar,
                         "--frame", frame], text)

    def fk(self, robot, leg, joints, frame="leg"):
        return self.run(["fk", "--robot", robot, "--leg", str(leg), "--joints", ",".join(f"{q:.6f}" for q in joints),
                         "--frame", frame])[0]


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


# -- seed 002 tables 4-9 ------------------------------------------------------

# Seed 002 tables 4-9, desired points [cm] (x and z shared; y per leg) and
# the largest per-axis error the paper measured on its robot per table [cm].
S002_X = [7, 8, 9, 10, 11, 12, 13]
S002_Z = [-5, -4, -3, -2, -1, 1, 2]
S002_Y_CORNER = [1, 2, 3, 4, 5, 6, 7]       # tables 4, 6, 7, 9 (legs 1, 3, 4, 6)
S002_Y_MIDDLE = [-3, -2, -1, 1, 2, 3, 4]    # tables 5, 8 (legs 2, 5)
S002_PAPER_MAX_ERR_CM = {4: 0.3, 5: 0.3, 6: 0.3, 7: 0.3, 8: 0.2, 9: 0.4}


def seed002(cli):
    rows, worst = [], {"float": 0.0, "fixed": 0.0}
    all_ok = True
    for t in range(4, 10):
        leg = t - 4  # the paper's leg k is Strider's leg k-1 (test_robot_kinematics.cpp)
        ys = S002_Y_MIDDLE if t in (5, 8) else S002_Y_CORNER
        pts = [(x * 10.0, y * 10.0, z * 10.0) for x, y, z in zip(S002_X, ys, S002_Z)]
        cells = []
        for scalar in ("float", "fixed"):
            res = cli.ik_many("hexapod18", leg, pts, scalar)
            ok = sum(r["status"] == "ok" for r in res)
            all_ok &= ok == len(pts)
            err = 0.0
            for p, r in zip(pts, res):
                if r["joints_deg"] is None:
                    continue
                err = max(err, dist(cli.fk("hexapod18", leg, r["joints_deg"])["foot_mm"], p))
            worst[scalar] = max(worst[scalar], err)
            cells += [f"{ok}/{len(pts)}", fmt(err)]
        rows.append([f"table {t}", f"leg {leg + 1} (Strider leg {leg})", f"{S002_PAPER_MAX_ERR_CM[t] * 10:.0f}"] + cells)
    md = ("Seed 002 tested seven foot positions per leg on its hexapod and measured the foot with a ruler "
          "(tables 4-9). Strider solves the same points (leg frame, cm -> mm) with the hexapod18 model's IK and "
          "checks them with its FK; the error is FK(IK(p)) - p, i.e. the solver alone, without servos or "
          "structure. Errors are from the CLI's printed values (0.0001 deg, 0.0001 mm resolution).\n\n")
    md += table(["table", "paper leg", "paper: worst per-axis error on the robot [mm]", "float: ok", "float: FK(IK(p)) - p [mm]",
                 "fixed: ok", "fixed: FK(IK(p)) - p [mm]"], rows)
    summary = [("002", "tables 4-9: 42 foot positions, position error", "<= 4 mm per axis (measured on the robot)",
                f"{'all 42 solve ok' if all_ok else 'NOT all solve ok'}; IK error <= {fmt(worst['float'])} mm "
                f"float, {fmt(worst['fixed'])} mm fixed (solver only)")]
    return md, summary


# -- seed 001 body pose ranges ------------------------------------------------

def rot_zyx(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = (math.cos(math.radians(roll)), math.sin(math.radians(roll)),
                              math.cos(math.radians(pitch)), math.sin(math.radians(pitch)),
                              math.cos(math.radians(yaw)), math.sin(math.radians(yaw)))
    # R = Rz(yaw) Ry(pitch) Rx(roll), seed 001's default order (test_dog12_body_pose.cpp)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def moved_foot(p, pose):
    r = rot_zyx(*pose)  # the body turns by R, the feet stay: foot in body = R^T p
    return tuple(sum(r[i][j] * p[i] for i in range(3)) for j in range(3))


S001_RANGE = {"roll": 28, "pitch": 21, "yaw": 21}  # seed 001 table 4 [deg]


def seed001(cli, quick):
    legs = cli.run(["legs", "--robot", "dog12"])
    scan = 60
    poses = []
    for axis in range(3):
        for a in range(-scan, scan + 1):
            pose = [0.0, 0.0, 0.0]
            pose[axis] = float(a)
            poses.append(tuple(pose))
    corners = [(sr * 28.0, sp * 21.0, sy * 21.0) for sr in (-1, 1) for sp in (-1, 1) for sy in (-1, 1)]
    poses += corners
    status = {}  # (pose, scalar) -> all four legs ok
    worst = {"float": 0.0, "fixed": 0.0}
    for leg in legs:
        stand = leg["stand_mm"]
        feet = [moved_foot(stand, p) for p in poses]
        for scalar in ("float", "fixed"):
            res = cli.ik_many("dog12", leg["leg"], feet, scalar, frame="body")
            for pose, foot, r in zip(poses, feet, res):
                key = (pose, scalar)
                status[key] = status.get(key, True) and r["status"] == "ok"
                in_seed = all(abs(v) <= S001_RANGE[n] for v, n in zip(pose, ("roll", "pitch", "yaw")))
                if r["status"] == "ok" and in_seed and (pose in corners or pose.count(0.0) == 2) and not quick \
                        and abs(sum(pose)) % 7 == 0:  # every 7th degree and the corners: FK check
                    got = cli.fk("dog12", leg["leg"], r["joints_deg"], frame="body")["foot_mm"]
                    worst[scalar] = max(worst[scalar], dist(got, foot))
    rows = []
    ranges_ok = True
    for axis, name in enumerate(("roll", "pitch", "yaw")):
        cells = [name, f"+-{S001_RANGE[name]}"]
        for scalar in ("float", "fixed"):
            lo = hi = 0
            while hi < scan and status[(tuple(float(hi + 1) if i == axis else 0.0 for i in range(3)), scalar)]:
                hi += 1
            while -lo < scan and status[(tuple(float(lo - 1) if i == axis else 0.0 for i in range(3)), scalar)]:
                lo -= 1
            ranges_ok &= hi >= S001_RANGE[name] and -lo >= S001_RANGE[name]
            cells.append(f"{lo} .. {hi}" + (" (scan limit)" if hi == scan or -lo == scan else ""))
        rows.append(cells)
    corners_ok = all(status[(c, s)] for c in corners for s in ("float", "fixed"))
    md = ("Seed 001 (table 4) gives its dog's body pose ranges: roll +-28 deg, pitch +-21 deg, yaw +-21 deg. "
          "Strider turns the dog12 body about its centre (R = Rz(yaw) Ry(pitch) Rx(roll)) with all four feet "
          f"held at the standing pose and asks the IK of every leg in the body frame; a pose counts when all "
          f"four legs solve `ok`. Scanned in 1 deg steps, one axis at a time, up to +-{scan} deg:\n\n")
    md += table(["axis", "seed 001 range [deg]", "float: all legs ok [deg]", "fixed: all legs ok [deg]"], rows)
    md += (f"\nThe eight corners (+-28, +-21, +-21 at once): {'all solve ok' if corners_ok else 'NOT all solve'}. "
           + ("" if quick else f"Foot position error of the solved poses (FK of the IK joints, every 7th degree and "
                                f"the corners): {fmt(worst['float'])} mm float, {fmt(worst['fixed'])} mm fixed.") + "\n")
    summary = [("001", "body pose ranges roll / pitch / yaw", "+-28 / +-21 / +-21 deg",
                f"{'covered' if ranges_ok else 'NOT covered'}, corners {'ok' if corners_ok else 'FAIL'}; "
                f"float: {' / '.join(r[2] for r in rows)} deg")]
    return md, summary


# -- accuracy sweeps ----------------------------------------------------------

def accuracy(cli, quick):
    n = 40 if quick else 250
    rows = []
    for robot in (r["name"] for r in cli.run(["robots"])):
        leg = cli.run(["legs", "--robot", robot])[0]
        lim = leg["limits_deg"]
        rng = random.Random(20260)
        qs = [[rng.uniform(lo, hi) for lo, hi in lim] for _ in range(n)]
        pts = [tuple(cli.fk(robot, 0, q)["foot_mm"]) for q in qs]
        res = {s: cli.ik_many(robot, 0, pts, s) for s in ("float", "fixed")}
        cells = [robot, leg["kind"], str(n)]
        for s in ("float", "fixed"):
            errs = []
            for p, r in zip(pts, res[s]):
                if r["status"] == "ok":
                    errs.append(dist(cli.fk(robot, 0, r["joints_deg"])["foot_mm"], p))
            ok = len(errs)
            rms = math.sqrt(sum(e * e for e in errs) / ok) if ok else None
            cells += [f"{ok}", fmt(max(errs) if errs else None), fmt(rms)]
        dq = [max(abs(a - b) for a, b in zip(f["joints_deg"], x["joints_deg"]))
              for f, x in zip(res["float"], res["fixed"]) if f["status"] == "ok" and x["status"] == "ok"]
        cells.append(fmt(max(dq) if dq else None))
        rows.append(cells)
    md = (f"Leg 0 of every model: {n} joint vectors drawn uniformly within the joint limits (fixed seed), their "
          "feet by FK, then IK of those feet in float and in fixed point (Q16.16), and FK of the IK's joints "
          "again. `ok` counts the points the IK solved with status ok (others are limits the IK's own branch "
          "would break, or points at the edge of the workspace); the errors are over those. Values come "
          "through the CLI's printed numbers (0.0001 mm and 0.0001 deg resolution), so float errors at that "
          "level are the print resolution, not the solver.\n\n")
    md += table(["robot", "leg type", "points", "float ok", "float worst [mm]", "float RMS [mm]", "fixed ok",
                 "fixed worst [mm]", "fixed RMS [mm]", "worst fixed - float joint [deg]"], rows)
    return md, []


# -- PSO: seed 003 table 4 and pyswarms ---------------------------------------

def pso_data(build, reuse, quick):
    cached = RESULTS / "pso.json"
    if reuse and cached.is_file():
        return json.loads(cached.read_text()), "reused"
    bench = build / "tools" / "pso_bench" / "pso_bench"
    if not bench.is_file():
        raise NotMeasured(f"pso_bench is not built (cmake --build {build.name} --target pso_bench)")
    for name in ("numpy", "pyswarms"):  # not imported here: pyswarms' import writes report.log into the cwd
        if not _importable(name):
            raise NotMeasured(f"{name} is not installed for {sys.executable} (tools/dev python_env)")
    runs = "5" if quick else "21"
    p = subprocess.run([sys.executable, str(ROOT / "tools" / "pso_bench" / "pso_compare.py"), "--pso-bench",
                        str(bench), "--runs", runs, "--json", str(cached)], capture_output=True, text=True,
                       timeout=1200)
    if p.returncode not in (0, 1) or not cached.is_file():
        raise NotMeasured(f"pso_compare.py failed (exit {p.returncode}): {p.stderr.strip()[-300:]}")
    return json.loads(cached.read_text()), "measured"


def _solver_name(r):
    if r["scalar"] != "double" or "cost" not in r:
        return f"Strider {r['scalar']}"
    return f"Strider double, {'swarm-vectorised' if r['cost'] == 'swarm' else 'per-particle'} cost"


def seed003_pso(data):
    lib = {(r["case"], r["scalar"], r.get("cost", "each")): r for r in data["strider"]}
    py = {r["case"]: r for r in data["pyswarms"]}
    rows = []
    for case in ("a", "b"):
        for scalar, cost in (("double", "each"), ("double", "swarm"), ("float", "each"), ("fixed", "each")):
            r = lib.get((case, scalar, cost))
            if r:
                q = r["best_joints_deg"]
                rows.append([case, _solver_name(r), fmt(r["median_cost_mm"]), fmt(r["worst_cost_mm"]),
                             f"{q[0]:.4f}, {q[1]:.4f}", fmt(r["median_ms"])])
        r = py[case]
        q = r["best_joints_deg"]
        rows.append([case, f"pyswarms {r['version']}", fmt(r["median_cost_mm"]), fmt(r["worst_cost_mm"]),
                     f"{q[0]:.4f}, {q[1]:.4f}", fmt(r["median_ms"])])
    md = ("Seed 003 ran pyswarms (swarm 20, 1000 iterations, c1 = c2 = 1.5, w = 0.5) to find the joint angles "
          "of its 70/70 mm leg for the target (10, 0, 0), reporting best cost 1.14e-14 and joints "
          "[13.34156399, 17.29916917] in 1.75-1.85 s per run (table 4). Those numbers fit radians with "
          "bounds 0..20 and a 100 mm target (case a); the stated intent, degrees with bounds 0..20 deg, is "
          "case b (see docs/kinematics.md). Both, "
          f"{data['runs']} seeds each, medians (time: thread CPU time); joints of the best run (case a: angles "
          "beyond 360 deg are the seed's own unwrapped radians):\n\n")
    md += table(["case", "solver", "median final cost [mm]", "worst final cost [mm]", "joints [deg]",
                 "median time per run [ms]"], rows)
    b = lib.get(("b", "double", "each"))
    summary = [("003", "table 4: PSO joint angles, cost, run time", "cost 1.14e-14, [13.34, 17.29], 1.8 s/run",
                f"case b double: cost {fmt(b['median_cost_mm'])} mm, [{b['best_joints_deg'][0]:.2f}, "
                f"{b['best_joints_deg'][1]:.2f}] deg, {fmt(b['median_ms'])} ms/run" if b else "-")]
    return md, summary


def pso_vs_pyswarms(data):
    # The seed-by-seed interleaved timings (pso_compare.py); older files had
    # one Strider row per case in "strider".
    timed = data.get("strider_interleaved") or [r for r in data["strider"] if r["scalar"] == "double"]
    lib = {(r["case"], r.get("cost", "each")): r for r in timed}
    py = {r["case"]: r for r in data["pyswarms"]}
    rows, to_cost, full, wall = [], {}, {}, {}
    for c in data["comparison"]:
        case = c["case"]
        pr = py[case]
        for cost in ("each", "swarm"):
            lr, cr = lib.get((case, cost)), c.get(cost)
            if lr is None or cr is None:
                continue
            rows.append([case, "swarm-vectorised (" + lr.get("cost_math", "") + ")" if cost == "swarm"
                         else "per particle (" + lr.get("cost_math", "libm") + ")",
                         f"{fmt(pr.get('median_iterations_to_1e-6'))} / {fmt(lr.get('median_iterations_to_1e-6'))}",
                         f"{fmt(pr.get('median_ms_to_1e-6'))} / {fmt(lr.get('median_ms_to_1e-6'))}",
                         f"**{cr['ratio_to_1e-6']:.0f}x**" if "ratio_to_1e-6" in cr else "-",
                         f"{fmt(pr['median_ms'])} / {fmt(lr['median_ms'])}",
                         f"{fmt(pr['median_cost_mm'])} / {fmt(lr['median_cost_mm'])}",
                         f"**{cr['ratio_full_run']:.0f}x**"])
            if "ratio_to_1e-6" in cr:
                to_cost.setdefault(cost, []).append(cr["ratio_to_1e-6"])
                wall.setdefault(cost, []).append(cr.get("ratio_to_1e-6_wall", cr["ratio_to_1e-6"]))
            full.setdefault(cost, []).append(cr["ratio_full_run"])
    md = ("Seed 003's problem solved by pyswarms and by Strider's `kinematics/pso.h` (in double, the precision "
          "numpy uses) in the same run on the same machine "
          f"({data['host_cpu']}, Python {data['python']}), {data['runs']} seeds each, medians. Same settings "
          "(table 3) and cost (eq 15). pyswarms calls its cost once per iteration for the whole swarm (numpy "
          "arrays); Strider is timed both ways: `minimize_swarm()` with the cost vectorised over the swarm in "
          "the same way (glibc's vector sin/cos), and `minimize()` with the cost called per particle (libm). "
          "Equal final cost: each run is timed until its best cost first falls below 1e-6 mm (the convergence "
          "mark test/chain/test_pso.cpp uses for the seed's experiment; pyswarms is rerun with the same seed for "
          "exactly the iterations it needed, so its time is measured, not scaled). Equal work: both run all 1000 "
          "iterations (final costs in the table). Times are thread CPU time, each side after an untimed warm-up "
          "run, the seeds interleaved (Strider then pyswarms, then the other way round) so that both see the "
          "same machine load; wall time would favour Strider under load, as the long pyswarms runs are "
          "preempted more often. Made by tools/pso_bench (pso_bench.cpp, pso_compare.py).\n\n")
    md += table(["case", "Strider's cost", "iterations to 1e-6 mm pyswarms / Strider",
                 "time to 1e-6 mm [ms] pyswarms / Strider", "speed-up at equal cost",
                 "1000 iterations [ms] pyswarms / Strider", "final cost [mm] pyswarms / Strider",
                 "speed-up at equal work"], rows)
    # The target compares like with like: both costs vectorised over the swarm.
    head = "swarm" if "swarm" in to_cost else "each"
    verdict = "met" if to_cost.get(head) and min(to_cost[head]) >= 100 else "NOT met"
    if to_cost.get(head):
        md += (f"\nTarget: >= 100x faster at equal final cost: **{verdict}** (smallest speed-up "
               f"{min(to_cost[head]):.0f}x with the swarm-vectorised cost as pyswarms', "
               f"{min(wall[head]):.0f}x in wall time, which favours Strider under load; at equal work {min(full[head]):.0f}-{max(full[head]):.0f}x)")
        if head == "swarm" and to_cost.get("each"):
            md += (f"; with the cost called per particle {min(to_cost['each']):.0f}-{max(to_cost['each']):.0f}x "
                   f"at equal cost, {min(full['each']):.0f}-{max(full['each']):.0f}x at equal work")
        md += "."
    else:
        md += "\nTarget: >= 100x faster at equal final cost: not measured (no run reached 1e-6 mm)."
    md += (" Times depend on the machine and its load, so the ratio moves between runs; this page shows one "
           "run. Float and fixed point, as the firmware runs them, are in the table above.\n")
    summary = [("003", "PSO against pyswarms (same run)", ">= 100x faster at equal cost",
                (f"{min(to_cost[head]):.0f}x or more at equal cost, {verdict}; {min(full[head]):.0f}x or more at "
                 "equal work" + (f" (per-particle cost: {min(to_cost['each']):.0f}x / {min(full['each']):.0f}x)"
                                 if head == "swarm" and to_cost.get("each") else "")
                 if to_cost.get(head) else "not measured"))]
    return md, summary


# -- simulator ----------------------------------------------------------------

def sim_metrics(build, reuse):
    """Runs every scenario in tools/sim/scenarios with strider-sim (library
    mode) and returns {name: metrics}."""
    sim = build / "tools" / "sim" / "strider-sim"
    scen_dir = ROOT / "tools" / "sim" / "scenarios"
    if not sim.is_file():
        raise NotMeasured("strider-sim is not built (tools/sim, needs libbullet-dev)")
    scenarios = sorted(scen_dir.glob("*.scenario"))
    if not scenarios:
        raise NotMeasured("no scenarios in tools/sim/scenarios")
    out = {}
    for s in scenarios:
        d = RESULTS / "sim" / s.stem
        m = d / "metrics.json"
        if not (reuse and m.is_file()):
            d.mkdir(parents=True, exist_ok=True)
            p = subprocess.run([str(sim), str(s), "--out", str(d), "--quiet"], capture_output=True, text=True,
                               timeout=900)
            if p.returncode != 0 or not m.is_file():
                out[s.stem] = {"error": f"exit {p.returncode}: {p.stderr.strip()[-200:]}"}
                continue
        out[s.stem] = json.loads(m.read_text())
    return out


def find(metrics, pattern):
    rx = re.compile(pattern)
    return {k: v for k, v in metrics.items() if rx.search(k) and "error" not in v}


def seed000(metrics):
    if isinstance(metrics, NotMeasured):
        return not_measured(str(metrics)), [("000", "forward speed / 360 deg turn", "155 mm/s / 6 s",
                                              "not measured (simulator)")]
    fwd = find(metrics, r"^sprawl8_(forward|walk)")
    turn = find(metrics, r"^sprawl8_(turn|rotate)")
    rows, summary_cells = [], []
    for name, m in sorted(fwd.items()):
        cmd = scenario_commands(name)
        rows.append([name, "forward", cmd, fmt(m.get("speed_mm_s")), fmt(m.get("lateral_drift_mm")),
                     fmt(m.get("max_tilt_deg")), "yes" if m.get("fell") else "no", m.get("mode", "-")])
        summary_cells.append(f"{fmt(m.get('speed_mm_s'))} mm/s ({cmd})")
    for name, m in sorted(turn.items()):
        t = m.get("turn_360_s")
        rows.append([name, f"turn: 360 deg in {fmt(t) if t is not None else '(not reached)'} s",
                     scenario_commands(name), fmt(m.get("yaw_rate_deg_s")), fmt(m.get("lateral_drift_mm")),
                     fmt(m.get("max_tilt_deg")), "yes" if m.get("fell") else "no", m.get("mode", "-")])
        summary_cells.append(f"360 deg in {fmt(t)} s" if t is not None else "turn: 360 deg not reached")
    if not rows:
        return not_measured("no sprawl8 forward or turn scenario has metrics"), [
            ("000", "forward speed / 360 deg turn", "155 mm/s / 6 s", "not measured")]
    md = ("Seed 000's robot walked 155 mm/s on its best surface and turned 360 deg in about 6 s. The sprawl8 "
          "model with the seed's dimensions in the Bullet simulator (strider-sim, scenarios in tools/sim/"
          "scenarios; speed and turn rate as strider-sim's metrics.json defines them, docs/simulator.md):\n\n")
    md += table(["scenario", "motion", "commands", "speed [mm/s] or yaw rate [deg/s]", "lateral drift [mm]",
                 "max tilt [deg]", "fell", "mode"], rows)
    if not turn:
        md += "\nTurning: " + not_measured("no sprawl8 turn scenario in tools/sim/scenarios")
    return md, [("000", "forward speed / 360 deg turn", "155 mm/s / 6 s", "; ".join(summary_cells))]


def scenario_commands(name):
    """The gait and motion lines a scenario sends, e.g. 'gait trot, walk 155'."""
    path = ROOT / "tools" / "sim" / "scenarios" / f"{name}.scenario"
    if not path.is_file():
        return "-"
    cmds = re.findall(r"send\s+((?:gait|walk|turn|strafe|vel)\b[^\\#\n]*)", path.read_text())
    return ", ".join(c.strip() for c in cmds) or "-"


S003_TABLE5 = {  # seed 003 table 5: gait -> {target cm: experimental error %}
    "walk": {10: 10, 20: 5, 100: 5.6, 200: 0.55},
    "trot": {10: 2, 20: 2.5, 100: 0.4, 200: 0.35},
    "pace": {10: 10, 20: 1.5, 100: 1.1, 200: 0.65},
}


def seed003_distance(metrics):
    head = ("003", "table 5: distance reached, walk/trot/pace", "errors 0.35-10 %")
    if isinstance(metrics, NotMeasured):
        return not_measured(str(metrics)), [head + ("not measured (simulator)",)]
    rows, errs = [], []
    runs = find(metrics, r"^mammal8_(walk|trot|pace)_\d+mm")
    order = {"walk": 0, "trot": 1, "pace": 2}  # the paper's order, then by distance

    def key(name):
        g, mm = re.match(r"^mammal8_(walk|trot|pace)_(\d+)mm", name).groups()
        return order[g], int(mm)

    for name in sorted(runs, key=key):
        m = runs[name]
        gait, mm = re.match(r"^mammal8_(walk|trot|pace)_(\d+)mm", name).groups()
        cm = int(mm) // 10
        odo, err = m.get("odometry_mm"), m.get("odometry_error_pct")
        # strider-sim's error counts the displacement along the way the gait
        # went: reached = commanded (1 - error), negative when it slid back.
        along = odo * (1.0 - err / 100.0) if odo is not None and err is not None else None
        if err is not None:
            errs.append(abs(err))
        paper = S003_TABLE5.get(gait, {}).get(cm)
        rows.append([gait, f"{cm}", fmt(odo), fmt(along), fmt(m.get("distance_mm")), fmt(err),
                     fmt(paper) if paper is not None else "-", "yes" if m.get("fell") else "no"])
    if not rows:
        return not_measured("no mammal8_<gait>_<mm>mm scenario has metrics"), [head + ("not measured",)]
    md = ("Seed 003 walked its robot 10, 20, 100 and 200 cm in each gait and measured the distance reached "
          "(table 5). mammal8 in the simulator, commanded by the scenarios' `walk` and `stop` lines; "
          "'commanded' is the distance the gait engine's own odometry covered, 'reached' the body's "
          "displacement in the simulated world along that way (negative: it went backward), error = "
          "(commanded - reached) / commanded as strider-sim's metrics.json reports it:\n\n")
    md += table(["gait", "target [cm]", "commanded [mm]", "reached along it [mm]", "displacement [mm]", "error [%]",
                 "paper's error [%]", "fell"], rows)
    back = sum(1 for r in rows if r[3].startswith("-") and r[3] != "-")
    return md, [head + ((f"errors {fmt(min(errs))}-{fmt(max(errs))} % over {len(rows)} runs"
                         + (f"; {back} of them went backward" if back else "")) if errs else "-",)]


def sim_table(metrics):
    if isinstance(metrics, NotMeasured):
        return not_measured(str(metrics))
    rows = []
    for name, m in sorted(metrics.items()):
        if "error" in m:
            rows.append([name, f"failed: {m['error']}"] + ["-"] * 6)
            continue
        rows.append([name, m.get("robot", "-"), fmt(m.get("distance_mm")), fmt(m.get("speed_mm_s")),
                     fmt(m.get("heading_change_deg")), fmt(m.get("max_tilt_deg")), "yes" if m.get("fell") else "no",
                     fmt(m.get("real_time_factor"))])
    return ("Every scenario of tools/sim/scenarios in library mode (strider-sim):\n\n"
            + table(["scenario", "robot", "distance [mm]", "speed [mm/s]", "heading change [deg]", "max tilt [deg]",
                     "fell", "x real time"], rows))


def physics_check(metrics, cli_path, reuse):
    """strider-sim's sprawl8 and mammal8 runs replayed in pybullet and MuJoCo
    (sim_crosscheck.py), where installed."""
    if isinstance(metrics, NotMeasured):
        raise metrics
    engines = [e for e in ("pybullet", "mujoco") if _importable(e)]
    if not engines:
        raise NotMeasured("neither pybullet nor mujoco is installed for this Python (tools/dev results installs them)")
    runs, skipped = [], []
    for k, v in sorted(metrics.items()):
        if v.get("robot") not in ("sprawl8", "mammal8") or "error" in v:
            continue  # the cross-check builds 2-DOF legs (sprawl, planar)
        scene = RESULTS / "sim" / k / "scene.json"
        if scene.is_file() and json.loads(scene.read_text()).get("obstacles_mm"):
            skipped.append(k)  # the replay has no obstacles and no sonar: open loop only
        else:
            runs.append(k)
    if not runs:
        raise NotMeasured("no sprawl8 or mammal8 scenario ran (the cross-check is built for their legs)")
    rows, flagged, versions, checks = [], [], {}, []
    for name in runs:
        got = {}
        for e in engines:
            out = RESULTS / "sim" / name / f"{e}.json"
            if not (reuse and out.is_file()):
                p = subprocess.run([sys.executable, str(ROOT / "tools" / "results" / "sim_crosscheck.py"), "--run",
                                    str(RESULTS / "sim" / name), "--cli", str(cli_path), "--engine", e, "--json",
                                    str(out)], capture_output=True, text=True, timeout=600)
                if p.returncode != 0 or not out.is_file():
                    continue
            got[e] = json.loads(out.read_text())
            checks.append((name, got[e]))
            versions[e] = got[e].get("engine_version", "?")
            if disagree(got[e]):
                flagged.append(f"{name} ({e})")
        if not got:
            rows.append([name, "failed"] + ["-"] * 3)
            continue
        d0 = next(iter(got.values()))
        rows.append([name, f"{fmt(d0['duration_s'])} s",
                     " / ".join([fmt(d0["strider_sim_distance_mm"])] +
                                [fmt(got[e]["other_distance_mm"]) if e in got else "-" for e in engines]),
                     " / ".join([fmt(d0["strider_sim_heading_deg"])] +
                                [fmt(got[e]["other_heading_deg"]) if e in got else "-" for e in engines]),
                     " / ".join([fmt(d0["strider_sim_max_tilt_deg"])] +
                                [fmt(got[e]["other_max_tilt_deg"]) if e in got else "-" for e in engines])])
    who = " / ".join(["strider-sim"] + engines)
    md = ("The servo targets a strider-sim run sent (trace.csv, every 20 ms tick) are replayed open loop on the "
          "same robot built independently in " + " and ".join(engines) + " (tools/results/sim_crosscheck.py): "
          "same sizes, masses, friction and servo torque and speed limits, but the other simulator's own bodies, "
          "contacts, motors and solver, and no servo dead band or PWM quantisation. pybullet is Bullet too, so it "
          "checks how strider-sim builds and drives the robot; MuJoCo is an independent physics engine with a "
          "different servo model (a position actuator saturating at the stall torque). From the moment "
          "strider-sim counts the robot ready to the end of the run ("
          + ", ".join(f"{e} {v}" for e, v in versions.items()) + "):\n\n")
    md += table(["scenario", "compared", f"distance [mm] {who}", f"heading change [deg] {who}",
                 f"max tilt [deg] {who}"], rows)
    if flagged:
        md += (f"\nDisagreeing by more than 20 % in distance or in heading change (and by more than 10 mm or "
               f"10 deg): {', '.join(flagged)}. The simulators do not agree there, so strider-sim's figures for "
               "those motions are uncertain by at least that much; the cause is not investigated here.\n")
    else:
        md += "\nAll runs agree within 20 % (or 10 mm / 10 deg) in distance and heading change.\n"
    if skipped:
        md += (f"\nNot replayed: {', '.join(skipped)} (obstacles: the open-loop replay has neither the obstacles "
               "nor the sonar that made the robot react to them).\n")
    summary = []
    for e in engines:
        done = [d for name, d in checks if d.get("engine", e) == e]
        agree = sum(not disagree(d) for d in done)
        summary.append(("-", f"strider-sim against {e} (open-loop replay)", "agree within 20 %",
                        f"{agree} of {len(done)} runs agree"))
    return md, summary


def disagree(d):
    """strider-sim and the other simulator differ by more than 20 % (and by
    more than 10 mm / 10 deg) in distance or heading change."""
    def off(a, b, floor):
        return abs(a - b) > max(floor, 0.2 * abs(a))
    return (off(d["strider_sim_distance_mm"], d["other_distance_mm"], 10.0)
            or off(d["strider_sim_heading_deg"], d["other_heading_deg"], 10.0))


def gait_tune_data(build, reuse):
    cached = RESULTS / "gait_tune.json"
    if reuse and cached.is_file():
        d = json.loads(cached.read_text())
        if "default_cost" in d:  # else made by an older gait_tune: measure again
            return d
    exe = build / "tools" / "pso_bench" / "gait_tune"
    if not exe.is_file():
        raise NotMeasured("gait_tune is not built (tools/pso_bench, needs the simulator's core: libbullet-dev)")
    # sprawl8 in trot, its fastest gait (as strider-sim's sprawl8_forward scenario walks)
    p = subprocess.run([str(exe), "--robot", "sprawl8", "--gait", "trot"], capture_output=True, text=True,
                       timeout=1800)
    lines = [line for line in p.stdout.splitlines() if line.startswith("{")]
    if not lines:
        raise NotMeasured(f"gait_tune failed (exit {p.returncode}): {p.stderr.strip()[-300:]}")
    cached.write_text(lines[0] + "\n")
    return json.loads(lines[0])


def gait_tuning(d):
    keys = [("step_length_mm", "step length [mm]"), ("step_height_mm", "step height [mm]"), ("cycle_s", "cycle [s]"),
            ("speed_mm_s", "forward speed along the heading [mm/s] (score)"),
            ("start_dir_speed_mm_s", "speed in the starting direction [mm/s]"),
            ("max_tilt_deg", "max tilt [deg] (<= {tilt})"),
            ("body_drift_pct", "crabbing: sideways drift in the body frame [% of distance] (<= {drift})"),
            ("turn_deg_s", "turning [deg/s] (<= {turn})"),
            ("heading_deg", "heading change [deg]"),
            ("lateral_pct", "sideways drift from the starting direction [% of distance] (not a constraint)"),
            ("fell", "fell"), ("feasible", "meets the constraints")]
    c, lo_hi = d["constraints"], d["bounds"]
    limits = {"tilt": fmt(c["max_tilt_deg"]), "drift": fmt(c["max_body_drift_pct"]),
              "turn": fmt(c["max_heading_deg_s"])}
    windows = d["windows"]
    rows = []

    def cell(v):
        return ("yes" if v else "no") if isinstance(v, bool) else fmt(v)

    for k, label in keys:
        row = [label.format(**limits)]
        for i, w in enumerate(windows):
            if k in ("step_length_mm", "step_height_mm", "cycle_s") and i > 0:
                row += ["", ""]
            else:
                row += [cell(w["default"].get(k)), cell(w["tuned"].get(k))]
        rows.append(row)
    on_bound = [(name, label.split(" [")[0], lo, hi) for (name, label), (lo, hi) in zip(keys[:3], lo_hi)
                if min(abs(d["tuned"][name] - lo), abs(d["tuned"][name] - hi)) <= 1e-2 * (hi - lo)]
    cps = " and ".join(f"{fmt(t)} s" for t in d["checkpoints_s"])
    md = (f"Strider's PSO (`kinematics/pso.h`, float, swarm {d['swarm']}, {d['iterations']} iterations, "
          f"{d['evaluations']} rollouts in {fmt(d['tune_wall_s'])} s, {fmt(d['tune_cpu_s'])} s of CPU) tunes "
          f"{d['robot']}'s {d['gait']} gait: step length, step height and cycle time, for forward speed. Each "
          "candidate is a library-mode rollout in strider-sim's Bullet world (RobotApp, the firmware's chain, with "
          "the candidate's gait parameters; `walk 500`, the gait engine caps the speed at what the parameters "
          f"allow), scored by its forward speed along the heading over {fmt(d['walk_s'])} s of walking (the "
          "body-frame velocity integrated, as strider-sim's `body_drift_mm`, docs/simulator.md). One particle "
          "starts at the model's gait parameters, so the tuned gait is never worse than them on the tuning's cost "
          f"(the default's: {fmt(-d['default_cost']) + ' mm/s' if d['default_cost'] < 0 else 'infeasible, it breaks a constraint (with the margin)'}). "
          f"Constraints: no fall, tilt <= {limits['tilt']} deg, crabbing (sideways drift in the body frame, turning "
          f"with the heading) <= {limits['drift']} % of the distance, turning <= {limits['turn']} deg/s on average, each "
          f"checked at {cps} of the rollout; tuned with {d.get('margin_pct', 30)} % margin on drift and turning. "
          "The sideways drift from the starting direction is shown but not constrained: with any heading drift "
          "it grows without bound on a long open-loop walk, whatever the gait (the turning limit covers the "
          f"heading). Bounds: step length {fmt(lo_hi[0][0])}-{fmt(lo_hi[0][1])} mm (up to the longest forward "
          "stride every leg reaches, the gait engine's own stride limit at the lowest step height of the box), "
          f"height {fmt(lo_hi[1][0])}-{fmt(lo_hi[1][1])} mm, cycle {fmt(lo_hi[2][0])}-{fmt(lo_hi[2][1])} s. "
          f"Both gaits over the tuning window ({fmt(d['walk_s'])} s), over a validation walk twice as long "
          f"({fmt(d['check_walk_s'])} s) and over its second half alone ({fmt(d['walk_s'])}-"
          f"{fmt(d['check_walk_s'])} s, never seen by the tuning; the simulation is deterministic, so the first "
          f"{fmt(d['walk_s'])} s of the validation walk are the tuning's own rollout), the constraints (without the "
          "margin) applied to each (tools/pso_bench/gait_tune.cpp):\n\n")

    def span(w):
        r = w["default"]
        return f"{fmt(r['walk_s'])} s" if r.get("from_s", 0) == 0 else f"{fmt(r['from_s'])}-{fmt(r['to_s'])} s"

    head = [""]
    for w in windows:
        head += [f"default, {span(w)}", f"tuned, {span(w)}"]
    md += table(head, rows)
    for name, label, lo, hi in on_bound:
        at_hi = abs(d["tuned"][name] - hi) <= abs(d["tuned"][name] - lo)
        if name == "step_length_mm" and at_hi:
            md += (f"\nThe tuned {label} is at (within 1 % of) the legs' forward reach ({fmt(hi)} mm): the gait "
                   "engine would not walk a longer stride.\n")
        elif name == "step_height_mm" and not at_hi:
            md += (f"\nThe tuned {label} is on (within 1 % of) the search box's lower bound ({fmt(lo)} mm, half "
                   "the model's): a lower swing may be faster still on the simulator's flat floor, but clears "
                   "less (the model's height is chosen to step over a cable).\n")
        else:
            md += (f"\nThe tuned {label} is on (within 1 % of) the search box's {'upper' if at_hi else 'lower'} "
                   "bound: a wider box may find a faster gait.\n")
    tw, vw = windows[0], windows[1]
    ratio = tw["tuned"]["speed_mm_s"] / tw["default"]["speed_mm_s"] if tw["default"]["speed_mm_s"] > 0 else None

    def verdict(name):
        bad = [span(w) for w in windows if not w[name].get("feasible")]
        return "meets the constraints over every window" if not bad else "does NOT meet the constraints over " + \
            ", ".join(bad)

    summary = [("000", f"gait tuned by PSO in the simulator ({d['robot']})", "155 mm/s (seed 000's robot)",
                f"{fmt(tw['tuned']['speed_mm_s'])} mm/s tuned vs {fmt(tw['default']['speed_mm_s'])} default over "
                f"{fmt(d['walk_s'])} s" + (f" ({ratio:.2f}x)" if ratio else "") +
                f", {fmt(vw['tuned']['speed_mm_s'])} vs {fmt(vw['default']['speed_mm_s'])} over the "
                f"{fmt(d['check_walk_s'])} s validation walk; tuned {verdict('tuned')}, default {verdict('default')}")]
    return md, summary


def _importable(name):
    import importlib.util
    return importlib.util.find_spec(name) is not None


# -- AVR ------------------------------------------------------------------------

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


# -- page -------------------------------------------------------------------------

def git_describe():
    try:
        rev = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                             timeout=10).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, timeout=10).stdout.strip()
        return f"{rev}{' with local changes' if dirty else ''}" if rev else "unknown"
    except OSError:
        return "unknown"


def section(title, fn, *args):
    """Runs one section; a missing source or a failing tool becomes 'not measured'."""
    try:
        md, summary = fn(*args)
    except NotMeasured as e:
        md, summary = not_measured(str(e)), []
    except (RuntimeError, OSError, subprocess.TimeoutExpired, KeyError, ValueError) as e:
        md, summary = not_measured(f"the measurement failed: {type(e).__name__}: {e}"), []
    return f"## {title}\n\n{md}\n", summary


SECTION_GROUPS = {"pso": ("Seed 003: PSO joint angles, table 4", "PSO: Strider against pyswarms"),
                  "gait": ("Gait tuning by PSO (simulator rollouts)",)}


def splice(old_text, parts, summary, notes):
    """Replaces the regenerated sections and their summary rows in a page."""
    text = old_text
    for md in parts:
        title = md.split("\n", 1)[0]
        start = text.find(title + "\n")
        if start < 0:
            raise SystemExit(f"{title!r} is not on the page: regenerate it whole")
        end = text.find("\n## ", start + len(title))
        text = text[:start] + md.rstrip() + "\n" + (text[end:] if end >= 0 else "")
    for seed, figure, paper, value in summary:
        row = f"| {seed} | {figure} | {paper} | {value} |"
        text, n = re.subn(r"^\| " + re.escape(seed) + r" \| " + re.escape(figure) + r" \|.*$",
                          lambda _m: row, text, count=1, flags=re.M)
        if n == 0:
            raise SystemExit(f"summary row {figure!r} is not on the page: regenerate it whole")
    # One note per group regenerated, after the page's "Generated" line.
    for group, line in notes:
        text = re.sub(r"^Regenerated since \(--only( " + re.escape(group) + r")?\):.*\n\n", "", text, flags=re.M)
    head, sep, rest = text.partition("\n## Summary")
    text = head.rstrip("\n") + "\n\n" + "\n\n".join(line for _, line in notes) + "\n" + sep + rest
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=os.environ.get("STRIDER_BUILD_DIR", str(ROOT / "out" / "build")))
    ap.add_argument("--out", default=str(ROOT / "docs" / "results.md"))
    ap.add_argument("--reuse", action="store_true", help="reuse out/results measurements when present")
    ap.add_argument("--quick", action="store_true", help="few samples: a check of the generator, not for docs")
    ap.add_argument("--no-slow", action="store_true", help="skip the PSO comparison and the simulator")
    ap.add_argument("--only", help="comma-separated section groups (" + ", ".join(SECTION_GROUPS) + "): "
                    "measure just those and replace them and their summary rows in the existing page")
    a = ap.parse_args()
    only = set(a.only.split(",")) if a.only else None
    if only and not only <= set(SECTION_GROUPS):
        ap.error(f"--only takes {', '.join(SECTION_GROUPS)}")
    wanted = {t for g in only for t in SECTION_GROUPS[g]} if only else None
    build = pathlib.Path(a.build).resolve()
    RESULTS.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()

    cli_path = build / "tools" / "cli" / "strider"
    cli = Cli(str(cli_path)) if cli_path.is_file() else None

    def needs_cli(fn):
        def run(*args):
            if cli is None:
                raise NotMeasured(f"the strider CLI is not built ({build.name}/tools/cli/strider)")
            return fn(cli, *args)
        return run

    def slow(measure, *titles):
        """A slow source, measured only when a section that needs it is wanted."""
        if wanted is not None and not wanted & set(titles):
            return NotMeasured("not wanted")
        try:
            if a.no_slow:
                raise NotMeasured("skipped in this run (--no-slow)")
            return measure()
        except NotMeasured as e:
            return e

    pso = slow(lambda: pso_data(build, a.reuse, a.quick)[0], *SECTION_GROUPS["pso"])
    sim = slow(lambda: sim_metrics(build, a.reuse), "Seed 000: speed and turning (simulator)",
               "Seed 003: distances walked, table 5 (simulator)", "Simulator against pybullet and MuJoCo")

    def from_pso(fn):
        def run():
            if isinstance(pso, NotMeasured):
                raise pso
            return fn(pso)
        return run

    parts, summary = [], []

    def add(title, fn, *args):
        if wanted is not None and title not in wanted:
            return
        md, rows = section(title, fn, *args)
        parts.append(md)
        summary.extend(rows)

    add("Seed 000: speed and turning (simulator)", seed000, sim)
    add("Seed 001: body pose ranges", needs_cli(seed001), a.quick)
    add("Seed 002: foot positions, tables 4-9", needs_cli(seed002))
    add("Seed 003: PSO joint angles, table 4", from_pso(seed003_pso))
    add("Seed 003: distances walked, table 5 (simulator)", seed003_distance, sim)
    add("PSO: Strider against pyswarms", from_pso(pso_vs_pyswarms))
    def avr_section():
        if a.no_slow:
            raise NotMeasured("skipped in this run (--no-slow)")
        return avr(avr_data(build, a.reuse))

    add("AVR cycles and sizes", avr_section)
    add("IK accuracy, float and fixed point", needs_cli(accuracy), a.quick)
    if wanted is None:
        parts.append(f"## Simulator scenarios\n\n{sim_table(sim)}\n")
    add("Simulator against pybullet and MuJoCo", physics_check, sim, cli_path, a.reuse)
    tune = slow(lambda: gait_tune_data(build, a.reuse), *SECTION_GROUPS["gait"])

    def from_tune():
        if isinstance(tune, NotMeasured):
            raise tune
        return gait_tuning(tune)

    add("Gait tuning by PSO (simulator rollouts)", from_tune)

    stamp = (f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC from commit {git_describe()} on "
             f"{cpu_name()}{' (--quick: reduced samples)' if a.quick else ''}"
             f"{' (--reuse: measurements from out/results where present)' if a.reuse else ''}")
    if only:
        text = splice(pathlib.Path(a.out).read_text(), parts, summary,
                      [(g, f"Regenerated since (--only {g}): {', '.join(SECTION_GROUPS[g])}, {stamp}.")
                       for g in SECTION_GROUPS if g in only])
    else:
        head = ["# Results", "",
                "<!-- Generated by tools/results/make_results.py (tools/dev results); edits here are overwritten. -->",
                "",
                "What Strider measures against its seed papers and against other implementations. Everything on "
                "this page is regenerated by one script, `tools/results/make_results.py` (run by `tools/dev "
                "results`); numbers quoted from the papers say so. A figure whose source is not available says "
                "\"not measured\" and why.", "",
                f"Generated {stamp}.", "",
                "## Summary", ""]
        if not summary:
            head.append(not_measured("no section produced a figure"))
        else:
            head.append(table(["seed", "figure", "paper / target", "Strider"], summary))
        text = "\n".join(head) + "\n" + "\n".join(parts)
    text = re.sub(r"\n{3,}", "\n\n", text).rstrip() + "\n"
    pathlib.Path(a.out).write_text(text)
    print(f"wrote {a.out} in {time.monotonic() - t0:.1f} s ({cli.calls if cli else 0} CLI calls)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
