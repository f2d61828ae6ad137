//! SprawlLeg: the 2-DOF sprawling leg of seed 000 (Atique et al. 2018).
//!
//! Frame: DH frame 0 of seed 000, origin on the hip yaw axis, z up. Joint t1
//! yaws the leg about z (eq 7), joint t2 pitches the shank (eq 8); the thigh
//! a1 stays horizontal. t1 = t2 = 0 puts the foot at (a1 + a2, 0, 0).
//! The foot can only reach the torus (rho - a1)^2 + z^2 = a2^2 (rho = sqrt(x^2
//! + y^2)): eqs 7-8 give the angles of the nearest point of that surface, so
//! any target off the surface is clamped onto it.
#ifndef STRIDER_KINEMATICS_SPRAWL_LEG_H
#define STRIDER_KINEMATICS_SPRAWL_LEG_H

#include "../math/vec3.h"
#include "ik_status.h"
#include "joints.h"

namespace strider {

template <typename S>
struct SprawlLeg {
  static constexpr uint8_t kDof = 2;
  using Joints = JointVector<S, kDof>;

  S a1_mm;  //!< thigh, hip yaw axis to knee axis [mm]
  S a2_mm;  //!< leg (shank), knee axis to foot [mm]
  JointLimits<S, kDof> limits;

  //! Seed 000 eqs 4-6.
  Vec3<S> fk(const Joints& q) const {
    const S reach = a1_mm + a2_mm * cos(q[1]);
    return Vec3<S>(reach * cos(q[0]), reach * sin(q[0]), a2_mm * sin(q[1]));
  }

  //! Seed 000 eqs 7-8, then reachability and joint limits. Writes q and
  //! reached unless the status is kUnreachable.
  IkStatus ik(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
              const IkOptions<S>& opt = IkOptions<S>()) const {
    const S rho = sqrt(target.x * target.x + target.y * target.y);
    const S dr = rho - a1_mm;
    // On the knee circle the shank direction is undefined.
    if (abs(dr) + abs(target.z) <= ScalarTraits<S>::ik_tolerance_mm()) return IkStatus::kUnreachable;
    Joints sol;
    // On the yaw axis any t1 is a nearest point; keep the leg straight out.
    sol[0] = rho > S(0) ? atan2(target.y, target.x) : S(0);  // eq 7
    sol[1] = atan2(target.z, dr);                              // eq 8
    IkStatus status = IkStatus::kOk;
    const S miss = abs(sqrt(dr * dr + target.z * target.z) - a2_mm);
    if (miss > opt.max_clamp_mm) return IkStatus::kUnreachable;
    if (miss > opt.tolerance_mm) status = IkStatus::kClamped;
    if (limits.clamp_into(sol)) status = worst(status, IkStatus::kJointLimit);
    q = sol;
    reached = fk(sol);
    return status;
  }
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_SPRAWL_LEG_H
