"""The tuner's search space: the gait parameters a phone can set live
(`set step_height|step_length|cycle|duty|swing`, `height`), their ranges
around a model's defaults, and the outputs made from a parameter set (the
command script and the rows of gait_params.h and gait_library.h).

A parameter set is a dict with the keys of PARAMS; values are on the grid of
each parameter's step, so that what the tuner writes is exactly what it
walked."""
import math

# key: (protocol line, unit, grid step, range as factors of the default)
PARAMS = {
    "step_height_mm": ("set step_height", "mm", 0.5, (0.3, 1.0)),
    "step_length_mm": ("set step_length", "mm", 0.5, (0.5, 2.5)),
    "cycle_s": ("set cycle", "s", 0.05, (0.4, 2.0)),
    "duty": ("set duty", "", 0.01, None),  # DUTY_RANGE
    "swing": ("set swing", "", None, None),  # SWINGS
    "body_height_mm": ("height", "mm", 0.5, (0.8, 1.2)),
}
SHORT = {"step_height": "step_height_mm", "step_length": "step_length_mm", "cycle": "cycle_s", "duty": "duty",
         "swing": "swing", "height": "body_height_mm"}
SWINGS = ("rectangle", "semicircle", "ellipse", "cycloid", "parabola", "bezier")  # swing_trajectory.h

# Duty ranges per gait (gait_library.h's tables with their offsets): from the
# least duty that keeps the support its static_asserts ask for (quadrupeds 2
# feet down, the walk 3; hexapods tripod 3, ripple 4, wave 5) and, for the
# walk and crawl, which shift the body, a four-foot window between swings;
# up to a swing of a tenth to a fifth of the cycle, what the servos can lift
# and carry a foot in at the cycles searched.
DUTY_RANGE = {
    "walk": (0.76, 0.95), "crawl": (0.55, 0.90), "trot": (0.50, 0.80), "pace": (0.50, 0.80),
    "tripod": (0.50, 0.80), "ripple": (0.67, 0.90), "wave": (0.84, 0.95),
}


def on_grid(value, step):
    """value rounded to a multiple of step (and tidied of float noise)."""
    return round(round(value / step) * step, 6)


def ranges(defaults, gait, names, overrides=None, bounds=None):
    """{key: (low, high, step) or tuple of choices} for the parameters in
    `names`, around `defaults` (a parameter set: the model's values), with
    `overrides` {key: (low, high)} taking the place of the computed ones,
    within `bounds` (strider-sim's `gait.bounds`: what the robot accepts of
    each `set`, so that the firmware takes what the tuner finds)."""
    out = {}
    bounds = bounds or {}
    for key in names:
        if key == "swing":
            out[key] = tuple(s for s in SWINGS if s in bounds.get("swings", SWINGS))
            continue
        _, _, step, factors = PARAMS[key]
        if overrides and key in overrides:
            lo, hi = overrides[key]
        elif key == "duty":
            lo, hi = DUTY_RANGE[gait]
        else:
            lo, hi = defaults[key] * factors[0], defaults[key] * factors[1]
            if key == "cycle_s":
                lo, hi = max(lo, 0.2), min(hi, 10.0)
        if key in bounds:
            lo, hi = max(lo, bounds[key][0]), min(hi, bounds[key][1])
        lo, hi = math.ceil(lo / step - 1e-9) * step, math.floor(hi / step + 1e-9) * step
        if not lo < hi:
            raise ValueError(f"{key}: empty range {lo:g}..{hi:g}")
        out[key] = (round(lo, 6), round(hi, 6), step)
    return out


def snapped(defaults, space):
    """The defaults moved onto the grid (and into the range) of every searched
    parameter: where the search starts."""
    out = {}
    for key, r in space.items():
        if isinstance(r[0], str):
            out[key] = defaults[key] if defaults[key] in r else r[0]
        else:
            lo, hi, step = r
            out[key] = min(hi, max(lo, on_grid(defaults[key], step)))
    return out


def shortest_cycle(duty, lift_ms):
    """The shortest cycle [s] the robot takes with `duty` (gait_tuner.h): the
    servos' lift `lift_ms` must fit the swing, (1 - duty) x cycle, rounded as
    the firmware rounds (to 0.01 s, half up, then one more), at least 0.2 s."""
    if lift_ms <= 0 or duty >= 1:
        return 0.2
    return max(20, math.floor(lift_ms / (10 * (1 - duty)) + 0.5) + 1) / 100


def complete(params, defaults, lift_ms=0.0):
    """A full parameter set: params (tidied of the grid's float noise) with the
    defaults for what was not searched; a searched cycle too short for the
    duty is raised onto the grid above the shortest the robot takes (it would
    refuse it, and walks no faster than its servos step anyway)."""
    out = {}
    for key in PARAMS:
        v = params.get(key, defaults[key])
        out[key] = round(v, 6) if isinstance(v, float) and key in params else v
    if "cycle_s" in params:
        step = PARAMS["cycle_s"][2]
        least = shortest_cycle(out["duty"], lift_ms)
        if out["cycle_s"] < least - 1e-9:
            out["cycle_s"] = round(math.ceil(least / step - 1e-9) * step, 6)
    return out


def fmt(value):
    """A number as a command takes it: no exponent, no trailing zeros."""
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return text if text not in ("", "-0") else "0"


def command_lines(gait, params, from_duty=None):
    """The protocol lines that set `params` on a robot walking `gait` (without
    `save`). The robot checks the cycle against the duty and the duty against
    the cycle: a longer share down goes after its cycle, a shorter one
    (than `from_duty`, the gait's own) before it, so that each line is taken."""
    keys = list(PARAMS)
    if from_duty is not None and "duty" in params and params["duty"] < from_duty:
        keys.remove("duty")
        keys.insert(keys.index("cycle_s"), "duty")
    lines = [f"gait {gait}"]
    for key in keys:
        if key in params:
            v = params[key]
            lines.append(f"{PARAMS[key][0]} {v if isinstance(v, str) else fmt(v)}")
    return lines


def command_script(robot, gait, objective, params, from_duty=None):
    """The command script file: comments, the lines, `save`."""
    head = [f"# {robot} {gait}, tuned for {objective} in strider-sim (tools/tune/tune_gait.py).",
            "# Send line by line (robotctl send, or a terminal app, CR+LF); `save` keeps them."]
    return "\n".join(head + command_lines(gait, params, from_duty) + ["save"]) + "\n"


def _f(v):
    text = f"{v:.6f}".rstrip("0")
    return (text + "0" if text.endswith(".") else text) + "f"


def gait_rows(robot, gait, objective, params, info):
    """C++ rows in the formats of gait_params.h (the model's GaitParams) and
    gait_library.h (the GaitTable with the tuned duty), from `info` (the
    `gait` object of strider-sim's metrics.json: table and other defaults)."""
    d = info["defaults"]
    t = info["table"]
    shape = "SwingShape::k" + params["swing"].capitalize()
    offsets = list(t["offsets"]) + [0.0] * (6 - len(t["offsets"]))
    table_name = "kGait" + gait.capitalize()
    return "\n".join([
        f"// {robot} {gait}, tuned for {objective} in strider-sim (tools/tune/tune_gait.py).",
        "// gait_params.h, kGaitParams: the model's gait defaults, with the tuned step, cycle and swing",
        "// (default_gait set to the tuned gait):",
        f'{{"{robot}", "{gait}", {shape}, {_f(params["step_height_mm"])}, {_f(params["step_length_mm"])}, '
        f'{_f(params["cycle_s"])}, {_f(d["stance_depth_mm"])}, {_f(d["foot_radius_mm"])}, {_f(d["com_x_mm"])}, '
        f'{_f(d["com_y_mm"])}, {_f(d["margin_mm"])}, {_f(d["shift_budget_mm"])}, {_f(d["sit_drop_mm"])}, '
        f'{_f(d["transition_s"])}}},',
        "// gait_library.h: the gait's table with the tuned duty (the same leg offsets):",
        f'constexpr GaitTable {table_name} STRIDER_GAIT_STORAGE = {{"{gait}", {t["legs"]}, {_f(params["duty"])}, '
        f'{{{", ".join(_f(o) for o in offsets)}}}, {str(t["shift_body"]).lower()}, '
        f'{str(t["relabel_by_direction"]).lower()}}};',
        f"// body height: `height {fmt(params['body_height_mm'])}` (mm; the model's standing height is "
        f"{fmt(info['body_height_mm'])} mm before any `height`)",
    ]) + "\n"
