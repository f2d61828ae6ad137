//! IEEE-754 bit access for float: sign, magnitude, NaN and ordering tests as
//! integer operations (on the AVR a float comparison is a ~50-cycle library
//! call); NaN patterns lie above +inf.
#ifndef STRIDER_MATH_FLOAT_BITS_H
#define STRIDER_MATH_FLOAT_BITS_H

#include <stdint.h>
#include <string.h>

namespace strider {
namespace detail {

constexpr uint32_t kFloatSignBit = 0x80000000UL;
constexpr uint32_t kFloatMagMask = 0x7FFFFFFFUL;
constexpr uint32_t kFloatInfBits = 0x7F800000UL;  //!< +inf; larger magnitudes are NaN
constexpr uint32_t kFloatOneBits = 0x3F800000UL;  //!< 1.0f
constexpr uint32_t kFloatHalfBits = 0x3F000000UL; //!< 0.5f

inline uint32_t float_bits(float f) {
  uint32_t u;
  memcpy(&u, &f, sizeof u);
  return u;
}

inline float bits_float(uint32_t u) {
  float f;
  memcpy(&f, &u, sizeof f);
  return f;
}

//! num / den (0 < num < den < 2^24) as the nearest float, ties to even,
//! from integer operations only (the float division's result, without its
//! soft-float call on the AVR).
inline float ratio_float(uint32_t num, uint32_t den) {
  uint8_t e = 0;
  while (num < den) num <<= 1, ++e;  // num / den in [1, 2): the value is that x 2^-e
  uint32_t q = 1, r = num - den;
  for (uint8_t i = 0; i < 23; ++i) {
    r <<= 1;
    q <<= 1;
    if (r >= den) r -= den, q |= 1u;
  }
  if (2 * r > den || (2 * r == den && (q & 1u))) ++q;
  if (q == (uint32_t(1) << 24)) q >>= 1, --e;  // rounded up to the next power of two
  return bits_float((uint32_t(127 - e) << 23) | (q & 0x7FFFFFu));
}

//! The bits of |f| (sign cleared).
inline uint32_t magnitude_bits(float f) { return float_bits(f) & kFloatMagMask; }

inline bool is_nan_bits(uint32_t mag) { return mag > kFloatInfBits; }
inline bool is_finite(float v) { return magnitude_bits(v) < kFloatInfBits; }

//! a < b for non-NaN floats, from the bits; -0 == +0, as with <.
inline __attribute__((always_inline)) bool float_less(float a, float b) {
  const uint32_t ua = float_bits(a), ub = float_bits(b);
  if ((ua ^ ub) & kFloatSignBit) return (ua & kFloatSignBit) != 0 && ((ua | ub) << 1) != 0;  // not -0 < +0
  return (ua & kFloatSignBit) ? ub < ua : ua < ub;  // negatives: the larger magnitude is less
}

//! v == 0 (either sign) from the bits.
inline bool float_is_zero(float v) { return magnitude_bits(v) == 0; }

}  // namespace detail
}  // namespace strider

#endif  // STRIDER_MATH_FLOAT_BITS_H
