#!/usr/bin/env python3
"""Sweeps a gait's speed, step and cycle in strider-sim and ranks them by how
closely the robot reaches commanded distances (seed 003 table 5, eq 16).

Each candidate is a speed [mm/s], step height [mm], step length [mm] and cycle
time at low speed [s] (strider-sim --step-height/--step-length/--cycle, library
mode). It walks each distance of --distances once: `gait G`, `walk V`, and
`stop` after distance / V seconds, on the robot's own control code. Its error
over a run is strider-sim's odometry_error_pct: how much of the gait engine's
own dead reckoning (the distance the feet were commanded to push, which the
speed ramp keeps at the commanded distance) the body did not make good; above
100 % the robot went backward. A candidate's score is its worst |error| over
the distances; a fall scores infinity.

Candidates are drawn at random (--seed) from the grid below without repeats;
--samples of them are walked. The first is the model's own gait defaults at
--default-speed. Output: a table of the --top best on stdout, and with --json
FILE every candidate with its runs.

    tools/sim/sweep_gait.py --robot mammal8 --gait trot --samples 150
    tools/sim/sweep_gait.py --robot mammal8 --gait pace --samples 150 -- --foot-pad 10

Options after `--` go to strider-sim as they are (world options such as
--foot-pad, --friction, --step).
"""
import argparse
import concurrent.futures
import itertools
import json
import math
import os
import pathlib
import random
import sys
import tempfile

import rollout

ROOT = pathlib.Path(__file__).resolve().parents[2]
DEFAULT_SIM = ROOT / "out" / "build" / "tools" / "sim" / "strider-sim"

# The grid: what a 2-DOF or 3-DOF hobby-servo robot can be asked for. 0: the
# model's default (gait_params.h).
SPEEDS_MM_S = (10, 20, 30, 50, 75, 100, 150)
STEP_HEIGHTS_MM = (5, 8, 10, 15, 20, 30)
STEP_LENGTHS_MM = (20, 30, 40, 60, 80)
CYCLES_S = (0.4, 0.6, 0.8, 1.0, 1.5, 2.0)

WALK_AT_S = 3.0   # after the soft start and stand-up (the scenarios' own time)
SETTLE_S = 5.0    # after `stop`: the ramp down and the last steps


def scenario_text(robot, gait, speed, distance):
    stop_at = WALK_AT_S + distance / speed
    return rollout.scenario(robot, math.ceil(stop_at + SETTLE_S),
                            [(0.5, rollout.DEADMAN_OFF), (1, f"gait {gait}"), (WALK_AT_S, f"walk {speed:g}"),
                             (stop_at, "stop")])


def walk_once(sim, work, robot, gait, cand, distance, sim_args):
    """One run; the metrics strider-sim wrote, or None and its error."""
    name = f"{gait}_{cand['speed_mm_s']:g}_{distance:g}_{os.getpid()}_{random.getrandbits(40):x}"
    run = rollout.run_scenario(sim, scenario_text(robot, gait, cand["speed_mm_s"], distance), work / name,
                               [*sim_args, *rollout.gait_args(cand)])
    return run["metrics"], run["error"]


def score(runs):
    if any(r.get("error") or r["fell"] for r in runs):
        return math.inf
    return max(abs(r["odometry_error_pct"]) for r in runs)


def evaluate(sim, work, robot, gait, cand, distances, sim_args):
    runs = []
    for d in distances:
        m, err = walk_once(sim, work, robot, gait, cand, d, sim_args)
        if m is None:
            runs.append({"distance_mm": d, "error": err})
            break
        runs.append({"commanded_mm": d, "distance_mm": m["distance_mm"], "odometry_mm": m["odometry_mm"],
                     "odometry_error_pct": m["odometry_error_pct"], "max_tilt_deg": m["max_tilt_deg"],
                     "fell": m["fell"]})
    return dict(cand, runs=runs, score=score(runs))


def candidates(samples, seed, default_speed):
    grid = list(itertools.product(SPEEDS_MM_S, STEP_HEIGHTS_MM, STEP_LENGTHS_MM, CYCLES_S))
    rng = random.Random(seed)
    picked = rng.sample(grid, min(max(samples - 1, 0), len(grid)))
    first = {"speed_mm_s": default_speed, "step_height_mm": 0, "step_length_mm": 0, "cycle_s": 0}
    rest = [{"speed_mm_s": s, "step_height_mm": h, "step_length_mm": l, "cycle_s": c} for s, h, l, c in picked]
    return [first] + rest


def describe(c):
    def val(v, unit):
        return f"{v:g}{unit}" if v else "default"
    return (f"{c['speed_mm_s']:g} mm/s, height {val(c['step_height_mm'], ' mm')}, "
            f"length {val(c['step_length_mm'], ' mm')}, cycle {val(c['cycle_s'], ' s')}")


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    sim_args = []
    if "--" in argv:
        at = argv.index("--")
        argv, sim_args = argv[:at], argv[at + 1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--robot", default="mammal8")
    ap.add_argument("--gait", default="trot")
    ap.add_argument("--distances", default="100,200,1000", help="commanded distances [mm], comma-separated")
    ap.add_argument("--samples", type=int, default=100, help="candidates walked, the defaults first")
    ap.add_argument("--default-speed", type=float, default=100.0, help="speed of the defaults candidate [mm/s]")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--top", type=int, default=10)
    ap.add_argument("--sim", default=str(DEFAULT_SIM), help="the strider-sim binary")
    ap.add_argument("--json", help="write every candidate and its runs to this file")
    a = ap.parse_args(argv)
    try:
        distances = [float(x) for x in a.distances.split(",")]
    except ValueError:
        ap.error(f"--distances {a.distances!r}: expected numbers [mm]")
    if not distances or min(distances) <= 0 or a.samples < 1 or a.jobs < 1 or a.default_speed <= 0:
        ap.error("distances, samples, jobs and the default speed must be positive")
    if not os.access(a.sim, os.X_OK):
        ap.error(f"strider-sim not found at {a.sim} (build it: tools/dev test, or pass --sim)")

    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        cands = candidates(a.samples, a.seed, a.default_speed)
        with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
            results = list(pool.map(lambda c: evaluate(a.sim, work, a.robot, a.gait, c, distances, sim_args), cands))
    errors = [r for r in results if any(run.get("error") for run in r["runs"])]
    ranked = sorted(results, key=lambda r: r["score"])
    dist_names = " / ".join(f"{d:g}" for d in distances)
    print(f"{a.robot} {a.gait}: {len(results)} candidates over {dist_names} mm"
          f"{' with ' + ' '.join(sim_args) if sim_args else ''}; error [%] of each distance (above 100: backward)")
    for r in ranked[:a.top]:
        errs = " / ".join(f"{run['odometry_error_pct']:.1f}" if "odometry_error_pct" in run else "err"
                          for run in r["runs"])
        worst = "fell" if math.isinf(r["score"]) else f"{r['score']:.1f} %"
        print(f"  worst {worst:>8}  [{errs}]  {describe(r)}")
    default = results[0]
    print(f"defaults ({describe(default)}): worst "
          f"{'fell' if math.isinf(default['score']) else format(default['score'], '.1f') + ' %'}")
    if errors:
        print(f"{len(errors)} candidates did not run: {errors[0]['runs'][-1]['error']}")
    if a.json:
        plain = [dict(r, score=None if math.isinf(r["score"]) else r["score"]) for r in ranked]  # JSON has no inf
        pathlib.Path(a.json).write_text(json.dumps({"robot": a.robot, "gait": a.gait, "distances_mm": distances,
                                                    "sim_args": sim_args, "candidates": plain}, indent=1))
    return 1 if len(errors) == len(results) else 0


if __name__ == "__main__":
    sys.exit(main())
