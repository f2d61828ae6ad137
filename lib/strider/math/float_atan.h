//! atan2, asin and acos for float: short minimax polynomials in the forms of
//! Cephes' atanf / asinf (S. L. Moshier, 1989-1992), refitted by
//! tools/fit_float_poly.py, instead of avr-libc's slower ones; error below
//! 5e-7 rad (docs/fixed-point.md, "float atan2, asin, acos"). Total: NaN in
//! gives 0 (acos: pi/2), asin/acos clamp their input to [-1, 1].
#ifndef STRIDER_MATH_FLOAT_ATAN_H
#define STRIDER_MATH_FLOAT_ATAN_H

#include <math.h>
#include <stdint.h>

#include "float_bits.h"

namespace strider {
namespace detail {

constexpr float kPiF = 3.14159265358979f;
constexpr float kHalfPiF = 1.57079632679490f;
constexpr float kQuarterPiF = 0.785398163397448f;
constexpr float kTanPi8F = 0.414213562373095f;

//! atan t for |t| <= tan(pi/8): t P(t^2), degree 3; error 1.1e-7.
inline float atan_poly(float t) {
  const float z = t * t;
  return t * (((-1.077971160e-01f * z + 1.958097368e-01f) * z - 3.331416845e-01f) * z + 9.999976158e-01f);
}

//! asin x for |x| <= 1/2: x P(x^2), degree 4; error 2.1e-8.
inline float asin_poly(float x) {
  const float z = x * x;
  return x * ((((5.332168192e-02f * z + 3.813697770e-02f) * z + 7.576181740e-02f) * z + 1.666310132e-01f) * z +
              1.000000477e+00f);
}

//! acos a for a in [1/2, 1]: sqrt(w) Q(w) with w = 1 - a (exact in float),
//! degree 4; error 4.3e-8. sqrt(w) carries the singularity at a = 1.
inline float acos_near_one(float a) {
  const float w = 1.0f - a;
  return ::sqrtf(w) *
         ((((4.713015165e-03f * w + 6.741728634e-03f) * w + 2.678584866e-02f) * w + 1.178259179e-01f) * w +
          1.414214253e+00f);
}

//! |v| clamped to [0, 1]; NaN gives 0.
inline float unit_magnitude(float v) {
  const uint32_t m = magnitude_bits(v);
  return m <= kFloatOneBits ? bits_float(m) : (is_nan_bits(m) ? 0.0f : 1.0f);
}

}  // namespace detail

//! atan2(y, x) in [-pi, pi] [rad]; atan2(0, 0) = 0; error < 5e-7 rad.
//! Branches on the float bits (float_bits.h): no float comparison.
inline float atan2(float y, float x) {
  const uint32_t yb = detail::float_bits(y), xb = detail::float_bits(x);
  const uint32_t my = yb & detail::kFloatMagMask, mx = xb & detail::kFloatMagMask;
  if (detail::is_nan_bits(my) || detail::is_nan_bits(mx)) return 0.0f;
  const bool steep = my > mx;  // fold into the first octant: lo <= hi
  const uint32_t hi_bits = steep ? my : mx;
  const uint32_t lo_bits = steep ? mx : my;
  if (hi_bits == 0) return 0.0f;
  float hi = detail::bits_float(hi_bits);
  float lo = detail::bits_float(lo_bits);
  if (hi_bits == detail::kFloatInfBits) {  // infinite: only the direction is left
    hi = 1.0f;
    lo = lo_bits == detail::kFloatInfBits ? 1.0f : 0.0f;
  }
  // One division: t = lo/hi, or (lo - hi)/(lo + hi) around pi/4, so that
  // |t| <= tan(pi/8) (Cephes' reduction).
  float a;
  if (detail::float_bits(lo) > detail::float_bits(detail::kTanPi8F * hi)) {
    a = detail::kQuarterPiF + detail::atan_poly((lo - hi) / (lo + hi));
  } else {
    a = detail::atan_poly(lo / hi);
  }
  if (steep) a = detail::kHalfPiF - a;
  if (xb & detail::kFloatSignBit) a = detail::kPiF - a;
  return (yb & detail::kFloatSignBit) ? -a : a;
}

//! asin(v) in [-pi/2, pi/2] [rad]; v clamped to [-1, 1]; error < 5e-7 rad.
inline float asin(float v) {
  const float a = detail::unit_magnitude(v);
  const float r = detail::float_bits(a) <= detail::kFloatHalfBits ? detail::asin_poly(a)
                                                                  : detail::kHalfPiF - detail::acos_near_one(a);
  return (detail::float_bits(v) & detail::kFloatSignBit) ? -r : r;
}

//! acos(v) in [0, pi] [rad]; v clamped to [-1, 1]; error < 5e-7 rad.
inline float acos(float v) {
  const float a = detail::unit_magnitude(v);
  const bool negative = (detail::float_bits(v) & detail::kFloatSignBit) != 0;
  if (detail::float_bits(a) <= detail::kFloatHalfBits) {
    const float s = detail::asin_poly(a);
    return detail::kHalfPiF - (negative ? -s : s);
  }
  const float r = detail::acos_near_one(a);
  return negative ? detail::kPiF - r : r;
}

}  // namespace strider

#endif  // STRIDER_MATH_FLOAT_ATAN_H
