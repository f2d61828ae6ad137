//! SprawlLeg: the 2-DOF sprawling leg of seed 000 (Atique et al. 2018).
//!
//! Frame: DH frame 0 of seed 000, origin on the hip yaw axis, z up. Joint t1
//! yaws the leg about z (eq 7), joint t2 pitches the shank (eq 8); the thigh
//! a1 stays horizontal. t1 = t2 = 0 puts the foot at (a1 + a2, 0, 0).
//! The foot can only reach the torus swept by the knee circle of radius a1
//! and the shank a2. Eqs 7-8 face the target (t1 = atan2(y, x)) and give the
//! nearest point of the near half, |sqrt((rho - a1)^2 + z^2) - a2| away (rho =
//! sqrt(x^2 + y^2)); a target inside that circle can be nearer the far half
//! (t1 + pi, knee folded back past the yaw axis: a2 > a1 reaches under the
//! hip), so both are tried and the nearer wins. Any target off the surface is
//! clamped onto it. On the yaw axis (rho = 0) t1 is free and set to 0; on the
//! knee circle (rho = a1, z = 0) the shank direction is undefined and the
//! target is unreachable.
//!
//! Squares are taken in working units (leg_ik_common.h) chosen per call, so
//! the plain aggregate {a1_mm, a2_mm, limits} needs no cached constants.
#ifndef STRIDER_KINEMATICS_SPRAWL_LEG_H
#define STRIDER_KINEMATICS_SPRAWL_LEG_H

#include "../math/vec3.h"
#include "ik_status.h"
#include "joints.h"
#include "leg_ik_common.h"

namespace strider {

template <typename S>
struct SprawlLeg {
  static constexpr uint8_t kDof = 2;
  using Joints = JointVector<S, kDof>;

  S a1_mm;  //!< thigh, hip yaw axis to knee axis [mm]
  S a2_mm;  //!< leg (shank), knee axis to foot [mm]
  JointLimits<S, kDof> limits;

  //! Same as the aggregate {a1, a2, limits}; for symmetry with the other legs.
  static constexpr SprawlLeg make(S a1, S a2, const JointLimits<S, kDof>& limits) {
    return SprawlLeg{a1, a2, limits};
  }

  //! Seed 000 eqs 4-6.
  Vec3<S> fk(const Joints& q) const {
    const S reach = a1_mm + a2_mm * cos(q[1]);
    return Vec3<S>(reach * cos(q[0]), reach * sin(q[0]), a2_mm * sin(q[1]));
  }

  //! Seed 000 eqs 7-8, then reachability and joint limits. Writes q and
  //! reached unless the status is kUnreachable.
  IkStatus ik(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
              const IkOptions<S>& opt = IkOptions<S>()) const {
    const S bound_xy = a1_mm + a2_mm + opt.max_clamp_mm;
    if (!leg_ik::within(target.x, bound_xy) || !leg_ik::within(target.y, bound_xy) ||
        !leg_ik::within(target.z, a2_mm + opt.max_clamp_mm))
      return IkStatus::kUnreachable;  // farther than max_clamp from the torus
    // Working units per call (leg_ik_common.h), so the aggregate needs no cache.
    const int8_t n = leg_ik::unit_shift(a1_mm + a2_mm);
    const S x = leg_ik::to_unit(target.x, n), y = leg_ik::to_unit(target.y, n), z = leg_ik::to_unit(target.z, n);
    const S a1 = leg_ik::to_unit(a1_mm, n), a2 = leg_ik::to_unit(a2_mm, n);
    Joints sol;
    S rho = S(0);
    if (target.x == S(0) && target.y == S(0)) {
      sol[0] = leg_ik::free_angle(limits, 0, S(0));  // on the yaw axis
    } else {
      sol[0] = atan2(target.y, target.x);  // eq 7
      const S rho2 = x * x + y * y;
      // Near the axis a Fixed square loses the digits that matter: hypot.
      rho = leg_ik::tiny_square(rho2) ? leg_ik::to_unit(leg_ik::hypot(target.x, target.y), n) : sqrt(rho2);
    }
    S dr = rho - a1;
    if (dr == S(0) && z == S(0)) return IkStatus::kUnreachable;  // on the knee circle
    const S knee2 = dr * dr + z * z;
    S miss = abs(sqrt(knee2) - a2);
    if (knee2 < a2 * a2 && rho > S(0)) {
      const S dr_far = -rho - a1;  // facing away: the target is behind the yaw axis
      const S miss_far = abs(sqrt(dr_far * dr_far + z * z) - a2);
      if (miss_far < miss) {
        dr = dr_far;
        miss = miss_far;
        sol[0] = wrap_pi(sol[0] + pi<S>());
      }
    }
    S zl = z;
    leg_ik::lift_pair(dr, zl);  // keeps the digits of a foot near the knee circle
    sol[1] = atan2(zl, dr);  // eq 8
    miss = leg_ik::from_unit(miss, n);
    IkStatus status = leg_ik::miss_status(miss, opt);
    if (status == IkStatus::kUnreachable) return status;
    Vec3<S> at = fk(sol);
    status = leg_ik::apply_limits(*this, target, sol, at, status, opt);
    q = sol;
    reached = at;
    return status;
  }
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_SPRAWL_LEG_H
