// LevelCalibration (lib/strider/sensing/level_calibration.h), typed over
// float and Fixed: the mean of a still, level second of MPU-6050-like
// readings with an offset, rounding, and the refusals (a turning reading, a
// reading or a mean too far from level, upside down, NaN), each ending the
// run with nothing kept.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "scalar_conv.h"
#include "sensing/level_calibration.h"

using strider::Fixed;
using strider::ImuSample;
using strider::LevelCalibration;
using strider::LevelCalStatus;
using strider::Vec3;
using strider_test::sc;

namespace {

constexpr double kG = 9.80665;
constexpr double kDeg = M_PI / 180.0;
constexpr double kAccelNoiseMg = 6.4;  // 400 ug/rtHz over 260 Hz, rms
constexpr double kGyroNoise = 0.081 * kDeg;

template <typename S>
class LevelCalibrationTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(LevelCalibrationTest, Scalars);

template <typename S>
ImuSample<S> sample(double ax_mg, double ay_mg, double az_g, double wx, double wy, double wz) {
  ImuSample<S> s;
  s.accel_m_s2 = Vec3<S>(sc<S>(ax_mg * kG / 1000), sc<S>(ay_mg * kG / 1000), sc<S>(az_g * kG));
  s.gyro_rad_s = Vec3<S>(sc<S>(wx), sc<S>(wy), sc<S>(wz));
  s.temp_c = sc<S>(25.0);
  return s;
}

// 50 noisy readings of offsets up to the data sheet's 50 mg (and a gyro
// offset the filter's bias estimate removes): the offsets within 4 sigma /
// sqrt(50) plus the 1 mg rounding; exactly 50 readings; done ends the run.
TYPED_TEST(LevelCalibrationTest, MeanOfAStillLevelSecond) {
  using S = TypeParam;
  std::mt19937 rng(22);
  std::normal_distribution<double> na(0.0, kAccelNoiseMg), nw(0.0, kGyroNoise);
  std::uniform_real_distribution<double> off(-80.0, 80.0), bias(-0.3, 0.3);
  for (int trial = 0; trial < 300; ++trial) {
    const double ox = off(rng), oy = off(rng);
    const Vec3<S> b(sc<S>(bias(rng)), sc<S>(bias(rng)), sc<S>(bias(rng)));
    LevelCalibration<S> c;
    EXPECT_FALSE(c.running());
    c.start();
    EXPECT_TRUE(c.running());
    int8_t x = 111, y = 111;
    LevelCalStatus st = LevelCalStatus::kCollecting;
    int k = 0;
    while (st == LevelCalStatus::kCollecting) {
      st = c.add(sample<S>(ox + na(rng), oy + na(rng), 1.0 + na(rng) / 1000, strider_test::dbl(b.x) + nw(rng),
                           strider_test::dbl(b.y) + nw(rng), strider_test::dbl(b.z) + nw(rng)),
                 b, &x, &y);
      ++k;
      if (st == LevelCalStatus::kCollecting) {
        EXPECT_EQ(x, 111) << "nothing written while collecting";
      }
    }
    ASSERT_EQ(st, LevelCalStatus::kDone) << trial;
    EXPECT_EQ(k, strider::kLevelCalSamples);
    const double tol = 4 * kAccelNoiseMg / std::sqrt(50.0) + 0.5 + 0.02;
    EXPECT_NEAR(x, ox, tol) << trial;
    EXPECT_NEAR(y, oy, tol) << trial;
    EXPECT_FALSE(c.running());
    EXPECT_EQ(c.add(sample<S>(0, 0, 1, 0, 0, 0), b, &x, &y), LevelCalStatus::kIdle);
  }
}

// Noise-free readings: the mean rounded half away from zero, to the mg.
TYPED_TEST(LevelCalibrationTest, RoundsToTheMilliG) {
  using S = TypeParam;
  const double cases[][2] = {{49.9, -26.4}, {0.0, 0.0}, {0.4, -0.4}, {0.6, -0.6}, {-86.6, 86.6}, {12.3, 45.7}};
  for (const auto& cs : cases) {
    LevelCalibration<S> c;
    c.start();
    int8_t x = 0, y = 0;
    LevelCalStatus st = LevelCalStatus::kCollecting;
    while (st == LevelCalStatus::kCollecting) st = c.add(sample<S>(cs[0], cs[1], 1, 0, 0, 0), Vec3<S>(), &x, &y);
    ASSERT_EQ(st, LevelCalStatus::kDone) << cs[0];
    EXPECT_EQ(x, int(std::lround(cs[0]))) << cs[0];
    EXPECT_EQ(y, int(std::lround(cs[1]))) << cs[1];
  }
}

// Each refusal at reading n of the run: the status, the run over, nothing written.
TYPED_TEST(LevelCalibrationTest, RefusalsEndTheRunAndKeepNothing) {
  using S = TypeParam;
  const double turn = 4.0 * kDeg;  // past the 3 deg/s a still robot stays within
  struct Case {
    ImuSample<S> bad;
    LevelCalStatus want;
    const char* what;
  };
  const Case cases[] = {
      {sample<S>(10, 0, 1, turn, 0, 0), LevelCalStatus::kMoving, "roll rate"},
      {sample<S>(10, 0, 1, 0, -turn, 0), LevelCalStatus::kMoving, "pitch rate"},
      {sample<S>(260, 0, 1, 0, 0, 0), LevelCalStatus::kNotLevel, "x past 250 mg"},
      {sample<S>(0, -260, 1, 0, 0, 0), LevelCalStatus::kNotLevel, "y past -250 mg"},
      {sample<S>(0, 0, 0.7, 0, 0, 0), LevelCalStatus::kNotLevel, "z under 0.8 g (falling)"},
      {sample<S>(0, 0, 1.3, 0, 0, 0), LevelCalStatus::kNotLevel, "z over 1.2 g (bouncing)"},
      {sample<S>(0, 0, -1, 0, 0, 0), LevelCalStatus::kNotLevel, "upside down"},
  };
  for (const Case& cs : cases) {
    for (int at : {0, 1, 25, 49}) {
      LevelCalibration<S> c;
      c.start();
      int8_t x = 77, y = 77;
      for (int i = 0; i < at; ++i)
        ASSERT_EQ(c.add(sample<S>(10, -5, 1, 0.01, 0, 0), Vec3<S>(), &x, &y), LevelCalStatus::kCollecting);
      EXPECT_EQ(c.add(cs.bad, Vec3<S>(), &x, &y), cs.want) << cs.what << " at " << at;
      EXPECT_FALSE(c.running()) << cs.what;
      EXPECT_EQ(x, 77) << cs.what;
      EXPECT_EQ(y, 77) << cs.what;
      // A new run after a refusal starts from nothing.
      c.start();
      LevelCalStatus st = LevelCalStatus::kCollecting;
      while (st == LevelCalStatus::kCollecting) st = c.add(sample<S>(20, 30, 1, 0, 0, 0), Vec3<S>(), &x, &y);
      EXPECT_EQ(st, LevelCalStatus::kDone);
      EXPECT_EQ(x, 20);
      EXPECT_EQ(y, 30);
    }
  }
  // The gyro is judged less the bias: a 10 deg/s offset with its estimate is still.
  LevelCalibration<S> c;
  c.start();
  int8_t x = 0, y = 0;
  const Vec3<S> b(sc<S>(10 * kDeg), sc<S>(-10 * kDeg), sc<S>(10 * kDeg));
  EXPECT_EQ(c.add(sample<S>(0, 0, 1, 10 * kDeg, -10 * kDeg, 10 * kDeg), b, &x, &y), LevelCalStatus::kCollecting);
  EXPECT_EQ(c.add(sample<S>(0, 0, 1, 10 * kDeg, -10 * kDeg, 10 * kDeg), Vec3<S>(), &x, &y), LevelCalStatus::kMoving);
  // A rate about z is not judged (its offset is not learnt): still collecting.
  EXPECT_EQ(c.add(sample<S>(0, 0, 1, 0, 0, 20 * kDeg), Vec3<S>(), &x, &y), LevelCalStatus::kIdle);  // the run above ended
  c.start();
  EXPECT_EQ(c.add(sample<S>(0, 0, 1, 0, 0, 20 * kDeg), Vec3<S>(), &x, &y), LevelCalStatus::kCollecting);
  // stop() ends a run.
  c.start();
  c.stop();
  EXPECT_EQ(c.add(sample<S>(0, 0, 1, 0, 0, 0), Vec3<S>(), &x, &y), LevelCalStatus::kIdle);
}

// Every reading within 250 mg but a mean past 87 mg (5 deg): not level.
TYPED_TEST(LevelCalibrationTest, AMeanPastFiveDegreesIsNotLevel) {
  using S = TypeParam;
  for (double mg : {88.0, -88.0, 120.0, 249.0}) {
    for (int axis = 0; axis < 2; ++axis) {
      LevelCalibration<S> c;
      c.start();
      int8_t x = 5, y = 5;
      LevelCalStatus st = LevelCalStatus::kCollecting;
      while (st == LevelCalStatus::kCollecting)
        st = c.add(sample<S>(axis == 0 ? mg : 0, axis == 1 ? mg : 0, 1, 0, 0, 0), Vec3<S>(), &x, &y);
      EXPECT_EQ(st, LevelCalStatus::kNotLevel) << mg;
      EXPECT_EQ(x, 5);
      EXPECT_EQ(y, 5);
    }
  }
  // 86.6 mg (4.97 deg) is taken.
  LevelCalibration<S> c;
  c.start();
  int8_t x = 0, y = 0;
  LevelCalStatus st = LevelCalStatus::kCollecting;
  while (st == LevelCalStatus::kCollecting) st = c.add(sample<S>(-86.6, 0, 1, 0, 0, 0), Vec3<S>(), &x, &y);
  EXPECT_EQ(st, LevelCalStatus::kDone);
  EXPECT_EQ(x, -87);
}

// The caller's tag (0..3) survives the run and its end; it does not count.
TYPED_TEST(LevelCalibrationTest, TheTagIsKept) {
  using S = TypeParam;
  for (uint8_t tag = 0; tag < 4; ++tag) {
    LevelCalibration<S> c;
    c.start(tag);
    EXPECT_EQ(c.tag(), tag);
    int8_t x = 0, y = 0;
    int k = 0;
    LevelCalStatus st = LevelCalStatus::kCollecting;
    while (st == LevelCalStatus::kCollecting) {
      st = c.add(sample<S>(-3, 4, 1, 0, 0, 0), Vec3<S>(), &x, &y);
      ++k;
    }
    EXPECT_EQ(st, LevelCalStatus::kDone);
    EXPECT_EQ(k, strider::kLevelCalSamples);
    EXPECT_EQ(x, -3);
    EXPECT_EQ(y, 4);
    EXPECT_EQ(c.tag(), tag);
    EXPECT_FALSE(c.running());
  }
}

// Float garbage: a NaN or infinite reading is a refusal, never an offset.
TEST(LevelCalibrationFloat, NanAndInfinityAreRefused) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (int field = 0; field < 6; ++field) {
    for (float bad : {nan, inf, -inf}) {
      LevelCalibration<float> c;
      c.start();
      ImuSample<float> s = sample<float>(0, 0, 1, 0, 0, 0);
      float* f[6] = {&s.accel_m_s2.x, &s.accel_m_s2.y, &s.accel_m_s2.z, &s.gyro_rad_s.x, &s.gyro_rad_s.y, &s.gyro_rad_s.z};
      *f[field] = bad;
      int8_t x = 9, y = 9;
      const LevelCalStatus st = c.add(s, Vec3<float>(), &x, &y);
      if (field == 5) {  // z's rate is not judged
        EXPECT_EQ(st, LevelCalStatus::kCollecting);
        continue;
      }
      EXPECT_EQ(st, field < 3 ? LevelCalStatus::kNotLevel : LevelCalStatus::kMoving) << field;
      EXPECT_FALSE(c.running());
      EXPECT_EQ(x, 9);
    }
  }
}

}  // namespace
