//! Elementary functions for Fixed (Q16.16), named like <cmath> so that
//! scalar-generic code calls abs / sqrt / hypot / sin / cos / atan2 / asin /
//! acos unqualified for float and Fixed alike.
//!
//! Integer-only with flash lookup tables: no float, no 64-bit type, no 32-bit
//! division, bounded time, bit-identical on the host and the AVR. All are
//! total (sqrt of a negative = 0, atan2(0, 0) = 0, asin/acos clamp to
//! [-1, 1]). Methods, sources and measured error bounds: docs/fixed-point.md.
#ifndef STRIDER_MATH_FIXED_MATH_H
#define STRIDER_MATH_FIXED_MATH_H

#include "fixed.h"
#include "fixed_atan.h"
#include "fixed_atan_lean.h"
#include "fixed_sqrt.h"
#include "fixed_trig.h"

namespace strider {

//! |v|, saturating: abs(min()) = max().
inline Fixed abs(Fixed v) { return v < Fixed() ? -v : v; }

}  // namespace strider

#endif  // STRIDER_MATH_FIXED_MATH_H
