//! The servo tick map's per-frame arithmetic, per scalar: ticks from a
//! joint's distance from its lowest limit (Fixed: one 16 x 16-bit product
//! and byte shifts; float: one product), the exact long division its Fixed
//! slope is set up with, and the finite and sign tests of its clamp.
#ifndef STRIDER_CONTROL_SERVO_TICK_MATH_H
#define STRIDER_CONTROL_SERVO_TICK_MATH_H

#include <stdint.h>

#include "../math/float_bits.h"
#include "../math/mul16.h"
#include "../math/scalar.h"
#include "pca9685_timing.h"

namespace strider {

namespace servo_ticks_detail {

using detail::float_bits;
using detail::kFloatInfBits;
using detail::kFloatSignBit;
using detail::magnitude_bits;

//! floor(num 2^bits / den) by long division, bit by bit (den < 2^31, the
//! quotient < 2^32: the caller's bound); *inexact: a remainder is left.
STRIDER_NOINLINE inline uint32_t div_shifted(uint32_t num, uint32_t den, uint8_t bits, bool* inexact) {
  uint32_t q = num / den, r = num % den;
  for (; bits != 0; --bits) {
    r <<= 1;
    q <<= 1;
    if (r >= den) {
      r -= den;
      q |= 1u;
    }
  }
  if (inexact) *inexact = r != 0;
  return q;
}

//! ticks = (d [Q16.16] * k) >> shift + base [Q16.16], rounded (shift in
//! [3, 17], d in [0, 4) rad: configure()). d has 18 significant bits, so the
//! product is 18 x 16 bits: one 16 x 16-bit product and up to two adds for
//! d's integer part, summed 8 bits down (whole bytes); the usual shift of 8
//! (a slope of 128 to 255 ticks per rad, every 50 Hz servo) then needs no
//! shift at all.
inline uint16_t ticks_of(Fixed d, uint16_t k, uint8_t shift, uint32_t base_q16) {
  const uint32_t u = uint32_t(d.raw());                         // < 2^18
  const uint32_t lo = detail::mul_u16(uint16_t(u), k);          // bits 0-31 of d k
  // Bits 16-17 of d times k (< 2^18): d's integer part is 0-3, two adds.
  const uint8_t whole = uint8_t(u >> 16);
  uint32_t hi = (whole & 1u) ? uint32_t(k) : 0u;
  if (whole & 2u) hi += uint32_t(k) << 1;
  uint32_t p;
  if (shift >= 8) {
    p = (lo >> 8) + (hi << 8);  // d k 2^-8, exact (< 2^26)
    for (uint8_t n = uint8_t(shift - 8); n != 0; --n) p >>= 1;
  } else {
    p = lo;
    for (uint8_t n = shift; n != 0; --n) p >>= 1;
    p += hi << (16 - shift);
  }
  p += base_q16 + 0x8000u;
  const uint16_t t = uint16_t(p >> 16);
  return t > kPca9685MaxTick ? kPca9685MaxTick : t;
}
//! base_half: ticks of the lowest limit + 0.5 (rounding folded in).
inline uint16_t ticks_of(float d, float ticks_per_rad, float base_half) {
  // 0 <= d <= travel and base + slope travel < 4096 (configure()): in range.
  const uint16_t t = uint16_t(d * ticks_per_rad + base_half);
  return t > kPca9685MaxTick ? kPca9685MaxTick : t;
}

// Decisions on float bits (float_bits.h): a float comparison is a library
// call on the AVR, an integer one a few cycles.
inline bool finite(float v) { return magnitude_bits(v) < kFloatInfBits; }
inline bool finite(Fixed) { return true; }
//! v < 0 (v finite; -0 is not).
inline bool below_zero(float v) { return (float_bits(v) & kFloatSignBit) != 0 && magnitude_bits(v) != 0; }
inline bool below_zero(Fixed v) { return v.raw() < 0; }
//! a > b for finite a >= 0 and b >= 0.
inline bool above(float a, float b) { return float_bits(a) > float_bits(b); }
inline bool above(Fixed a, Fixed b) { return a.raw() > b.raw(); }

}  // namespace servo_ticks_detail

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_TICK_MATH_H
