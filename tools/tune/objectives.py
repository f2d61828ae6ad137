"""What a trial walks and how it is scored.

A trial walks a few runs in strider-sim (each a rollout, one Ray task):
  sprint      `walk SPRINT` for WALK_S seconds: the best 2 s of forward speed
  cruise      `walk SPEED` for WALK_S seconds: cost of transport and stability margin
  distance D  `walk SPEED`, `stop` after D / SPEED seconds (seed 003 table 5)
and each objective is one number from its runs:
  speed           best 2 s window of forward (+x) displacement / 2 s [mm/s], higher is better
  distance_error  worst over the distances of |D - made| / D [%] (seed 003 eq 16 with the commanded
                  distance as the theoretical one): made is the body's displacement along the
                  starting heading from the walk command to the end, settled after the stop; lower
  energy          cost of transport: the servos' work / (mass g distance), lower
  stability       mean static stability margin while walking [mm]: the CoM's ground projection
                  to the support polygon of the feet down (to the line or point of one or two
                  feet down; negative outside), higher
  mix             sum of weight x value / scale, the maximized ones negated; lower
A run that falls, or whose parameters the robot refuses, scores PENALTY.
"""
import math
import os
import pathlib
import shutil
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "sim"))
import rollout  # noqa: E402  (tools/sim)
import render_trace  # noqa: E402  (tools/sim: the support polygon's geometry)
import space  # noqa: E402

WALK_AT_S = 3.0       # the walk command: after the soft start and stand-up
SETTLE_S = 4.0        # after `stop`, for the distance runs
FIRMWARE_BOOT_S = 4.0  # firmware mode: its boot (velocity limit search on the AVR) takes 3 s more

# name: (direction, scale for mix, penalty, unit)
OBJECTIVES = {
    "speed": ("maximize", 100.0, 0.0, "mm/s"),
    "distance_error": ("minimize", 10.0, 200.0, "%"),
    "energy": ("minimize", 1.0, 10.0, ""),
    "stability": ("maximize", 10.0, -100.0, "mm"),
}


def parse_weights(text):
    """'speed=1,energy=0.5' -> {'speed': 1.0, 'energy': 0.5}."""
    weights = {}
    for part in filter(None, (p.strip() for p in text.split(","))):
        name, _, w = part.partition("=")
        if name not in OBJECTIVES:
            raise ValueError(f"unknown objective {name!r} in --weights (one of {', '.join(OBJECTIVES)})")
        weights[name] = float(w) if w else 1.0
    if not weights or any(w < 0 for w in weights.values()) or not any(weights.values()):
        raise ValueError("--weights: at least one positive weight, none negative")
    return weights


class Objective:
    """One objective (or a weighted mix) over its runs."""

    def __init__(self, name, weights=None, speed_mm_s=100.0, sprint_mm_s=500.0, distances_mm=(100, 200, 1000),
                 walk_s=8.0):
        self.name = name
        self.terms = dict(weights) if name == "mix" else {name: 1.0}
        self.direction = "minimize" if name == "mix" else OBJECTIVES[name][0]
        self.unit = "" if name == "mix" else OBJECTIVES[name][3]
        self.speed, self.sprint, self.walk_s = speed_mm_s, sprint_mm_s, walk_s
        self.distances = tuple(distances_mm)

    def runs(self):
        """The runs a trial walks, as specs for walk_run()."""
        specs = []
        if self.terms.get("speed"):
            specs.append({"kind": "sprint", "speed": self.sprint, "walk_s": self.walk_s})
        if self.terms.get("energy") or self.terms.get("stability"):
            specs.append({"kind": "cruise", "speed": self.speed, "walk_s": self.walk_s})
        if self.terms.get("distance_error"):
            specs += [{"kind": "distance", "speed": self.speed, "distance_mm": float(d)} for d in self.distances]
        return specs

    def term_values(self, results):
        """{objective: value} from the results of runs() (same order)."""
        by_kind = {}
        for spec, res in zip(self.runs(), results):
            by_kind.setdefault(spec["kind"], []).append(res)
        values = {}
        for name in self.terms:
            if not self.terms[name]:
                continue
            penalty = OBJECTIVES[name][2]
            kind = {"speed": "sprint", "energy": "cruise", "stability": "cruise", "distance_error": "distance"}[name]
            runs = by_kind[kind]
            if any(r["failed"] for r in runs):
                values[name] = penalty
            elif name == "speed":
                values[name] = runs[0]["forward_speed_mm_s"]
            elif name == "energy":
                cot = runs[0]["cost_of_transport"]
                values[name] = penalty if cot is None else min(cot, penalty)
            elif name == "stability":
                values[name] = runs[0]["margin_mm"]
            else:
                values[name] = min(penalty, max(abs(r["distance_error_pct"]) for r in runs))
        return values

    def value(self, terms):
        """The number the study optimizes, from term_values()."""
        if self.name != "mix":
            return terms[self.name]
        cost = 0.0
        for name, w in self.terms.items():
            direction, scale, _, _ = OBJECTIVES[name]
            cost += w * terms[name] / scale * (-1.0 if direction == "maximize" else 1.0)
        return cost

    def better(self, a, b):
        """True when value a is strictly better than b."""
        return a > b if self.direction == "maximize" else a < b


def run_lines(gait, params, defaults, spec, t0=0.0):
    """(time, line) pairs of one run: deadman off, the gait, the parameters
    as the `set` and `height` lines a phone sends (in the order the robot
    takes them), the walk and, for a distance, the stop."""
    sends = [(t0 + 0.5, rollout.DEADMAN_OFF), (t0 + 1.0, f"gait {gait}")]
    t = t0 + 1.2
    for line in space.command_lines(gait, params, defaults["duty"])[1:]:
        sends.append((t, line))
        t += 0.2
    walk_at = max(t0 + WALK_AT_S, t + 0.2)
    sends.append((walk_at, f"walk {spec['speed']:g}"))
    if spec["kind"] == "distance":
        stop_at = walk_at + spec["distance_mm"] / spec["speed"]
        sends.append((stop_at, "stop"))
        end = stop_at + SETTLE_S
    else:
        end = walk_at + spec["walk_s"] + 0.5
    return sends, walk_at, math.ceil(end)


def support_margin(row, legs):
    """Static stability margin [mm] of one trace row: render_trace's for 3+
    feet down; with one or two, minus the CoM's distance to that point or
    line; None with none down."""
    m = render_trace.stability_margin(row, legs)
    if m is not None:
        return m
    feet = render_trace.convex_hull([(row[f"foot_{i}_x"], row[f"foot_{i}_y"]) for i in range(legs)
                                     if row[f"contact_{i}"] > 0.5])
    if not feet:
        return None
    p = (row["com_x_mm"], row["com_y_mm"])
    return -render_trace.segment_distance(p, feet[0], feet[-1])


def measure(spec, run, walk_at, legs):
    """The numbers of one finished run that the objectives use."""
    m, trace = run["metrics"], run["trace"]
    walking = [r for r in trace if r["t"] >= walk_at - 1e-9]
    best = 0.0
    k0 = 0
    for k, r in enumerate(walking):  # best 2 s window of forward displacement
        while r["t"] - walking[k0]["t"] > 2.0 + 1e-9:
            k0 += 1
        if r["t"] - walking[k0]["t"] >= 2.0 - 1e-9:
            best = max(best, (r["x_mm"] - walking[k0]["x_mm"]) / 2.0)
    margins = [support_margin(r, legs) for r in walking if r["t"] >= walk_at + 1.0]
    margins = [x for x in margins if x is not None]
    made = walking[-1]["x_mm"] - walking[0]["x_mm"] if walking else 0.0
    d = spec.get("distance_mm")
    return {
        "forward_speed_mm_s": best,
        "cost_of_transport": m.get("cost_of_transport"),
        "margin_mm": sum(margins) / len(margins) if margins else -100.0,
        "odometry_error_pct": m.get("odometry_error_pct"),
        "odometry_mm": m.get("odometry_mm"),
        "made_mm": made,
        "distance_error_pct": (d - made) / d * 100.0 if d else None,
        "max_tilt_deg": m["max_tilt_deg"],
        "fell": m["fell"],
    }


def walk_run(sim, robot, gait, params, defaults, spec, firmware=None, keep=None):
    """One rollout: the run `spec` of a trial with parameter set `params`
    (library mode, the simulator's gait options), or on the firmware ELF with
    the parameters sent as `set` lines. Returns the measures, `failed` and
    why, and the robot's replies. keep: a folder to leave the run's files in."""
    work = pathlib.Path(keep) if keep else pathlib.Path(tempfile.mkdtemp(prefix="strider-tune-"))
    try:
        t0 = FIRMWARE_BOOT_S if firmware else 0.0
        # Both modes take the parameters as the robot does, as `set` lines: a
        # tune is what a phone can send (the walker keeps the velocity limits
        # it found at start-up; options that configure it anew would not).
        sends, walk_at, duration = run_lines(gait, params, defaults, spec, t0)
        args = ["--firmware", str(firmware)] if firmware else []
        run = rollout.run_scenario(sim, rollout.scenario(robot, duration, sends), work, args, trace=True)
        out = {"spec": spec, "sends": sends, "failed": False, "why": None, "log": run["log"]}
        if run["error"]:
            return dict(out, failed=True, why=run["error"])
        # The simulator's duty refused for the gait tuned (not for the one the robot boots in).
        refusals = [text for _, text in run["log"]
                    if text.startswith("err") or (text.startswith("sim duty") and f" gait {gait}:" in text)]
        out.update(measure(spec, run, walk_at, len([k for k in run["trace"][0] if k.startswith("contact_")])))
        out["gait"] = run["metrics"].get("gait")
        if refusals:
            out.update(failed=True, why="refused: " + refusals[0])
        elif out["fell"]:
            out.update(failed=True, why="fell")
        return out
    finally:
        if not keep:
            shutil.rmtree(work, ignore_errors=True)


def probe(sim, robot, gait=None):
    """The model's defaults for `gait` (None: its default gait) as a parameter
    set, and strider-sim's `gait` object (table and other defaults): a 2 s
    run that picks the gait."""
    sends = [(0.5, rollout.DEADMAN_OFF)] + ([(1.0, f"gait {gait}")] if gait else [])
    with tempfile.TemporaryDirectory(prefix="strider-tune-") as tmp:
        run = rollout.run_scenario(sim, rollout.scenario(robot, 2, sends), tmp)
    if run["error"]:
        raise RuntimeError(f"strider-sim: {run['error']}")
    info = run["metrics"].get("gait")
    replies = [t for _, t in run["log"] if t.startswith("ok gait") or t.startswith("err")]
    if info is None or (gait and info["name"] != gait):
        raise RuntimeError(f"{robot} has no gait {gait!r} ({replies[-1] if replies else 'no reply'})")
    defaults = {"step_height_mm": info["step_height_mm"], "step_length_mm": info["step_length_mm"],
                "cycle_s": info["cycle_s"], "duty": info["duty"], "swing": info["swing"],
                "body_height_mm": info["body_height_mm"]}
    return defaults, info


def default_firmware(sim, robot):
    """The firmware ELF of `robot` in the build that holds `sim`, or None."""
    elf = pathlib.Path(sim).resolve().parents[2] / "src" / f"strider_firmware_{robot}.elf"
    return elf if elf.is_file() and os.access(sim, os.X_OK) else None
