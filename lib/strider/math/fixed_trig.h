//! sin and cos for Fixed (Q16.16 radians), and the exact angle reduction that
//! they share with wrap_pi / wrap_two_pi.
//!
//! Method (docs/fixed-point.md): reduce the angle to [-pi, pi] in Q8.24
//! (2^-24 rad) with a two-part 2 pi (Cody-Waite), fold into [0, pi/2], then
//! interpolate linearly in a 404-node table of sin at steps of 2^-8 rad.
//! Integer-only, no division, bounded time; sin(-x) = -sin(x) and
//! cos(-x) = cos(x) bit for bit.
#ifndef STRIDER_MATH_FIXED_TRIG_H
#define STRIDER_MATH_FIXED_TRIG_H

#include <stdint.h>

#include "fixed.h"
#include "fixed_ops.h"

namespace strider {
namespace detail {

// Angles in Q8.24 [2^-24 rad], rounded to nearest.
constexpr int32_t kPiQ24 = 52707179;       //!< pi 2^24
constexpr int32_t kHalfPiQ24 = 26353589;   //!< pi/2 2^24
constexpr int32_t kTwoPiQ24 = 105414357;   //!< 2 pi 2^24 (integer part)
constexpr uint16_t kTwoPiQ24Lo = 4363;     //!< (2 pi 2^24 - kTwoPiQ24) 2^16
constexpr uint16_t kInvTwoPiQ16 = 10430;   //!< 2^16 / (2 pi), truncated
constexpr int32_t kPiRaw = 205887;         //!< pi in Q16.16
constexpr int32_t kTwoPiRaw = 411775;      //!< 2 pi in Q16.16

//! |a| 2^24 - n 2 pi 2^24 modulo 2^32 for |a| = ua / 2^16 >= 8 rad, with
//! n = round(|a| / 2 pi) within +-1: the true value is within +-3 pi.
inline uint32_t reduce_large_angle_q24(uint32_t ua) {
  // n from the high half of |a| alone (|a| < 2^15 rad, so n < 2^13).
  const uint16_t n = hi16(mul_u16(hi16(ua), kInvTwoPiQ16) + uint32_t(0x8000));
  // n 2 pi 2^24 = n kTwoPiQ24 (low 32 bits, from two 16x16 products)
  // + n kTwoPiQ24Lo / 2^16 (rounded).
  const uint16_t n_hi = uint16_t(mul_u16(n, uint16_t(kTwoPiQ24 >> 16)));
  const uint32_t n_two_pi = mul_u16(n, uint16_t(kTwoPiQ24)) + (uint32_t(n_hi) << 16);
  return (ua << 8) - n_two_pi - hi16(mul_u16(n, kTwoPiQ24Lo) + uint32_t(0x8000));
}

//! raw / 2^16 [rad] reduced modulo 2 pi into [-pi, pi], in Q8.24.
//! Error below 1 unit of 2^-24 rad (6e-8 rad) for every input. Odd in raw.
//! Inlined: below 8 rad it is a shift and one conditional 2 pi.
STRIDER_ALWAYS_INLINE int32_t reduce_angle_q24(int32_t raw) {
  const uint32_t ua = abs_u32(raw);
  int32_t s = to_signed(ua < 0x80000UL ? ua << 8 : reduce_large_angle_q24(ua));
  if (s > kPiQ24) {
    s -= kTwoPiQ24;
  } else if (s < -kPiQ24) {
    s += kTwoPiQ24;
  }
  return raw < 0 ? -s : s;
}

//! sin(x) for x in [0, pi/2 + 2^-24] (Q8.24) as Q16.16 in [0, 2^16].
//! The table holds 65535 sin; v += v >> 16 rescales it to 65536 sin.
STRIDER_ALWAYS_INLINE int32_t sin_first_quadrant(uint32_t x) {
  const uint16_t i = uint16_t(x >> 16);
  const uint16_t f = uint16_t(x);
  const uint16_t t0 = flash_u16(FixedTables<>::kSin, i);
  const uint16_t t1 = flash_u16(FixedTables<>::kSin, uint16_t(i + 1U));
  uint32_t v = (uint32_t(t0) << 8) + (mul_u16(uint16_t(t1 - t0), f) >> 8);
  v += v >> 16;
  return int32_t((v + 128U) >> 8);
}

//! Rounds a Q8.24 angle to Q16.16, half away from zero (odd).
STRIDER_ALWAYS_INLINE int32_t q24_to_raw(int32_t a) {
  const int32_t m = int32_t((abs_u32(a) + 128U) >> 8);
  return a < 0 ? -m : m;
}

//! wrap_pi for Fixed: the result r has -pi < r <= pi in Fixed comparisons
//! (pi = pi<Fixed>()) and is within 1 LSB of the exact wrapped angle.
inline Fixed wrap_pi_impl(Fixed a) {
  const int32_t q = reduce_angle_q24(a.raw());
  int32_t r = q24_to_raw(q);
  // -kPiRaw is outside the interval: an angle that rounds to it goes to the
  // nearer of -kPiRaw + 1 and kPiRaw around the circle (the midpoint is
  // -52707050.5 in Q8.24), which keeps the error within 0.92 LSB.
  if (r <= -kPiRaw) r = q <= int32_t(-52707051) ? kPiRaw : -kPiRaw + 1;
  return Fixed::from_raw(r);
}

//! wrap_two_pi for Fixed: 0 <= r < two_pi<Fixed>(), within 1 LSB.
inline Fixed wrap_two_pi_impl(Fixed a) {
  const int32_t r = q24_to_raw(reduce_angle_q24(a.raw()));
  return Fixed::from_raw(r < 0 ? r + kTwoPiRaw : r);
}

}  // namespace detail

//! sin(a) [a in rad], any a; abs error < 1.1 LSB = 1.7e-5 (measured 1.59e-5).
inline Fixed sin(Fixed a) {
  const int32_t r = detail::reduce_angle_q24(a.raw());
  uint32_t m = detail::abs_u32(r);
  if (m > uint32_t(detail::kHalfPiQ24)) m = uint32_t(detail::kPiQ24) - m;
  const int32_t v = detail::sin_first_quadrant(m);
  return Fixed::from_raw(r < 0 ? -v : v);
}

//! cos(a) [a in rad] = sin(pi/2 - |a|); abs error < 1.1 LSB = 1.7e-5.
inline Fixed cos(Fixed a) {
  const int32_t m = int32_t(detail::abs_u32(detail::reduce_angle_q24(a.raw())));
  const int32_t c = detail::kHalfPiQ24 - m;  // in [-pi/2, pi/2]
  const int32_t v = detail::sin_first_quadrant(detail::abs_u32(c));
  return Fixed::from_raw(c < 0 ? -v : v);
}

}  // namespace strider

#endif  // STRIDER_MATH_FIXED_TRIG_H
