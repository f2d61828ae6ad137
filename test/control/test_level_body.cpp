// `level on|off` (control/level_body.h): the integrator alone, then RobotApp
// on hexapod18 with a fake IMU whose body is tilted by the ground plus the
// walker's body pose: the pose settles at minus the ground's tilt, `level off`
// puts it back, no IMU refuses it (err 34), and the gyro's offset is learnt
// with the fast gains until the robot first stands. Float and Fixed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "control/robot_app.h"
#include "fakes/fake_store.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "robots/all_robots.h"

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

template <typename S>
double d(S v) {
  return double(v);
}
double d(strider::Fixed v) { return v.to_double(); }

TEST(LevelBody, StepsEveryFifthTickAgainstTheTiltWithinThePoseLimit) {
  strider::LevelBody<float> level;
  float roll = 0.1f, pitch = -0.2f;
  EXPECT_FALSE(level.step(0.05f, 0.05f, &roll, &pitch));  // off: nothing
  level.set_enabled(true);
  for (int k = 1; k < strider::kLevelEveryTicks; ++k) EXPECT_FALSE(level.step(0.05f, -0.1f, &roll, &pitch)) << k;
  ASSERT_TRUE(level.step(0.05f, -0.1f, &roll, &pitch));
  const double k = strider::kLevelGain * strider::kLevelEveryTicks * 0.02;  // 0.2 of the tilt a step
  EXPECT_NEAR(roll, 0.1 - k * 0.05, 1e-6);
  EXPECT_NEAR(pitch, -0.2 + k * 0.1, 1e-6);
  // The pose command's own limit, 30 deg, holds however long the tilt lasts.
  for (int n = 0; n < 1000; ++n) level.step(1.0f, -1.0f, &roll, &pitch);
  EXPECT_NEAR(roll, -strider::kLevelMaxRad, 1e-6);
  EXPECT_NEAR(pitch, strider::kLevelMaxRad, 1e-6);
  level.set_enabled(false);
  EXPECT_FALSE(level.step(1.0f, 1.0f, &roll, &pitch));
  EXPECT_NEAR(roll, -strider::kLevelMaxRad, 1e-6);
}

TEST(LevelBody, LearningGainsAreFasterAndGoBack) {
  using G = strider::AttitudeGains<strider::Fixed>;
  const G def = strider::attitude_gains_default<strider::Fixed>();
  const G fast = strider::LevelBody<strider::Fixed>::learning_gains(def, true);
  EXPECT_NEAR(fast.kp.to_double(), strider::kLearnKp, 1e-4);
  EXPECT_NEAR(fast.ki.to_double(), strider::kLearnKi, 1e-4);
  EXPECT_EQ(fast.trust_g.raw(), def.trust_g.raw());
  EXPECT_EQ(fast.reject_g.raw(), def.reject_g.raw());
  const G back = strider::LevelBody<strider::Fixed>::learning_gains(fast, false);
  EXPECT_EQ(back.kp.raw(), def.kp.raw());
  EXPECT_EQ(back.ki.raw(), def.ki.raw());
  // Critically damped (kp^2 = 4 ki): no overshoot while it learns.
  EXPECT_DOUBLE_EQ(strider::kLearnKp * strider::kLearnKp, 4 * strider::kLearnKi);
}

struct Lines {
  std::vector<std::string> sent;
  std::vector<uint8_t> ports;
  void send_line(uint8_t port, const char* line) {
    sent.emplace_back(line);
    ports.push_back(port);
  }
};

// RobotApp on hexapod18 standing on ground tilted by (ground_roll,
// ground_pitch); the IMU reads the body's tilt, ground + the body pose the
// walker is at, and a constant gyro offset.
template <typename S>
struct Rig {
  using App = strider::RobotApp<S, strider_test::RecordingServo, strider_test::FakeStore>;
  strider_test::RecordingServo out;
  strider_test::FakeStore store;
  Lines lines;
  App app{*strider::find_robot("hexapod18"), out, store};
  uint32_t now_us = 1000;
  double ground_roll, ground_pitch;
  double gyro_offset_rad_s;
  bool imu;
  double last_roll = 0, last_pitch = 0;
  double accel_offset_x_mg = 0, accel_offset_y_mg = 0;  // the part's error, added to what it reads
  double gyro_wobble_rad_s = 0;                          // a rate that alternates sign every tick (a shaking robot)
  bool reads_fail = false;                               // the part stops answering: imu(nullptr), as the firmware's glue
  int ticks = 0;

  Rig(double roll_deg, double pitch_deg, bool with_imu = true, double offset_deg_s = 0)
      : ground_roll(roll_deg * kDeg), ground_pitch(pitch_deg * kDeg), gyro_offset_rad_s(offset_deg_s * kDeg),
        imu(with_imu) {
    EXPECT_TRUE(app.begin(now_us, lines));
    app.set_imu_present(imu);
    last_roll = ground_roll;
    last_pitch = ground_pitch;
  }
  double body_roll() const { return ground_roll + d(app.motion().walker().engine().body_pose().roll_rad); }
  double body_pitch() const { return ground_pitch + d(app.motion().walker().engine().body_pose().pitch_rad); }
  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; t += 20) {
      now_us += strider::kTickPeriodUs;
      const double r = body_roll(), p = body_pitch();
      strider::ImuSample<S> s;
      const double g = 9.80665;
      s.accel_m_s2 = strider::Vec3<S>(S(float(-g * std::sin(p) + accel_offset_x_mg * g / 1000)),
                                      S(float(g * std::sin(r) * std::cos(p) + accel_offset_y_mg * g / 1000)),
                                      S(float(g * std::cos(r) * std::cos(p))));
      const double wobble = (++ticks % 2 ? 1 : -1) * gyro_wobble_rad_s;
      s.gyro_rad_s = strider::Vec3<S>(S(float((r - last_roll) / 0.02 + gyro_offset_rad_s + wobble)),
                                      S(float((p - last_pitch) / 0.02 + gyro_offset_rad_s)), S(float(gyro_offset_rad_s)));
      s.temp_c = S(25);
      last_roll = r;
      last_pitch = p;
      app.imu(reads_fail ? nullptr : &s, lines);
      app.tick(now_us, lines);
      out.writes.clear();
      out.relaxed.clear();
    }
  }
  std::string send(const std::string& text) {
    lines.sent.clear();
    for (char c : text) app.on_byte(0, uint8_t(c), now_us, lines);
    return lines.sent.empty() ? "" : lines.sent.back();
  }
};

template <typename S>
class LevelAppTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(LevelAppTest, Scalars);

TYPED_TEST(LevelAppTest, HoldsTheBodyLevelOnASlopeAndLetsGo) {
  Rig<TypeParam> rig(5.0, -8.7);
  rig.run_ms(4000);  // soft start, stand up
  EXPECT_EQ(rig.app.motion().walker().engine().state(), strider::GaitState::kStanding);
  EXPECT_NEAR(rig.body_roll() / kDeg, 5.0, 0.01);  // level off: the body takes the slope
  EXPECT_NE(rig.send("status\n").find(" imu=ok roll=5.0 pitch=-8."), std::string::npos) << rig.send("status\n");
  EXPECT_EQ(rig.send("level on\n"), "ok level on");
  rig.run_ms(4000);
  EXPECT_NEAR(rig.body_roll() / kDeg, 0.0, 0.2);
  EXPECT_NEAR(rig.body_pitch() / kDeg, 0.0, 0.2);
  const std::string st = rig.send("status\n");
  EXPECT_NE(st.find(" imu=level roll="), std::string::npos) << st;
  // Walking, the level keeps acting.
  EXPECT_EQ(rig.send("walk 50\n").rfind("ok move", 0), 0u);
  rig.ground_pitch = -4.0 * kDeg;  // the slope eases
  rig.run_ms(4000);
  EXPECT_NEAR(rig.body_pitch() / kDeg, 0.0, 0.3);
  EXPECT_EQ(rig.send("stop\n"), "ok stop");
  EXPECT_EQ(rig.send("level off\n"), "ok level off");
  rig.run_ms(3000);
  EXPECT_NEAR(rig.body_roll() / kDeg, 5.0, 0.01);
  EXPECT_NEAR(rig.body_pitch() / kDeg, -4.0, 0.01);
  EXPECT_NE(rig.send("status\n").find(" imu=ok "), std::string::npos);
}

TYPED_TEST(LevelAppTest, WithoutAnImuLevelIsRefusedAndNothingChanges) {
  Rig<TypeParam> rig(5.0, -8.7, false);
  rig.run_ms(4000);
  EXPECT_EQ(rig.send("level on\n"), "err 34 no imu: level needs an MPU-6050 on the I2C bus (status shows imu=)");
  EXPECT_EQ(rig.send("level off\n").rfind("err 34 ", 0), 0u);
  rig.run_ms(2000);
  EXPECT_FALSE(rig.app.level().enabled());
  EXPECT_NEAR(rig.body_roll() / kDeg, 5.0, 1e-6);
  EXPECT_NE(rig.send("status\n").find(" imu=none"), std::string::npos);
}

// An uncalibrated part (20 deg/s on every axis): learnt while the robot sits
// and stands up, with the fast gains, then the default gains again. With the
// default gains alone the error would still be several degrees at 4 s.
TYPED_TEST(LevelAppTest, LearnsTheGyroOffsetBeforeItStands) {
  Rig<TypeParam> rig(0.0, 0.0, true, 20.0);
  EXPECT_TRUE(rig.app.level().learning());
  rig.run_ms(4000);
  EXPECT_FALSE(rig.app.level().learning());
  EXPECT_NEAR(d(rig.app.attitude().gains().kp), 1.0, 1e-4);
  const auto bias = rig.app.attitude().gyro_bias_rad_s();
  EXPECT_NEAR(d(bias.x) / kDeg, 20.0, 1.0);
  EXPECT_NEAR(d(bias.y) / kDeg, 20.0, 1.0);
  EXPECT_NEAR(d(rig.app.attitude().roll_rad()) / kDeg, 0.0, 1.0);
  EXPECT_NEAR(d(rig.app.attitude().pitch_rad()) / kDeg, 0.0, 1.0);
  // The default gains alone, the same 4 s at rest: still several degrees off.
  strider::AttitudeFilter<TypeParam> plain;
  const TypeParam w = TypeParam(float(20.0 * kDeg)), z = TypeParam(0);
  for (int k = 0; k < 200; ++k)
    plain.update(strider::Vec3<TypeParam>(z, z, TypeParam(9.80665f)), strider::Vec3<TypeParam>(w, w, w), TypeParam(0.02f));
  EXPECT_GT(std::fabs(d(plain.roll_rad()) / kDeg), 3.0);
}

template <typename S>
double roll_deg(const Rig<S>& rig) { return d(rig.app.attitude().roll_rad()) / kDeg; }
template <typename S>
double pitch_deg(const Rig<S>& rig) { return d(rig.app.attitude().pitch_rad()) / kDeg; }

// `cal level` on level ground with a part 49.9 / -26.4 mg off (the
// simulator's seed-1 draw: 2.9 / 1.5 deg of false tilt): the reply comes a
// second later with the offsets, they are saved with the settings (and load
// again), and the attitude reads level; on a 5 / -8.7 deg slope the level
// body then holds the body within 0.2 deg of level instead of the offset's
// tilt.
TYPED_TEST(LevelAppTest, CalLevelMeasuresSavesAndAppliesTheOffsets) {
  Rig<TypeParam> rig(0.0, 0.0, true, 10.0);
  rig.accel_offset_x_mg = 49.9;
  rig.accel_offset_y_mg = -26.4;
  rig.run_ms(6000);
  // Uncalibrated: the offsets' tilt (pitch positive nose down: +x reads as nose up).
  EXPECT_NEAR(pitch_deg(rig), -2.86, 0.3);
  EXPECT_NEAR(roll_deg(rig), -1.51, 0.3);
  EXPECT_EQ(rig.send("cal show\n").substr(rig.send("cal show\n").find(" level_mg=")), " level_mg=0,0");
  EXPECT_EQ(rig.send("cal level\n"), "");  // measuring: no reply yet
  rig.lines.sent.clear();
  rig.run_ms(980);
  EXPECT_TRUE(rig.lines.sent.empty()) << "49 samples: still measuring";
  rig.run_ms(20);
  ASSERT_EQ(rig.lines.sent.size(), 1u);
  EXPECT_EQ(rig.lines.sent[0], "ok cal level x_mg=50 y_mg=-26 saved");
  EXPECT_EQ(rig.app.controller().settings().accel_x_mg, 50);
  EXPECT_EQ(rig.app.controller().settings().accel_y_mg, -26);
  const std::string show = rig.send("cal show\n");
  EXPECT_EQ(show.substr(show.find(" level_mg=")), " level_mg=50,-26");
  strider::Settings saved;
  ASSERT_EQ(strider::load_settings(rig.store, &saved), strider::SettingsStatus::kOk);
  EXPECT_EQ(saved.accel_x_mg, 50);
  EXPECT_EQ(saved.accel_y_mg, -26);
  rig.run_ms(20);  // the attitude taken again from the corrected accelerometer at once
  EXPECT_NEAR(pitch_deg(rig), 0.0, 0.05);
  EXPECT_NEAR(roll_deg(rig), 0.0, 0.05);
  rig.run_ms(8000);  // the bias learnt meanwhile and the 1 mg rounding: within 0.1 deg
  EXPECT_NEAR(pitch_deg(rig), 0.0, 0.1);
  EXPECT_NEAR(roll_deg(rig), 0.0, 0.1);
  // On a slope, the level holds the body level, not 2.9 deg off it.
  rig.ground_roll = 5.0 * kDeg;
  rig.ground_pitch = -8.7 * kDeg;
  EXPECT_EQ(rig.send("level on\n"), "ok level on");
  rig.run_ms(8000);
  EXPECT_NEAR(rig.body_roll() / kDeg, 0.0, 0.2);
  EXPECT_NEAR(rig.body_pitch() / kDeg, 0.0, 0.2);
  // A second robot from the same EEPROM starts with the offsets.
  typename Rig<TypeParam>::App app2{*strider::find_robot("hexapod18"), rig.out, rig.store};
  EXPECT_EQ(app2.controller().settings().accel_x_mg, 50);
}

// The late reply goes to the port that asked, checked when the line was
// (`$cal level*hhhh`, protocol.md's checked lines).
TYPED_TEST(LevelAppTest, CalLevelAnswersThePortThatAskedInKind) {
  Rig<TypeParam> rig(0.0, 0.0);
  rig.accel_offset_x_mg = -12;
  rig.run_ms(4000);
  const std::string text = "cal level";
  char crc[8];
  std::snprintf(crc, sizeof crc, "*%04x", unsigned(strider::line_crc(text.c_str(), uint16_t(text.size()))));
  rig.lines.sent.clear();
  rig.lines.ports.clear();
  for (char c : "$" + text + crc + "\n") rig.app.on_byte(1, uint8_t(c), rig.now_us, rig.lines);
  EXPECT_TRUE(rig.lines.sent.empty());
  rig.run_ms(1000);
  ASSERT_EQ(rig.lines.sent.size(), 1u);
  EXPECT_EQ(rig.lines.ports[0], 1);
  const std::string want = "ok cal level x_mg=-12 y_mg=0 saved";
  char check[8];
  std::snprintf(check, sizeof check, "*%04x", unsigned(strider::line_crc(want.c_str(), uint16_t(want.size()))));
  EXPECT_EQ(rig.lines.sent[0], want + check);
  // A plain line on port 0: a plain reply there.
  EXPECT_EQ(rig.send("cal level\n"), "");
  rig.lines.ports.clear();
  rig.run_ms(1000);
  ASSERT_EQ(rig.lines.sent.size(), 1u);
  EXPECT_EQ(rig.lines.ports[0], 0);
  EXPECT_EQ(rig.lines.sent[0], "ok cal level x_mg=-12 y_mg=0 saved");  // measured raw again: the same offsets
}

// The refusals: each a clear err, nothing measured, nothing saved.
TYPED_TEST(LevelAppTest, CalLevelRefusals) {
  {  // no part
    Rig<TypeParam> rig(0.0, 0.0, false);
    rig.run_ms(4000);
    EXPECT_EQ(rig.send("cal level\n"), "err 34 no imu: level needs an MPU-6050 on the I2C bus (status shows imu=)");
  }
  Rig<TypeParam> rig(0.0, 0.0);
  rig.accel_offset_x_mg = 30;
  // Sitting (not stood up yet).
  rig.run_ms(100);
  const std::string not_still = "err 35 not standing still: stop, stand, level off, pose 0 0 0, keep still 1 s";
  EXPECT_EQ(rig.send("cal level\n"), not_still);
  rig.run_ms(4000);
  // Walking.
  EXPECT_EQ(rig.send("walk 50\n").rfind("ok move", 0), 0u);
  rig.run_ms(500);
  EXPECT_EQ(rig.send("cal level\n"), not_still);
  EXPECT_EQ(rig.send("stop\n"), "ok stop");
  rig.run_ms(3000);
  // With the level on, or a body pose.
  EXPECT_EQ(rig.send("level on\n"), "ok level on");
  EXPECT_EQ(rig.send("cal level\n"), not_still);
  EXPECT_EQ(rig.send("level off\n"), "ok level off");
  rig.run_ms(1000);
  EXPECT_EQ(rig.send("pose 5 0 0\n").rfind("ok pose", 0), 0u);
  rig.run_ms(1000);
  EXPECT_EQ(rig.send("cal level\n"), not_still);
  EXPECT_EQ(rig.send("pose 0 0 0\n").rfind("ok pose", 0), 0u);
  rig.run_ms(1000);
  // In calibration mode.
  EXPECT_EQ(rig.send("cal start\n"), "ok cal start");
  EXPECT_EQ(rig.send("cal level\n").rfind("err 21 ", 0), 0u);
  EXPECT_EQ(rig.send("cal abort\n"), "ok cal aborted");
  rig.run_ms(3000);
  // Shaking while measuring: err 35 when it happens.
  EXPECT_EQ(rig.send("cal level\n"), "");
  EXPECT_EQ(rig.send("cal level\n"), not_still);  // measuring already
  rig.lines.sent.clear();
  rig.gyro_wobble_rad_s = 5.0 * kDeg;
  rig.run_ms(100);
  ASSERT_EQ(rig.lines.sent.size(), 1u);
  EXPECT_EQ(rig.lines.sent[0], not_still);
  rig.gyro_wobble_rad_s = 0;
  rig.run_ms(3000);
  // A walk command while measuring ends it too.
  EXPECT_EQ(rig.send("cal level\n"), "");
  rig.run_ms(200);
  rig.lines.sent.clear();
  for (char c : std::string("walk 50\n")) rig.app.on_byte(0, uint8_t(c), rig.now_us, rig.lines);
  rig.run_ms(100);
  ASSERT_GE(rig.lines.sent.size(), 2u);
  EXPECT_EQ(rig.lines.sent[1], not_still);
  EXPECT_EQ(rig.send("stop\n"), "ok stop");
  rig.run_ms(3000);
  // The part stops answering while measuring: err 34 at the first failed
  // read (every line gets its reply), nothing kept.
  EXPECT_EQ(rig.send("cal level\n"), "");
  rig.run_ms(200);
  rig.lines.sent.clear();
  rig.reads_fail = true;
  rig.run_ms(2000);
  ASSERT_EQ(rig.lines.sent.size(), 1u);
  EXPECT_EQ(rig.lines.sent[0], "err 34 no imu: level needs an MPU-6050 on the I2C bus (status shows imu=)");
  rig.reads_fail = false;
  rig.run_ms(1000);
  // On a 6 deg slope: not level.
  rig.ground_roll = 6.0 * kDeg;
  rig.run_ms(8000);
  EXPECT_EQ(rig.send("cal level\n"), "");
  rig.lines.sent.clear();
  rig.run_ms(1000);
  ASSERT_EQ(rig.lines.sent.size(), 1u);
  EXPECT_EQ(rig.lines.sent[0], "err 36 not level: stand on level ground (within 5 deg)");
  // Nothing was kept or written.
  EXPECT_EQ(rig.app.controller().settings().accel_x_mg, 0);
  EXPECT_EQ(rig.app.controller().settings().accel_y_mg, 0);
  strider::Settings saved;
  EXPECT_EQ(strider::load_settings(rig.store, &saved), strider::SettingsStatus::kEmpty);
}

}  // namespace
