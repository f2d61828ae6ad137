//! Body pose kinematics: move and tilt the body while the feet stay on the
//! ground (seed 001 section 2.3 with algorithm 2; seed 000 eqs 9-11 are the
//! translation-only case; frames: docs/kinematics.md).
#ifndef STRIDER_KINEMATICS_BODY_POSE_H
#define STRIDER_KINEMATICS_BODY_POSE_H

#include "../math/rotation.h"
#include "../math/transform.h"
#include "leg_mount.h"

namespace strider {

template <typename S>
struct BodyPose {
  Vec3<S> translation_mm;  //!< body centre in the stance frame [mm]
  S roll_rad;              //!< about x [rad]
  S pitch_rad;             //!< about y [rad]
  S yaw_rad;               //!< about z [rad]
  RotationOrder order;     //!< how R is composed (math/rotation.h)

  static constexpr BodyPose zero() {
    return BodyPose{Vec3<S>(), S(0), S(0), S(0), RotationOrder::kZYX};
  }
  static constexpr BodyPose make(const Vec3<S>& t, S roll, S pitch, S yaw,
                                 RotationOrder order = RotationOrder::kZYX) {
    return BodyPose{t, roll, pitch, yaw, order};
  }
};

//! The moved body frame in the stance frame: rotation R, translation t.
template <typename S>
Transform<S> body_transform(const BodyPose<S>& pose) {
  return Transform<S>{rotation_rpy(pose.roll_rad, pose.pitch_rad, pose.yaw_rad, pose.order),
                      pose.translation_mm};
}

//! A stance-frame foot in the moved body frame: p' = R^T (p - t) [mm].
template <typename S>
Vec3<S> foot_in_body(const Transform<S>& body, const Vec3<S>& foot_stance_mm) {
  return body.apply_inverse(foot_stance_mm);
}

//! Each of `count` stance feet in the moved body frame (optional feet_body_mm)
//! and in its leg frame through mounts[i] [mm]; robot-sized bodies keep Fixed
//! products far from overflow.
template <typename S>
void body_pose_feet(const BodyPose<S>& pose, const Vec3<S>* feet_stance_mm, const LegMount<S>* mounts,
                    uint8_t count, Vec3<S>* feet_leg_mm, Vec3<S>* feet_body_mm = nullptr) {
  const Transform<S> body = body_transform(pose);
  for (uint8_t i = 0; i < count; ++i) {
    const Vec3<S> p = foot_in_body(body, feet_stance_mm[i]);
    if (feet_body_mm != nullptr) feet_body_mm[i] = p;
    feet_leg_mm[i] = mounts[i].body_to_leg(p);
  }
}

}  // namespace strider

#endif  // STRIDER_KINEMATICS_BODY_POSE_H
