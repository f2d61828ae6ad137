#!/usr/bin/env python3
"""Strider's PSO against pyswarms on seed 003's problem, side by side in one
run (docs/results.md, "PSO: Strider against pyswarms").

Both solve the same problem with the same settings (seed 003 table 3: swarm
20, 1000 iterations, c1 = c2 = 1.5, w = 0.5; cost = the distance of the foot
of a 70/70 mm two-link leg to the target, eq 15), once per seed:
  case a: bounds 0..20 rad, target (100, 0) mm (the paper's printed numbers);
  case b: bounds 0..20 deg, target FK(13.34156399 deg, 17.29916917 deg).
Figures per implementation: median wall time of a full 1000-iteration run
and its final cost, and the median time until the best cost first fell
below 1e-6 mm (pyswarms: rerun with the same seed for exactly the iterations
it needed, so the time is measured, not scaled). The C++ side is
tools/pso_bench/pso_bench.cpp.

usage: pso_compare.py --pso-bench PATH [--runs N] [--json OUT] [--smoke]
Exit status 0; 1 when either side misses 1e-6 mm in the median (a smoke test
can fail); 77 when pyswarms or numpy is not installed.
"""
import argparse
import json
import logging
import math
import pathlib
import platform
import statistics
import subprocess
import sys
import time

TARGET_COST_MM = 1e-6
LINK_MM = 70.0
SEED_T_DEG = (13.34156399, 17.29916917)


def problem(case):
    if case == "a":
        return 20.0, (100.0, 0.0)
    t1, t2 = (math.radians(t) for t in SEED_T_DEG)
    return math.radians(20.0), (LINK_MM * (math.cos(t1) + math.cos(t1 + t2)),
                                LINK_MM * (math.sin(t1) + math.sin(t1 + t2)))


def run_pyswarms(case, runs, iterations):
    import numpy as np
    import pyswarms as ps

    logging.disable(logging.CRITICAL)  # its reporter would log every run
    hi, (tx, tz) = problem(case)

    def cost(q):  # seed 003 eqs 3 and 15, vectorised over the swarm
        x = LINK_MM * np.cos(q[:, 0]) + LINK_MM * np.cos(q[:, 0] + q[:, 1])
        z = LINK_MM * np.sin(q[:, 0]) + LINK_MM * np.sin(q[:, 0] + q[:, 1])
        return np.sqrt((x - tx) ** 2 + (z - tz) ** 2)

    def optimizer():
        return ps.single.GlobalBestPSO(n_particles=20, dimensions=2, options={"c1": 1.5, "c2": 1.5, "w": 0.5},
                                       bounds=(np.zeros(2), np.full(2, hi)))

    ms, costs, ms_to, it_to, best = [], [], [], [], (math.inf, None)
    for r in range(runs):
        np.random.seed(1 + r)
        o = optimizer()
        t0 = time.perf_counter()
        c, pos = o.optimize(cost, iters=iterations, verbose=False)
        ms.append((time.perf_counter() - t0) * 1e3)
        costs.append(float(c))
        if c < best[0]:
            best = (float(c), [math.degrees(float(v)) for v in pos])
        hist = np.asarray(o.cost_history)
        below = np.nonzero(hist < TARGET_COST_MM)[0]
        if below.size:
            k = int(below[0]) + 1
            np.random.seed(1 + r)  # the same swarm again, stopped there
            o = optimizer()
            t0 = time.perf_counter()
            o.optimize(cost, iters=k, verbose=False)
            ms_to.append((time.perf_counter() - t0) * 1e3)
            it_to.append(k)
    out = {"impl": "pyswarms", "version": ps.__version__, "scalar": "double (numpy float64)", "case": case,
           "runs": runs, "swarm": 20, "iterations": iterations, "median_ms": statistics.median(ms),
           "min_ms": min(ms), "max_ms": max(ms), "median_cost_mm": statistics.median(costs),
           "worst_cost_mm": max(costs), "best_joints_deg": best[1], "reached_1e-6": len(it_to)}
    if it_to:
        out["median_iterations_to_1e-6"] = statistics.median(it_to)
        out["median_ms_to_1e-6"] = statistics.median(ms_to)
    return out


def run_strider(pso_bench, runs, iterations):
    p = subprocess.run([pso_bench, "--runs", str(runs), "--iterations", str(iterations)], capture_output=True,
                       text=True, timeout=600)
    rows = [json.loads(line) for line in p.stdout.splitlines() if line.startswith("{")]
    if not rows:
        raise RuntimeError(f"pso_bench printed nothing (exit {p.returncode}): {p.stderr.strip()}")
    return rows


def cpu_name():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


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
    try:
        import numpy  # noqa: F401
        import pyswarms  # noqa: F401
    except ImportError as e:
        print(f"SKIP: {e.name} is not installed (tools/dev python_env installs it)")
        return 77
    strider_rows = run_strider(a.pso_bench, a.runs, a.iterations)
    py_rows = [run_pyswarms(c, a.runs, a.iterations) for c in ("a", "b")]
    ok = True
    comparison = []
    for py in py_rows:
        lib = next(r for r in strider_rows if r["case"] == py["case"] and r["scalar"] == "double")
        row = {"case": py["case"], "problem": lib["problem"],
               "ratio_full_run": py["median_ms"] / lib["median_ms"],
               "pyswarms_median_cost_mm": py["median_cost_mm"], "strider_median_cost_mm": lib["median_cost_mm"]}
        if "median_ms_to_1e-6" in py and "median_ms_to_1e-6" in lib:
            row["ratio_to_1e-6"] = py["median_ms_to_1e-6"] / lib["median_ms_to_1e-6"]
        comparison.append(row)
        ok = ok and py["median_cost_mm"] < TARGET_COST_MM and lib["median_cost_mm"] < TARGET_COST_MM
        print(f"case {py['case']} ({lib['problem']}): pyswarms {py['median_ms']:.1f} ms, cost "
              f"{py['median_cost_mm']:.1e} mm; strider double {lib['median_ms']:.3f} ms, cost "
              f"{lib['median_cost_mm']:.1e} mm; {row['ratio_full_run']:.0f}x"
              + (f"; to 1e-6 mm {row['ratio_to_1e-6']:.0f}x" if "ratio_to_1e-6" in row else ""))
    result = {"host_cpu": cpu_name(), "python": platform.python_version(), "runs": a.runs,
              "iterations": a.iterations, "pyswarms": py_rows, "strider": strider_rows, "comparison": comparison}
    if a.json:
        path = pathlib.Path(a.json)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(result, indent=1) + "\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
