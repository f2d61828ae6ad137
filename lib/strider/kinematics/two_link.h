//! TwoLink: the planar two-link problem every analytic leg reduces to
//! (seed 003 eqs 3-5; the femur and tibia of seed 002 eqs 8-11 and of seed
//! 001 eqs 4.12-4.21), and KneeBranch, the choice between its two solutions.
//! Inputs are in working units (math/working_units.h), solve_wide's in wide
//! units (wide_units.h).
#ifndef STRIDER_KINEMATICS_TWO_LINK_H
#define STRIDER_KINEMATICS_TWO_LINK_H

#include "leg_ik_common.h"
#include "wide_sqrt.h"

namespace strider {

//! Which of its two solutions a two-link IK returns: the sign of the knee angle.
enum class KneeBranch : uint8_t {
  kPositive = 0,  //!< knee angle in [0, pi]
  kNegative = 1   //!< knee angle in [-pi, 0]
};

namespace leg_ik {

//! The planar two-link problem in working units:
//!   (h, v) = a1 (cos ta, sin ta) + a2 (cos(ta + tb), sin(ta + tb)).
//! Law of cosines with every quantity multiplied by 2 a1 a2 so that no
//! reciprocal is needed (seed 003 eqs 4-5, seed 002 eqs 8-11):
//!   2 a1 a2 cos tb = D^2 - a1^2 - a2^2,
//!   2 a1 a2 |sin tb| = sqrt(((a1 + a2)^2 - D^2) (D^2 - (a1 - a2)^2)),
//! which stays accurate near the stretched and folded boundaries, and
//!   ta = atan2(v, h) - atan2(a2 sin tb, a1 + a2 cos tb)
//! as a single atan2 by the angle-difference identity.
template <typename S>
struct TwoLink {
  S a1;        //!< first link [unit]
  S a2;        //!< second link [unit]
  S outer2;    //!< (a1 + a2)^2 [unit^2]
  S inner2;    //!< (a1 - a2)^2 [unit^2]
  S sum_sq;    //!< a1^2 + a2^2 [unit^2]
  S diff_sq;   //!< a1^2 - a2^2 [unit^2]

  static constexpr TwoLink make(S a1_unit, S a2_unit) {
    return TwoLink{a1_unit,
                   a2_unit,
                   (a1_unit + a2_unit) * (a1_unit + a2_unit),
                   (a1_unit - a2_unit) * (a1_unit - a2_unit),
                   a1_unit * a1_unit + a2_unit * a2_unit,
                   a1_unit * a1_unit - a2_unit * a2_unit};
  }

  //! Solves for (h, v) [unit] on the given branch. A target outside the
  //! annulus (a1 - a2)^2 <= D^2 <= (a1 + a2)^2 is replaced by the nearest
  //! annulus point on the same ray (stretched or folded leg); returns true
  //! then. ta in (-pi, pi], tb in [-pi, pi]; never NaN.
  bool solve(S h, S v, KneeBranch branch, S& ta, S& tb) const { return solve(h, v, h * h + v * v, branch, ta, tb); }
  //! The same with d2 = h^2 + v^2 already at hand.
  bool solve(S h, S v, S d2, KneeBranch branch, S& ta, S& tb) const {
    // Comparisons through lt(): a float comparison is a library call on the AVR.
    if (!lt(d2, outer2)) {  // stretched; also catches a saturated d2
      ta = atan2(v, h);
      tb = S(0);
      return lt(outer2, d2);
    }
    if (!lt(inner2, d2)) {  // folded: the foot sits at (a1 - a2)(cos ta, sin ta)
      tb = branch == KneeBranch::kNegative ? -pi<S>() : pi<S>();
      if (is_zero(h) && is_zero(v)) {
        ta = S(0);  // any direction is as near
      } else {
        ta = lt(a1, a2) ? atan2(-v, -h) : atan2(v, h);
      }
      return lt(d2, inner2);
    }
    const S c = d2 - sum_sq;                          // 2 a1 a2 cos tb
    S s = sqrt((outer2 - d2) * (d2 - inner2));        // 2 a1 a2 |sin tb|
    if (branch == KneeBranch::kNegative) s = -s;
    tb = atan2(s, c);
    S k1 = d2 + diff_sq;                              // 2 a1 (a1 + a2 cos tb)
    S k2 = s;                                         // 2 a1 (a2 sin tb)
    if (lt(d2, S(1))) {  // only a short D makes both pairs small (folded, a1 ~ a2)
      lift_pair(k1, k2);
      lift_pair(h, v);
    }
    ta = atan2(v * k1 - h * k2, h * k1 + v * k2);
    return false;
  }
};

//! TwoLink::solve in 16/32-bit integers for (h, v) [wide units] strictly
//! inside the annulus; false, ta and tb untouched, otherwise or for links of
//! 8 units or more. kSharedAtan2 calls the out-of-line lean atan2.
template <bool kSharedAtan2 = false>
STRIDER_ALWAYS_INLINE bool solve_wide_inline(const TwoLink<Fixed>& link, int32_t h, int32_t v, KneeBranch branch,
                                             Fixed& ta, Fixed& tb) {
  if (link.outer2.raw() >= (int32_t(64) << 16)) return false;  // a1 + a2 >= 8 units
  const uint32_t d2 = wide::sq_sum(h, v);
  const uint32_t outer2 = uint32_t(link.outer2.raw()) << 8, inner2 = uint32_t(link.inner2.raw()) << 8;
  if (!(d2 < outer2 && d2 > inner2)) return false;
  const int32_t c = int32_t(d2) - wide::from_sq(link.sum_sq);          // 2 a1 a2 cos tb [Q6.24]
  int32_t s = int32_t(wide::sqrt_product(outer2 - d2, d2 - inner2));  // 2 a1 a2 |sin tb|
  if (branch == KneeBranch::kNegative) s = -s;
  const int32_t k1 = int32_t(d2) + wide::from_sq(link.diff_sq);  // 2 a1 (a1 + a2 cos tb); diff_sq < 0 for a1 < a2
  // tb = atan2(s, c); ta = atan2(v, h) - atan2(s, k1): two lean atan2s are
  // cheaper on the AVR than the angle-difference identity in 16 bits.
  tb = Fixed::from_raw(kSharedAtan2 ? detail::atan2_lean_call(s, c) : detail::atan2_lean_raw(s, c));
  int32_t a = kSharedAtan2 ? detail::atan2_lean_call(v, h) - detail::atan2_lean_call(s, k1)
                           : detail::atan2_lean_raw(v, h) - detail::atan2_lean_raw(s, k1);
  ta = Fixed::from_raw(detail::wrap_pi_once_raw(a));
  return true;
}

//! solve_wide_inline() as one out-of-line copy for the leg types that share
//! it (planar, abduction), with the shared lean atan2.
inline bool solve_wide(const TwoLink<Fixed>& link, int32_t h, int32_t v, KneeBranch branch, Fixed& ta, Fixed& tb) {
  return solve_wide_inline<true>(link, h, v, branch, ta, tb);
}

}  // namespace leg_ik
}  // namespace strider

#endif  // STRIDER_KINEMATICS_TWO_LINK_H
