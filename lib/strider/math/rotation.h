//! Rotation matrices about the coordinate axes (seed 001 eqs 5.1-5.3) and
//! body rotations from roll, pitch and yaw in any of the six Tait-Bryan
//! orders (seed 001 algorithm 2).
//!
//! Angles: roll about x, pitch about y, yaw about z [rad], right-handed.
//!
//! RotationOrder names the factors of the product left to right:
//!   kXYZ: R = Rx(roll) * Ry(pitch) * Rz(yaw)
//!   kZYX: R = Rz(yaw) * Ry(pitch) * Rx(roll)   (Strider's default)
//! and likewise for the other four. Applied to a vector, the rightmost factor
//! acts first, so kZYX rolls first, then pitches, then yaws about the fixed
//! axes; read from the left it is the intrinsic yaw-pitch-roll sequence.
//!
//! Seed 001's listing keys its table by the application order instead, i.e.
//! its key is the Strider name reversed ('zyx' lists [rotX, rotY, rotZ] =
//! kXYZ). The listing repeats the key 'xzy' three times and has a typo 'yzy'
//! (its matrices make it 'yzx'), and it lacks its own default 'xyz' =
//! Rz Ry Rx. Strider takes the six distinct orders; kZYX is that default.
#ifndef STRIDER_MATH_ROTATION_H
#define STRIDER_MATH_ROTATION_H

#include "mat3.h"

namespace strider {

//! The order of the three elementary rotations, named left to right as they
//! are multiplied (see the file comment).
enum class RotationOrder : uint8_t { kXYZ, kXZY, kYXZ, kYZX, kZXY, kZYX };

//! Rotation about x from its cosine and sine (seed 001 eq 5.1).
template <typename S>
constexpr Mat3<S> rot_x_cs(S c, S s) {
  return Mat3<S>{{{S(1), S(0), S(0)}, {S(0), c, -s}, {S(0), s, c}}};
}
//! Rotation about y from its cosine and sine (seed 001 eq 5.2).
template <typename S>
constexpr Mat3<S> rot_y_cs(S c, S s) {
  return Mat3<S>{{{c, S(0), s}, {S(0), S(1), S(0)}, {-s, S(0), c}}};
}
//! Rotation about z from its cosine and sine (seed 001 eq 5.3).
template <typename S>
constexpr Mat3<S> rot_z_cs(S c, S s) {
  return Mat3<S>{{{c, -s, S(0)}, {s, c, S(0)}, {S(0), S(0), S(1)}}};
}

//! Rotation by roll about x [rad] (seed 001 eq 5.1).
template <typename S>
Mat3<S> rot_x(S roll) { return rot_x_cs(cos(roll), sin(roll)); }
//! Rotation by pitch about y [rad] (seed 001 eq 5.2).
template <typename S>
Mat3<S> rot_y(S pitch) { return rot_y_cs(cos(pitch), sin(pitch)); }
//! Rotation by yaw about z [rad] (seed 001 eq 5.3).
template <typename S>
Mat3<S> rot_z(S yaw) { return rot_z_cs(cos(yaw), sin(yaw)); }

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

//! The three elementary matrices and their product (float, double: the
//! operators' own zero terms and their signs kept).
template <typename S>
Mat3<S> product(S roll, S pitch, S yaw, RotationOrder order) {
  const Mat3<S> x = rot_x(roll);
  const Mat3<S> y = rot_y(pitch);
  const Mat3<S> z = rot_z(yaw);
  // The factors left to right; one product for all orders.
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

//! Fixed: the same product without the zero and unit terms, which are
//! exact in Fixed (a product by 0 or 1 is exact, a sum with 0 too, and a
//! sum of two terms does not depend on their order), so the bits are those
//! of product(): from the identity, each factor turns two columns of the
//! product so far in place (12 products a factor, not 27, and one matrix
//! on the stack instead of five). test/chain's
//! RotationRpy.FixedIsTheMatrixProduct checks it bit for bit.
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
