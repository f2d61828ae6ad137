"""tools/results/make_results.py on this build: the CLI-based tables are
measured, the slow sources are skipped and must say "not measured"."""
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("STRIDER_CLI", "")


@unittest.skipIf(not os.access(CLI, os.X_OK), f"the strider CLI is not built ({CLI or '$STRIDER_CLI unset'})")
class MakeResults(unittest.TestCase):
    def test_quick_page(self):
        build = pathlib.Path(CLI).parents[2]
        with tempfile.TemporaryDirectory() as tmp:
            out = pathlib.Path(tmp) / "results.md"
            p = subprocess.run([sys.executable, str(ROOT / "tools" / "results" / "make_results.py"), "--build",
                                str(build), "--out", str(out), "--quick", "--no-slow"],
                               capture_output=True, text=True, timeout=120)
            self.assertEqual(p.returncode, 0, p.stderr)
            text = out.read_text()
        for title in ("## Summary", "## Seed 000", "## Seed 001", "## Seed 002", "## Seed 003: PSO",
                      "## PSO: Strider against pyswarms", "## AVR cycles", "## IK accuracy"):
            self.assertIn(title, text)
        self.assertIn("all 42 solve ok", text)
        self.assertIn("| 001 | body pose ranges roll / pitch / yaw | +-28 / +-21 / +-21 deg | covered", text)
        self.assertIn("not measured: skipped in this run (--no-slow)", text)
        self.assertNotIn("measurement failed", text)

    def test_only_replaces_just_those_sections(self):
        build = pathlib.Path(CLI).parents[2]
        page = (ROOT / "docs" / "results.md").read_text()
        with tempfile.TemporaryDirectory() as tmp:
            out = pathlib.Path(tmp) / "results.md"
            out.write_text(page)
            p = subprocess.run([sys.executable, str(ROOT / "tools" / "results" / "make_results.py"), "--build",
                                str(build), "--out", str(out), "--only", "pso", "--no-slow"],
                               capture_output=True, text=True, timeout=120)
            self.assertEqual(p.returncode, 0, p.stderr)
            text = out.read_text()

        def sections(t):
            return {s.split("\n", 1)[0]: s for s in t.split("\n## ")[1:]}

        old, new = sections(page), sections(text)
        self.assertEqual(set(old), set(new))
        for title in ("Seed 003: PSO joint angles, table 4", "PSO: Strider against pyswarms"):
            self.assertIn("not measured: skipped in this run (--no-slow)", new[title])
        for title in old:
            if not title.startswith(("Seed 003: PSO", "PSO:", "Summary")):
                self.assertEqual(old[title], new[title], title)
        self.assertIn("Regenerated since (--only pso): Seed 003: PSO joint angles, table 4, PSO: Strider against", text)


if __name__ == "__main__":
    unittest.main()
