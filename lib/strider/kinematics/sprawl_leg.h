//! SprawlLeg: the 2-DOF sprawling leg of seed 000 (Atique et al. 2018).
//! Origin on the hip yaw axis, z up; t1 yaws the leg about z (eq 7), t2
//! pitches the shank (eq 8), the thigh a1 stays horizontal; t1 = t2 = 0 puts
//! the foot at (a1 + a2, 0, 0). A target off the foot's torus is clamped onto
//! it, near and far half (t1 + pi) both tried (docs/kinematics.md, "2-DOF
//! sprawling leg"); working units are chosen per call, so nothing is cached.
#ifndef STRIDER_KINEMATICS_SPRAWL_LEG_H
#define STRIDER_KINEMATICS_SPRAWL_LEG_H

#include "two_link.h"  // with leg_ik_common.h, joints.h and ik_status.h

namespace strider {

namespace leg_ik {

//! For a target inside the knee circle (miss < 0) [wide units]: whether
//! the near half of the torus is at least as near as the far half (t1 + pi);
//! false also when the far knee distance does not fit wide units.
STRIDER_NOINLINE inline bool sprawl_near_half_wins(int32_t rho, int32_t a1, int32_t a2, int32_t z, int32_t miss) {
  const uint32_t far = uint32_t(rho) + uint32_t(a1);
  if (far >= 0x80000000UL) return false;
  const uint32_t far2 = wide::sq(int32_t(far)) + wide::sq(z);
  if (far2 >= 0x40000000UL) return false;
  const int32_t miss_far = wide::sqrt_sq_call(far2) - a2;
  return !(miss_far < 0 ? -miss_far < -miss : miss_far < -miss);
}

//! The integer fast path of SprawlLeg<Fixed>::ik() (docs/fixed-point.md,
//! "Leg IK fast path"): the joints and the miss distance [mm], or false
//! (float, and every case it leaves) for the general path.
template <typename Leg, typename S>
bool sprawl_solve_fast(const Leg&, const Vec3<S>&, JointVector<S, 2>&, S&) {
  return false;
}
template <typename Leg>
STRIDER_ALWAYS_INLINE bool sprawl_solve_fast(const Leg& leg, const Vec3<Fixed>& target, JointVector<Fixed, 2>& sol,
                                             Fixed& miss_mm) {
  // Lengths of 2^14 mm and more could overflow their raw sum.
  const uint32_t ra1 = uint32_t(leg.a1_mm.raw()), ra2 = uint32_t(leg.a2_mm.raw());
  if (ra1 >= 0x40000000UL || ra2 >= 0x40000000UL) return false;
  const int8_t n = units::unit_shift(Fixed::from_raw(int32_t(ra1 + ra2)));
  int32_t x, y, z, a1, a2;
  if (!wide::from_mm_call(target.x, n, x) || !wide::from_mm_call(target.y, n, y) ||
      !wide::from_mm_call(target.z, n, z) || !wide::from_mm_call(leg.a1_mm, n, a1) ||
      !wide::from_mm_call(leg.a2_mm, n, a2))
    return false;
  const uint32_t rho2 = wide::sq(x) + wide::sq(y);  // [Q6.24]
  if (rho2 < 0x10000UL || rho2 >= 0x40000000UL) return false;
  const int32_t rho = wide::sqrt_sq_call(rho2);
  const int32_t dr = rho - a1;  // both in [0, 8) units
  const uint32_t knee2 = wide::sq(dr) + wide::sq(z);
  if (knee2 < 0x10000UL || knee2 >= 0x40000000UL) return false;  // on the knee circle, or far out
  const int32_t knee = wide::sqrt_sq_call(knee2);
  const int32_t miss = knee - a2;  // > 0: outside the torus
  if (miss < 0 && !sprawl_near_half_wins(rho, a1, a2, z, miss)) return false;
  if (!wide::to_mm(detail::abs_u32(miss), n, miss_mm)) return false;
  sol[0] = Fixed::from_raw(detail::atan2_lean_call(target.y.raw(), target.x.raw()));  // eq 7
  sol[1] = Fixed::from_raw(detail::atan2_lean_call(z, dr));                           // eq 8
  return true;
}

}  // namespace leg_ik

template <typename S>
struct SprawlLeg {
  static constexpr uint8_t kDof = 2;
  using Joints = JointVector<S, kDof>;

  S a1_mm;  //!< thigh, hip yaw axis to knee axis [mm]
  S a2_mm;  //!< leg (shank), knee axis to foot [mm]
  JointLimits<S, kDof> limits;

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
    {
      Joints sol;
      S miss;
      if (leg_ik::sprawl_solve_fast(*this, target, sol, miss)) {  // Fixed only
        const IkStatus status = leg_ik::miss_status(miss, opt);
        if (status != IkStatus::kUnreachable) return finish_at_fk(target, sol, status, opt, q, reached);
      }
    }
    return ik_general(target, q, reached, opt);
  }

 private:
  // The end of both paths: the point reached is fk(sol), then the limits.
  STRIDER_NOINLINE IkStatus finish_at_fk(const Vec3<S>& target, Joints& sol, IkStatus status, const IkOptions<S>& opt,
                                         Joints& q, Vec3<S>& reached) const {
    Vec3<S> at = fk(sol);
    status = leg_ik::apply_limits(*this, target, sol, at, status, opt);
    q = sol;
    reached = at;
    return status;
  }

  // Every case the fast path leaves, out of line (ik()'s prologue stays small).
  STRIDER_NOINLINE IkStatus ik_general(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
                                       const IkOptions<S>& opt) const {
    const S bound_xy = a1_mm + a2_mm + opt.max_clamp_mm;
    if (!leg_ik::within(target.x, bound_xy) || !leg_ik::within(target.y, bound_xy) ||
        !leg_ik::within(target.z, a2_mm + opt.max_clamp_mm))
      return IkStatus::kUnreachable;  // farther than max_clamp from the torus
    const int8_t n = units::unit_shift(a1_mm + a2_mm);
    const S x = units::to_unit(target.x, n), y = units::to_unit(target.y, n), z = units::to_unit(target.z, n);
    const S a1 = units::to_unit(a1_mm, n), a2 = units::to_unit(a2_mm, n);
    Joints sol;
    S rho = S(0);
    if (target.x == S(0) && target.y == S(0)) {
      sol[0] = leg_ik::free_angle(limits, 0, S(0));  // on the yaw axis
    } else {
      sol[0] = atan2(target.y, target.x);  // eq 7
      const S rho2 = x * x + y * y;
      // Near the axis a Fixed square loses the digits that matter: units::norm.
      rho = leg_ik::tiny_square(rho2) ? units::to_unit(units::norm(target.x, target.y, S()), n) : sqrt(rho2);
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
    miss = units::from_unit(miss, n);
    IkStatus status = leg_ik::miss_status(miss, opt);
    if (status == IkStatus::kUnreachable) return status;
    return finish_at_fk(target, sol, status, opt, q, reached);
  }
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_SPRAWL_LEG_H
