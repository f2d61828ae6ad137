#!/usr/bin/env python3
"""Regenerates docs/results.md: every figure in it is measured by this run
(or read from a result file a measuring tool wrote) and nothing is typed in
by hand, except the seed papers' own numbers, which are quoted as such.
A section whose source is missing says "not measured: <why>".

Sources:
- the `strider` CLI (seed 001 pose ranges, seed 002 tables 4-9, accuracy);
- tools/pso_bench (pso_bench + pso_compare.py: seed 003 table 4, pyswarms);
- tools/bench (avr_cycles, firmware_figures.py) for AVR cycles and sizes,
  else out/bench/avr.json from an earlier `tools/dev bench`;
- strider-sim and tools/sim/scenarios (seed 000 speed and turning, seed 003
  table 5 distances), when the simulator is built;
- tools/pso_bench/gait_tune (PSO gait tuning over strider-sim rollouts);
- tools/sim/measure_speed.py (the phone pad per model: each firmware in
  strider-sim's firmware mode, RC buttons at four slider steps);
- tools/results/sim_crosscheck.py (strider-sim's runs replayed in pybullet
  and MuJoCo), when they are installed.
Intermediate results go to out/results/.

usage: make_results.py [--build DIR] [--out docs/results.md] [--reuse] [--quick] [--no-slow]
                       [--only pso,gait,pad,seed003]
  --reuse  take the PSO comparison, gait tuning, simulator metrics and
           cross-check replays from out/results when present instead of
           measuring them again
  --quick  fewer samples (a check of the generator itself, not for docs)
  --no-slow  skip the PSO comparison, the simulator and the gait tuning
           (they then read "not measured"); for the generator's own test
  --only   measure only the named section groups (pso: seed 003 table 4
           and the pyswarms comparison; gait: the gait tuning; pad: the phone
           pad per model; seed003: seed 003 table 5 in the simulator) and replace
           those sections and their summary rows in the existing page
"""
import argparse
import datetime
import os
import pathlib
import re
import sys
import time

from results_avr import avr, avr_data
from results_common import RESULTS, ROOT, Cli, NotMeasured, cpu_name, git_describe, not_measured, section, table
from results_kinematics import accuracy, seed001, seed002
from results_pad import pad_data, pad_table
from results_pso import pso_data, pso_vs_pyswarms, seed003_pso
from results_sim import gait_tune_data, gait_tuning, physics_check, seed000, seed003_distance, sim_metrics, sim_table


SECTION_GROUPS = {"pso": ("Seed 003: PSO joint angles, table 4", "PSO: Strider against pyswarms"),
                  "gait": ("Gait tuning by PSO (simulator rollouts)",),
                  "pad": ("Phone pad per model (simulator, firmware mode)",),
                  "seed003": ("Seed 003: distances walked, table 5 (simulator)",)}


def splice(old_text, parts, summary, notes):
    """Replaces the regenerated sections and their summary rows in a page."""
    text = old_text
    for md in parts:
        title = md.split("\n", 1)[0]
        start = text.find(title + "\n")
        if start < 0:
            raise SystemExit(f"{title!r} is not on the page: regenerate it whole")
        end = text.find("\n## ", start + len(title))
        text = text[:start] + md.rstrip() + "\n" + (text[end:] if end >= 0 else "")
    for seed, figure, paper, value in summary:
        row = f"| {seed} | {figure} | {paper} | {value} |"
        text, n = re.subn(r"^\| " + re.escape(seed) + r" \| " + re.escape(figure) + r" \|.*$",
                          lambda _m: row, text, count=1, flags=re.M)
        if n == 0:
            raise SystemExit(f"summary row {figure!r} is not on the page: regenerate it whole")
    # One note per group regenerated, after the page's "Generated" line.
    for group, line in notes:
        text = re.sub(r"^Regenerated since \(--only( " + re.escape(group) + r")?\):.*\n\n", "", text, flags=re.M)
    head, sep, rest = text.partition("\n## Summary")
    text = head.rstrip("\n") + "\n\n" + "\n\n".join(line for _, line in notes) + "\n" + sep + rest
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=os.environ.get("STRIDER_BUILD_DIR", str(ROOT / "out" / "build")))
    ap.add_argument("--out", default=str(ROOT / "docs" / "results.md"))
    ap.add_argument("--reuse", action="store_true", help="reuse out/results measurements when present")
    ap.add_argument("--quick", action="store_true", help="few samples: a check of the generator, not for docs")
    ap.add_argument("--no-slow", action="store_true", help="skip the PSO comparison and the simulator")
    ap.add_argument("--only", help="comma-separated section groups (" + ", ".join(SECTION_GROUPS) + "): "
                    "measure just those and replace them and their summary rows in the existing page")
    a = ap.parse_args()
    only = set(a.only.split(",")) if a.only else None
    if only and not only <= set(SECTION_GROUPS):
        ap.error(f"--only takes {', '.join(SECTION_GROUPS)}")
    wanted = {t for g in only for t in SECTION_GROUPS[g]} if only else None
    build = pathlib.Path(a.build).resolve()
    RESULTS.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()

    cli_path = build / "tools" / "cli" / "strider"
    cli = Cli(str(cli_path)) if cli_path.is_file() else None

    def needs_cli(fn):
        def run(*args):
            if cli is None:
                raise NotMeasured(f"the strider CLI is not built ({build.name}/tools/cli/strider)")
            return fn(cli, *args)
        return run

    def slow(measure, *titles):
        """A slow source, measured only when a section that needs it is wanted."""
        if wanted is not None and not wanted & set(titles):
            return NotMeasured("not wanted")
        try:
            if a.no_slow:
                raise NotMeasured("skipped in this run (--no-slow)")
            return measure()
        except NotMeasured as e:
            return e

    pso = slow(lambda: pso_data(build, a.reuse, a.quick)[0], *SECTION_GROUPS["pso"])
    sim = slow(lambda: sim_metrics(build, a.reuse), "Seed 000: speed and turning (simulator)",
               "Seed 003: distances walked, table 5 (simulator)", "Simulator against pybullet and MuJoCo")

    def using(data, fn):
        """fn(data) for a section, or the reason a slow source was not measured."""
        def run():
            if isinstance(data, NotMeasured):
                raise data
            return fn(data)
        return run

    parts, summary = [], []

    def add(title, fn, *args):
        if wanted is not None and title not in wanted:
            return
        md, rows = section(title, fn, *args)
        parts.append(md)
        summary.extend(rows)

    add("Seed 000: speed and turning (simulator)", seed000, sim)
    pad = slow(lambda: pad_data(build, a.reuse), *SECTION_GROUPS["pad"])
    add("Phone pad per model (simulator, firmware mode)", using(pad, pad_table))
    add("Seed 001: body pose ranges", needs_cli(seed001), a.quick)
    add("Seed 002: foot positions, tables 4-9", needs_cli(seed002))
    add("Seed 003: PSO joint angles, table 4", using(pso, seed003_pso))
    add("Seed 003: distances walked, table 5 (simulator)", seed003_distance, sim)
    add("PSO: Strider against pyswarms", using(pso, pso_vs_pyswarms))
    def avr_section():
        if a.no_slow:
            raise NotMeasured("skipped in this run (--no-slow)")
        return avr(avr_data(build, a.reuse))

    add("AVR cycles and sizes", avr_section)
    add("IK accuracy, float and fixed point", needs_cli(accuracy), a.quick)
    if wanted is None:
        parts.append(f"## Simulator scenarios\n\n{sim_table(sim)}\n")
    add("Simulator against pybullet and MuJoCo", physics_check, sim, cli_path, a.reuse)
    tune = slow(lambda: gait_tune_data(build, a.reuse), *SECTION_GROUPS["gait"])
    add("Gait tuning by PSO (simulator rollouts)", using(tune, gait_tuning))

    stamp = (f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC from commit {git_describe()} on "
             f"{cpu_name()}{' (--quick: reduced samples)' if a.quick else ''}"
             f"{' (--reuse: measurements from out/results where present)' if a.reuse else ''}")
    if only:
        text = splice(pathlib.Path(a.out).read_text(), parts, summary,
                      [(g, f"Regenerated since (--only {g}): {', '.join(SECTION_GROUPS[g])}, {stamp}.")
                       for g in SECTION_GROUPS if g in only])
    else:
        head = ["# Results", "",
                "<!-- Generated by tools/results/make_results.py (tools/dev results); edits here are overwritten. -->",
                "",
                "What Strider measures against its seed papers and against other implementations. Everything on "
                "this page is regenerated by one script, `tools/results/make_results.py` (run by `tools/dev "
                "results`); numbers quoted from the papers say so. A figure whose source is not available says "
                "\"not measured\" and why.", "",
                f"Generated {stamp}.", "",
                "## Summary", ""]
        if not summary:
            head.append(not_measured("no section produced a figure"))
        else:
            head.append(table(["seed", "figure", "paper / target", "Strider"], summary))
        text = "\n".join(head) + "\n" + "\n".join(parts)
    text = re.sub(r"\n{3,}", "\n\n", text).rstrip() + "\n"
    pathlib.Path(a.out).write_text(text)
    print(f"wrote {a.out} in {time.monotonic() - t0:.1f} s ({cli.calls if cli else 0} CLI calls)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
