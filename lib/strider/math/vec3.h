//! Vec3: a 3-vector of scalar S (float or Fixed) [mm unless named otherwise].
#ifndef STRIDER_MATH_VEC3_H
#define STRIDER_MATH_VEC3_H

#include "scalar.h"

namespace strider {

template <typename S>
struct Vec3 {
  S x, y, z;

  constexpr Vec3() : x(), y(), z() {}
  constexpr Vec3(S x_, S y_, S z_) : x(x_), y(y_), z(z_) {}

  //! Converts between scalars (float <-> Fixed) through double.
  template <typename T>
  static Vec3 from(const Vec3<T>& v) {
    return Vec3(scalar<S>(to_double(v.x)), scalar<S>(to_double(v.y)), scalar<S>(to_double(v.z)));
  }

  constexpr S operator[](uint8_t i) const { return i == 0 ? x : (i == 1 ? y : z); }

  friend constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return Vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
  friend constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return Vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
  constexpr Vec3 operator-() const { return Vec3(-x, -y, -z); }
  friend constexpr Vec3 operator*(const Vec3& a, S k) { return Vec3(a.x * k, a.y * k, a.z * k); }
  friend constexpr Vec3 operator*(S k, const Vec3& a) { return a * k; }
  Vec3& operator+=(const Vec3& o) { return *this = *this + o; }
  Vec3& operator-=(const Vec3& o) { return *this = *this - o; }
  friend constexpr bool operator==(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
  friend constexpr bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }
};

template <typename S> constexpr S dot(const Vec3<S>& a, const Vec3<S>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename S> constexpr Vec3<S> cross(const Vec3<S>& a, const Vec3<S>& b) {
  return Vec3<S>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

}  // namespace strider

#endif  // STRIDER_MATH_VEC3_H
