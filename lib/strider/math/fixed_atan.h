//! atan2, asin and acos for Fixed (Q16.16), integer-only and division-free:
//! the octant fold, a table reciprocal refined by an exact residual and the
//! atan table; asin and acos through atan2 (docs/fixed-point.md, "atan2,
//! asin, acos").
#ifndef STRIDER_MATH_FIXED_ATAN_H
#define STRIDER_MATH_FIXED_ATAN_H

#include <stdint.h>

#include "fixed.h"
#include "fixed_ops.h"
#include "fixed_sqrt.h"
#include "fixed_trig.h"

namespace strider {
namespace detail {

//! atan(lo / hi) for 0 <= lo <= hi, hi > 0, in Q8.24 [0, pi/4].
inline uint32_t atan_ratio_q24(uint32_t lo, uint32_t hi) {
  normalize_pair(hi, lo);
  const uint16_t hh = hi16(hi), hl = uint16_t(hi);
  const uint16_t r = recip_q30(hh, uint8_t(hl >> 8));  // 2^46 / hi
  // t0 = lo / hi in Q0.16 from the top half of lo, within 7 units; below 1.
  uint32_t p = mul_u16(hi16(lo), r);  // ~ (lo / hi) 2^30
  if (p > 0x3FFFFFFFUL) p = 0x3FFFFFFFUL;
  const uint16_t t0 = hi16(p << 2);
  // Exact residual e = lo - t0 hi / 2^16 (modulo 2^32; true |e| < 2^19),
  // then t = t0 + e / hi in Q0.24, where e 2^24 / hi = (e / 2^8) r / 2^14.
  const int32_t e = to_signed(lo - mul_u16(t0, hh) - hi16(mul_u16(t0, hl)));
  const uint16_t dt = hi16(mul_u16(uint16_t(abs_u32(e) >> 8), r) << 2);
  uint32_t t = uint32_t(t0) << 8;
  if (e >= 0) {
    t += dt;
  } else {
    t = t > dt ? t - dt : 0;
  }
  if (t > 0x1000000UL) t = 0x1000000UL;
  // atan t = t - D(t); D in units of 2^-18, increasing, interpolated in
  // units of 2^-26 and scaled to 2^-24.
  const uint16_t i = hi16(t);
  const uint16_t d0 = flash_u16(FixedTables<>::kAtan, i);
  const uint16_t d1 = flash_u16(FixedTables<>::kAtan, uint16_t(i + 1U));
  return t - (((uint32_t(d0) << 8) + (mul_u16(uint16_t(d1 - d0), uint16_t(t)) >> 8)) >> 2);
}

//! Angle of the point (ax, ay) with ax, ay >= 0, in Q8.24 [0, pi/2];
//! 0 for (0, 0).
STRIDER_ALWAYS_INLINE uint32_t atan2_first_quadrant_q24(uint32_t ay, uint32_t ax) {
  if (ay > ax) return uint32_t(kHalfPiQ24) - atan_ratio_q24(ax, ay);
  if (ax == 0) return 0;
  return atan_ratio_q24(ay, ax);
}

//! acos(ax / 2^16) for ax in [0, 2^16], in Q8.24 [0, pi/2].
inline uint32_t acos_unit_q24(uint32_t ax) {
  if (ax >= 0x10000UL) return 0;
  if (ax == 0) return uint32_t(kHalfPiQ24);
  // p = (1 - x)(1 + x) 2^32 exactly: (2^16 - ax)(2^16 + ax) < 2^32.
  const uint16_t a = uint16_t(0x10000UL - ax);
  uint32_t p = mul_u16(a, uint16_t(ax)) + (uint32_t(a) << 16);
  const uint8_t h = uint8_t(normalize_even(p) / 2);  // p >= 2^17 - 1, so h <= 7
  // root ~ sqrt((1 - x^2) 2^32) 2^(11 + h); its +-1 is far below what atan needs.
  const uint32_t root = isqrt_q22_call(p);
  // Both legs scaled by 2^32: x 2^32 and sqrt(1 - x^2) 2^32 = root 2^(5 - h).
  const uint32_t y = h > 5 ? shr_round(root, uint8_t(h - 5)) : root << (5 - h);
  return atan2_first_quadrant_q24(y, ax << 16);
}

//! Clamps a raw value to [-2^16, 2^16] (the input range of asin, acos).
STRIDER_ALWAYS_INLINE int32_t clamp_unit_raw(int32_t raw) {
  return raw > Fixed::kOneRaw ? Fixed::kOneRaw : raw < -Fixed::kOneRaw ? -Fixed::kOneRaw : raw;
}

}  // namespace detail

//! atan2(y, x) in [-pi, pi] [rad]; atan2(0, 0) = 0; abs error < 0.75 LSB
//! = 1.2e-5 rad (measured 1.05e-5).
inline Fixed atan2(Fixed y, Fixed x) {
  uint32_t a = detail::atan2_first_quadrant_q24(detail::abs_u32(y.raw()), detail::abs_u32(x.raw()));
  if (x.raw() < 0) a = uint32_t(detail::kPiQ24) - a;
  const int32_t r = int32_t((a + 128U) >> 8);
  return Fixed::from_raw(y.raw() < 0 ? -r : r);
}

//! acos(v) in [0, pi] [rad]; v is clamped to [-1, 1]; abs error < 0.75 LSB
//! = 1.2e-5 rad (measured 1.03e-5) for every input, also next to +-1.
inline Fixed acos(Fixed v) {
  const int32_t raw = detail::clamp_unit_raw(v.raw());
  uint32_t a = detail::acos_unit_q24(detail::abs_u32(raw));
  if (raw < 0) a = uint32_t(detail::kPiQ24) - a;
  return Fixed::from_raw(int32_t((a + 128U) >> 8));
}

//! asin(v) in [-pi/2, pi/2] [rad]; v is clamped to [-1, 1]; abs error
//! < 0.75 LSB = 1.2e-5 rad (measured 1.03e-5).
inline Fixed asin(Fixed v) {
  const int32_t raw = detail::clamp_unit_raw(v.raw());
  const uint32_t a = uint32_t(detail::kHalfPiQ24) - detail::acos_unit_q24(detail::abs_u32(raw));
  const int32_t r = int32_t((a + 128U) >> 8);
  return Fixed::from_raw(raw < 0 ? -r : r);
}

}  // namespace strider

#endif  // STRIDER_MATH_FIXED_ATAN_H
