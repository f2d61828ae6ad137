"""The tuner's outputs: the results table (CSV and printed), the plot of the
search, and the firmware check's reading of the robot's replies."""
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import optuna  # noqa: E402

import space  # noqa: E402


def _cell(v):
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


def write_csv(path, objective, records, baseline):
    """One row per trial (the defaults first): its parameters, objective
    value, each objective term and why a run failed."""
    keys = list(space.PARAMS)
    terms = list(objective.terms)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["trial", *keys, "value", *terms, "failed"])
        for rec in [baseline] + records:
            w.writerow([rec["trial"], *(rec["params"][k] for k in keys), rec["value"],
                        *(rec["terms"].get(t) for t in terms), "; ".join(rec["failed"])])


def table(objective, records, baseline, top=10):
    """The printed table: the best `top` trials and the defaults."""
    ranked = sorted(records, key=lambda r: r["value"], reverse=objective.direction == "maximize")[:top]
    head = ["trial", "value", "height", "length", "cycle", "duty", "swing", "body h", "note"]
    rows = []
    for rec in [baseline] + ranked:
        p = rec["params"]
        rows.append([rec["trial"], _cell(rec["value"]), _cell(p["step_height_mm"]), _cell(p["step_length_mm"]),
                     _cell(p["cycle_s"]), _cell(p["duty"]), p["swing"], _cell(p["body_height_mm"]),
                     "; ".join(rec["failed"])[:40]])
    widths = [max(len(str(r[i])) for r in [head] + rows) for i in range(len(head))]
    lines = ["  ".join(str(c).rjust(widths[i]) for i, c in enumerate(r)).rstrip() for r in [head] + rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    lines.insert(3, "")  # the defaults, then the ranking
    return "\n".join(lines)


def plot(path, study, objective, records, baseline, title):
    """search.png: the objective of each trial with the best so far and the
    defaults; the parameters' importance (optuna's PED-ANOVA); the objective
    over the most important numeric parameter."""
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    ax = axes[0]
    xs = [int(r["trial"]) for r in records]
    ys = [r["value"] for r in records]
    ok = [not r["failed"] for r in records]
    ax.scatter([x for x, o in zip(xs, ok) if o], [y for y, o in zip(ys, ok) if o], s=14, label="trial")
    ax.scatter([x for x, o in zip(xs, ok) if not o], [y for y, o in zip(ys, ok) if not o], s=18, marker="x",
               color="tab:red", label="fell or refused")
    best, line = None, []
    for y in ys:
        best = y if best is None or objective.better(y, best) else best
        line.append(best)
    ax.step(xs, line, where="post", color="tab:green", label="best so far")
    ax.axhline(baseline["value"], color="gray", ls="--", label="defaults")
    ax.set_xlabel("trial")
    ax.set_ylabel(f"{objective.name}" + (f" [{objective.unit}]" if objective.unit else "") +
                  (" (higher is better)" if objective.direction == "maximize" else " (lower is better)"))
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=9)

    ax = axes[1]
    importance = {}
    try:
        importance = optuna.importance.get_param_importances(study, evaluator=optuna.importance.PedAnovaImportanceEvaluator())
    except (RuntimeError, ValueError, ImportError) as e:  # too few or too alike trials
        ax.text(0.5, 0.5, f"no importance: {e}"[:60], ha="center", fontsize=8)
    if importance:
        names = list(importance)[::-1]
        ax.barh(names, [importance[n] for n in names])
        ax.set_xlabel("importance (PED-ANOVA)")
    ax.set_title("parameter importance", fontsize=9)

    ax = axes[2]
    numeric = [n for n in (importance or space.PARAMS) if n != "swing" and n in records[0]["params"]]
    if numeric and records:
        key = numeric[0]
        sc = ax.scatter([r["params"][key] for r in records], ys, c=xs, cmap="viridis", s=14)
        ax.axvline(baseline["params"][key], color="gray", ls="--", label="default")
        fig.colorbar(sc, ax=ax, label="trial")
        ax.set_xlabel(key)
        ax.set_ylabel(objective.name)
        ax.legend(fontsize=8)
    ax.set_title("objective over the most important parameter", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def replies(result):
    """(sent line, reply) for each line of a run, in order: every line gets
    one reply, `ok ...` or `err ...` (docs/protocol.md)."""
    answers = [text for _, text in result["log"] if text.startswith("ok") or text.startswith("err")]
    sent = [line for _, line in result["sends"]]
    return [(line, answers[i] if i < len(answers) else "(no reply)") for i, line in enumerate(sent)]


def firmware_verdict(results):
    """The parameter lines and their replies; the refused ones."""
    pairs = [(line, reply) for line, reply in replies(results[0])
             if line.startswith("set ") or line.startswith("height ")]
    refused = [(line, reply) for line, reply in pairs if not reply.startswith("ok")]
    return pairs, refused


def is_finite(v):
    return isinstance(v, (int, float)) and math.isfinite(v)
