// `level on|off` (control/level_body.h): the integrator alone, then RobotApp
// on hexapod18 with a fake IMU whose body is tilted by the ground plus the
// walker's body pose: the pose settles at minus the ground's tilt, `level off`
// puts it back, no IMU refuses it (err 34), and the gyro's offset is learnt
// with the fast gains until the robot first stands. Float and Fixed.
#include <gtest/gtest.h>

#include <cmath>
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
  void send_line(uint8_t, const char* line) { sent.emplace_back(line); }
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
      s.accel_m_s2 = strider::Vec3<S>(S(float(-g * std::sin(p))), S(float(g * std::sin(r) * std::cos(p))),
                                      S(float(g * std::cos(r) * std::cos(p))));
      s.gyro_rad_s = strider::Vec3<S>(S(float((r - last_roll) / 0.02 + gyro_offset_rad_s)),
                                      S(float((p - last_pitch) / 0.02 + gyro_offset_rad_s)), S(float(gyro_offset_rad_s)));
      s.temp_c = S(25);
      last_roll = r;
      last_pitch = p;
      app.imu(&s, lines);
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

}  // namespace
