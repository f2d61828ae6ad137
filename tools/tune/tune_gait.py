#!/usr/bin/env python3
"""Tunes a gait's live parameters (step height and length, cycle, duty, swing
shape, body height) by strider-sim rollouts: an optuna study (TPE or CMA-ES,
ask/tell) whose rollouts run as Ray tasks, on this machine (`ray.init()`) or
on a Ray cluster (--address). The search walks library mode; the best is then
checked on the model's firmware on the virtual Mega, its parameters sent as
the `set` lines a phone would send. docs/tuning.md explains the objectives.

    tools/tune/tune_gait.py --model sprawl8 --gait trot --objective speed --trials 60
    tools/tune/tune_gait.py --model mammal8 --gait trot --objective distance_error --workers 2
    tools/tune/tune_gait.py --model sprawl8 --objective mix --weights speed=1,energy=0.5
    tools/tune/tune_gait.py --model hexapod18 --objective speed --address 10.0.0.5:6379 --workers 32

Writes to --out: trials.csv, search.png, best.json, gait_row.txt (rows for
gait_params.h and gait_library.h), commands.txt (the command script for
robotctl or a phone), best_run_*/ and firmware_run_*/ (strider-sim's files
of the best parameters' runs, for tools/sim/render_trace.py).
"""
import argparse
import json
import os
import pathlib
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
DEFAULT_SIM = ROOT / "out" / "build" / "tools" / "sim" / "strider-sim"

import objectives  # noqa: E402
import space  # noqa: E402


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--model", required=True, help="robot model (strider robots): sprawl8, mammal8, ...")
    ap.add_argument("--gait", help="gait to tune (default: the model's default gait)")
    ap.add_argument("--objective", default="speed", choices=[*objectives.OBJECTIVES, "mix"])
    ap.add_argument("--weights", default="", help="for mix: e.g. speed=1,energy=0.5,stability=0.2")
    ap.add_argument("--trials", type=int, default=40)
    ap.add_argument("--workers", type=int, default=0,
                    help="rollouts at once (default: this machine's CPUs, or the cluster's with --address)")
    ap.add_argument("--address", help="a Ray cluster to run on (ray start --head prints it), e.g. 10.0.0.5:6379")
    ap.add_argument("--out", help="output folder (default out/tune/MODEL_GAIT_OBJECTIVE)")
    ap.add_argument("--sampler", default="tpe", choices=["tpe", "cmaes"])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--params", default="step_height,step_length,cycle,duty,swing,height",
                    help="parameters searched (the others stay at the defaults)")
    ap.add_argument("--range", action="append", default=[], metavar="NAME=LO:HI",
                    help="a range of its own for a parameter, e.g. step_height=5:25 (repeatable)")
    ap.add_argument("--speed", type=float, default=100.0, help="walk speed of the cruise and distance runs [mm/s]")
    ap.add_argument("--sprint-speed", type=float, default=500.0,
                    help="walk speed asked in the speed run [mm/s]: the gait engine limits it to what it can do")
    ap.add_argument("--distances", default="100,200,1000", help="distances of distance_error [mm]")
    ap.add_argument("--walk-s", type=float, default=8.0, help="walking time of the speed and cruise runs [s]")
    ap.add_argument("--sim", default=str(DEFAULT_SIM), help="the strider-sim binary (same path on every node)")
    ap.add_argument("--firmware", help="firmware ELF for the final check (default: the model's in the build)")
    ap.add_argument("--no-firmware-check", action="store_true", help="skip the firmware-mode check")
    ap.add_argument("--top", type=int, default=10, help="trials in the printed table")
    ap.add_argument("--no-progress", action="store_true", help="no progress bar")
    a = ap.parse_args(argv)
    if a.trials < 1 or a.workers < 0 or a.speed <= 0 or a.sprint_speed <= 0 or a.walk_s < 3:
        ap.error("--trials >= 1, --workers >= 0, speeds > 0, --walk-s >= 3")
    try:
        a.weights = objectives.parse_weights(a.weights) if a.objective == "mix" else None
        a.distances = [float(x) for x in a.distances.split(",")]
        a.params = [space.SHORT[n.strip()] for n in a.params.split(",") if n.strip()]
        a.ranges = {}
        for r in a.range:
            name, _, lohi = r.partition("=")
            lo, _, hi = lohi.partition(":")
            a.ranges[space.SHORT[name]] = (float(lo), float(hi))
    except (ValueError, KeyError) as e:
        ap.error(f"{e} (parameters: {', '.join(space.SHORT)})")
    if not a.distances or min(a.distances) <= 0 or not a.params:
        ap.error("--distances positive, --params not empty")
    if not os.access(a.sim, os.X_OK):
        ap.error(f"strider-sim not found at {a.sim} (tools/dev tune builds it, or pass --sim)")
    return a


def run_summary(results):
    """The measures of a trial's runs, for best.json and the printout."""
    keys = ("forward_speed_mm_s", "made_mm", "distance_error_pct", "odometry_mm", "odometry_error_pct",
            "cost_of_transport", "margin_mm", "max_tilt_deg", "fell", "why")
    out = []
    for r in results:
        row = dict(r["spec"])
        row.update({k: (round(r[k], 3) if isinstance(r.get(k), float) else r.get(k)) for k in keys})
        out.append(row)
    return out


def describe_runs(summary):
    parts = []
    for r in summary:
        if r["kind"] == "distance" and r["made_mm"] is not None:
            parts.append(f"{r['distance_mm']:g} mm: made {r['made_mm']:.0f} ({r['distance_error_pct']:+.1f} %)")
        elif r["kind"] == "sprint" and r["forward_speed_mm_s"] is not None:
            parts.append(f"sprint {r['forward_speed_mm_s']:.1f} mm/s, tilt {r['max_tilt_deg']:.1f} deg")
        elif r["kind"] == "cruise" and r["margin_mm"] is not None:
            parts.append(f"cruise: cost of transport {r['cost_of_transport']}, margin {r['margin_mm']:.1f} mm")
        if r["why"]:
            parts.append(r["why"])
    return "; ".join(parts)


def firmware_check(a, robot, gait, objective, best, defaults, out):
    """The best parameters on the firmware: the objective's runs with the
    parameters sent as `set` lines (Ray tasks too). A refused line means
    the firmware walked its own values: reported as refused, not as a check."""
    import ray

    elf = pathlib.Path(a.firmware) if a.firmware else objectives.default_firmware(a.sim, robot)
    if elf is None or not elf.is_file():
        return {"status": "skipped", "why": f"no firmware ELF for {robot} (build it, or pass --firmware)"}
    check = ray.remote(num_cpus=1)(objectives.walk_run)
    specs = objective.runs()
    refs = [check.remote(a.sim, robot, gait, best["params"], defaults, spec, str(elf), str(out / f"firmware_run_{i}"))
            for i, spec in enumerate(specs)]
    results = ray.get(refs)
    import report

    pairs, refused = report.firmware_verdict(results)
    # What it walked: a refused line is no failure of the walk itself (a fall still is).
    walked = [dict(r, failed=bool(r.get("fell")) or (r["failed"] and not r["why"].startswith("refused")))
              for r in results]
    terms = objective.term_values(walked)
    res = {"elf": str(elf), "replies": [{"sent": s, "reply": r} for s, r in pairs],
           "value": objective.value(terms), "terms": terms, "runs": run_summary(results)}
    if refused:
        res.update(status="refused", why="; ".join(f"`{s}` -> `{r}`" for s, r in refused))
    else:
        res.update(status="ok", why=None)
    return res


def main(argv=None):
    a = parse_args(sys.argv[1:] if argv is None else argv)
    import ray  # the heavy imports after the argument checks

    import report
    import search

    defaults, info = objectives.probe(a.sim, a.model, a.gait)
    gait = info["name"]
    objective = objectives.Objective(a.objective, a.weights, a.speed, a.sprint_speed, a.distances, a.walk_s)
    try:
        search_space = space.ranges(defaults, gait, a.params, a.ranges, info.get("bounds"))
    except (ValueError, KeyError) as e:
        sys.exit(f"tune_gait.py: {e}")
    out = pathlib.Path(a.out or ROOT / "out" / "tune" / f"{a.model}_{gait}_{a.objective}")
    out.mkdir(parents=True, exist_ok=True)

    t_ray = time.monotonic()
    resources = search.start_ray(a.workers or os.cpu_count() or 1, a.address)
    workers = a.workers or int(resources.get("CPU", 1))
    ray_s = time.monotonic() - t_ray
    where = f"Ray cluster {a.address}" if a.address else "Ray on this machine"
    print(f"{a.model} {gait}: {a.objective}{' ' + str(a.weights) if a.weights else ''}, {a.trials} trials of "
          f"{len(objective.runs())} rollouts, {workers} at once ({where}: {resources.get('CPU', 0):g} CPUs, "
          f"started in {ray_s:.1f} s), {a.sampler.upper()} sampler")
    print("searching: " + ", ".join(f"{k} {r[0]:g}..{r[1]:g}" if not isinstance(r[0], str) else f"{k} {'/'.join(r)}"
                                    for k, r in search_space.items()))
    s = search.Search(a.sim, a.model, gait, objective, defaults, search_space, a.sampler, a.seed,
                      info.get("bounds", {}).get("swing_lift_ms", 0.0))
    try:
        best = s.run(a.trials, workers, progress=not a.no_progress)
        rate = s.rollouts / s.rollout_s if s.rollout_s > 0 else 0.0
        print(f"{s.rollouts} rollouts in {s.rollout_s:.1f} s: {rate:.2f} rollouts/s on {workers} workers")
        base = s.baseline
        beats = best is not None and objective.better(best["value"], base["value"])
        print(report.table(objective, s.records, base, a.top))
        print(f"defaults: {base['value']:.4g}; best: trial {best['trial']}, {best['value']:.4g}"
              f"{'' if beats else ' (does not beat the defaults)'}")
        print(f"  defaults: {describe_runs(run_summary(base['runs']))}")
        print(f"  best:     {describe_runs(run_summary(best['runs']))}")

        # The best's runs again with their files kept (deterministic: the same numbers).
        for i, spec in enumerate(objective.runs()):
            objectives.walk_run(a.sim, a.model, gait, best["params"], defaults, spec, keep=out / f"best_run_{i}")
        fw = {"status": "skipped", "why": "--no-firmware-check"}
        if not a.no_firmware_check:
            fw = firmware_check(a, a.model, gait, objective, best, defaults, out)
        if fw["status"] == "ok":
            print(f"firmware check ({fw['elf']}): {fw['value']:.4g} with the best parameters sent as set lines "
                  f"(library mode {best['value']:.4g}): {describe_runs(fw['runs'])}")
        elif fw["status"] == "refused":
            print(f"firmware check: the firmware refused the parameters: {fw['why']}; it walked its own "
                  f"values for those ({a.objective} {fw['value']:.4g}), so this is no check of the tune")
        else:
            print(f"firmware check skipped: {fw['why']}")

        report.write_csv(out / "trials.csv", objective, s.records, base)
        title = f"{a.model} {gait}, {a.objective}: {len(s.records)} trials, {a.sampler.upper()}"
        report.plot(out / "search.png", s.study, objective, s.records, base, title)
        (out / "commands.txt").write_text(space.command_script(a.model, gait, a.objective, best["params"], defaults["duty"]))
        (out / "gait_row.txt").write_text(space.gait_rows(a.model, gait, a.objective, best["params"], info))
        summary = {
            "model": a.model, "gait": gait, "objective": a.objective, "weights": a.weights,
            "direction": objective.direction, "runs": objective.runs(), "sampler": a.sampler, "seed": a.seed,
            "trials": len(s.records), "workers": workers, "address": a.address, "ray_cpus": resources.get("CPU"),
            "rollouts": s.rollouts, "search_s": round(s.rollout_s, 3), "rollouts_per_s": round(rate, 3),
            "space": {k: list(v) for k, v in search_space.items()},
            "defaults": dict({k: base[k] for k in ("params", "value", "terms", "failed")},
                             runs=run_summary(base["runs"])),
            "best": dict({k: best[k] for k in ("trial", "params", "value", "terms", "failed")},
                         runs=run_summary(best["runs"])),
            "beats_defaults": beats, "firmware_check": fw,
        }
        (out / "best.json").write_text(json.dumps(summary, indent=1))
        print(f"wrote {out}/: trials.csv search.png best.json gait_row.txt commands.txt")
    finally:
        ray.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
