"""tools/sim/sweep_gait.py on this build's strider-sim: a tiny sweep runs, its
JSON has every candidate (the model's defaults among them) with one finished
run per distance, ranked by score; bad options exit 2."""
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SIM = os.environ.get("STRIDER_SIM", "")
SWEEP = ROOT / "tools" / "sim" / "sweep_gait.py"


@unittest.skipIf(not os.access(SIM, os.X_OK), f"strider-sim is not built ({SIM or '$STRIDER_SIM unset'})")
class SweepGait(unittest.TestCase):
    def sweep(self, *args):
        return subprocess.run([sys.executable, str(SWEEP), "--sim", SIM, *args], capture_output=True, text=True,
                              timeout=120)

    def test_tiny_sweep(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = pathlib.Path(tmp) / "sweep.json"
            p = self.sweep("--robot", "mammal8", "--gait", "walk", "--samples", "3", "--distances", "40,60",
                           "--default-speed", "15", "--jobs", "2", "--json", str(out))
            self.assertEqual(p.returncode, 0, p.stderr)
            data = json.loads(out.read_text())
        self.assertIn("mammal8 walk: 3 candidates over 40 / 60 mm", p.stdout)
        self.assertEqual(data["distances_mm"], [40, 60])
        cands = data["candidates"]
        self.assertEqual(len(cands), 3)
        defaults = [c for c in cands if c["step_height_mm"] == 0 and c["speed_mm_s"] == 15]
        self.assertEqual(len(defaults), 1)
        for c in cands:
            self.assertEqual([r["commanded_mm"] for r in c["runs"]], [40, 60])
            for r in c["runs"]:
                self.assertTrue(math.isfinite(r["odometry_error_pct"]))
                self.assertGreater(r["odometry_mm"], 0)
        scores = [math.inf if c["score"] is None else c["score"] for c in cands]
        self.assertEqual(scores, sorted(scores))
        # The score is the worst |error| of the runs.
        best = cands[0]
        if best["score"] is not None:
            self.assertAlmostEqual(best["score"], max(abs(r["odometry_error_pct"]) for r in best["runs"]))

    def test_world_options_pass_through_and_bad_ones_fail(self):
        p = self.sweep("--samples", "1", "--distances", "20", "--default-speed", "20", "--", "--foot-pad", "5")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("with --foot-pad 5", p.stdout)
        p = self.sweep("--samples", "1", "--distances", "20", "--", "--foot-pad", "-3")
        self.assertEqual(p.returncode, 1)
        self.assertIn("did not run", p.stdout)
        for bad in (["--distances", "-5"], ["--distances", "ten"], ["--samples", "0"]):
            p = self.sweep(*bad)
            self.assertEqual(p.returncode, 2, bad)


if __name__ == "__main__":
    unittest.main()
