//! AbductionLeg: the 3-DOF dog leg of seed 001 (Shahriar): abduction t1,
//! hip t2, knee t3; abduction link La at 90 deg to the femur Lb, tibia Lc.
//! Origin on the abduction axis x (forward), y left, z up; t1 in [0, 2 pi)
//! is the angle of La about +x from +y. Conventions, FK, IK and where Strider
//! departs from the seed: docs/kinematics.md, "3-DOF abduction leg".
#ifndef STRIDER_KINEMATICS_ABDUCTION_LEG_H
#define STRIDER_KINEMATICS_ABDUCTION_LEG_H

#include "two_link.h"  // with leg_ik_common.h, joints.h and ik_status.h

namespace strider {

//! Which side of the body an abduction leg hangs on (mirrors the leg plane).
enum class LegSide : uint8_t { kLeft = 0, kRight = 1 };

namespace leg_ik {

//! The integer fast path of AbductionLeg<Fixed>::ik() (docs/fixed-point.md,
//! "Leg IK fast path"): sol for a foot at least 1/16 working unit outside the
//! abduction cylinder and strictly inside the annulus of its leg plane, else
//! false (and float).
template <typename Leg, typename S>
bool abduction_solve_fast(const Leg&, const Vec3<S>&, JointVector<S, 3>&) {
  return false;
}
template <typename Leg>
STRIDER_ALWAYS_INLINE bool abduction_solve_fast(const Leg& leg, const Vec3<Fixed>& target, JointVector<Fixed, 3>& sol) {
  int32_t x, y, z;
  // La in fine units (2^3 finer than working units) below 8 fine units.
  if (!wide::from_mm(target.x, leg.unit_shift, x) || !wide::from_mm(target.y, leg.unit_shift, y) ||
      !wide::from_mm(target.z, leg.unit_shift, z) || uint32_t(leg.la_fine.raw()) >= (uint32_t(8) << 16))
    return false;
  // A^2 and La^2 in Q6.24 (la_fine_sq is in fine units^2: 2^6 finer).
  const uint32_t a2 = wide::sq(y) + wide::sq(z);
  const uint32_t la2 = uint32_t(leg.la_fine_sq.raw()) << 2;
  // p^2 = A^2 - La^2 keeps ~16 significant bits from 1/256 unit^2 (p = 1/16
  // unit) up; p < 8 units fits wide units.
  if (a2 <= la2) return false;
  const uint32_t p2 = a2 - la2;
  if (p2 < 0x10000UL || p2 >= 0x40000000UL) return false;
  const int32_t p = wide::sqrt_sq_call(p2);
  Fixed t2, t3;
  if (!solve_wide(leg.link, -x, p, KneeBranch::kPositive, t2, t3)) return false;  // back = -x, down = p
  // (y, z) turned by +alpha3 (left) or -alpha3 (right), alpha3 = atan2(p, La)
  // in [0, pi/2]; then algorithm 1's range [0, 2 pi).
  const int32_t la = wide::from_unit(leg.la_fine) >> 3;
  const int32_t turn = detail::atan2_lean_call(p, la);
  int32_t t1 = detail::atan2_lean_call(z, y);
  t1 = leg.side == LegSide::kLeft ? t1 + turn : t1 - turn;
  const int32_t two_pi_raw = two_pi<Fixed>().raw();
  if (t1 < 0) t1 += two_pi_raw;
  if (t1 >= two_pi_raw) t1 -= two_pi_raw;
  sol[0] = Fixed::from_raw(t1);
  sol[1] = t2;
  sol[2] = t3;
  return true;
}

}  // namespace leg_ik

template <typename S>
struct AbductionLeg {
  static constexpr uint8_t kDof = 3;
  using Joints = JointVector<S, kDof>;

  S la_mm;  //!< La, abduction axis to the hip axis, perpendicular to both [mm]
  S lb_mm;  //!< Lb, femur: hip axis to knee axis [mm]
  S lc_mm;  //!< Lc, tibia: knee axis to foot [mm]
  LegSide side;
  JointLimits<S, kDof> limits;
  // Filled by make(); do not set by hand.
  int8_t unit_shift;        //!< working units (math/working_units.h)
  S la_fine;                //!< La in fine units (working units * 8)
  S la_fine_sq;             //!< La^2 in fine units
  leg_ik::TwoLink<S> link;  //!< femur and tibia in working units

  //! Fine units, 8x finer than working units, for A^2 - La^2, which cancels
  //! when the foot is level with the hip.
  static constexpr int8_t kFineBits = 3;

  //! The leg with its cached working-unit constants. Always build legs here.
  static constexpr AbductionLeg make(S la, S lb, S lc, const JointLimits<S, kDof>& limits,
                                     LegSide side = LegSide::kLeft) {
    const int8_t n = units::unit_shift(lb + lc);
    const S la_f = units::to_unit(la, int8_t(n - kFineBits));
    return AbductionLeg{la, lb, lc, side, limits, n, la_f, la_f * la_f,
                        leg_ik::TwoLink<S>::make(units::to_unit(lb, n), units::to_unit(lc, n))};
  }

  //! t1 of the standing leg: La horizontal and pointing outward [rad].
  constexpr S standing_t1() const { return side == LegSide::kLeft ? S(0) : pi<S>(); }

  //! Foot = La u + xp x + d w (docs/kinematics.md).
  Vec3<S> fk(const Joints& q) const {
    const S c1 = cos(q[0]), s1 = sin(q[0]);
    const S t23 = q[1] + q[2];
    const S xp = -(lb_mm * cos(q[1]) + lc_mm * cos(t23));
    S d = lb_mm * sin(q[1]) + lc_mm * sin(t23);
    if (side == LegSide::kRight) d = -d;  // w_right = -w_left
    return Vec3<S>(xp, la_mm * c1 + d * s1, la_mm * s1 - d * c1);
  }

  //! Seed 001 eqs 4.1-4.21 and algorithm 1 (docs/kinematics.md), then
  //! reachability and joint limits. Writes q and reached unless kUnreachable.
  IkStatus ik(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
              const IkOptions<S>& opt = IkOptions<S>()) const {
    // Fixed's fast path: an exact solve, written to q only when it succeeds.
    if (!(opt.max_clamp_mm < S(0)) && leg_ik::abduction_solve_fast(*this, target, q)) {
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
    const S bound_x = lb_mm + lc_mm + opt.max_clamp_mm;
    const S bound_yz = la_mm + bound_x;
    if (!leg_ik::within(target.x, bound_x) || !leg_ik::within(target.y, bound_yz) ||
        !leg_ik::within(target.z, bound_yz))
      return IkStatus::kUnreachable;
    const int8_t fine = int8_t(unit_shift - kFineBits);
    const S y = units::to_unit(target.y, fine);
    const S z = units::to_unit(target.z, fine);
    const S a_sq = y * y + z * z;     // A^2, eq 4.1
    const S p_sq = a_sq - la_fine_sq;  // d^2 = A^2 - La^2 (triangle OCD, phi = 90 deg)
    Joints sol;
    S p = S(0);  // [fine unit]
    bool clamped = false;
    if (p_sq > S(0)) {
      p = sqrt(p_sq);
      // (y, z) turned by +alpha3 (left) or -alpha3 (right), times A^2.
      const S lz = la_fine * z, py = p * y;
      const S ly = la_fine * y, pz = p * z;
      sol[0] = side == LegSide::kLeft ? atan2(lz + py, ly - pz) : atan2(lz - py, ly + pz);
    } else {
      clamped = p_sq < S(0);  // inside the abduction cylinder: La points at the foot
      const bool on_axis = target.y == S(0) && target.z == S(0);
      sol[0] = on_axis ? leg_ik::free_angle(limits, 0, standing_t1()) : atan2(target.z, target.y);
    }
    if (sol[0] < S(0)) {  // algorithm 1's range [0, 2 pi); atan2 gave (-pi, pi]
      sol[0] += two_pi<S>();
      if (!(sol[0] < two_pi<S>())) sol[0] = S(0);  // -tiny + 2 pi rounds to 2 pi
    }
    // In the leg plane: backward = -x, down = p; D^2 = x^2 + p^2.
    const S back = units::to_unit(-target.x, unit_shift);
    const S d2 = back * back + units::to_unit(p_sq > S(0) ? p_sq : S(0), int8_t(2 * kFineBits));
    if (link.solve(back, units::to_unit(p, kFineBits), d2, KneeBranch::kPositive, sol[1], sol[2])) clamped = true;
    return leg_ik::finish(*this, target, sol, clamped, opt, q, reached);
  }
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_ABDUCTION_LEG_H
