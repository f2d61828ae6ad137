//! Transform: a rigid transform (rotation, then translation) of scalar S;
//! the 3x4 upper part of a homogeneous matrix.
#ifndef STRIDER_MATH_TRANSFORM_H
#define STRIDER_MATH_TRANSFORM_H

#include "mat3.h"

namespace strider {

template <typename S>
struct Transform {
  Mat3<S> rotation;
  Vec3<S> translation;  //!< [mm]

  static constexpr Transform identity() { return Transform{Mat3<S>::identity(), Vec3<S>()}; }

  //! Maps a point of the child frame into the parent frame.
  constexpr Vec3<S> apply(const Vec3<S>& p) const { return rotation * p + translation; }
  //! Maps a point of the parent frame into the child frame.
  Vec3<S> apply_inverse(const Vec3<S>& p) const { return rotation.transposed() * (p - translation); }

  //! this * child: first child, then this.
  friend Transform operator*(const Transform& a, const Transform& b) {
    return Transform{a.rotation * b.rotation, a.rotation * b.translation + a.translation};
  }
  Transform inverse() const {
    const Mat3<S> rt = rotation.transposed();
    return Transform{rt, -(rt * translation)};
  }
};

}  // namespace strider

#endif  // STRIDER_MATH_TRANSFORM_H
