//! TwoLink: the planar two-link problem every analytic leg reduces to
//! (seed 003 eqs 3-5; the femur and tibia of seed 002 eqs 8-11 and of seed
//! 001 eqs 4.12-4.21), and KneeBranch, the choice between its two solutions.
//!
//! Inputs are in working units (leg_ik_common.h), so Fixed can square them.
#ifndef STRIDER_KINEMATICS_TWO_LINK_H
#define STRIDER_KINEMATICS_TWO_LINK_H

#include "leg_ik_common.h"

namespace strider {

//! Which of the two elbow-up/elbow-down solutions a two-link IK returns: the
//! sign of the knee joint angle.
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
    if (!(d2 < outer2)) {  // stretched; also catches a saturated d2
      ta = atan2(v, h);
      tb = S(0);
      return d2 > outer2;
    }
    if (!(d2 > inner2)) {  // folded: the foot sits at (a1 - a2)(cos ta, sin ta)
      tb = branch == KneeBranch::kNegative ? -pi<S>() : pi<S>();
      if (h == S(0) && v == S(0)) {
        ta = S(0);  // any direction is as near
      } else {
        ta = a2 > a1 ? atan2(-v, -h) : atan2(v, h);
      }
      return d2 < inner2;
    }
    const S c = d2 - sum_sq;                          // 2 a1 a2 cos tb
    S s = sqrt((outer2 - d2) * (d2 - inner2));        // 2 a1 a2 |sin tb|
    if (branch == KneeBranch::kNegative) s = -s;
    tb = atan2(s, c);
    S k1 = d2 + diff_sq;                              // 2 a1 (a1 + a2 cos tb)
    S k2 = s;                                         // 2 a1 (a2 sin tb)
    if (d2 < S(1)) {  // only a short D makes both pairs small (folded, a1 ~ a2)
      lift_pair(k1, k2);
      lift_pair(h, v);
    }
    ta = atan2(v * k1 - h * k2, h * k1 + v * k2);
    return false;
  }
};

}  // namespace leg_ik
}  // namespace strider

#endif  // STRIDER_KINEMATICS_TWO_LINK_H
