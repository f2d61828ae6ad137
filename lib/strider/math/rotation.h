//! Rotation matrices about the coordinate axes (seed 001 eqs 5.1-5.3) and
//! body rotations from roll, pitch and yaw [rad] in any of the six
//! Tait-Bryan orders (seed 001 algorithm 2; docs/kinematics.md, "Frames").
#ifndef STRIDER_MATH_ROTATION_H
#define STRIDER_MATH_ROTATION_H

#include "mat3.h"

namespace strider {

//! The order of the three elementary rotations, left to right as multiplied:
//! kZYX, the default, is R = Rz(yaw) Ry(pitch) Rx(roll).
enum class RotationOrder : uint8_t { kXYZ, kXZY, kYXZ, kYZX, kZXY, kZYX };

//! Rotations about x, y and z by an angle [rad] (seed 001 eqs 5.1-5.3).
template <typename S>
Mat3<S> rot_x(S roll) {
  const S c = cos(roll), s = sin(roll);
  return Mat3<S>{{{S(1), S(0), S(0)}, {S(0), c, -s}, {S(0), s, c}}};
}
template <typename S>
Mat3<S> rot_y(S pitch) {
  const S c = cos(pitch), s = sin(pitch);
  return Mat3<S>{{{c, S(0), s}, {S(0), S(1), S(0)}, {-s, S(0), c}}};
}
template <typename S>
Mat3<S> rot_z(S yaw) {
  const S c = cos(yaw), s = sin(yaw);
  return Mat3<S>{{{c, -s, S(0)}, {s, c, S(0)}, {S(0), S(0), S(1)}}};
}

namespace rotation_detail {

//! The factors of an order, left to right, as axes (0 x, 1 y, 2 z) in two
//! bits each, the leftmost lowest.
constexpr uint8_t factors(RotationOrder order) {
  return order == RotationOrder::kXYZ   ? uint8_t(0 | 1 << 2 | 2 << 4)
         : order == RotationOrder::kXZY ? uint8_t(0 | 2 << 2 | 1 << 4)
         : order == RotationOrder::kYXZ ? uint8_t(1 | 0 << 2 | 2 << 4)
         : order == RotationOrder::kYZX ? uint8_t(1 | 2 << 2 | 0 << 4)
         : order == RotationOrder::kZXY ? uint8_t(2 | 0 << 2 | 1 << 4)
                                        : uint8_t(2 | 1 << 2 | 0 << 4);
}

//! The three elementary matrices and their product (float, double).
template <typename S>
Mat3<S> product(S roll, S pitch, S yaw, RotationOrder order) {
  const Mat3<S> x = rot_x(roll);
  const Mat3<S> y = rot_y(pitch);
  const Mat3<S> z = rot_z(yaw);
  const Mat3<S>* a = &z;
  const Mat3<S>* b = &y;
  const Mat3<S>* c = &x;
  switch (order) {
    case RotationOrder::kXYZ: a = &x, b = &y, c = &z; break;
    case RotationOrder::kXZY: a = &x, b = &z, c = &y; break;
    case RotationOrder::kYXZ: a = &y, b = &x, c = &z; break;
    case RotationOrder::kYZX: a = &y, b = &z, c = &x; break;
    case RotationOrder::kZXY: a = &z, b = &x, c = &y; break;
    case RotationOrder::kZYX: break;
  }
  return *a * *b * *c;
}

//! Fixed: the same bits without the exact zero and unit terms: each factor
//! turns two columns of the product so far in place (12 products, not 27).
inline Mat3<Fixed> product(Fixed roll, Fixed pitch, Fixed yaw, RotationOrder order) {
  const Fixed angle[3] = {roll, pitch, yaw};
  uint8_t axes = factors(order);
  Mat3<Fixed> m;
  Fixed* e = &m.m[0][0];
  for (uint8_t k = 0; k < 9; ++k) e[k] = Fixed::from_raw(k % 4 == 0 ? int32_t(1) << 16 : 0);
  for (uint8_t f = 0; f < 3; ++f, axes = uint8_t(axes >> 2)) {
    const uint8_t axis = axes & 3;
    // The columns this factor turns: the axes after its own, cyclically.
    const uint8_t p = axis == 2 ? 0 : uint8_t(axis + 1);
    const uint8_t q = p == 2 ? 0 : uint8_t(p + 1);
    const Fixed c = cos(angle[axis]), s = sin(angle[axis]), ns = -s;
    Fixed* a = e + p;
    Fixed* b = e + q;
    for (uint8_t i = 0; i < 3; ++i, a += 3, b += 3) {
      const Fixed mp = *a, mq = *b;
      *a = mp * c + mq * s;
      *b = mp * ns + mq * c;
    }
  }
  return m;
}

}  // namespace rotation_detail

//! The rotation for roll, pitch, yaw [rad] composed in `order` (seed 001
//! algorithm 2 with the six distinct orders). Entries stay within [-1, 1],
//! so the product is safe in Fixed.
template <typename S>
Mat3<S> rotation_rpy(S roll, S pitch, S yaw, RotationOrder order = RotationOrder::kZYX) {
  return rotation_detail::product(roll, pitch, yaw, order);
}

//! Strider's name of an order ("xyz" .. "zyx"), left to right as multiplied.
inline const char* to_string(RotationOrder order) {
  switch (order) {
    case RotationOrder::kXYZ: return "xyz";
    case RotationOrder::kXZY: return "xzy";
    case RotationOrder::kYXZ: return "yxz";
    case RotationOrder::kYZX: return "yzx";
    case RotationOrder::kZXY: return "zxy";
    case RotationOrder::kZYX: return "zyx";
  }
  return "zyx";
}

//! Parses Strider's name of an order (three lower-case letters); returns
//! false and leaves `order` alone for anything else.
inline bool parse_rotation_order(const char* text, RotationOrder& order) {
  const RotationOrder all[] = {RotationOrder::kXYZ, RotationOrder::kXZY, RotationOrder::kYXZ,
                               RotationOrder::kYZX, RotationOrder::kZXY, RotationOrder::kZYX};
  if (text == nullptr) return false;
  for (uint8_t i = 0; i < 6; ++i) {
    const char* name = to_string(all[i]);
    if (text[0] == name[0] && text[1] == name[1] && text[2] == name[2] && text[3] == '\0') {
      order = all[i];
      return true;
    }
  }
  return false;
}

}  // namespace strider

#endif  // STRIDER_MATH_ROTATION_H
