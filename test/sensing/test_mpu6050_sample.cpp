// MPU-6050 register words -> SI (lib/strider/sensing/mpu6050_sample.h),
// typed over float and Fixed: every word of every range against the data
// sheet's scale in double, and the byte order of a burst.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "math_test_util.h"
#include "scalar_conv.h"
#include "sensing/mpu6050_sample.h"

using strider::Fixed;
using strider::Mpu6050AccelRange;
using strider::Mpu6050GyroRange;
using strider_test::dbl;
using strider_test::MaxError;

namespace {

constexpr double kG = 9.80665;
constexpr double kDeg = 0.017453292519943295;

template <typename S>
struct Tol;
template <>
struct Tol<float> {
  static constexpr double kRelative = 1.2e-7;  // one float rounding of the product
  static constexpr double kAbsolute = 0.0;
};
template <>
struct Tol<Fixed> {
  static constexpr double kRelative = 5e-7;      // the scale constant's own rounding
  static constexpr double kAbsolute = 0.55 / 65536;  // the product's rounding
};

template <typename S>
class Mpu6050Sample : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(Mpu6050Sample, Scalars);

template <typename S>
double bound(double exact) {
  return Tol<S>::kAbsolute + Tol<S>::kRelative * std::fabs(exact);
}

TYPED_TEST(Mpu6050Sample, EveryWordOfEveryRange) {
  using S = TypeParam;
  const char* name = strider::ScalarTraits<S>::name();
  for (int r = 0; r < 4; ++r) {
    const auto ar = Mpu6050AccelRange(r);
    const auto gr = Mpu6050GyroRange(r);
    const double lsb_per_g = 16384.0 / (1 << r);
    const double lsb_per_dps[] = {131.0, 65.5, 32.8, 16.4};
    EXPECT_EQ(strider::mpu6050_accel_lsb_per_g(ar), lsb_per_g);
    EXPECT_EQ(strider::mpu6050_gyro_lsb_per_dps(gr), lsb_per_dps[r]);
    MaxError ea(std::string(name) + " accel range " + std::to_string(r) + " [m/s^2]");
    MaxError eg(std::string(name) + " gyro range " + std::to_string(r) + " [rad/s]");
    int beyond = 0;
    for (int w = -32768; w <= 32767; ++w) {
      const double a = w / lsb_per_g * kG, g = w / lsb_per_dps[r] * kDeg;
      const double da = std::fabs(dbl(strider::mpu6050_accel_m_s2<S>(int16_t(w), ar)) - a);
      const double dg = std::fabs(dbl(strider::mpu6050_gyro_rad_s<S>(int16_t(w), gr)) - g);
      ea.add(da, w);
      eg.add(dg, w);
      beyond += (da > bound<S>(a)) + (dg > bound<S>(g));
    }
    EXPECT_EQ(beyond, 0) << "range " << r;
    ea.expect_below(bound<S>(32768 / lsb_per_g * kG));
    eg.expect_below(bound<S>(32768 / lsb_per_dps[r] * kDeg));
  }
  MaxError et(std::string(name) + " temperature [deg C]");
  int beyond = 0;
  for (int w = -32768; w <= 32767; ++w) {
    const double t = w / 340.0 + 36.53;
    const double dt = std::fabs(dbl(strider::mpu6050_temp_c<S>(int16_t(w))) - t);
    et.add(dt, w);
    beyond += dt > bound<S>(t) + 1e-5;  // + the rounding of 36.53
  }
  EXPECT_EQ(beyond, 0);
  et.expect_below(bound<S>(133) + 1e-5);
}

TYPED_TEST(Mpu6050Sample, BurstIsBigEndianAccelTempGyro) {
  using S = TypeParam;
  // +1 g on z at +-2 g, -0.5 g on x, 100 on y; 25 deg C; +-500 deg/s: 65.5 = 1 deg/s.
  const int16_t words[7] = {-8192, 100, 16384, int16_t(std::lround((25 - 36.53) * 340)), 655, -131, 32767};
  uint8_t burst[strider::kMpu6050BurstBytes];
  for (int i = 0; i < 7; ++i) {
    burst[2 * i] = uint8_t(uint16_t(words[i]) >> 8);
    burst[2 * i + 1] = uint8_t(uint16_t(words[i]) & 0xFF);
  }
  EXPECT_EQ(strider::mpu6050_word(burst), -8192);
  EXPECT_EQ(strider::mpu6050_word(burst + 12), 32767);
  const strider::ImuSample<S> s = strider::mpu6050_sample<S>(burst, Mpu6050AccelRange::k2g, Mpu6050GyroRange::k500Dps);
  EXPECT_NEAR(dbl(s.accel_m_s2.x), -0.5 * kG, 1e-4);
  EXPECT_NEAR(dbl(s.accel_m_s2.y), 100 / 16384.0 * kG, 1e-4);
  EXPECT_NEAR(dbl(s.accel_m_s2.z), kG, 1e-4);
  EXPECT_NEAR(dbl(s.temp_c), 25.0, 2e-3);
  EXPECT_NEAR(dbl(s.gyro_rad_s.x), 10 * kDeg, 1e-5);
  EXPECT_NEAR(dbl(s.gyro_rad_s.y), -2 * kDeg, 1e-5);
  EXPECT_NEAR(dbl(s.gyro_rad_s.z), 32767 / 65.5 * kDeg, 1e-4);
}

}  // namespace
