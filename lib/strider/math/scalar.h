//! Scalar traits and the generic helpers that let one template serve float and Fixed.
#ifndef STRIDER_MATH_SCALAR_H
#define STRIDER_MATH_SCALAR_H

#include <stdint.h>

#include "fixed.h"
#include "fixed_math.h"
#include "float_math.h"

namespace strider {

template <typename S>
struct ScalarTraits;

template <>
struct ScalarTraits<float> {
  static constexpr bool kIsFixed = false;
  static constexpr const char* name() { return "float"; }
  static constexpr float from_double(double v) { return float(v); }
  static constexpr double to_double(float v) { return double(v); }
  //! Distance below which an IK target counts as reached exactly [mm].
  static constexpr float ik_tolerance_mm() { return 0.01f; }
};

template <>
struct ScalarTraits<Fixed> {
  static constexpr bool kIsFixed = true;
  static constexpr const char* name() { return "fixed"; }
  static constexpr Fixed from_double(double v) { return Fixed(v); }
  static constexpr double to_double(Fixed v) { return v.to_double(); }
  static constexpr Fixed ik_tolerance_mm() { return Fixed(0.1); }
};

//! A constant in scalar S; use with literals so AVR builds fold it.
template <typename S>
constexpr S scalar(double v) { return ScalarTraits<S>::from_double(v); }
template <typename S>
constexpr double to_double(S v) { return ScalarTraits<S>::to_double(v); }

template <typename S> constexpr S pi() { return scalar<S>(3.14159265358979323846); }
template <typename S> constexpr S half_pi() { return scalar<S>(1.57079632679489661923); }
template <typename S> constexpr S two_pi() { return scalar<S>(6.28318530717958647692); }
template <typename S> constexpr S deg_to_rad(double deg) { return scalar<S>(deg * 0.017453292519943295); }
constexpr double kRadToDeg = 57.29577951308232;
constexpr double kDegToRad = 0.017453292519943295;

template <typename S> constexpr S min_of(S a, S b) { return b < a ? b : a; }
template <typename S> constexpr S max_of(S a, S b) { return a < b ? b : a; }
template <typename S> constexpr S clamp(S v, S lo, S hi) { return v < lo ? lo : (hi < v ? hi : v); }

//! a + b, a - b, -a and |a|, Fixed's saturating results bit for bit, always
//! in place (avr-gcc keeps Fixed's operators out of line in a large firmware).
STRIDER_ALWAYS_INLINE float add_inline(float a, float b) { return a + b; }
STRIDER_ALWAYS_INLINE Fixed add_inline(Fixed a, Fixed b) { return Fixed::from_raw(Fixed::sat_add_fast(a.raw(), b.raw())); }
STRIDER_ALWAYS_INLINE float sub_inline(float a, float b) { return a - b; }
STRIDER_ALWAYS_INLINE Fixed sub_inline(Fixed a, Fixed b) { return Fixed::from_raw(Fixed::sat_sub_fast(a.raw(), b.raw())); }
STRIDER_ALWAYS_INLINE float neg_inline(float a) { return -a; }
STRIDER_ALWAYS_INLINE Fixed neg_inline(Fixed a) { return Fixed::from_raw(Fixed::neg_raw(a.raw())); }
STRIDER_ALWAYS_INLINE float abs_inline(float a) { return abs(a); }
STRIDER_ALWAYS_INLINE Fixed abs_inline(Fixed a) { return a.raw() < 0 ? neg_inline(a) : a; }

//! Wrap an angle [rad] to (-pi, pi], -pi<S>() < result <= pi<S>(), and to
//! [0, 2 pi) (seed 001's angle_range_limiter), 0 <= result < two_pi<S>():
//! bounded time, NaN or an infinity gives 0; Fixed within 1 LSB.
using detail::wrap_pi;
using detail::wrap_two_pi;

}  // namespace strider

#endif  // STRIDER_MATH_SCALAR_H
