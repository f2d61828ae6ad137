//! LegMount: where a leg frame sits on the body (body frame: origin at the
//! body centre, x forward, y left, z up). Seed 000 eqs 9-11 are the case
//! yaw = 0: x = xc - x0, y = yc - y0, z = zc.
#ifndef STRIDER_KINEMATICS_LEG_MOUNT_H
#define STRIDER_KINEMATICS_LEG_MOUNT_H

#include "../math/vec3.h"

namespace strider {

template <typename S>
struct LegMount {
  Vec3<S> origin_mm;  //!< leg frame origin in the body frame [mm]
  S yaw_rad;          //!< rotation of the leg frame about body z [rad]
  S cos_yaw;          //!< cached cos(yaw_rad)
  S sin_yaw;          //!< cached sin(yaw_rad)

  static LegMount make(const Vec3<S>& origin, S yaw) {
    return LegMount{origin, yaw, cos(yaw), sin(yaw)};
  }

  //! A body-frame point in the leg frame (seed 000 eqs 9-11, plus yaw).
  Vec3<S> body_to_leg(const Vec3<S>& p) const {
    const Vec3<S> d = p - origin_mm;
    return Vec3<S>(cos_yaw * d.x + sin_yaw * d.y, -sin_yaw * d.x + cos_yaw * d.y, d.z);
  }
  //! A leg-frame point in the body frame.
  Vec3<S> leg_to_body(const Vec3<S>& p) const {
    return Vec3<S>(cos_yaw * p.x - sin_yaw * p.y + origin_mm.x, sin_yaw * p.x + cos_yaw * p.y + origin_mm.y,
                   p.z + origin_mm.z);
  }
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_LEG_MOUNT_H
