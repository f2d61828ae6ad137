//! The servo tick map's arithmetic, per scalar: the slope and offset of
//! ticks over a joint's distance from its lowest limit (set up once), and per
//! frame the ticks from that distance and the sign tests of its clamp.
#ifndef STRIDER_CONTROL_SERVO_TICK_MATH_H
#define STRIDER_CONTROL_SERVO_TICK_MATH_H

#include <stdint.h>

#include "../math/float_bits.h"
#include "../math/mul16.h"
#include "../math/scalar.h"
#include "pca9685_timing.h"
#include "servo_map.h"

namespace strider {

//! The slope and offset of ticks over d, per scalar: Fixed keeps a 16-bit
//! slope with its scale (one 16 x 16-bit product per joint), float its own.
template <typename S>
struct ServoTickScale;
template <>
struct ServoTickScale<Fixed> {
  uint32_t base_q16;  //!< ticks of the lowest limit [Q16.16 ticks]
  uint16_t k;         //!< ticks_per_rad 2^shift, in [2^15, 2^16)
  uint8_t shift;      //!< scale of k
};
template <>
struct ServoTickScale<float> {
  float base;           //!< ticks of the lowest limit + 0.5 (rounding) [ticks]
  float ticks_per_rad;  //!< [ticks/rad]
};

namespace servo_ticks_detail {

using detail::float_bits;
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
//! [3, 17], d in [0, 4) rad): one 16 x 16-bit product and up to two adds for
//! d's integer part, summed 8 bits down (the usual shift of 8 needs none).
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

// Decisions on float bits: a float comparison is a library call on the AVR.
//! v < 0 (v finite; -0 is not).
inline bool below_zero(float v) { return (float_bits(v) & kFloatSignBit) != 0 && magnitude_bits(v) != 0; }
inline bool below_zero(Fixed v) { return v.raw() < 0; }
//! a > b for finite a >= 0 and b >= 0.
inline bool above(float a, float b) { return float_bits(a) > float_bits(b); }
inline bool above(Fixed a, Fixed b) { return a.raw() > b.raw(); }

//! min_pulse + angle us_per_rad [Q16.16 us]; false below 0 us or from 65536 us.
inline bool pulse_q16(const ServoChannel<Fixed>& ch, Fixed angle, uint32_t* q16) {
  const int32_t p = (angle * ch.us_per_rad).raw();
  if (p == Fixed::kMaxRaw || p == Fixed::kMinRaw) return false;  // saturated
  const uint32_t m = uint32_t(ch.min_pulse_us) << 16;
  if (p < 0) {
    if (uint32_t(-p) > m) return false;
    *q16 = m - uint32_t(-p);
  } else {
    if (uint32_t(p) > ~m) return false;
    *q16 = m + uint32_t(p);
  }
  return true;
}
// The slope and offset of the ticks over the servo angle from lo, for
// servo_pulse_us()'s pulse before its rounding: ticks = us * 262144 /
// period_x64. False: a limit beyond the pulse range, a travel of 4 rad or
// more, a slope or a pulse out of range.
inline bool set_scale(ServoTickScale<float>& sc, const ServoChannel<float>& ch, float lo, float hi,
                      const Pca9685Timing& timing) {
  const double ticks_per_us = 262144.0 / double(timing.period_x64());
  const double lo_us = double(ch.min_pulse_us < ch.max_pulse_us ? ch.min_pulse_us : ch.max_pulse_us);
  const double hi_us = double(ch.min_pulse_us < ch.max_pulse_us ? ch.max_pulse_us : ch.min_pulse_us);
  const double us_per_rad = double(ch.us_per_rad);
  const double at_lo = double(ch.min_pulse_us) + double(lo) * us_per_rad;
  const double at_hi = double(ch.min_pulse_us) + double(hi) * us_per_rad;
  if (at_lo < lo_us || at_hi > hi_us || !(us_per_rad >= 0.0)) return false;
  const double tpr = us_per_rad * ticks_per_us;
  const double base = at_lo * ticks_per_us;
  const double travel = double(hi - lo);
  sc.ticks_per_rad = float(tpr);
  sc.base = float(base + 0.5);
  return travel < 4.0 && base + tpr * travel < 4096.0;
}
// Fixed: integers only; slope and offset are exact quotients rounded once.
inline bool set_scale(ServoTickScale<Fixed>& sc, const ServoChannel<Fixed>& ch, Fixed lo, Fixed hi,
                      const Pca9685Timing& timing) {
  const uint32_t period = timing.period_x64();  // 34,952 .. 3.4e6
  const uint16_t lo_us = ch.min_pulse_us < ch.max_pulse_us ? ch.min_pulse_us : ch.max_pulse_us;
  const uint16_t hi_us = ch.min_pulse_us < ch.max_pulse_us ? ch.max_pulse_us : ch.min_pulse_us;
  const int32_t upr = ch.us_per_rad.raw();
  uint32_t at_lo, at_hi;  // [Q16.16 us]
  if (upr < 0 || !pulse_q16(ch, lo, &at_lo) || !pulse_q16(ch, hi, &at_hi)) return false;
  if (at_lo < (uint32_t(lo_us) << 16) || at_hi > (uint32_t(hi_us) << 16)) return false;
  if ((hi - lo).raw() >= (int32_t(4) << Fixed::kFracBits)) return false;  // travel < 4 rad
  // ticks_per_rad = upr 4 / period < 8192, and ticks(hi) = at_hi 4 / period
  // [Q16.16] < 4096 (at_lo <= at_hi: upr >= 0, lo <= hi).
  if (upr / period >= 2048u || at_hi / period >= 1024u) return false;
  // x = ticks_per_rad 2^18, truncated (< 2^31); inexact: a remainder.
  bool inexact = false;
  const uint32_t x = div_shifted(uint32_t(upr), period, 20, &inexact);
  if (x < (uint32_t(1) << 17) || (x == (uint32_t(1) << 17) && !inexact)) return false;  // ticks_per_rad > 0.5
  // k = ticks_per_rad 2^shift in [2^15, 2^16): the largest shift <= 17
  // with ticks_per_rad 2^(shift + 1) < 65535.5, i.e. x < 131071 2^(16 - shift).
  uint8_t shift = 2;
  while (shift < 17 && x < (uint32_t(131071) << (16 - shift))) ++shift;
  sc.shift = shift;
  sc.k = uint16_t((x + (uint32_t(1) << (17 - shift))) >> (18 - shift));  // rounded
  // base_q16 = at_lo 2^18 / period, rounded (< 2^28).
  sc.base_q16 = (div_shifted(at_lo, period, 19, nullptr) + 1u) >> 1;
  return true;
}
inline uint16_t ticks(const ServoTickScale<Fixed>& sc, Fixed d) {
  return ticks_of(d, sc.k, sc.shift, sc.base_q16);
}
inline uint16_t ticks(const ServoTickScale<float>& sc, float d) {
  return ticks_of(d, sc.ticks_per_rad, sc.base);
}

}  // namespace servo_ticks_detail

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_TICK_MATH_H
