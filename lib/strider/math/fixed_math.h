//! Elementary functions for Fixed (interim: through float; replaced by table
//! and integer versions).
#ifndef STRIDER_MATH_FIXED_MATH_H
#define STRIDER_MATH_FIXED_MATH_H

#include "fixed.h"
#include "float_math.h"

namespace strider {

inline Fixed abs(Fixed v) { return v < Fixed() ? -v : v; }
inline Fixed sqrt(Fixed v) { return Fixed(sqrt(v.to_float())); }
inline Fixed sin(Fixed a) { return Fixed(sin(a.to_float())); }
inline Fixed cos(Fixed a) { return Fixed(cos(a.to_float())); }
inline Fixed atan2(Fixed y, Fixed x) { return Fixed(atan2(y.to_float(), x.to_float())); }
inline Fixed asin(Fixed v) { return Fixed(asin(v.to_float())); }
inline Fixed acos(Fixed v) { return Fixed(acos(v.to_float())); }

}  // namespace strider

#endif  // STRIDER_MATH_FIXED_MATH_H
