// The IMU and battery scenarios (docs/imu.md), in library mode and, with the
// AVR build, with the firmware on the virtual Mega: hexapod18 levels its body
// on a 10 deg ramp (`level on`), also with the default part's accelerometer
// offsets after `cal level` on the flat, sprawl8 is kicked over and refuses to walk
// until set upright, sprawl8's draining pack warns, then sits it down.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "sim_run.h"

namespace {

using strider_sim::RunResult;

RunResult run(const std::string& name, const std::string& elf, const strider_sim::RunOptions& base = {}) {
  strider_sim::Scenario sc;
  std::string error;
  EXPECT_TRUE(strider_sim::load_scenario(std::string(STRIDER_SIM_SCENARIOS) + "/" + name + ".scenario", &sc, &error))
      << error;
  strider_sim::RunOptions opt = base;
  opt.firmware_elf = elf;
  RunResult r = strider_sim::run_scenario(sc, opt);
  EXPECT_TRUE(r.ok) << r.error;
  return r;
}

// The time of the first line the robot sent that starts with text at or
// after from_s; -1: none.
double line_at(const RunResult& r, const std::string& text, double from_s = 0) {
  for (const auto& l : r.log)
    if (l.t_s >= from_s && l.text.rfind(text, 0) == 0) return l.t_s;
  return -1;
}
std::string line_text(const RunResult& r, const std::string& text, double from_s = 0) {
  for (const auto& l : r.log)
    if (l.t_s >= from_s && l.text.rfind(text, 0) == 0) return l.text;
  return "";
}

struct Tilt {
  double roll = 0, pitch = 0;  // largest |roll| and |pitch| over the window [deg]
};
Tilt max_tilt(const RunResult& r, double from_s, double to_s) {
  Tilt t;
  for (const auto& row : r.trace) {
    if (row.t_s < from_s || row.t_s > to_s) continue;
    t.roll = std::max(t.roll, std::fabs(row.body.roll_deg));
    t.pitch = std::max(t.pitch, std::fabs(row.body.pitch_deg));
  }
  return t;
}

// hexapod18_ramp: standing on the ramp the body takes its slope (5.0 deg of
// roll, 8.7 of pitch); from 2 s after `level on` (at 6 s), standing, walking
// along the slope and standing again, roll and pitch stay within 2 deg. The
// part's gyro offsets are seed 1's (learnt at power-up); its accelerometer's
// are 0: the level is as good as the accelerometer's zero (50 mg is 2.9 deg).
void expect_level_on_the_ramp(const std::string& elf) {
  strider_sim::RunOptions opt;
  opt.sensors.imu.random_bias = false;
  opt.sensors.imu.gyro_bias_dps = strider_sim::Vec{19.9, 17.3, -14.9};
  opt.sensors.imu.accel_bias_mg = strider_sim::Vec{};
  const RunResult r = run("hexapod18_ramp", elf, opt);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.metrics.replies_err, 0);
  EXPECT_FALSE(r.metrics.fell);
  EXPECT_GE(line_at(r, "ok level on"), 6.0);
  EXPECT_NE(line_text(r, "ok status", 9).find(" imu=level roll="), std::string::npos);
  const Tilt off = max_tilt(r, 4, 6), on = max_tilt(r, 8, 20);
  std::printf("[ metrics  ] hexapod18_ramp %s: level off roll %.2f pitch %.2f deg, level on (8-20 s) %.2f / %.2f deg\n",
              r.metrics.mode.c_str(), off.roll, off.pitch, on.roll, on.pitch);
  EXPECT_NEAR(off.roll, 5.0, 0.5);
  EXPECT_NEAR(off.pitch, 8.7, 0.5);
  EXPECT_LT(on.roll, 2.0);
  EXPECT_LT(on.pitch, 2.0);
  // It walked up the slope meanwhile.
  EXPECT_GT(r.metrics.final_x_mm, 30.0);  // 3 s at 40 mm/s, less the ramp-up
}

// hexapod18_ramp_cal: the default part (seed 1's draw: 49.9 / -26.4 mg of
// accelerometer offset, 19.9 / 17.3 / -14.9 deg/s of gyro offset). `cal
// level` on the flat at 6 s measures and saves the offsets; the ground tilts
// to the 10 deg ramp at 9 s, `level on` at 12 s: from 14 s, standing,
// walking along the slope and standing again, roll and pitch stay within 2
// deg. The same run without `cal level` settles the offsets' 1.5 / 2.9 deg
// off level, past 2 deg in pitch.
void expect_calibrated_level_on_the_ramp(const std::string& elf) {
  strider_sim::RunOptions opt;  // the default part: offsets drawn with seed 1
  const RunResult r = run("hexapod18_ramp_cal", elf, opt);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.metrics.replies_err, 0);
  EXPECT_FALSE(r.metrics.fell);
  // The part's offsets plus what the body leans on the flat (0.1 deg is 1.7 mg).
  const std::string cal = line_text(r, "ok cal level", 6);
  int x_mg = 0, y_mg = 0;
  ASSERT_EQ(std::sscanf(cal.c_str(), "ok cal level x_mg=%d y_mg=%d saved", &x_mg, &y_mg), 2) << cal;
  EXPECT_NEAR(x_mg, 49.9, 3.0) << cal;
  EXPECT_NEAR(y_mg, -26.4, 3.0) << cal;
  const double cal_at = line_at(r, "ok cal level", 6);
  EXPECT_GT(cal_at, 6.9);
  EXPECT_LT(cal_at, 7.3);
  EXPECT_GE(line_at(r, "ok level on"), 12.0);
  const Tilt flat = max_tilt(r, 7, 9), on = max_tilt(r, 14, 26);
  // Without the calibration: the same scenario, `cal level` left out.
  strider_sim::Scenario sc;
  std::string error;
  ASSERT_TRUE(strider_sim::load_scenario(std::string(STRIDER_SIM_SCENARIOS) + "/hexapod18_ramp_cal.scenario", &sc, &error))
      << error;
  sc.sends.erase(std::remove_if(sc.sends.begin(), sc.sends.end(),
                                [](const strider_sim::TimedSend& s) { return s.bytes == "cal level\n"; }),
                 sc.sends.end());
  strider_sim::RunOptions uncal = opt;
  uncal.firmware_elf = elf;
  const RunResult u = strider_sim::run_scenario(sc, uncal);
  ASSERT_TRUE(u.ok) << u.error;
  const Tilt u_on = max_tilt(u, 14, 26), u_end = max_tilt(u, 21, 26), end = max_tilt(r, 21, 26);
  std::printf("[ metrics  ] hexapod18_ramp_cal %s: flat %.2f / %.2f deg; level on (14-26 s) uncalibrated %.2f / %.2f, "
              "after cal level %.2f / %.2f deg; standing 21-26 s %.2f / %.2f against %.2f / %.2f\n",
              r.metrics.mode.c_str(), flat.roll, flat.pitch, u_on.roll, u_on.pitch, on.roll, on.pitch, u_end.roll,
              u_end.pitch, end.roll, end.pitch);
  EXPECT_LT(flat.roll, 1.0);
  EXPECT_LT(flat.pitch, 1.0);
  EXPECT_LT(on.roll, 2.0);
  EXPECT_LT(on.pitch, 2.0);
  EXPECT_GT(u_on.pitch, 2.0) << "the offset's tilt without the calibration";
  EXPECT_GT(r.metrics.final_x_mm, 30.0);  // it walked along the slope
}

// sprawl8_shove: the kick tips it over; the fall is seen within 0.5 s, the
// servos go limp and walking is refused (err 33) until 1 s after upright.
void expect_fall_and_recovery(const std::string& elf) {
  const RunResult r = run("sprawl8_shove", elf);
  ASSERT_TRUE(r.ok);
  const double fall = line_at(r, "info fall"), cleared = line_at(r, "info fall cleared");
  std::printf("[ metrics  ] sprawl8_shove %s: fall seen %.2f s after the shove, cleared %.2f s after upright\n",
              r.metrics.mode.c_str(), fall - 5.0, cleared - 8.0);
  EXPECT_GT(fall, 5.0);
  EXPECT_LT(fall, 5.5);
  EXPECT_GE(line_at(r, "err 33 fallen", 6.5), 6.5);
  const std::string fallen = line_text(r, "ok status", 7);
  EXPECT_NE(fallen.find(" imu=fallen"), std::string::npos) << fallen;
  EXPECT_NE(fallen.find(" servos=off"), std::string::npos) << fallen;
  EXPECT_NE(fallen.find("mode=relaxed"), std::string::npos) << fallen;
  EXPECT_GT(cleared, 9.0);
  EXPECT_LT(cleared, 9.5);
  EXPECT_GE(line_at(r, "ok move", 10.5), 10.5);
  EXPECT_NE(line_text(r, "ok status", 13).find(" imu=ok"), std::string::npos);
  double x_walk = 0, x_end = 0;
  for (const auto& row : r.trace) {
    if (row.t_s <= 10.5) x_walk = row.body.pos_mm.x;
    if (row.t_s <= 14.0) x_end = row.body.pos_mm.x;
  }
  EXPECT_GT(x_end - x_walk, 20.0) << "walks again once upright";  // after the soft start and stand-up: 1.5 s of it
}

// sprawl8_battery: low, then critical; the robot sits and refuses to walk
// (err 32); the pack never dips below 6.2 V (the Mega's regulator, 1.1 V of
// dropout, keeps its 5 V above it), so the warning comes before a brown-out.
void expect_battery_low_then_critical(const std::string& elf) {
  const RunResult r = run("sprawl8_battery", elf);
  ASSERT_TRUE(r.ok);
  const double low = line_at(r, "info battery low"), critical = line_at(r, "info battery critical");
  std::printf("[ metrics  ] sprawl8_battery %s: low at %.2f s, critical at %.2f s, pack min %.2f V\n",
              r.metrics.mode.c_str(), low, critical, r.metrics.battery_min_v);
  EXPECT_GT(low, 3.0);
  EXPECT_GT(critical, low + 2.0);
  EXPECT_LT(critical, 20.0);
  EXPECT_GE(line_at(r, "err 32 battery critical", 20), 20.0);
  const std::string st = line_text(r, "ok status", 21);
  EXPECT_NE(st.find(" state=sitting"), std::string::npos) << st;
  EXPECT_GT(r.metrics.battery_min_v, 6.2);
  EXPECT_FALSE(r.metrics.fell);
}

TEST(SimSensorScenarios, LibraryLevelsHexapod18OnTheRamp) { expect_level_on_the_ramp(""); }
TEST(SimSensorScenarios, LibraryCalibratedLevelsHexapod18OnTheRamp) { expect_calibrated_level_on_the_ramp(""); }
TEST(SimSensorScenarios, LibrarySeesTheFallAndWaitsForUpright) { expect_fall_and_recovery(""); }
TEST(SimSensorScenarios, LibraryWarnsThenSitsOnADrainingPack) { expect_battery_low_then_critical(""); }

#ifdef STRIDER_SIM_HEXAPOD18_ELF
TEST(SimSensorScenarios, FirmwareLevelsHexapod18OnTheRamp) { expect_level_on_the_ramp(STRIDER_SIM_HEXAPOD18_ELF); }
TEST(SimSensorScenarios, FirmwareCalibratedLevelsHexapod18OnTheRamp) {
  expect_calibrated_level_on_the_ramp(STRIDER_SIM_HEXAPOD18_ELF);
}
TEST(SimSensorScenarios, FirmwareSeesTheFallAndWaitsForUpright) { expect_fall_and_recovery(STRIDER_SIM_SPRAWL8_ELF); }
TEST(SimSensorScenarios, FirmwareWarnsThenSitsOnADrainingPack) {
  expect_battery_low_then_critical(STRIDER_SIM_SPRAWL8_ELF);
}
#endif

}  // namespace
