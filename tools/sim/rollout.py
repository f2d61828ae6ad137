"""One strider-sim run from Python: a scenario written from timed lines, the
simulator in a subprocess, and what it wrote read back. Shared by the gait
sweep (sweep_gait.py) and the tuner (tools/tune).

    text = scenario("mammal8", 12, [(0.5, "$deadman off*cb77"), (1, "gait trot"), (3, "walk 100")])
    run = run_scenario(sim, text, work_dir, gait_args({"step_height_mm": 12}))
    run["metrics"]["distance_mm"], run["log"], run["trace"]
"""
import csv
import json
import pathlib
import subprocess

# The deadman off, a checked line (docs/protocol.md): a scenario sends no keep-alives.
DEADMAN_OFF = "$deadman off*cb77"

# strider-sim's gait override options, by the key a parameter set uses.
GAIT_OPTIONS = (("step_height_mm", "--step-height"), ("step_length_mm", "--step-length"), ("cycle_s", "--cycle"),
                ("duty", "--duty"), ("swing", "--swing"))


def scenario(robot, duration_s, sends):
    """Scenario text: `robot`, `duration` and one `at T send LINE\\n` per
    (T [s], LINE) of sends."""
    lines = [f"robot {robot}", f"duration {duration_s:g}"]
    lines += [f"at {t:.3f} send {text}\\n" for t, text in sends]
    return "\n".join(lines) + "\n"


def gait_args(params):
    """strider-sim options for the gait values in params (a missing, zero or
    empty value: the model's own)."""
    args = []
    for key, opt in GAIT_OPTIONS:
        v = params.get(key)
        if v:
            args += [opt, v if isinstance(v, str) else f"{v:g}"]
    return args


def read_log(path):
    """robot.log as [(t [s], line)]."""
    out = []
    for line in pathlib.Path(path).read_text().splitlines():
        t, _, text = line.partition(" ")
        out.append((float(t), text))
    return out


def read_trace(path):
    """trace.csv as a list of {column: float}."""
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def run_scenario(sim, text, work, args=(), trace=False, timeout_s=600):
    """Writes `text` to work/run.scenario, runs strider-sim on it into work/
    and returns {"metrics", "log", "trace" (with trace=True), "error"}: error
    is None, or strider-sim's last line of stderr when it failed (metrics
    and log are then None)."""
    work = pathlib.Path(work)
    work.mkdir(parents=True, exist_ok=True)
    path = work / "run.scenario"
    path.write_text(text)
    cmd = [str(sim), str(path), "--out", str(work), "--quiet", *args]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout_s)
    if p.returncode != 0:
        lines = p.stderr.strip().splitlines() or [f"strider-sim exited {p.returncode}"]
        return {"metrics": None, "log": None, "trace": None, "error": lines[-1]}
    return {"metrics": json.loads((work / "metrics.json").read_text()), "log": read_log(work / "robot.log"),
            "trace": read_trace(work / "trace.csv") if trace else None, "error": None}
