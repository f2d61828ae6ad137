//! Elementary functions for float, named like <cmath> so scalar-generic code
//! calls strider::sqrt / sin / cos / atan2 / asin / acos for float and Fixed.
#ifndef STRIDER_MATH_FLOAT_MATH_H
#define STRIDER_MATH_FLOAT_MATH_H

#include <math.h>

namespace strider {

inline float abs(float v) { return v < 0.0f ? -v : v; }
inline float sqrt(float v) { return v <= 0.0f ? 0.0f : ::sqrtf(v); }
inline float sin(float a) { return ::sinf(a); }
inline float cos(float a) { return ::cosf(a); }
inline float atan2(float y, float x) { return ::atan2f(y, x); }
inline float asin(float v) { return ::asinf(v < -1.0f ? -1.0f : v > 1.0f ? 1.0f : v); }
inline float acos(float v) { return ::acosf(v < -1.0f ? -1.0f : v > 1.0f ? 1.0f : v); }

}  // namespace strider

#endif  // STRIDER_MATH_FLOAT_MATH_H
