//! How the generated velocity-limit table and VelocityLimits store their
//! numbers: 16-bit words that convert to float and Fixed without a
//! division. Strides in 1/32 mm (up to 2047 mm), servo figures in Q16.16.
#ifndef STRIDER_GAIT_VELOCITY_LIMIT_ENCODING_H
#define STRIDER_GAIT_VELOCITY_LIMIT_ENCODING_H

#include <stdint.h>

#include "../math/float_bits.h"
#include "../math/scalar.h"
#include "../robots/robot_model.h"

namespace strider {
namespace velocity_limit_encoding {

//! Stride codes per millimetre (a power of two: exact in Fixed).
constexpr uint16_t kStrideUnitsPerMm = 32;
//! Fixed raw (Q16.16) per code: 2^16 / 32.
constexpr uint8_t kStrideRawShift = 11;

//! A stride [mm] in [0, 2047.97] as its code, rounded (negative: 0).
inline uint16_t stride_code(float mm) {
  const float v = mm * float(kStrideUnitsPerMm) + 0.5f;
  return v <= 0.0f ? uint16_t(0) : v >= 65535.0f ? uint16_t(65535) : uint16_t(v);
}
inline uint16_t stride_code(Fixed mm) {
  const int32_t raw = mm.raw();
  if (raw <= 0) return 0;
  const uint32_t v = (uint32_t(raw) + (uint32_t(1) << (kStrideRawShift - 1))) >> kStrideRawShift;
  return v >= 65535u ? uint16_t(65535) : uint16_t(v);
}
//! A non-negative value as Q16.16, rounded (host side).
inline uint32_t q16_code(float v) {
  const double q = double(v) * 65536.0 + 0.5;
  return q <= 0.0 ? 0u : q >= 2147483647.0 ? 2147483647u : uint32_t(q);
}

//! The stride [mm] of a code.
constexpr float stride_of(uint16_t code, float) { return float(code) * (1.0f / float(kStrideUnitsPerMm)); }
constexpr Fixed stride_of(uint16_t code, Fixed) { return Fixed::from_raw(int32_t(uint32_t(code) << kStrideRawShift)); }
//! The value of a Q16.16 code.
constexpr float q16_of(uint32_t code, float) { return float(code) * (1.0f / 65536.0f); }
constexpr Fixed q16_of(uint32_t code, Fixed) { return Fixed::from_raw(int32_t(code)); }

//! mm [mm] in 1/16 mm, rounded half away from zero, from the float's bits
//! (no float arithmetic on the AVR); beyond |mm| < 2048 the low 16 bits,
//! NaN and infinities 0.
inline uint16_t sixteenths(float mm) {
  const uint32_t u = detail::float_bits(mm);
  const uint8_t e = uint8_t(u >> 23);  // biased exponent
  if (e == 0xFF) return 0;
  // 2 |mm| 16 = m 2^(e - 145), m the 24-bit significand: halves of a sixteenth.
  const uint32_t m = (u & 0x7FFFFFUL) | 0x800000UL;
  uint32_t halves;
  if (e < 121) halves = 0;  // below 2^-6: under half a sixteenth (zero and subnormals too)
  else if (e <= 145) halves = m >> (145 - e);
  else halves = e < 153 ? m << (e - 145) : 0;
  const uint16_t n = uint16_t((halves + 1) >> 1);
  return (u & detail::kFloatSignBit) ? uint16_t(-n) : n;
}

//! Words of a model's geometry fingerprint.
constexpr uint8_t kFingerprintWords = 8;

//! A model's geometry in a few words (kind, legs, links and the first leg's
//! mount and standing foot in 1/16 mm): a stored table entry is used only
//! for a model that matches it.
inline void geometry_fingerprint(const RobotModel& m, uint16_t* out) {
  out[0] = uint16_t(uint8_t(m.kind) | (uint16_t(m.leg_count) << 8));
  out[1] = sixteenths(m.links.l1_mm);
  out[2] = sixteenths(m.links.l2_mm);
  out[3] = sixteenths(m.links.l3_mm);
  out[4] = sixteenths(m.links.d1_mm);
  out[5] = sixteenths(m.legs[0].mount_mm.x);
  out[6] = sixteenths(m.legs[0].stand_mm.x);
  out[7] = sixteenths(m.legs[0].stand_mm.z);
}

}  // namespace velocity_limit_encoding
}  // namespace strider

#endif  // STRIDER_GAIT_VELOCITY_LIMIT_ENCODING_H
