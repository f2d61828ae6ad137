//! CoxaFemurTibiaLeg: the 3-DOF hexapod leg of seed 002 (Qingsheng and
//! Andika 2018), also seed 004's hip yaw / hip elevation / knee leg.
//! Origin on the coxa (yaw) axis, z up, x along the coxa at t1 = 0. t1 yaws
//! about z, t2 and t3 pitch femur and tibia, positive upward; all zero: leg
//! stretched out. IK: t1 = atan2(py, px) (eq 12), then the two-link problem
//! h = rho - l1, v = pz - d1 (eq 11); a target inside the annulus' hole is
//! tried facing away (t1 + pi). Seed 004 as this leg: docs/kinematics.md.
#ifndef STRIDER_KINEMATICS_COXA_FEMUR_TIBIA_LEG_H
#define STRIDER_KINEMATICS_COXA_FEMUR_TIBIA_LEG_H

#include "two_link.h"  // with leg_ik_common.h, joints.h and ik_status.h

namespace strider {

namespace leg_ik {

//! The integer fast path of CoxaFemurTibiaLeg<Fixed>::ik() (docs/fixed-point.md,
//! "Leg IK fast path"): a kOk solve of a target off the yaw axis, in front of
//! it and strictly inside the femur-tibia annulus; else false (and float).
//! With yaw, the target is in axes turned by *yaw about z against the leg
//! frame (a walker's offset from the mount): t1 is its angle less *yaw, and
//! only a solve inside the joint limits counts.
template <typename Leg, typename S>
bool cft_solve_fast(const Leg&, const Vec3<S>&, const S*, JointVector<S, 3>&) {
  return false;
}
template <typename Leg>
STRIDER_NOINLINE_NOCLONE bool cft_solve_fast(const Leg& leg, const Vec3<Fixed>& target, const Fixed* yaw,
                                             JointVector<Fixed, 3>& sol) {
  uint32_t x = 0, y = 0;  // |x|, |y|: only their squares are needed
  int32_t v;
  Fixed dz;
  if (!wide::from_mm_abs(target.x, leg.unit_shift, x) || !wide::from_mm_abs(target.y, leg.unit_shift, y) ||
      !wide::sub_raw(target.z, leg.d1_mm, dz) || !wide::from_mm(dz, leg.unit_shift, v) ||
      leg.coxa_unit.raw() >= (int32_t(8) << 16))
    return false;
  const uint32_t rho2 = wide::sq_sum(int32_t(x), int32_t(y));  // [Q6.24]; x, y < 2^31
  // rho >= 1/16 unit keeps ~16 significant bits; rho < 8 units fits wide units.
  if (rho2 < 0x10000UL || rho2 >= 0x40000000UL) return false;
  JointVector<Fixed, 3> q;
  int32_t t1 = detail::atan2_lean_raw(target.y.raw(), target.x.raw());  // eq 12
  if (yaw != nullptr) {
    t1 = detail::wrap_pi_once_raw(t1 - yaw->raw());
    if (t1 < leg.limits.lo[0].raw() || leg.limits.hi[0].raw() < t1) return false;
  }
  q[0] = Fixed::from_raw(t1);
  const int32_t h = wide::sqrt_sq(rho2) - wide::from_unit(leg.coxa_unit);  // eq 11, row 1
  if (!solve_wide_inline(leg.link, h, v, leg.branch, q[1], q[2])) return false;
  if (yaw != nullptr && (q[1] < leg.limits.lo[1] || leg.limits.hi[1] < q[1] || q[2] < leg.limits.lo[2] ||
                         leg.limits.hi[2] < q[2]))
    return false;
  sol[0] = q[0];
  sol[1] = q[1];
  sol[2] = q[2];
  return true;
}

}  // namespace leg_ik

template <typename S>
struct CoxaFemurTibiaLeg {
  static constexpr uint8_t kDof = 3;
  using Joints = JointVector<S, kDof>;

  S d1_mm;     //!< height of the femur axis above the leg origin [mm]
  S coxa_mm;   //!< l1, yaw axis to femur axis [mm]
  S femur_mm;  //!< l2, femur axis to tibia axis [mm]
  S tibia_mm;  //!< l3, tibia axis to foot [mm]
  KneeBranch branch;  //!< sign of the t3 that ik() returns
  JointLimits<S, kDof> limits;
  // Filled by make(); do not set by hand.
  int8_t unit_shift;        //!< working units (math/working_units.h)
  S coxa_unit;              //!< l1 in working units
  S reach_mm;               //!< l2 + l3 [mm]
  leg_ik::TwoLink<S> link;  //!< femur and tibia in working units

  //! The leg with its cached working-unit constants. Always build legs here.
  static constexpr CoxaFemurTibiaLeg make(S d1, S coxa, S femur, S tibia, const JointLimits<S, kDof>& limits,
                                          KneeBranch branch = KneeBranch::kNegative) {
    const int8_t n = units::unit_shift(femur + tibia);
    return CoxaFemurTibiaLeg{d1, coxa, femur, tibia, branch, limits, n, units::to_unit(coxa, n), femur + tibia,
                             leg_ik::TwoLink<S>::make(units::to_unit(femur, n), units::to_unit(tibia, n))};
  }

  //! Seed 002 eqs 5-7.
  Vec3<S> fk(const Joints& q) const {
    const S t23 = q[1] + q[2];
    const S reach = tibia_mm * cos(t23) + femur_mm * cos(q[1]) + coxa_mm;
    return Vec3<S>(reach * cos(q[0]), reach * sin(q[0]),
                   tibia_mm * sin(t23) + femur_mm * sin(q[1]) + d1_mm);
  }

  //! Seed 002 eqs 11-12 and the two-link solution, then reachability and
  //! joint limits. Writes q and reached unless kUnreachable.
  IkStatus ik(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
              const IkOptions<S>& opt = IkOptions<S>()) const {
    // Fixed's fast path, within ik_general()'s bounds while max_clamp >= 0.
    if (!(opt.max_clamp_mm < S(0)) && leg_ik::cft_solve_fast(*this, target, static_cast<const S*>(nullptr), q)) {
      if (!leg_ik::limits_contain(limits, q)) return leg_ik::finish(*this, target, q, false, opt, q, reached);
      leg_ik::copy_point(target, reached);  // what finish() does for an exact solve inside the limits
      return IkStatus::kOk;
    }
    return ik_general(target, q, reached, opt);
  }

 private:
  // Every case the fast path leaves, out of line (ik()'s prologue stays small).
  STRIDER_NOINLINE IkStatus ik_general(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
                                       const IkOptions<S>& opt) const {
    Joints sol;
    const S bound_z = reach_mm + opt.max_clamp_mm;
    const S bound_xy = coxa_mm + bound_z;
    if (!leg_ik::within(target.x, bound_xy) || !leg_ik::within(target.y, bound_xy) ||
        !leg_ik::within(target.z - d1_mm, bound_z))
      return IkStatus::kUnreachable;
    const S x = units::to_unit(target.x, unit_shift);
    const S y = units::to_unit(target.y, unit_shift);
    const S v = units::to_unit(target.z - d1_mm, unit_shift);  // eq 11, row 2
    S rho = S(0);  // [unit]
    if (leg_ik::is_zero(target.x) && leg_ik::is_zero(target.y)) {
      sol[0] = leg_ik::free_angle(limits, 0, S(0));  // on the yaw axis
    } else {
      sol[0] = atan2(target.y, target.x);  // eq 12
      const S rho2 = x * x + y * y;
      // Near the axis a Fixed square loses the digits that matter: units::norm.
      rho = leg_ik::tiny_square(rho2) ? units::to_unit(units::norm(target.x, target.y, S()), unit_shift) : sqrt(rho2);
    }
    S h = rho - coxa_unit;  // eq 11, row 1
    S d2 = h * h + v * v;
    if (leg_ik::lt(d2, link.inner2) && leg_ik::lt(S(0), coxa_unit) && leg_ik::lt(S(0), rho)) {
      const S h_far = -rho - coxa_unit;
      const S d2_far = h_far * h_far + v * v;
      if (far_side_is_nearer(d2, d2_far)) {
        h = h_far;
        d2 = d2_far;
        sol[0] = wrap_pi(sol[0] + pi<S>());
      }
    }
    const bool clamped = link.solve(h, v, d2, branch, sol[1], sol[2]);
    return leg_ik::finish(*this, target, sol, clamped, opt, q, reached);
  }

  // For a target inside the annulus' hole: is facing away nearer? [unit^2]
  bool far_side_is_nearer(S d2_near, S d2_far) const {
    if (!(d2_far > link.outer2)) return true;
    const S miss_near = abs(link.a1 - link.a2) - sqrt(d2_near);
    const S miss_far = sqrt(d2_far) - (link.a1 + link.a2);
    return miss_far < miss_near;
  }
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_COXA_FEMUR_TIBIA_LEG_H
