"""The simulator sections of docs/results.md: strider-sim's scenarios (seed 000
speed and turning, seed 003 table 5 distances, every scenario), their replay
in pybullet and MuJoCo (sim_crosscheck.py) and the PSO gait tuning over
strider-sim rollouts (tools/pso_bench/gait_tune)."""
import json
import re
import subprocess
import sys

from results_common import RESULTS, ROOT, NotMeasured, fmt, importable, not_measured, table


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


RUN_003 = r"^mammal8_(seed_)?(walk|trot|pace)_(\d+)mm$"


def seed003_distance(metrics):
    head = ("003", "table 5: distance reached, walk/trot/pace", "errors 0.35-10 %")
    if isinstance(metrics, NotMeasured):
        return not_measured(str(metrics)), [head + ("not measured (simulator)",)]
    rows, errs = [], {}
    runs = find(metrics, RUN_003)
    order = {"walk": 0, "trot": 1, "pace": 2}  # the paper's order, then by distance

    def key(name):
        seed, g, mm = re.match(RUN_003, name).groups()
        return bool(seed), order[g], int(mm)

    for name in sorted(runs, key=key):
        m = runs[name]
        seed, gait, mm = re.match(RUN_003, name).groups()
        cm = int(mm) // 10
        odo, err = m.get("odometry_mm"), m.get("odometry_error_pct")
        # strider-sim's error counts the displacement along the way the gait
        # went: reached = commanded (1 - error), negative when it slid back.
        along = odo * (1.0 - err / 100.0) if odo is not None and err is not None else None
        if err is not None:
            errs.setdefault((bool(seed), gait), []).append(abs(err))
        paper = S003_TABLE5.get(gait, {}).get(cm)
        rows.append([gait, scenario_commands(name), f"{cm}", fmt(odo), fmt(along), fmt(m.get("distance_mm")), fmt(err),
                     fmt(paper) if paper is not None else "-", "yes" if m.get("fell") else "no"])
    if not rows:
        return not_measured("no mammal8_<gait>_<mm>mm scenario has metrics"), [head + ("not measured",)]
    md = ("Seed 003 walked its robot 10, 20, 100 and 200 cm in each gait and measured the distance reached "
          "(table 5), in 10 mm steps at 2.5-4.2 mm/s. mammal8 in the simulator, commanded by the scenarios' "
          "`walk` and `stop` lines: first its default gaits (15-100 mm/s), then at the seed's own point "
          "(`mammal8_seed_*`: the presets `walk10`, `trot10`, `pace10` at the seed's speeds, 20 mm rubber pads, "
          "the servos at 200 Hz; docs/gaits.md). 'commanded' is the distance the gait engine's own odometry "
          "covered, 'reached' the body's displacement in the simulated world along that way (negative: it went "
          "backward), error = (commanded - reached) / commanded as strider-sim's metrics.json reports it "
          "(library mode; firmware mode in docs/simulator.md). pace10 walks with a speed correction of its own "
          "(lib/strider/gait/speed_correction.h: the gait 1 / 0.866 faster than commanded, for the slip of its "
          "dragging feet), so its odometry runs past the target: compare its displacement with the target "
          "(the firmware's are within 2.3 %, docs/simulator.md):\n\n")
    md += table(["gait", "commands", "target [cm]", "commanded [mm]", "reached along it [mm]", "displacement [mm]",
                 "error [%]", "paper's error [%]", "fell"], rows)
    back = sum(1 for r in rows if r[4].startswith("-") and r[4] != "-")

    def span(seed):
        parts = [f"{g} {fmt(min(errs[seed, g]))}-{fmt(max(errs[seed, g]))}" for g in order if (seed, g) in errs]
        return ", ".join(parts)

    cell = "; ".join(c for c in (f"default gaits {span(False)} %" if span(False) else "",
                                 f"seed's point {span(True)} %" if span(True) else "") if c)
    return md, [head + ((cell + (f"; {back} runs went backward" if back else "")) if errs else "-",)]


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
    engines = [e for e in ("pybullet", "mujoco") if importable(e)]
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
