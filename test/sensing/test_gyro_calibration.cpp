// GyroCalibration (lib/strider/sensing/gyro_calibration.h), typed over float
// and Fixed: the mean of a still stretch of MPU-6050-like readings, runs
// restarted by motion, and the edge cases.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "scalar_conv.h"
#include "sensing/gyro_calibration.h"

using strider::Fixed;
using strider::GyroCalibration;
using strider::GyroCalibrationStatus;
using strider::Vec3;
using strider_test::dbl;
using strider_test::sc;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kNoise = 0.005 * 16.12 * kDeg;  // 0.005 deg/s/rtHz over 260 Hz [rad/s rms]

template <typename S>
class GyroCalibrationTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(GyroCalibrationTest, Scalars);

template <typename S>
Vec3<S> v3(double x, double y, double z) {
  return Vec3<S>(sc<S>(x), sc<S>(y), sc<S>(z));
}

// 50 still readings with noise: the mean within 4 sigma / sqrt(50) (plus a
// Fixed LSB) of the offset, for offsets up to the part's 20 deg/s.
TYPED_TEST(GyroCalibrationTest, MeanOfAStillStretch) {
  using S = TypeParam;
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, kNoise);
  std::uniform_real_distribution<double> u(-20 * kDeg, 20 * kDeg);
  for (int trial = 0; trial < 200; ++trial) {
    const double b[3] = {u(rng), u(rng), u(rng)};
    GyroCalibration<S> c;
    GyroCalibrationStatus st = GyroCalibrationStatus::kCollecting;
    int k = 0;
    while (st != GyroCalibrationStatus::kDone) {
      st = c.add(v3<S>(b[0] + n(rng), b[1] + n(rng), b[2] + n(rng)));
      ASSERT_NE(st, GyroCalibrationStatus::kRestarted) << trial;
      ++k;
    }
    EXPECT_EQ(k, 50);
    EXPECT_TRUE(c.done());
    const double tol = 4 * kNoise / std::sqrt(50.0) + 3.0 / 65536;
    EXPECT_NEAR(dbl(c.offset().x), b[0], tol);
    EXPECT_NEAR(dbl(c.offset().y), b[1], tol);
    EXPECT_NEAR(dbl(c.offset().z), b[2], tol);
    // Done: later readings change nothing.
    EXPECT_EQ(c.add(v3<S>(1, 1, 1)), GyroCalibrationStatus::kDone);
    EXPECT_NEAR(dbl(c.offset().x), b[0], tol);
  }
}

// The legs come on and shake the body: every jump beyond the spread starts
// the run again, and the offset is the mean of the still run at the end.
TYPED_TEST(GyroCalibrationTest, MotionRestartsTheRun) {
  using S = TypeParam;
  GyroCalibration<S> c(10, sc<S>(2 * kDeg));
  for (int k = 0; k < 5; ++k) EXPECT_EQ(c.add(v3<S>(0.01, 0, 0)), GyroCalibrationStatus::kCollecting);
  EXPECT_EQ(c.collected(), 5);
  EXPECT_EQ(c.add(v3<S>(0.01, 0.2, 0)), GyroCalibrationStatus::kRestarted);  // a jerk on y
  EXPECT_EQ(c.collected(), 1);
  EXPECT_EQ(c.add(v3<S>(0.01, 0, 0)), GyroCalibrationStatus::kRestarted);    // and back
  for (int k = 0; k < 8; ++k) EXPECT_EQ(c.add(v3<S>(0.02, -0.01, 0.005)), GyroCalibrationStatus::kCollecting);
  EXPECT_EQ(c.add(v3<S>(0.02, -0.01, 0.005)), GyroCalibrationStatus::kDone);
  EXPECT_NEAR(dbl(c.offset().x), 0.019, 2e-4);  // (0.01 + 9 x 0.02) / 10
  EXPECT_NEAR(dbl(c.offset().y), -0.009, 2e-4);
  // Exactly the spread apart is still still.
  GyroCalibration<S> d(2, sc<S>(0.5));
  EXPECT_EQ(d.add(v3<S>(0, 0, 0)), GyroCalibrationStatus::kCollecting);
  EXPECT_EQ(d.add(v3<S>(0.5, -0.5, 0)), GyroCalibrationStatus::kDone);
}

TYPED_TEST(GyroCalibrationTest, EdgeCases) {
  using S = TypeParam;
  GyroCalibration<S> one(0);  // a count of 0 is 1
  EXPECT_EQ(one.add(v3<S>(0.1, 0.2, 0.3)), GyroCalibrationStatus::kDone);
  EXPECT_NEAR(dbl(one.offset().z), 0.3, 1e-4);
  GyroCalibration<S> c;
  EXPECT_FALSE(c.done());
  EXPECT_EQ(dbl(c.offset().x), 0.0);
  c.add(v3<S>(0.1, 0, 0));
  c.restart();
  EXPECT_EQ(c.collected(), 0);
  if (!strider::ScalarTraits<S>::kIsFixed) {
    for (int k = 0; k < 10; ++k) c.add(v3<S>(0, 0, 0));
    EXPECT_EQ(c.add(v3<S>(std::numeric_limits<double>::quiet_NaN(), 0, 0)), GyroCalibrationStatus::kRestarted);
    EXPECT_EQ(c.collected(), 0);
    EXPECT_EQ(c.add(v3<S>(INFINITY, 0, 0)), GyroCalibrationStatus::kRestarted);
  }
  // 255 readings at the largest rate a Fixed sum can take (255 x 35 rad/s).
  GyroCalibration<S> big(255, sc<S>(1.0));
  GyroCalibrationStatus st = GyroCalibrationStatus::kCollecting;
  for (int k = 0; k < 255; ++k) st = big.add(v3<S>(34.9, -34.9, 34.9));
  EXPECT_EQ(st, GyroCalibrationStatus::kDone);
  EXPECT_NEAR(dbl(big.offset().y), -34.9, 1e-3);
}

}  // namespace
