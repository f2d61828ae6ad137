"""What every section of docs/results.md shares (tools/results/make_results.py):
the page's paths, "not measured", number and table formatting, the `strider`
CLI, and running one section."""
import json
import math
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
RESULTS = ROOT / "out" / "results"
# tools/bench's host_info, bench_report and firmware_figures, for the page's
# stamp and the AVR section.
sys.path.insert(0, str(ROOT / "tools" / "bench"))
from host_info import cpu_name  # noqa: E402,F401 (the page's stamp, re-exported)


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


def importable(name):
    import importlib.util
    return importlib.util.find_spec(name) is not None


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
