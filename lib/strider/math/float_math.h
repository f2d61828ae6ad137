//! Elementary functions for float, named like <cmath> as fixed_math.h's for
//! Fixed: sqrt, sin and cos are libm's, atan2, asin and acos the polynomials
//! of float_atan.h. All are total: NaN in gives 0, sin/cos of an infinity 0.
#ifndef STRIDER_MATH_FLOAT_MATH_H
#define STRIDER_MATH_FLOAT_MATH_H

#include <math.h>
#include <stdint.h>

#include "float_atan.h"
#include "float_bits.h"

namespace strider {

//! |v| (clears the sign bit).
inline float abs(float v) { return detail::bits_float(detail::magnitude_bits(v)); }

//! sqrt(v); 0 for v <= 0 and NaN.
inline float sqrt(float v) {
  // bits - 1 < inf bits <=> v in (0, +inf]: positive, not NaN.
  return detail::float_bits(v) - 1U < detail::kFloatInfBits ? ::sqrtf(v) : 0.0f;
}

//! sin(a) and cos(a) [a in rad]; 0 for NaN and infinities.
inline float sin(float a) { return detail::is_finite(a) ? ::sinf(a) : 0.0f; }
inline float cos(float a) { return detail::is_finite(a) ? ::cosf(a) : 0.0f; }

//! sqrt(a^2 + b^2) without overflow or underflow of the squares; 0 for NaN.
inline float hypot(float a, float b) {
  const uint32_t ma = detail::magnitude_bits(a), mb = detail::magnitude_bits(b);
  if (detail::is_nan_bits(ma) || detail::is_nan_bits(mb)) return 0.0f;
  const uint32_t hi_bits = ma > mb ? ma : mb;
  const float hi = detail::bits_float(hi_bits);
  const float lo = detail::bits_float(ma > mb ? mb : ma);
  if (hi_bits == 0 || hi_bits == detail::kFloatInfBits) return hi;
  // Squares overflow above 2^64 and lose bits below 2^-63: scale there.
  if (hi_bits > 0x5D800000UL || hi_bits < 0x21800000UL) {  // 2^60, 2^-60
    const float t = lo / hi;
    return hi * ::sqrtf(1.0f + t * t);
  }
  return ::sqrtf(hi * hi + lo * lo);
}

namespace detail {

constexpr float kTwoPiF = 6.28318530717959f;
constexpr float kThreePiF = 9.42477796076938f;
constexpr float kInvTwoPiF = 0.159154943091895f;
// Cody-Waite split of 2 pi: kTwoPiHiF has 8 significant bits, so n * hi is
// exact for |n| < 2^16.
constexpr float kTwoPiHiF = 6.28125f;
constexpr float kTwoPiLoF = 1.9353071795864769e-3f;

//! wrap_pi for float: (-pi, pi] with pi = pi<float>(), no loop; NaN and
//! infinities give 0 (docs/fixed-point.md, "wrap_pi and wrap_two_pi").
inline float wrap_pi(float a) {
  const uint32_t mag = magnitude_bits(a);
  if (mag >= kFloatInfBits) return 0.0f;  // NaN or infinite
  float r = a;
  if (mag > float_bits(kThreePiF)) {
    const float k = a * kInvTwoPiF;
    if (magnitude_bits(k) < 0x4B000000UL) {  // |k| < 2^23: n fits int32 exactly
      const float n = float(int32_t((float_bits(k) & kFloatSignBit) ? k - 0.5f : k + 0.5f));
      r = (a - n * kTwoPiHiF) - n * kTwoPiLoF;
    } else {
      r = ::fmodf(a, kTwoPiF);  // exact remainder of float(2 pi), in (-2 pi, 2 pi)
    }
  }
  // r is in [-3 pi, 3 pi]: one exact (Sterbenz) step lands in (-pi, pi].
  const uint32_t r_bits = float_bits(r);
  const uint32_t pi_bits = float_bits(kPiF);
  if (r_bits & kFloatSignBit) {
    if ((r_bits & kFloatMagMask) >= pi_bits) r += kTwoPiF;
  } else if (r_bits > pi_bits) {
    r -= kTwoPiF;
  }
  return r;
}

//! wrap_two_pi for float: [0, 2 pi) with 2 pi = two_pi<float>().
inline float wrap_two_pi(float a) {
  float r = wrap_pi(a);
  if (float_bits(r) & kFloatSignBit) {
    r += kTwoPiF;
    if (float_bits(r) >= float_bits(kTwoPiF)) r = 0.0f;  // -tiny + 2 pi rounds up to 2 pi
  }
  return r;
}

}  // namespace detail
}  // namespace strider

#endif  // STRIDER_MATH_FLOAT_MATH_H
