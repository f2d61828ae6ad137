//! Working units of the gait code: Fixed (Q16.16) overflows above 32767, so
//! squares of body-sized distances (hundreds of mm) are taken in units of
//! 2^shift mm, with shift chosen so that the lengths involved lie below 8
//! units. Float works in millimetres (shift 0, conversions are no-ops).
//! Shifts are exact for Fixed and cost no multiplication.
#ifndef STRIDER_GAIT_GAIT_UNITS_H
#define STRIDER_GAIT_GAIT_UNITS_H

#include <stdint.h>

#include "../math/scalar.h"

namespace strider {
namespace gait_units {

//! The shift for lengths up to `length` [mm]: length 2^-shift < 8.
constexpr int8_t shift_for(float) { return 0; }
constexpr int8_t shift_for(Fixed length) {
  uint32_t r = Fixed::abs_raw(length.raw());
  int8_t n = 0;
  while (r >= (uint32_t(8) << Fixed::kFracBits)) {
    r >>= 1;
    ++n;
  }
  return n;
}

constexpr float to_unit(float mm, int8_t) { return mm; }
constexpr Fixed to_unit(Fixed mm, int8_t shift) { return mm.scaled_pow2(-shift); }
constexpr float from_unit(float v, int8_t) { return v; }
constexpr Fixed from_unit(Fixed v, int8_t shift) { return v.scaled_pow2(shift); }

//! |(x, y)| [mm] without overflowing Fixed.
template <typename S>
S length_mm(S x, S y, int8_t shift) {
  const S ux = to_unit(x, shift), uy = to_unit(y, shift);
  return from_unit(sqrt(ux * ux + uy * uy), shift);
}

}  // namespace gait_units
}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_UNITS_H
