// Whole scenarios in library mode (tools/sim/scenarios): the firmware's own
// control chain (RobotApp) fed the scenario's Bluetooth bytes, driving the
// Bullet world through the servo pulses. Each test prints its metrics and the
// speed-up over real time; docs/simulator.md compares them with the seeds.
//
// The asserted bounds are what the simulated robots do today, with margin:
// they catch a broken chain (no motion, wrong direction, falls, collisions),
// not a few per cent of speed. The seeds' targets that the simulation does
// not reach yet are DISABLED_ tests below, with the measured values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <algorithm>

#include "sim_run.h"

namespace {

using strider_sim::Metrics;
using strider_sim::RunResult;

RunResult run_file(const std::string& name, bool avoid_off = false,
                   strider_sim::Solver solver = strider_sim::WorldConfig{}.solver,
                   double cfm = strider_sim::WorldConfig{}.solver_cfm, double foot_pad_half_mm = 0.0) {
  strider_sim::Scenario sc;
  std::string error;
  const std::string path = std::string(STRIDER_SIM_SCENARIOS) + "/" + name + ".scenario";
  EXPECT_TRUE(strider_sim::load_scenario(path, &sc, &error)) << error;
  if (avoid_off) sc.sends.insert(sc.sends.begin(), strider_sim::TimedSend{0.1, "avoid off\n"});
  strider_sim::RunOptions opt;
  opt.world.solver = solver;
  opt.world.solver_cfm = cfm;
  opt.world.foot_pad_half_mm = foot_pad_half_mm;
  RunResult r = strider_sim::run_scenario(sc, opt);
  EXPECT_TRUE(r.ok) << r.error;
  const Metrics& m = r.metrics;
  std::printf(
      "[ metrics  ] %s: distance %.0f mm, top speed %.1f mm/s, heading %+.1f deg, drift %.1f mm, tilt %.1f deg, "
      "odometry %.0f mm (error %.1f %%)%s%s, %.1f s simulated in %.2f s CPU: %.1fx real time\n",
      name.c_str(), m.distance_mm, m.speed_mm_s, m.heading_change_deg, m.lateral_drift_mm, m.max_tilt_deg,
      m.odometry_mm, m.odometry_error_pct, m.fell ? ", FELL" : "",
      m.has_obstacles ? (", clearance " + std::to_string(int(m.min_clearance_mm)) + " mm").c_str() : "", m.sim_time_s,
      m.cpu_time_s, m.real_time_factor);
  EXPECT_EQ(m.replies_err, 0) << "the robot rejected a scenario line";
  return r;
}

bool log_has(const RunResult& r, const std::string& text) {
  for (const auto& l : r.log)
    if (l.text.find(text) != std::string::npos) return true;
  return false;
}

TEST(SimScenarios, Sprawl8WalksForward) {
  const Metrics m = run_file("sprawl8_forward").metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_GT(m.final_x_mm, 800.0);                 // 8 s of trot (seed: 155 mm/s, 1240 mm)
  EXPECT_GT(m.speed_mm_s, 50.0);
  EXPECT_LT(m.lateral_drift_mm, 0.05 * m.distance_mm);  // seed target: < 5 %
  EXPECT_LT(std::fabs(m.heading_change_deg), 10.0);
}

TEST(SimScenarios, Sprawl8TurnsAFullCircle) {
  const Metrics m = run_file("sprawl8_turn").metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_GT(m.heading_change_deg, 360.0);  // anticlockwise, 8 s at 80 deg/s asked
  ASSERT_GT(m.turn_360_s, 0.0);
  EXPECT_LT(m.turn_360_s, 9.0);            // seed target 6 s
  EXPECT_LT(m.distance_mm, 50.0);          // in place
}

TEST(SimScenarios, Sprawl8StrafesLeftOnTheRcButton) {
  const Metrics m = run_file("sprawl8_strafe").metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_GT(m.final_y_mm, 150.0);  // left = +y
  EXPECT_LT(m.lateral_drift_mm, 0.1 * m.distance_mm);  // little forward or backward motion
  EXPECT_LT(std::fabs(m.heading_change_deg), 10.0);
}

TEST(SimScenarios, Sprawl8CrawlsForward) {
  const Metrics m = run_file("sprawl8_crawl").metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_GT(m.final_x_mm, 150.0);
  EXPECT_LT(m.lateral_drift_mm, 0.1 * m.distance_mm);
}

TEST(SimScenarios, Hexapod18TripodWalksForward) {
  const Metrics m = run_file("hexapod18_tripod").metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_GT(m.final_x_mm, 450.0);   // 6 s at 100 mm/s
  EXPECT_GT(m.speed_mm_s, 80.0);
  EXPECT_LT(m.lateral_drift_mm, 0.1 * m.distance_mm);
  EXPECT_LT(m.max_tilt_deg, 5.0);   // three feet down at every instant
  // A tripod's stance feet do not slip much: within 15 % of the gait's own odometry.
  EXPECT_LT(std::fabs(m.odometry_error_pct), 15.0);
}

// Seed 003 table 5: the mammal robot over 10, 20 and 100 cm in walk, trot
// and pace. The simulated robot stays up in every run; how far it gets is
// printed (the DISABLED_ target test below asserts the seed's accuracy).
class Mammal8Distance : public ::testing::TestWithParam<const char*> {};

TEST_P(Mammal8Distance, StaysUpAndWalks) {
  const std::string name = GetParam();
  const Metrics m = run_file(name).metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_LT(m.max_tilt_deg, 25.0);
  EXPECT_GT(m.odometry_mm, 50.0);  // the gait engine walked its part
  // The walk goes forward within 10 % of its odometry (measured 0-1.5 %
  // short at the 4 ms step, -0.5 to 3.9 % at 1-3 ms; 44-52 % with the CoM
  // on the support diagonal, and 120-290 % backward with the PGS solver);
  // the trot makes at least 35 % of it (measured 32-48 % short at 4 ms,
  // 30-53 % at 2-3 ms).
  if (name.find("_walk_") != std::string::npos) {
    EXPECT_LT(std::fabs(m.odometry_error_pct), 10.0);
  }
  if (name.find("_trot_") != std::string::npos) {
    EXPECT_LT(m.odometry_error_pct, 65.0);
  }
}

INSTANTIATE_TEST_SUITE_P(SeedTable5, Mammal8Distance,
                         ::testing::Values("mammal8_walk_100mm", "mammal8_walk_200mm", "mammal8_walk_1000mm",
                                           "mammal8_trot_100mm",
                                           "mammal8_trot_200mm", "mammal8_trot_1000mm", "mammal8_pace_100mm",
                                           "mammal8_pace_200mm", "mammal8_pace_1000mm"));

// The exact solver (MLCP, the default) against 40 PGS iterations on mammal8's
// walk: PGS leaves a residual that sags the loaded stance knees (mean 2.4 deg
// against 0.05) and lets the stance feet creep backward: the walk goes 73 mm
// backward on it, 101 mm forward on MLCP (docs/simulator.md).
double mean_stance_knee_error_deg(const RunResult& r, int dof) {
  double sum = 0;
  int n = 0;
  for (const auto& row : r.trace) {
    if (row.t_s < 3.5) continue;  // walking from 3 s
    for (size_t leg = 0; leg < row.contact.size(); ++leg)
      if (row.contact[leg]) {
        const size_t k = leg * size_t(dof) + 1;  // the knee
        sum += std::fabs(row.q_deg[k] - row.target_deg[k]);
        ++n;
      }
  }
  return n > 0 ? sum / n : 0.0;
}

TEST(SimScenarios, ExactSolverKeepsMammal8StanceKneesOnTarget) {
  const RunResult mlcp = run_file("mammal8_walk_100mm", false, strider_sim::Solver::kMlcp);
  const RunResult pgs = run_file("mammal8_walk_100mm", false, strider_sim::Solver::kPgs);
  const double e_mlcp = mean_stance_knee_error_deg(mlcp, 2), e_pgs = mean_stance_knee_error_deg(pgs, 2);
  std::printf("[ metrics  ] mammal8 stance knee error: MLCP %.2f deg, PGS %.2f deg\n", e_mlcp, e_pgs);
  EXPECT_LT(e_mlcp, 0.8);
  EXPECT_GT(e_pgs, 2.0 * e_mlcp);
  EXPECT_GT(mlcp.metrics.final_x_mm, pgs.metrics.final_x_mm + 50.0);
}

// Four feet down and eight stiff motors make the exact solver's matrix
// singular or nearly so: without constraint force mixing Dantzig gave up on
// about half of the walk's steps, which Bullet then solved with PGS (and its
// residual). The default CFM (WorldConfig::solver_cfm) regularises it.
TEST(SimScenarios, ExactSolverSolvesAlmostEveryStep) {
  const RunResult with_cfm = run_file("mammal8_walk_200mm");
  const RunResult without = run_file("mammal8_walk_200mm", false, strider_sim::Solver::kMlcp, 0.0);
  const double steps = with_cfm.metrics.sim_time_s / strider_sim::WorldConfig{}.step_s;
  std::printf("[ metrics  ] mammal8 walk, MLCP fallbacks to PGS: %ld of %.0f steps with CFM, %ld without\n",
              with_cfm.metrics.solver_fallbacks, steps, without.metrics.solver_fallbacks);
  EXPECT_LT(double(with_cfm.metrics.solver_fallbacks), 0.05 * steps);
  EXPECT_GT(without.metrics.solver_fallbacks, 4 * with_cfm.metrics.solver_fallbacks);
}

// Feet as capsules across the legs (--foot-pad): two diagonal feet then
// hold the trotting mammal8 level instead of letting it tip onto a swing
// foot, and it walks farther (docs/simulator.md, mammal8 item 9: 18 deg
// against 2 deg of tilt, 123 against 168 mm).
TEST(SimScenarios, FootPadsKeepTheMammal8TrotLevel) {
  const RunResult ball = run_file("mammal8_trot_200mm");
  const RunResult pad = run_file("mammal8_trot_200mm", false, strider_sim::WorldConfig{}.solver,
                                 strider_sim::WorldConfig{}.solver_cfm, 15.0);
  EXPECT_FALSE(ball.metrics.fell);
  EXPECT_FALSE(pad.metrics.fell);
  EXPECT_GT(ball.metrics.max_tilt_deg, 10.0);
  EXPECT_LT(pad.metrics.max_tilt_deg, 5.0);
  EXPECT_GT(pad.metrics.distance_mm, ball.metrics.distance_mm + 25.0);
}

// The highest a foot was in the air once the robot had stood up [mm above
// the lowest foot on the ground]: the swing apex the gait walked.
double highest_swing_mm(const RunResult& r) {
  double ground = 1e9, top = -1e9;
  for (const strider_sim::TraceRow& row : r.trace) {
    if (row.t_s < r.metrics.ready_s + 1.0) continue;
    for (size_t i = 0; i < row.feet_mm.size(); ++i) {
      if (row.contact[i]) ground = std::min(ground, row.feet_mm[i].z);
      else top = std::max(top, row.feet_mm[i].z);
    }
  }
  return top - ground;
}

// strider-sim --step-height/--step-length/--cycle/--swing: the walker takes
// them instead of the model's defaults (gait_params.h: mammal8 20 mm
// steps), in library mode only; what it cannot walk is an error, not a run.
TEST(SimScenarios, GaitOverridesChangeTheStepInLibraryModeOnly) {
  strider_sim::Scenario sc;
  std::string error;
  ASSERT_TRUE(strider_sim::load_scenario(std::string(STRIDER_SIM_SCENARIOS) + "/mammal8_walk_100mm.scenario", &sc,
                                         &error))
      << error;
  strider_sim::RunOptions opt;
  const RunResult standard = strider_sim::run_scenario(sc, opt);
  opt.gait.step_height_mm = 8.0;
  opt.gait.swing = "bezier";
  const RunResult low = strider_sim::run_scenario(sc, opt);
  ASSERT_TRUE(standard.ok && low.ok) << standard.error << low.error;
  const double standard_mm = highest_swing_mm(standard), low_mm = highest_swing_mm(low);
  std::printf("[ metrics  ] mammal8 walk: swing apex %.1f mm by default, %.1f mm with --step-height 8\n", standard_mm,
              low_mm);
  EXPECT_GT(standard_mm, 15.0);
  EXPECT_LT(standard_mm, 30.0);
  EXPECT_LT(low_mm, 12.0);
  EXPECT_GT(low.metrics.distance_mm, 50.0);  // and still walks

  opt.gait.swing = "zigzag";
  const RunResult bad_shape = strider_sim::run_scenario(sc, opt);
  EXPECT_FALSE(bad_shape.ok);
  EXPECT_NE(bad_shape.error.find("zigzag"), std::string::npos) << bad_shape.error;
  opt.gait.swing.clear();
  opt.firmware_elf = "firmware.elf";
  const RunResult firmware = strider_sim::run_scenario(sc, opt);
  EXPECT_FALSE(firmware.ok);
  EXPECT_NE(firmware.error.find("library mode"), std::string::npos) << firmware.error;
}

TEST(SimScenarios, AvoidanceKeepsTheBodyClearOfAWall) {
  const RunResult r = run_file("sprawl8_obstacle");
  const Metrics& m = r.metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_TRUE(log_has(r, "info avoid sidestep"));
  // Clearing walks the body its half-width past the beam's edge: the body
  // box stays 90 mm from the wall and no leg touches it (2-8 mm at closest;
  // before that rule: the body came within 6.5-8.8 mm and legs brushed it).
  EXPECT_GT(m.min_clearance_mm, 40.0);
  EXPECT_EQ(m.collisions, 0);
  EXPECT_GT(m.final_y_mm, 150.0);       // it went round to the left
  // The same walk blind: the sprawling front feet run into the wall and the
  // robot stays in front of it. Where along the wall it slides is chaotic
  // (legs scraping a box edge): 0-125 mm measured, never round it.
  const Metrics blind = run_file("sprawl8_obstacle", true).metrics;
  EXPECT_LT(blind.min_robot_clearance_mm, 1.0);
  EXPECT_GT(blind.collisions, 0);
  EXPECT_LT(std::fabs(blind.final_y_mm), 150.0);
  EXPECT_LT(blind.final_x_mm, 500.0);
}

TEST(SimScenarios, SameScenarioSameMetrics) {
  const RunResult a = run_file("sprawl8_crawl");
  const RunResult b = run_file("sprawl8_crawl");
  std::string ma = strider_sim::metrics_json(a.metrics), mb = strider_sim::metrics_json(b.metrics);
  auto strip_times = [](std::string s) {  // wall and CPU time differ between runs
    for (const char* key : {"\"wall_time_s\"", "\"cpu_time_s\"", "\"real_time_factor\"", "\"real_time_factor_wall\""}) {
      const size_t at = s.find(key);
      if (at != std::string::npos) s.erase(at, s.find('\n', at) - at);
    }
    return s;
  };
  EXPECT_EQ(strip_times(ma), strip_times(mb));
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (size_t k = 0; k < a.trace.size(); ++k) {
    ASSERT_EQ(a.trace[k].body.pos_mm.x, b.trace[k].body.pos_mm.x) << "row " << k;
    ASSERT_EQ(a.trace[k].body.yaw_deg, b.trace[k].body.yaw_deg) << "row " << k;
    ASSERT_EQ(a.trace[k].q_deg, b.trace[k].q_deg) << "row " << k;
  }
}

// ---- the seeds' figures ------------------------------------------------------

// Seed 000: 155 mm/s forward (`walk 155`: gait/speed_correction.h).
// Measured: 163 mm/s, drift 0.25 % (1236-1239 mm from 1 to 4 ms steps; 178 mm/s
// with the PGS solver).
TEST(SimTargets, Sprawl8Reaches155MmPerSecond) {
  const Metrics m = run_file("sprawl8_forward").metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_GE(m.speed_mm_s, 155.0);
  EXPECT_LT(m.lateral_drift_mm, 0.05 * m.distance_mm);
}

// dog12 (seed 001) stands on its DS5160 servos and trots forward. With the
// MG996R it could not stand; with a 35 kg cm DS3235 the right-hand knees sag
// 17 deg and the robot rolls 10 deg and walks backward (-336 mm).
TEST(SimScenarios, Dog12StandsAndTrotsForward) {
  const RunResult r = run_file("dog12_stand");
  const Metrics& m = r.metrics;
  EXPECT_FALSE(m.fell);
  EXPECT_GT(m.final_x_mm, 100.0);  // 6 s at 100 mm/s asked (600 mm): measured ~175 mm
  ASSERT_FALSE(r.trace.empty());
  // Standing before the walk: the body at its standing height, level.
  for (const auto& row : r.trace)
    if (row.t_s > 3.5 && row.t_s < 4.0) {
      EXPECT_GT(row.body.pos_mm.z, 340.0) << "t " << row.t_s;
      EXPECT_LT(std::fabs(row.body.roll_deg), 2.0) << "t " << row.t_s;
    }
}

// spider12 (seed 004, MG90S servos) stands, walks, turns and walks round a
// wall in library mode. Measured: 241 mm forward in 8 s at `walk 60` (its
// gait tops out at about 32 mm/s), 6 % short of its odometry; 102 deg in 8 s
// at `turn 30`; round a 160 mm wall with its legs 110 mm clear, 720 mm ahead
// at the end.
TEST(SimScenarios, Spider12WalksTurnsAndAvoidsAWall) {
  const Metrics walk = run_file("spider12_walk").metrics;
  EXPECT_FALSE(walk.fell);
  EXPECT_GT(walk.final_x_mm, 150.0);
  EXPECT_LT(std::fabs(walk.final_y_mm), 40.0);
  EXPECT_LT(walk.odometry_error_pct, 25.0);
  const Metrics turn = run_file("spider12_turn").metrics;
  EXPECT_FALSE(turn.fell);
  EXPECT_GT(turn.heading_change_deg, 60.0);
  EXPECT_LT(turn.distance_mm, 40.0);
  const Metrics wall = run_file("spider12_obstacle").metrics;
  EXPECT_FALSE(wall.fell);
  EXPECT_EQ(wall.collisions, 0);
  EXPECT_GT(wall.final_x_mm, 450.0 + 20.0);  // past the wall's far face
}

// Seed 000: 360 deg in 6 s. The trot turns in place at up to 82.6 deg/s
// (servo speed, at most 0.4 rad per stance); the feet slide ~12 %, so the
// scenario asks 80 deg/s for the seed's 60 at the body. Measured: 5.5 s
// (72 deg/s at the body; PGS 5.6 s; 7.44 s when the stance turn was capped at
// 0.25 rad).
TEST(SimTargets, Sprawl8Turns360InSixSeconds) {
  EXPECT_LE(run_file("sprawl8_turn").metrics.turn_360_s, 6.0);
}

// Seed 003 table 5's distances, the scenarios `<prefix>_{100,200,1000}mm`:
// no fall, the body within `pct` % of the gait's odometry (the commanded 10,
// 20 and 100 cm), and with max_tilt_deg > 0 tilted less than that.
void expect_table5_distances(const std::string& prefix, double pct, double max_tilt_deg = 0.0) {
  for (const char* mm : {"100", "200", "1000"}) {
    const std::string s = prefix + "_" + mm + "mm";
    const Metrics m = run_file(s).metrics;
    EXPECT_FALSE(m.fell) << s;
    EXPECT_LT(std::fabs(m.odometry_error_pct), pct) << s;
    if (max_tilt_deg > 0.0) {
      EXPECT_LT(m.max_tilt_deg, max_tilt_deg) << s;
    }
  }
}

// Seed 003 table 5: distance reached within 2 % of the gait's own distance
// (the commanded 10, 20 and 100 cm). The walk meets it: 0.0 / 0.5 / 1.5 %
// short at the 4 ms step (-0.5 to 3.9 % at 1-3 ms steps, foot friction
// 0.7-0.9 or CFM 1e-5: a few slips decide the last per cent).
TEST(SimTargets, Mammal8WalkReachesCommandedDistanceWithin2Percent) {
  expect_table5_distances("mammal8_walk", 2.0);
}

// Share of the trace rows from t0 to t1 [s] with at least `feet` feet on the
// ground.
double share_with_feet_down(const RunResult& r, double t0, double t1, int feet) {
  int rows = 0, down = 0;
  for (const strider_sim::TraceRow& row : r.trace) {
    if (row.t_s < t0 || row.t_s > t1) continue;
    ++rows;
    down += int(std::count(row.contact.begin(), row.contact.end(), true)) >= feet;
  }
  return rows > 0 ? double(down) / rows : 0.0;
}

// Why the pace cannot reach its distances (docs/simulator.md, "mammal8's
// trot and pace"): the CoM is 45 mm beside the two feet a pace keeps down,
// so the body rolls onto the lifted side at once and its feet swing on the
// ground. Over the steady part of the 1000 mm pace (duty 0.5: two feet down
// by design) three or four feet touch in 95 % of the rows; the trot, whose
// diagonal passes through the CoM, keeps to two in 97 %.
TEST(SimScenarios, Mammal8PaceSwingsItsFeetOnTheGround) {
  const RunResult pace = run_file("mammal8_pace_1000mm");
  const RunResult trot = run_file("mammal8_trot_1000mm");
  const double pace_share = share_with_feet_down(pace, 5.0, 12.0, 3);
  const double trot_share = share_with_feet_down(trot, 5.0, 12.0, 3);
  std::printf("[ metrics  ] mammal8 rows with 3+ feet down, 5-12 s: pace %.0f %%, trot %.0f %%\n", 100 * pace_share,
              100 * trot_share);
  EXPECT_GT(pace_share, 0.7);
  EXPECT_LT(trot_share, 0.3);
  EXPECT_GT(pace.metrics.odometry_error_pct, 100.0);  // backward: the dragging feet carry more than half
}

// Seed 003 table 5 at the seed's own operating point: 10 mm steps at the
// seed's speeds (walk 2.5, trot 4.2, pace 3.1 mm/s), 20 mm rubber pads
// (`feet pad 5`), the servos at 200 Hz (docs/gaits.md). The walk reaches
// 100, 200 and 1000 mm within 5 % of its odometry (measured 1.2 / 2.1 /
// 3.8 % short; at 50 Hz 35-48 %: the 4.9 us tick is inside the MG996R's 5 us
// dead band, so each slow joint moves in 0.9 deg jumps and the other feet
// slide; docs/simulator.md).
TEST(SimTargets, Mammal8SeedWalkReachesCommandedDistanceWithin5Percent) {
  expect_table5_distances("mammal8_seed_walk", 5.0);
}

// The trot at the seed's point, the same target: trot10 moves the stance
// feet in 1.3 mm steps, all at once, and only while all four feet are down
// (gait/stance_ratchet.h), at duty 0.85 with 10 mm swings. Measured 3.6 /
// 1.9 / 1.2 % short of 100 / 200 / 1000 mm, tilt at most 1.1 deg (before:
// 66.6 / 65.7 / 64.9 %, the stance joints jumping through the servos' dead
// band each at its own moment and the feet fighting).
TEST(SimTargets, Mammal8SeedTrotReachesCommandedDistanceWithin5Percent) {
  expect_table5_distances("mammal8_seed_trot", 5.0, 3.0);
}

// mammal8's fast trot (`gait trot50` at 50 mm/s, twelve times the seed's
// trot) in library mode: within 5 % of the commanded distance, the speed
// times the time between `walk` and `stop` (the odometry runs past it by its
// speed correction), the body level within 5 deg (the default trot at 50
// mm/s: 15-18 deg, 40-70 % short). Measured 97.2 / 198.3 / 997.9 mm, tilt
// 2.2-3.5 deg; five starts 0.13-0.74 s apart -3.5..-0.4 %.
TEST(SimTargets, Mammal8FastTrotReachesCommandedDistanceWithin5Percent) {
  for (const double mm : {100.0, 200.0, 1000.0}) {
    const std::string s = "mammal8_fast_trot_" + std::to_string(int(mm)) + "mm";
    const Metrics m = run_file(s).metrics;
    EXPECT_FALSE(m.fell) << s;
    EXPECT_EQ(m.replies_err, 0) << s;
    EXPECT_NEAR(m.distance_mm, mm, 0.05 * mm) << s;
    EXPECT_LT(m.max_tilt_deg, 5.0) << s;
  }
}

// The pace at the seed's point, the same target in library mode. Measured
// with pace10's stance on all feet and its speed correction (measured in
// firmware mode, where it makes 100 / 200 / 1000 mm within 2.3 %:
// SimFirmware.Mammal8SeedPaceReachesItsDistanceWithin5Percent): 6.0 / 6.8 /
// 18.4 % short of the commanded distance (the odometry this test compares
// with runs 1 / 0.866 past it; uncorrected 18.8 / 18.7 / 27.2 % short, 51.5 /
// 49.5 / 53.3 % before the stance on all feet), no fall: while one side
// swings the CoM is 40 mm beside the feet kept down, the body tips onto the
// swinging feet and they drag, by more on the float build's ticks than on
// the firmware's (docs/simulator.md, "mammal8's trot and pace").
TEST(SimTargets, DISABLED_Mammal8SeedPaceReachesCommandedDistanceWithin5Percent) {
  expect_table5_distances("mammal8_seed_pace", 5.0);
}

}  // namespace

namespace {

// The pulse chain: ticks x (prescale + 1) / oscillator. A board whose
// oscillator runs 4 % fast (26 MHz) shortens every pulse, so the servos
// stand in another pose; `cal osc 26000000` makes the firmware's ticks
// right again (docs/calibration.md).
std::vector<double> standing_targets(double osc_hz, bool calibrate) {
  strider_sim::Scenario sc;
  std::string error;
  std::string text = "robot sprawl8\nduration 4\n";
  if (calibrate) text += "at 0.1 send cal start\\n\nat 0.3 send cal osc 26000000\\n\nat 0.5 send cal save\\n\n";
  EXPECT_TRUE(strider_sim::parse_scenario(text, &sc, &error)) << error;
  strider_sim::RunOptions opt;
  opt.world.osc_hz = osc_hz;
  const RunResult r = strider_sim::run_scenario(sc, opt);
  EXPECT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.metrics.replies_err, 0);
  return r.trace.back().target_deg;
}

TEST(SimScenarios, OscillatorCalibrationCorrectsThePulses) {
  const std::vector<double> nominal = standing_targets(25e6, false);
  const std::vector<double> fast = standing_targets(26e6, false);
  const std::vector<double> calibrated = standing_targets(26e6, true);
  ASSERT_EQ(nominal.size(), fast.size());
  double worst_fast = 0, worst_cal = 0;
  for (size_t k = 0; k < nominal.size(); ++k) {
    worst_fast = std::max(worst_fast, std::fabs(fast[k] - nominal[k]));
    worst_cal = std::max(worst_cal, std::fabs(calibrated[k] - nominal[k]));
  }
  std::printf("[ metrics  ] 26 MHz board: joints off by up to %.2f deg; after cal osc: %.2f deg\n", worst_fast,
              worst_cal);
  EXPECT_GT(worst_fast, 3.0);  // 4 % of a ~1500 us pulse is ~60 us, ~5 deg
  EXPECT_LT(worst_cal, 0.6);   // one PCA9685 tick (~0.44 deg) plus the dead band
}

}  // namespace
