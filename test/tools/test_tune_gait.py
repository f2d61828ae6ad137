"""tools/tune/tune_gait.py on this build's strider-sim: a small tune on 2
local Ray workers finds parameters that beat the model's defaults on its
objective, evaluated the same way (the rollouts again, without Ray: the
simulator is deterministic), and writes every output. Skipped when
strider-sim is not built or optuna, Ray or tqdm cannot be imported."""
import csv
import importlib.util
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SIM = os.environ.get("STRIDER_SIM", "")
TUNE = ROOT / "tools" / "tune" / "tune_gait.py"
MISSING = [m for m in ("optuna", "ray", "tqdm") if importlib.util.find_spec(m) is None]
TRIALS = 12


class TuneSpace(unittest.TestCase):
    """The parameter sets the tuner makes are ones the robot takes: the cycle
    against the duty (gait_tuner.h), and the lines in an order it accepts."""

    @classmethod
    def setUpClass(cls):
        sys.path.insert(0, str(TUNE.parent))
        import space
        cls.space = space

    def test_shortest_cycle_as_the_firmware_rounds(self):
        # sprawl8: lift 186.4 ms (gait.bounds); crawl 0.67 -> 0.57 s (err 25's range), 0.90 -> 1.87 s.
        self.assertAlmostEqual(self.space.shortest_cycle(0.67, 186.4), 0.57)
        self.assertAlmostEqual(self.space.shortest_cycle(0.90, 186.4), 1.87)
        self.assertAlmostEqual(self.space.shortest_cycle(0.50, 0.0), 0.2)

    def test_a_cycle_too_short_for_its_duty_is_raised_onto_the_grid(self):
        defaults = {"step_height_mm": 20.0, "step_length_mm": 40.0, "cycle_s": 0.8, "duty": 0.67,
                    "swing": "ellipse", "body_height_mm": 72.0}
        p = self.space.complete({"cycle_s": 0.6, "duty": 0.9}, defaults, 186.4)
        self.assertAlmostEqual(p["cycle_s"], 1.9)  # 1.87 up to the 0.05 s grid
        p = self.space.complete({"cycle_s": 2.5, "duty": 0.9}, defaults, 186.4)
        self.assertAlmostEqual(p["cycle_s"], 2.5)
        p = self.space.complete({"duty": 0.9}, defaults, 186.4)  # cycle not searched: left alone
        self.assertAlmostEqual(p["cycle_s"], 0.8)

    def test_a_longer_duty_goes_after_its_cycle_a_shorter_before(self):
        up = self.space.command_lines("crawl", {"cycle_s": 2.5, "duty": 0.9}, from_duty=0.67)
        self.assertEqual(up, ["gait crawl", "set cycle 2.5", "set duty 0.9"])
        down = self.space.command_lines("crawl", {"cycle_s": 0.6, "duty": 0.55}, from_duty=0.67)
        self.assertEqual(down, ["gait crawl", "set duty 0.55", "set cycle 0.6"])


@unittest.skipIf(not os.access(SIM, os.X_OK), f"strider-sim is not built ({SIM or '$STRIDER_SIM unset'})")
@unittest.skipIf(bool(MISSING), f"cannot import {', '.join(MISSING)} (tools/dev installs them into out/venv)")
class TuneGait(unittest.TestCase):
    def tune(self, *args, timeout=240):
        return subprocess.run([sys.executable, str(TUNE), "--sim", SIM, *args], capture_output=True, text=True,
                              timeout=timeout)

    def test_small_tune_on_two_workers_beats_the_defaults(self):
        # sprawl8's crawl, speed: 4 s walks, 12 trials of one rollout each.
        with tempfile.TemporaryDirectory() as tmp:
            out = pathlib.Path(tmp)
            t0 = time.monotonic()
            p = self.tune("--model", "sprawl8", "--gait", "crawl", "--objective", "speed", "--trials", str(TRIALS),
                          "--workers", "2", "--walk-s", "4", "--seed", "3", "--no-progress",
                          "--out", str(out))
            print(p.stdout[-3000:])
            self.assertEqual(p.returncode, 0, p.stderr[-3000:])
            print(f"tune: {time.monotonic() - t0:.1f} s")
            best = json.loads((out / "best.json").read_text())
            self.assertEqual(best["workers"], 2)
            self.assertEqual(best["ray_cpus"], 2)
            self.assertEqual(best["trials"], TRIALS)
            self.assertEqual(best["rollouts"], TRIALS + 1)  # and the defaults
            self.assertGreater(best["rollouts_per_s"], 0)
            self.assertEqual(best["direction"], "maximize")
            self.assertGreater(best["best"]["value"], best["defaults"]["value"])
            self.assertTrue(best["beats_defaults"])
            # The best parameters sent to the sprawl8 firmware as `set` lines:
            # every line taken (the search stays within what it accepts) and a walk.
            fw = best["firmware_check"]
            if fw["status"] != "skipped":  # no firmware ELF in this build
                self.assertEqual(fw["status"], "ok", fw)
                self.assertTrue(all(r["reply"].startswith("ok") for r in fw["replies"]), fw["replies"])
                self.assertGreater(len(fw["replies"]), 4)
                self.assertGreater(fw["value"], 0)

            # The same objective, evaluated again outside the tuner and Ray.
            sys.path.insert(0, str(TUNE.parent))
            import objectives

            objective = objectives.Objective("speed", walk_s=4.0)
            defaults, _ = objectives.probe(SIM, "sprawl8", "crawl")
            self.assertEqual(defaults, best["defaults"]["params"])
            values = {}
            for name in ("defaults", "best"):
                params = best[name]["params"]
                results = [objectives.walk_run(SIM, "sprawl8", "crawl", params, defaults, spec)
                           for spec in objective.runs()]
                values[name] = objective.value(objective.term_values(results))
                self.assertAlmostEqual(values[name], best[name]["value"], places=6)
            self.assertGreater(values["best"], values["defaults"])

            with open(out / "trials.csv", newline="") as f:
                rows = list(csv.DictReader(f))
            self.assertEqual([r["trial"] for r in rows], ["defaults"] + [str(k) for k in range(TRIALS)])
            self.assertGreater((out / "search.png").stat().st_size, 10000)
            script = (out / "commands.txt").read_text().splitlines()
            lines = [s for s in script if not s.startswith("#")]
            self.assertEqual(lines[0], "gait crawl")
            self.assertEqual(lines[-1], "save")
            # A shorter duty than the gait's own goes before its cycle (TuneSpace).
            order = ["step_height", "step_length", "cycle", "duty", "swing"]
            if best["best"]["params"]["duty"] < defaults["duty"]:
                order = ["step_height", "step_length", "duty", "cycle", "swing"]
            self.assertEqual([s.split()[1] for s in lines[1:6]], order)
            self.assertTrue(lines[6].startswith("height "))
            row = (out / "gait_row.txt").read_text()
            self.assertIn('{"sprawl8", "crawl", SwingShape::k', row)
            self.assertIn('constexpr GaitTable kGaitCrawl STRIDER_GAIT_STORAGE = {"crawl", 4, ', row)
            self.assertTrue((out / "best_run_0" / "trace.csv").is_file())

    def test_bad_options_exit_2(self):
        for bad in (["--model", "sprawl8", "--trials", "0"], ["--model", "sprawl8", "--params", "wings"],
                    ["--model", "sprawl8", "--objective", "mix", "--weights", "beauty=1"],
                    ["--model", "sprawl8", "--range", "duty=0.9"]):
            p = self.tune(*bad, timeout=60)
            self.assertEqual(p.returncode, 2, (bad, p.stderr))


if __name__ == "__main__":
    unittest.main()
