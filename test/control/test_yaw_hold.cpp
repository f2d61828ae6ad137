// The heading hold (control/yaw_hold.h): the integrator alone against a
// plant that veers or sticks, then RobotApp on sprawl8 with a fake IMU whose
// gyro reads the turn the gait walks, a veer and the part's offset. Float
// and Fixed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "control/robot_app.h"
#include "control/yaw_hold.h"
#include "fakes/app_rig.h"
#include "fakes/fake_store.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "robots/all_robots.h"
#include "scalar_conv.h"

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

using strider_test::dbl;

template <typename S>
class YawHoldTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(YawHoldTest, Scalars);

// A body that turns at the trim it is given plus a veer, the trim taking
// effect a tick later; the gyro reads it plus the part's offset.
template <typename S>
struct Plant {
  strider::YawHold<S> hold;
  double offset_rad_s, veer_rad_s;
  double heading_rad = 0;  // the body's, since walking began
  int16_t trim = 0;        // [0.1 deg/s], as walked
  // Stick-slip: the body turns only at a rate over `stick` [rad/s].
  double stick_rad_s = 0;
  double hz = 2.0;  // the gait's step rate: kp 1/s, ki 0.25/s^2

  Plant(double offset_deg_s, double veer_deg_s) : offset_rad_s(offset_deg_s * kDeg), veer_rad_s(veer_deg_s * kDeg) {}

  // One tick of a command [0.1 deg/s]; returns the body's rate [rad/s].
  double tick(int32_t command_tenths, bool walking, bool still) {
    double rate = walking ? (command_tenths + trim) * 0.1 * kDeg + veer_rad_s : 0.0;
    if (std::fabs(rate) <= stick_rad_s) rate = 0;
    heading_rad += rate * 0.02;
    if (hold.step(S(0), S(float(rate + offset_rad_s)), S(0), S(0), command_tenths, walking, still, S(float(hz)), S(0.02f))) trim = hold.trim_tenths();
    return rate;
  }
  void stand(int ticks) {
    for (int k = 0; k < ticks; ++k) tick(0, false, true);
  }
};

TYPED_TEST(YawHoldTest, LearnsTheOffsetStandingStillAndHoldsNothingBefore) {
  Plant<TypeParam> p(18.0, 1.0);
  // Walking before it ever stood: no offset, no hold.
  for (int k = 0; k < 500; ++k) p.tick(0, true, false);
  EXPECT_FALSE(p.hold.learnt());
  EXPECT_EQ(p.trim, 0);
  p.stand(strider::kYawOffsetReadings - 1);
  EXPECT_FALSE(p.hold.learnt());
  p.stand(1);
  ASSERT_TRUE(p.hold.learnt());
  EXPECT_NEAR(dbl(p.hold.offset_rad_s()) / kDeg, 18.0, 0.01);
}

TYPED_TEST(YawHoldTest, AMovingReadingStartsTheOffsetOver) {
  Plant<TypeParam> p(-5.0, 0.0);
  p.stand(30);
  p.offset_rad_s = 0.2;  // a bump: 11 deg/s, past the spread
  p.stand(1);
  p.offset_rad_s = -5.0 * kDeg;
  p.stand(strider::kYawOffsetReadings - 1);
  EXPECT_FALSE(p.hold.learnt());  // 30, the bump, 49: none 50 still in a row
  p.stand(1);
  ASSERT_TRUE(p.hold.learnt());
  EXPECT_NEAR(dbl(p.hold.offset_rad_s()) / kDeg, -5.0, 0.01);
}

// A veer of 1 deg/s walking straight (sprawl8's trot at 155 mm/s): held, the
// heading stays within a few degrees over a minute, and the trim settles at
// minus the veer.
TYPED_TEST(YawHoldTest, WalkingStraightHoldsTheHeadingAgainstAVeer) {
  Plant<TypeParam> p(12.0, -1.0);
  p.stand(60);
  double worst = 0;
  for (int k = 0; k < 3000; ++k) {
    p.tick(0, true, false);
    worst = std::max(worst, std::fabs(p.heading_rad));
  }
  // The unheld second of the ramp (1 deg), then about the veer over the
  // gain (1 deg) while the error builds; the integral takes both back.
  EXPECT_LT(worst / kDeg, 2.5);
  EXPECT_NEAR(p.trim, 10, 1);
  for (int k = 0; k < 1500; ++k) p.tick(0, true, false);
  // 30 s more: within a degree of the heading it had when the hold began,
  // a second in (the trim moves in 0.5 deg/s steps).
  EXPECT_NEAR(p.heading_rad / kDeg, -1.0, 1.0);
}

// A slow turn the body does not follow (it sticks under 1 deg/s): the trim
// pushes it over in fits, and the turn over 30 s is the command's.
TYPED_TEST(YawHoldTest, ASlowTurnThatSticksMakesTheCommandedTurnOnAverage) {
  Plant<TypeParam> p(3.0, 0.0);
  p.stick_rad_s = 1.0 * kDeg;
  p.stand(60);
  const int32_t command = 3;  // 0.3 deg/s
  for (int k = 0; k < 150; ++k) p.tick(command, true, false);  // settle
  const double start = p.heading_rad;
  for (int k = 0; k < 1500; ++k) p.tick(command, true, false);
  EXPECT_NEAR((p.heading_rad - start) / kDeg, 0.3 * 30, 0.3 * 30 * 0.10);
}

TYPED_TEST(YawHoldTest, ANewCommandOrAStopStartsOverWithoutTrim) {
  Plant<TypeParam> p(0.0, 2.0);
  p.stand(60);
  for (int k = 0; k < 500; ++k) p.tick(0, true, false);
  ASSERT_LT(p.trim, 0);
  p.tick(100, true, false);  // turn 10 deg/s
  EXPECT_EQ(p.trim, 0);
  EXPECT_EQ(dbl(p.hold.error_rad()), 0.0);
  // The ramp's second is not held.
  for (int k = 0; k < strider::kYawHoldSettleTicks; ++k) p.tick(100, true, false);
  EXPECT_EQ(p.trim, 0);
  for (int k = 0; k < 500; ++k) p.tick(100, true, false);
  EXPECT_LT(p.trim, 0);
  p.tick(0, false, false);  // stopping
  EXPECT_EQ(p.trim, 0);
}

TYPED_TEST(YawHoldTest, TheTrimStaysWithinItsLimit) {
  Plant<TypeParam> p(0.0, 0.0);
  p.stand(60);
  // The body does not turn at all (held fast): the error winds up to the limit only.
  for (int k = 0; k < 5000; ++k)
    if (p.hold.step(TypeParam(0), TypeParam(0), TypeParam(0), TypeParam(0), 300, true, false, TypeParam(2), TypeParam(0.02f))) p.trim = p.hold.trim_tenths();
  EXPECT_EQ(p.trim, int16_t(strider::kYawHoldMaxTrimDegS * 10));
  for (int k = 0; k < 5000; ++k)
    if (p.hold.step(TypeParam(0), TypeParam(1.0f), TypeParam(0), TypeParam(0), 300, true, false, TypeParam(2), TypeParam(0.02f))) p.trim = p.hold.trim_tenths();
  EXPECT_EQ(p.trim, -int16_t(strider::kYawHoldMaxTrimDegS * 10));
}

TEST(YawHold, ANonFiniteReadingChangesNothing) {
  strider::YawHold<float> hold;
  for (int k = 0; k < 60; ++k) hold.step(0.0f, 0.1f, 0.0f, 0.0f, 0, false, true, 2.0f, 0.02f);
  ASSERT_TRUE(hold.learnt());
  for (int k = 0; k < 200; ++k) hold.step(0.0f, 0.1f - 0.02f, 0.0f, 0.0f, 0, true, false, 2.0f, 0.02f);
  ASSERT_NE(hold.trim_tenths(), 0);
  const int16_t trim = hold.trim_tenths();
  const float err = hold.error_rad();
  EXPECT_FALSE(hold.step(0.0f, NAN, 0.0f, 0.0f, 0, true, false, 2.0f, 0.02f));
  EXPECT_FALSE(hold.step(0.0f, INFINITY, 0.0f, 0.0f, 0, true, false, 2.0f, 0.02f));
  EXPECT_FALSE(hold.step(NAN, 0.1f, 0.0f, 0.0f, 0, true, false, 2.0f, 0.02f));
  EXPECT_EQ(hold.trim_tenths(), trim);
  EXPECT_EQ(hold.error_rad(), err);
  EXPECT_NEAR(hold.offset_rad_s(), 0.1f, 1e-6f);
}

// The heading's rate, not the body z axis's: rolled by r, a body whose
// heading does not change reads gz = -gy tan r (Z-Y-X Euler rates); the
// hold sees no turn there, and does see gz alone on a level body.
TYPED_TEST(YawHoldTest, HoldsTheHeadingNotTheBodyZAxis) {
  using S = TypeParam;
  const double r = 0.1, p = 0.08, gy = 0.3, gz = -gy * std::tan(r);
  strider::YawHold<S> rolled, level;
  for (int k = 0; k < 60; ++k) {
    rolled.step(S(0), S(0), S(0), S(0), 0, false, true, S(2), S(0.02f));
    level.step(S(0), S(0), S(0), S(0), 0, false, true, S(2), S(0.02f));
  }
  for (int k = 0; k < 500; ++k) {
    rolled.step(S(float(gy)), S(float(gz)), S(float(r)), S(float(p)), 0, true, false, S(2), S(0.02f));
    level.step(S(0), S(float(gz)), S(0), S(0), 0, true, false, S(2), S(0.02f));
  }
  EXPECT_NEAR(dbl(rolled.error_rad()), 0.0, 2e-4);
  EXPECT_EQ(rolled.trim_tenths(), 0);
  EXPECT_GT(level.trim_tenths(), 5);  // gz = -0.03 rad/s: turning right, trimmed left
}

// RobotApp on sprawl8: the fake gyro reads the turn the gait walks (its
// engine's rate), a veer, and an offset; nothing else moves.
template <typename S, const char* robot_name>
struct RigOf {
  using App = strider::RobotApp<S, strider_test::RecordingServo, strider_test::FakeStore>;
  strider_test::RecordingServo out;
  strider_test::FakeStore store;
  strider_test::SentLines lines;
  App app{*strider::find_robot(robot_name), out, store};
  uint32_t now_us = 1000;
  double offset_rad_s = 15.0 * kDeg, veer_rad_s = 0;
  double heading_rad = 0;

  explicit RigOf(bool imu) {
    EXPECT_TRUE(app.begin(now_us, lines));
    app.set_imu_present(imu);
    EXPECT_EQ(send("$deadman off*cb77\n").rfind("ok", 0), 0u);  // a command holds until the next
  }
  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; t += 20) {
      now_us += strider::kTickPeriodUs;
      const auto& e = app.motion().walker().engine();
      const bool walking = e.state() == strider::GaitState::kWalking;
      const double rate = dbl(e.wz()) + (walking ? veer_rad_s : 0);
      heading_rad += rate * 0.02;
      strider::ImuSample<S> s;
      s.accel_m_s2 = strider::Vec3<S>(S(0), S(0), S(9.80665f));
      s.gyro_rad_s = strider::Vec3<S>(S(0), S(0), S(float(rate + offset_rad_s)));
      s.temp_c = S(25);
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

constexpr char kSprawl8[] = "sprawl8";
constexpr char kMammal8[] = "mammal8";
template <typename S>
using Rig = RigOf<S, kSprawl8>;

template <typename S>
class YawHoldAppTest : public ::testing::Test {};
TYPED_TEST_SUITE(YawHoldAppTest, Scalars);

TYPED_TEST(YawHoldAppTest, WalksStraightAgainstAVeerAndStatusKeepsTheCommand) {
  Rig<TypeParam> rig(true);
  rig.run_ms(5000);  // soft start, stand up, a second still
  ASSERT_TRUE(rig.app.yaw_hold().learnt());
  EXPECT_NEAR(dbl(rig.app.yaw_hold().offset_rad_s()) / kDeg, 15.0, 0.05);
  rig.veer_rad_s = 1.5 * kDeg;
  EXPECT_EQ(rig.send("walk 60\n").rfind("ok move", 0), 0u);
  rig.run_ms(20000);
  // 20 s at 1.5 deg/s would be 30 deg; held: a few.
  EXPECT_LT(std::fabs(rig.heading_rad) / kDeg, 4.0);
  EXPECT_LT(rig.app.motion().yaw_trim(), -5);  // [0.1 deg/s] against the veer
  EXPECT_EQ(rig.app.motion().command().wz, 0);
  const std::string st = rig.send("status\n");
  EXPECT_NE(st.find(" vx=60.0 vy=0.0 wz=0.0"), std::string::npos) << st;
  EXPECT_EQ(rig.send("stop\n"), "ok stop");
  rig.run_ms(100);
  EXPECT_EQ(rig.app.motion().yaw_trim(), 0);
}

TYPED_TEST(YawHoldAppTest, WithoutAnImuNothingIsHeld) {
  Rig<TypeParam> rig(false);
  rig.run_ms(5000);
  rig.veer_rad_s = 1.5 * kDeg;
  EXPECT_EQ(rig.send("walk 60\n").rfind("ok move", 0), 0u);
  rig.run_ms(10000);
  EXPECT_FALSE(rig.app.yaw_hold().learnt());
  EXPECT_EQ(rig.app.motion().yaw_trim(), 0);
  EXPECT_NEAR(rig.heading_rad / kDeg, 1.5 * 10, 1.0);
}

}  // namespace
