//! Elementary functions for Fixed (Q16.16), named like <cmath> so that
//! scalar-generic code calls them unqualified for float and Fixed alike:
//! integer-only, total and in bounded time (docs/fixed-point.md).
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
