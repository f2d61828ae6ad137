#!/usr/bin/env python3
"""Strider's PSO against pyswarms on seed 003's problem, side by side in one
run (docs/results.md, "PSO: Strider against pyswarms").

Both solve the same problem with the same settings (seed 003 table 3: swarm
20, 1000 iterations, c1 = c2 = 1.5, w = 0.5; cost = the distance of the foot
of a 70/70 mm two-link leg to the target, eq 15), once per seed:
  case a: bounds 0..20 rad, target (100, 0) mm (the paper's printed numbers);
  case b: bounds 0..20 deg, target FK(13.34156399 deg, 17.29916917 deg).
Figures per implementation: median time of a full 1000-iteration run and its
final cost, and the median time until the best cost first fell below 1e-6 mm
(pyswarms: rerun with the same seed for exactly the iterations it needed, so
the time is measured, not scaled). The C++ side is tools/pso_bench/pso_bench.cpp,
in double, with the cost called per particle (libm) and vectorised over the
swarm (libmvec; pyswarms' cost is vectorised over the swarm by numpy).

Measured fairly under load: both sides are timed in thread CPU time (wall
time is recorded too: under load a 10 ms pyswarms run is preempted far more
often than a 0.1 ms Strider run, which would favour Strider), each after an
untimed warm-up run, seed by seed interleaved (Strider then pyswarms, then the
other way round), so both see the same machine; medians over the seeds. Not
timed on either side: pyswarms' constructor (its swarm initialisation), while
Strider's minimize() includes its own.

usage: pso_compare.py --pso-bench PATH [--runs N] [--json OUT] [--smoke]
Exit status 0; 1 when either side misses 1e-6 mm in the median (a smoke test
can fail); 77 when pyswarms or numpy is not installed.
"""
import argparse
import json
import logging
import math
import os
import pathlib
import platform
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "bench"))
from host_info import cpu_name  # noqa: E402

TARGET_COST_MM = 1e-6
LINK_MM = 70.0
SEED_T_DEG = (13.34156399, 17.29916917)


def problem(case):
    if case == "a":
        return 20.0, (100.0, 0.0)
    t1, t2 = (math.radians(t) for t in SEED_T_DEG)
    return math.radians(20.0), (LINK_MM * (math.cos(t1) + math.cos(t1 + t2)),
                                LINK_MM * (math.sin(t1) + math.sin(t1 + t2)))


class Pyswarms:
    """pyswarms' GlobalBestPSO on one case, one seed at a time."""

    def __init__(self, case):
        import numpy as np
        import pyswarms as ps

        logging.disable(logging.CRITICAL)  # its reporter would log every run
        self.np, self.ps = np, ps
        self.hi, (self.tx, self.tz) = problem(case)
        self.optimizer(0).optimize(self.cost, iters=50, verbose=False)  # warm-up, untimed

    def cost(self, q):  # seed 003 eqs 3 and 15, vectorised over the swarm
        np = self.np
        x = LINK_MM * np.cos(q[:, 0]) + LINK_MM * np.cos(q[:, 0] + q[:, 1])
        z = LINK_MM * np.sin(q[:, 0]) + LINK_MM * np.sin(q[:, 0] + q[:, 1])
        return np.sqrt((x - self.tx) ** 2 + (z - self.tz) ** 2)

    def optimizer(self, seed):
        self.np.random.seed(seed)
        return self.ps.single.GlobalBestPSO(n_particles=20, dimensions=2, options={"c1": 1.5, "c2": 1.5, "w": 0.5},
                                            bounds=(self.np.zeros(2), self.np.full(2, self.hi)))

    def run(self, seed, iterations):
        o = self.optimizer(seed)
        c0, w0 = time.thread_time(), time.perf_counter()
        c, pos = o.optimize(self.cost, iters=iterations, verbose=False)
        out = {"ms": (time.thread_time() - c0) * 1e3, "wall_ms": (time.perf_counter() - w0) * 1e3,
               "cost_mm": float(c), "joints_deg": [math.degrees(float(v)) for v in pos]}
        below = self.np.nonzero(self.np.asarray(o.cost_history) < TARGET_COST_MM)[0]
        if below.size:
            k = int(below[0]) + 1
            o = self.optimizer(seed)  # the same swarm again, stopped there
            c0, w0 = time.thread_time(), time.perf_counter()
            o.optimize(self.cost, iters=k, verbose=False)
            out.update({"ms_to": (time.thread_time() - c0) * 1e3, "wall_ms_to": (time.perf_counter() - w0) * 1e3,
                        "iterations_to": k})
        return out


def run_strider_seed(pso_bench, case, seed, iterations):
    """pso_bench for one seed (after its own warm-up): one row per cost variant."""
    rows = run_pso_bench(pso_bench, ["--case", case, "--scalar", "double", "--runs", "1", "--seed", str(seed),
                                     "--iterations", str(iterations)])
    out = {}
    for r in rows:
        one = {"ms": r["median_ms"], "wall_ms": r["median_wall_ms"], "cost_mm": r["median_cost_mm"],
               "joints_deg": r["best_joints_deg"], "cost_math": r["cost_math"]}
        if "median_ms_to_1e-6" in r:
            one.update({"ms_to": r["median_ms_to_1e-6"], "wall_ms_to": r["median_wall_ms_to_1e-6"],
                        "iterations_to": r["median_iterations_to_1e-6"]})
        out[r["cost"]] = one
    return out


def summarise(samples, **fields):
    """Medians over the seeds of one implementation and case."""
    med = statistics.median
    best = min(samples, key=lambda s: s["cost_mm"])
    out = dict(fields)
    out.update({"runs": len(samples), "swarm": 20, "median_ms": med(s["ms"] for s in samples),
                "min_ms": min(s["ms"] for s in samples), "max_ms": max(s["ms"] for s in samples),
                "median_wall_ms": med(s["wall_ms"] for s in samples),
                "median_cost_mm": med(s["cost_mm"] for s in samples),
                "worst_cost_mm": max(s["cost_mm"] for s in samples), "best_joints_deg": best["joints_deg"]})
    to = [s for s in samples if "ms_to" in s]
    out["reached_1e-6"] = len(to)
    if to:
        out["median_iterations_to_1e-6"] = med(s["iterations_to"] for s in to)
        out["median_ms_to_1e-6"] = med(s["ms_to"] for s in to)
        out["median_wall_ms_to_1e-6"] = med(s["wall_ms_to"] for s in to)
    return out


def interleaved(pso_bench, case, runs, iterations):
    """Both implementations seed by seed, alternating which goes first."""
    py = Pyswarms(case)
    py_s, lib_s = [], {}
    for r in range(runs):
        seed = 1 + r
        if r % 2 == 0:
            lib = run_strider_seed(pso_bench, case, seed, iterations)
            py_s.append(py.run(seed, iterations))
        else:
            py_s.append(py.run(seed, iterations))
            lib = run_strider_seed(pso_bench, case, seed, iterations)
        for k, v in lib.items():
            lib_s.setdefault(k, []).append(v)
    py_row = summarise(py_s, impl="pyswarms", version=py.ps.__version__, scalar="double (numpy float64)", case=case,
                       iterations=iterations)
    lib_rows = [summarise(v, impl="strider", scalar="double", cost=k, cost_math=v[0]["cost_math"], case=case,
                          iterations=iterations) for k, v in sorted(lib_s.items())]
    return py_row, lib_rows


def run_pso_bench(pso_bench, args):
    p = subprocess.run([pso_bench] + args, capture_output=True, text=True, timeout=600)
    rows = [json.loads(line) for line in p.stdout.splitlines() if line.startswith("{")]
    if not rows:
        raise RuntimeError(f"pso_bench printed nothing (exit {p.returncode}): {p.stderr.strip()}")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pso-bench", required=True, help="the pso_bench executable")
    ap.add_argument("--runs", type=int, default=21, help="seeds per implementation and case (median)")
    ap.add_argument("--iterations", type=int, default=1000)
    ap.add_argument("--json", help="write the comparison here (docs/results.md reads it)")
    ap.add_argument("--smoke", action="store_true", help="few runs, check convergence only")
    a = ap.parse_args()
    if a.smoke:
        a.runs = 3
    # pyswarms (its import already) writes report.log into the working
    # directory: keep it out of the caller's (the checkout, when run there).
    a.pso_bench = os.path.abspath(a.pso_bench)
    json_out = os.path.abspath(a.json) if a.json else None
    scratch = tempfile.TemporaryDirectory(prefix="pso_compare-")
    os.chdir(scratch.name)
    try:
        import numpy  # noqa: F401
        import pyswarms  # noqa: F401
    except ImportError as e:
        print(f"SKIP: {e.name} is not installed (tools/dev python_env installs it)")
        return 77
    # Every scalar and cost, all seeds in one process (seed 003's table).
    strider_rows = run_pso_bench(a.pso_bench, ["--runs", str(a.runs), "--iterations", str(a.iterations)])
    ok = True
    comparison, py_rows, timed_rows = [], [], []
    for case in ("a", "b"):
        py, libs = interleaved(a.pso_bench, case, a.runs, a.iterations)
        py_rows.append(py)
        timed_rows += libs
        lib = {r["cost"]: r for r in libs}
        problem_text = next(r["problem"] for r in strider_rows if r["case"] == case)
        row = {"case": case, "problem": problem_text, "pyswarms_median_cost_mm": py["median_cost_mm"]}
        for cost, r in lib.items():
            row[cost] = {"ratio_full_run": py["median_ms"] / r["median_ms"],
                         "ratio_full_run_wall": py["median_wall_ms"] / r["median_wall_ms"],
                         "strider_median_cost_mm": r["median_cost_mm"]}
            if "median_ms_to_1e-6" in py and "median_ms_to_1e-6" in r:
                row[cost]["ratio_to_1e-6"] = py["median_ms_to_1e-6"] / r["median_ms_to_1e-6"]
                row[cost]["ratio_to_1e-6_wall"] = py["median_wall_ms_to_1e-6"] / r["median_wall_ms_to_1e-6"]
            ok = ok and r["median_cost_mm"] < TARGET_COST_MM
            print(f"case {case} ({problem_text}): pyswarms {py['median_ms']:.2f} ms, cost "
                  f"{py['median_cost_mm']:.1e} mm; strider double, {cost} cost, {r['median_ms']:.3f} ms, cost "
                  f"{r['median_cost_mm']:.1e} mm; {row[cost]['ratio_full_run']:.0f}x"
                  + (f"; to 1e-6 mm {row[cost]['ratio_to_1e-6']:.0f}x" if "ratio_to_1e-6" in row[cost] else ""))
        comparison.append(row)
        ok = ok and py["median_cost_mm"] < TARGET_COST_MM
    result = {"host_cpu": cpu_name(), "python": platform.python_version(), "runs": a.runs,
              "iterations": a.iterations, "timing": "thread CPU time, seeds interleaved", "pyswarms": py_rows,
              "strider": strider_rows, "strider_interleaved": timed_rows, "comparison": comparison}
    if json_out:
        path = pathlib.Path(json_out)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(result, indent=1) + "\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
