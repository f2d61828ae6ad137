//! MPU-6050 register words -> an ImuSample in SI units: the 14-byte burst
//! from ACCEL_XOUT_H (0x3B), big-endian words, with the data sheet's scales
//! (docs/imu.md, "MPU-6050 words to SI"). Fixed multiplies the word as a
//! Q16.16 raw value by the scale times 2^16: no float code.
#ifndef STRIDER_SENSING_MPU6050_SAMPLE_H
#define STRIDER_SENSING_MPU6050_SAMPLE_H

#include <stdint.h>

#include "../math/scalar.h"
#include "imu_sample.h"

namespace strider {

enum class Mpu6050AccelRange : uint8_t { k2g = 0, k4g = 1, k8g = 2, k16g = 3 };  //!< AFS_SEL
enum class Mpu6050GyroRange : uint8_t { k250Dps = 0, k500Dps = 1, k1000Dps = 2, k2000Dps = 3 };  //!< FS_SEL

constexpr uint8_t kMpu6050BurstBytes = 14;  //!< ACCEL_XOUT_H (0x3B) .. GYRO_ZOUT_L (0x48)

//! LSB per g of an accel range.
constexpr double mpu6050_accel_lsb_per_g(Mpu6050AccelRange r) { return 16384.0 / double(1 << uint8_t(r)); }
//! LSB per deg/s of a gyro range.
constexpr double mpu6050_gyro_lsb_per_dps(Mpu6050GyroRange r) {
  return r == Mpu6050GyroRange::k250Dps ? 131.0
         : r == Mpu6050GyroRange::k500Dps ? 65.5
         : r == Mpu6050GyroRange::k1000Dps ? 32.8
                                           : 16.4;
}

//! The big-endian word at be[0], be[1].
constexpr int16_t mpu6050_word(const uint8_t* be) { return int16_t(uint16_t(uint16_t(be[0]) << 8 | be[1])); }

namespace detail {
//! per_lsb as mpu6050_times() wants it (Fixed: times 2^16); constexpr use only.
template <typename S>
constexpr S mpu6050_scale(double per_lsb) {
  return scalar<S>(ScalarTraits<S>::kIsFixed ? per_lsb * 65536.0 : per_lsb);
}
inline float mpu6050_times(int16_t word, float scale) { return float(word) * scale; }
inline Fixed mpu6050_times(int16_t word, Fixed scale) { return Fixed::from_raw(word) * scale; }

//! A word [LSB] times the scale of range R: [m/s^2] or [rad/s].
template <typename S, Mpu6050AccelRange R>
STRIDER_ALWAYS_INLINE S mpu6050_accel(int16_t word) {
  constexpr S k = mpu6050_scale<S>(kStandardGravity / mpu6050_accel_lsb_per_g(R));
  return mpu6050_times(word, k);
}
template <typename S, Mpu6050GyroRange R>
STRIDER_ALWAYS_INLINE S mpu6050_gyro(int16_t word) {
  constexpr S k = mpu6050_scale<S>(kDegToRad / mpu6050_gyro_lsb_per_dps(R));
  return mpu6050_times(word, k);
}
}  // namespace detail

//! An accel word [LSB] -> [m/s^2].
template <typename S>
S mpu6050_accel_m_s2(int16_t word, Mpu6050AccelRange r) {
  switch (r) {
    case Mpu6050AccelRange::k2g: return detail::mpu6050_accel<S, Mpu6050AccelRange::k2g>(word);
    case Mpu6050AccelRange::k4g: return detail::mpu6050_accel<S, Mpu6050AccelRange::k4g>(word);
    case Mpu6050AccelRange::k8g: return detail::mpu6050_accel<S, Mpu6050AccelRange::k8g>(word);
    default: return detail::mpu6050_accel<S, Mpu6050AccelRange::k16g>(word);
  }
}
//! A gyro word [LSB] -> [rad/s].
template <typename S>
S mpu6050_gyro_rad_s(int16_t word, Mpu6050GyroRange r) {
  switch (r) {
    case Mpu6050GyroRange::k250Dps: return detail::mpu6050_gyro<S, Mpu6050GyroRange::k250Dps>(word);
    case Mpu6050GyroRange::k500Dps: return detail::mpu6050_gyro<S, Mpu6050GyroRange::k500Dps>(word);
    case Mpu6050GyroRange::k1000Dps: return detail::mpu6050_gyro<S, Mpu6050GyroRange::k1000Dps>(word);
    default: return detail::mpu6050_gyro<S, Mpu6050GyroRange::k2000Dps>(word);
  }
}
//! The TEMP_OUT word -> [deg C].
template <typename S>
S mpu6050_temp_c(int16_t word) {
  constexpr S k = detail::mpu6050_scale<S>(1.0 / 340.0), offset = scalar<S>(36.53);
  return detail::mpu6050_times(word, k) + offset;
}

//! The 14-byte burst from ACCEL_XOUT_H -> a sample in the chip's axes.
template <typename S>
ImuSample<S> mpu6050_sample(const uint8_t* burst, Mpu6050AccelRange accel, Mpu6050GyroRange gyro) {
  ImuSample<S> s;
  s.accel_m_s2 = Vec3<S>(mpu6050_accel_m_s2<S>(mpu6050_word(burst), accel),
                         mpu6050_accel_m_s2<S>(mpu6050_word(burst + 2), accel),
                         mpu6050_accel_m_s2<S>(mpu6050_word(burst + 4), accel));
  s.temp_c = mpu6050_temp_c<S>(mpu6050_word(burst + 6));
  s.gyro_rad_s = Vec3<S>(mpu6050_gyro_rad_s<S>(mpu6050_word(burst + 8), gyro),
                         mpu6050_gyro_rad_s<S>(mpu6050_word(burst + 10), gyro),
                         mpu6050_gyro_rad_s<S>(mpu6050_word(burst + 12), gyro));
  return s;
}

}  // namespace strider

#endif  // STRIDER_SENSING_MPU6050_SAMPLE_H
