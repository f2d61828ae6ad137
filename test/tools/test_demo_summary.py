"""The demo's summary (tools/demo/summary.py) says what each figure is and
claims nothing the run does not show: displacement and path length both,
labelled; the real-time factor on the wall clock with the CPU time beside it;
the solver fallbacks against the step count and explained; odometry only
where the run has it; avoidance only as the robot's own notices report it.

Run: python3 test/tools/run_unittest.py test_demo_summary"""
import json
import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "demo"))

import summary  # noqa: E402


def metrics(**over):
    m = {
        "robot": "sprawl8", "mode": "firmware", "distance_mm": 2535.0, "path_mm": 4812.0, "speed_mm_s": 122.9,
        "heading_change_deg": 89.9, "max_tilt_deg": 5.9, "fell": False, "min_clearance_mm": 164.3,
        "min_robot_clearance_mm": 81.3, "collisions": 0, "odometry_mm": None, "odometry_error_pct": None,
        "ready_s": 2.4, "sim_time_s": 36.0, "wall_time_s": 12.0, "cpu_time_s": 9.0, "real_time_factor": 4.0,
        "real_time_factor_wall": 3.0, "physics_steps": 9000, "solver": "mlcp", "solver_fallbacks": 297,
    }
    m.update(over)
    return m


def square_walk(side_mm=500.0, dt=0.02, speed=100.0):
    """Rows along three sides of a square, at `speed` mm/s."""
    rows, t = [], 0.0
    corners = [(0.0, 0.0), (side_mm, 0.0), (side_mm, side_mm), (0.0, side_mm)]
    for (x0, y0), (x1, y1) in zip(corners, corners[1:]):
        n = int(round(side_mm / speed / dt))
        for k in range(n):
            f = k / n
            rows.append({"t": t, "x_mm": x0 + f * (x1 - x0), "y_mm": y0 + f * (y1 - y0)})
            t += dt
    rows.append({"t": t, "x_mm": 0.0, "y_mm": side_mm})
    return rows


class SummaryTest(unittest.TestCase):
    def line(self, lines, start):
        found = [l for l in lines if l.startswith(start)]
        self.assertEqual(len(found), 1, f"{start!r} in {lines}")
        return found[0]

    def test_displacement_and_path_both_labelled(self):
        out = summary.summary_lines(metrics(), square_walk(), [])
        self.assertIn("2535 mm", self.line(out, "displacement (start to end, a straight line): "))
        path = self.line(out, "path length (along the body centre's track")
        self.assertIn("4812 mm with the sway of every step", path)

    def test_smoothed_path_of_a_known_track(self):
        rows = square_walk()
        # Three sides of 500 mm; the 1 s average cuts the two corners a little.
        self.assertAlmostEqual(summary.smoothed_path_mm(rows, smooth_s=0.0), 1500.0, delta=1.0)
        self.assertLess(summary.smoothed_path_mm(rows), 1500.0)
        self.assertGreater(summary.smoothed_path_mm(rows), 1400.0)
        zig = [{"t": k * 0.02, "x_mm": k * 2.0, "y_mm": 10.0 * (k % 2)} for k in range(500)]  # sway of 10 mm a step
        self.assertGreater(summary.smoothed_path_mm(zig, smooth_s=0.0), 4000.0)
        self.assertAlmostEqual(summary.smoothed_path_mm(zig), 998.0, delta=30.0)

    def test_real_time_factor_on_the_wall_clock_and_cpu_labelled(self):
        rtf = self.line(summary.summary_lines(metrics(), [], []), "real-time factor: ")
        self.assertIn("3.0x on the wall clock (36.0 s simulated in 12.0 s)", rtf)
        self.assertIn("CPU 9.0 s, 4.0x per CPU second", rtf)
        # A metrics.json from before real_time_factor_wall: from the times.
        m = metrics()
        del m["real_time_factor_wall"]
        self.assertIn("3.0x on the wall clock", self.line(summary.summary_lines(m, [], []), "real-time factor: "))

    def test_solver_fallbacks_explained_against_the_steps(self):
        fb = self.line(summary.summary_lines(metrics(), [], []), "physics solver fallbacks: ")
        self.assertIn("297 of 9000 steps (3.3 %)", fb)
        self.assertIn("MLCP", fb)
        self.assertIn("PGS", fb)
        out = summary.summary_lines(metrics(solver="pgs", solver_fallbacks=0), [], [])
        self.assertFalse([l for l in out if "fallback" in l], out)  # PGS alone: nothing falls back

    def test_odometry_only_where_there_is_one(self):
        out = summary.summary_lines(metrics(), [], [])
        self.assertFalse([l for l in out if "odometry" in l], out)
        out = summary.summary_lines(metrics(mode="library", odometry_mm=2600.0, odometry_error_pct=2.5), [], [])
        self.assertIn("2600 mm, the body 2.5 % short of it", self.line(out, "gait odometry (library mode"))

    def test_avoidance_as_the_robot_reported_it(self):
        log = ["0.160 info strider sprawl8 ready joints=8 boards=1", "10.052 ok move vx=120.0 vy=0.0 wz=0.0",
               "10.076 info avoid forward", "14.564 info avoid sidestep", "16.464 info avoid clearing",
               "17.744 info avoid forward", "35.020 ok stop"]
        out = summary.summary_lines(metrics(), [], log)
        self.assertEqual(self.line(out, "avoidance"),
                         "avoidance (the robot's notices): sidestepped at 14.6 s, walking forward again at 17.7 s")
        # The wall was there but the robot never met it: said so, not "round the wall".
        out = summary.summary_lines(metrics(), [], log[:3] + log[-1:])
        self.assertIn("never acted", self.line(out, "avoidance"))
        # No obstacle and no notice: no line at all, and no clearance line.
        out = summary.summary_lines(metrics(min_clearance_mm=None, min_robot_clearance_mm=None), [], log[:2])
        self.assertFalse([l for l in out if "avoid" in l or "obstacle" in l], out)

    def test_a_run_folder(self):
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "metrics.json"), "w") as f:
                json.dump(metrics(ready_s=1.0), f)
            with open(os.path.join(d, "trace.csv"), "w") as f:
                f.write("t,x_mm,y_mm,z_mm\n")
                for k in range(200):
                    f.write(f"{k * 0.02:.3f},{k * 2.0:.2f},0.00,60.0\n")
            with open(os.path.join(d, "robot.log"), "w") as f:
                f.write("3.0 info avoid sidestep\n")
            m, rows, log = summary.load(d)
            self.assertEqual(rows[0]["t"], 1.0)  # from ready_s on
            self.assertEqual(len(rows), 150)
            out = summary.summary_lines(m, rows, log)
            self.assertTrue(math.isclose(summary.smoothed_path_mm(rows), 298.0, abs_tol=60.0))
            self.assertIn("sidestepped at 3.0 s", self.line(out, "avoidance"))


if __name__ == "__main__":
    unittest.main()
