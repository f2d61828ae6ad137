//! Mat3: a row-major 3x3 matrix of scalar S, mostly rotations.
#ifndef STRIDER_MATH_MAT3_H
#define STRIDER_MATH_MAT3_H

#include "vec3.h"

namespace strider {

template <typename S>
struct Mat3 {
  S m[3][3];

  static constexpr Mat3 identity() {
    return Mat3{{{S(1), S(0), S(0)}, {S(0), S(1), S(0)}, {S(0), S(0), S(1)}}};
  }

  constexpr Vec3<S> row(uint8_t i) const { return Vec3<S>(m[i][0], m[i][1], m[i][2]); }
  constexpr Vec3<S> col(uint8_t j) const { return Vec3<S>(m[0][j], m[1][j], m[2][j]); }

  constexpr Mat3 transposed() const {
    return Mat3{{{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}}};
  }

  friend constexpr Vec3<S> operator*(const Mat3& a, const Vec3<S>& v) {
    return Vec3<S>(dot(a.row(0), v), dot(a.row(1), v), dot(a.row(2), v));
  }
  friend Mat3 operator*(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (uint8_t i = 0; i < 3; ++i)
      for (uint8_t j = 0; j < 3; ++j) r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
  }
};

}  // namespace strider

#endif  // STRIDER_MATH_MAT3_H
