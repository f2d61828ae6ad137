//! PlanarLeg: the 2-DOF planar (mammal) leg of seed 003 (Srinivas et al.
//! 2021): hip pitch t1, knee t2, links a1 and a2 in one vertical plane.
//! Origin on the hip axis, x forward, z up; both joints turn about -y; t1 =
//! -pi/2, t2 = 0 hangs straight down. FK eq 3, IK eqs 4-5 with `branch` the
//! sign of t2; a target off the leg plane is projected onto it
//! (docs/kinematics.md, "2-DOF planar leg").
#ifndef STRIDER_KINEMATICS_PLANAR_LEG_H
#define STRIDER_KINEMATICS_PLANAR_LEG_H

#include "two_link.h"  // with leg_ik_common.h, joints.h and ik_status.h

namespace strider {

template <typename S>
struct PlanarLeg {
  static constexpr uint8_t kDof = 2;
  using Joints = JointVector<S, kDof>;

  S a1_mm;            //!< thigh, hip axis to knee axis [mm]
  S a2_mm;            //!< shank, knee axis to foot [mm]
  KneeBranch branch;  //!< sign of the t2 that ik() returns
  JointLimits<S, kDof> limits;
  // Filled by make(); do not set by hand.
  int8_t unit_shift;         //!< working units (math/working_units.h)
  leg_ik::TwoLink<S> link;   //!< a1, a2 in working units

  //! The leg with its cached working-unit constants. Always build legs here.
  static constexpr PlanarLeg make(S a1, S a2, const JointLimits<S, kDof>& limits,
                                  KneeBranch branch = KneeBranch::kPositive) {
    const int8_t n = units::unit_shift(a1 + a2);
    return PlanarLeg{a1, a2, branch, limits, n,
                     leg_ik::TwoLink<S>::make(units::to_unit(a1, n), units::to_unit(a2, n))};
  }

  //! Seed 003 eq 3 (the position column of eq 2's A1 A2).
  Vec3<S> fk(const Joints& q) const {
    const S t12 = q[0] + q[1];
    return Vec3<S>(a1_mm * cos(q[0]) + a2_mm * cos(t12), S(0),
                   a1_mm * sin(q[0]) + a2_mm * sin(t12));
  }

  //! Seed 003 eqs 4-5 (as one atan2 each, see two_link.h), then
  //! reachability and joint limits. Writes q and reached unless kUnreachable.
  IkStatus ik(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
              const IkOptions<S>& opt = IkOptions<S>()) const {
    Joints sol;
    if (solve_fast(target, sol) && !(opt.max_clamp_mm < S(0))) {  // Fixed, strictly inside the annulus
      if (!leg_ik::limits_contain(limits, sol)) return leg_ik::finish(*this, target, sol, false, opt, q, reached);
      q = sol;  // what finish() does for an exact solve inside the limits
      reached = target;
      return IkStatus::kOk;
    }
    const S bound = a1_mm + a2_mm + opt.max_clamp_mm;
    if (!leg_ik::within(target.x, bound) || !leg_ik::within(target.z, bound) ||
        !leg_ik::within(target.y, opt.max_clamp_mm))
      return IkStatus::kUnreachable;
    bool clamped = link.solve(units::to_unit(target.x, unit_shift), units::to_unit(target.z, unit_shift),
                              branch, sol[0], sol[1]);
    if (!(target.y == S(0))) clamped = true;  // projected onto the leg plane
    return leg_ik::finish(*this, target, sol, clamped, opt, q, reached);
  }

 private:
  // The integer two-link path for a Fixed target in the leg plane.
  static bool solve_fast(const Vec3<float>&, JointVector<float, kDof>&) { return false; }
  template <typename T>
  bool solve_fast(const Vec3<T>& target, JointVector<T, kDof>& sol) const {
    int32_t h, v;
    return target.y == T(0) && leg_ik::wide::from_mm(target.x, unit_shift, h) &&
           leg_ik::wide::from_mm(target.z, unit_shift, v) && leg_ik::solve_wide(link, h, v, branch, sol[0], sol[1]);
  }
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_PLANAR_LEG_H
