//! Working units, and lengths that never overflow. Fixed overflows above
//! 32767, so squares are taken in units of 2^n mm, where the "unit shift" n
//! brings the lengths involved into [4, 8) units (a two-link solver's largest
//! product, (2 a1 a2 sin)^2, stays below 1024; a unit keeps 16 fraction
//! bits). Float works in millimetres: shift 0, the conversions no-ops.
#ifndef STRIDER_MATH_WORKING_UNITS_H
#define STRIDER_MATH_WORKING_UNITS_H

#include <stdint.h>

#include "scalar.h"
#include "vec3.h"

namespace strider {
namespace units {

//! The unit shift n for lengths up to `length` [mm]: length 2^-n in [4, 8).
constexpr int8_t unit_shift(float) { return 0; }
constexpr int8_t unit_shift(Fixed length) {
  uint32_t r = Fixed::abs_raw(length.raw());
  int8_t n = 0;
  if (r == 0) return 0;
  while (r >= (uint32_t(8) << Fixed::kFracBits)) { r >>= 1; ++n; }
  while (r < (uint32_t(4) << Fixed::kFracBits)) { r <<= 1; --n; }
  return n;
}

//! Millimetres to working units (rounded half away from zero), and back.
constexpr float to_unit(float v_mm, int8_t) { return v_mm; }
constexpr Fixed to_unit(Fixed v_mm, int8_t shift) {
  return shift <= 0 ? v_mm.scaled_pow2(-shift)
                    : Fixed::from_raw(v_mm.raw() < 0 ? -int32_t(((Fixed::abs_raw(v_mm.raw()) >> (shift - 1)) + 1u) >> 1)
                                                     : int32_t(((uint32_t(v_mm.raw()) >> (shift - 1)) + 1u) >> 1));
}
constexpr float from_unit(float v, int8_t) { return v; }
constexpr Fixed from_unit(Fixed v, int8_t shift) { return v.scaled_pow2(shift); }

//! |(x, y, z)| [mm] with the squares taken in units of 2^shift mm.
template <typename S>
S norm_in(S x, S y, S z, int8_t shift) {
  const S ux = to_unit(x, shift), uy = to_unit(y, shift), uz = to_unit(z, shift);
  return from_unit(sqrt(ux * ux + uy * uy + uz * uz), shift);
}

//! The shift of norm(): the largest magnitude in [32, 64) units, so that the
//! squares keep ~28 significant bits and sum below 12288.
inline int8_t norm_shift(uint32_t max_raw) {
  int8_t n = 0;
  while (max_raw >= (uint32_t(64) << Fixed::kFracBits)) { max_raw >>= 1; ++n; }
  while (max_raw < (uint32_t(32) << Fixed::kFracBits)) { max_raw <<= 1; --n; }
  return n;
}

//! |(x, y, z)| [mm] without overflow or loss of precision for any magnitude.
template <typename S>
S norm(S x, S y, S z) { return sqrt(x * x + y * y + z * z); }
inline Fixed norm(Fixed x, Fixed y, Fixed z) {
  uint32_t m = Fixed::abs_raw(x.raw());
  if (Fixed::abs_raw(y.raw()) > m) m = Fixed::abs_raw(y.raw());
  if (Fixed::abs_raw(z.raw()) > m) m = Fixed::abs_raw(z.raw());
  return m == 0 ? Fixed() : norm_in(x, y, z, norm_shift(m));
}
template <typename S>
S norm(const Vec3<S>& v) { return units::norm(v.x, v.y, v.z); }

//! |a - b| [mm].
template <typename S>
S distance(const Vec3<S>& a, const Vec3<S>& b) { return units::norm(a.x - b.x, a.y - b.y, a.z - b.z); }

}  // namespace units
}  // namespace strider

#endif  // STRIDER_MATH_WORKING_UNITS_H
