//! SwingFeet: the feet in the air, each on the swing it lifted with (its
//! length, shape and apex; gait and parameter changes apply to the next
//! lift), from where it lifted toward a touch-down point that moves at a
//! limited speed when the landing stride changes.
#ifndef STRIDER_GAIT_SWING_FEET_H
#define STRIDER_GAIT_SWING_FEET_H

#include "../math/vec3.h"
#include "phase.h"
#include "swing_trajectory.h"

namespace strider {

template <typename S, uint8_t kLegs>
struct SwingFeet {
  Vec3<S> lift[kLegs];    // where each foot lifted
  Vec3<S> target[kLegs];  // where it lands
  S apex[kLegs];
  S inv_swing[kLegs];
  uint32_t len[kLegs];
  SwingShape shape[kLegs];
  uint32_t elapsed[kLegs];
  bool settled[kLegs];  // target already at the touch-down point

  //! The touch-down points changed: every foot in the air steers again.
  void unsettle() {
    for (uint8_t i = 0; i < kLegs; ++i) settled[i] = false;
  }

  //! Moves foot i's target toward (wx, wy) by at most max_step (x and y in
  //! place, sums in place: scalar.h, the same bits as the operators).
  void settle(uint8_t i, S wx, S wy, S max_step) {
    Vec3<S>& t = target[i];
    const S lo = neg_inline(max_step);
    t.x = add_inline(t.x, clamp(sub_inline(wx, t.x), lo, max_step));
    t.y = add_inline(t.y, clamp(sub_inline(wy, t.y), lo, max_step));
    settled[i] = t.x == wx && t.y == wy;
  }

  //! Every foot in the air at its swing point, from where it lifted toward
  //! its target at ground height home[i].z; steer(i) first moves a target
  //! not yet settled. Feet of one swing group (a tripod's three) share their
  //! swing phase: the swing point of the last foot is reused then.
  template <typename Steer>
  STRIDER_ALWAYS_INLINE void step(Vec3<S>* foot, const bool* contact, const Vec3<S>* home, uint8_t n, Steer steer) {
    SwingPoint<S> sp{S(0), S(0)};
    uint32_t sp_elapsed = 0;
    S sp_inv = S(0), sp_apex = S(0), sp_lift = S(0);
    SwingShape sp_shape = SwingShape::kRectangle;
    bool sp_known = false, lift_known = false;  // lift_known: sp_lift = sp_apex * sp.w
    for (uint8_t i = 0; i < n; ++i) {
      if (contact[i]) continue;
      if (!settled[i]) steer(i);
      if (!sp_known || elapsed[i] != sp_elapsed || inv_swing[i] != sp_inv || shape[i] != sp_shape) {
        sp_elapsed = elapsed[i];
        sp_inv = inv_swing[i];
        sp_shape = shape[i];
        sp = swing_point(sp_shape, phase_to<S>(sp_elapsed) * sp_inv);
        sp_known = true;
        lift_known = false;
      }
      if (!lift_known || apex[i] != sp_apex) {
        sp_apex = apex[i];
        sp_lift = sp_apex * sp.w;
        lift_known = true;
      }
      // A foot that lifted from the ground line (no stance depth) keeps its
      // height but for the lift: no product for the zero difference.
      const Vec3<S>& l = lift[i];
      const S dz = sub_inline(home[i].z, l.z);
      foot[i].x = add_inline(l.x, sub_inline(target[i].x, l.x) * sp.u);
      foot[i].y = add_inline(l.y, sub_inline(target[i].y, l.y) * sp.u);
      foot[i].z = add_inline(dz == S(0) ? l.z : add_inline(l.z, dz * sp.u), sp_lift);
    }
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_SWING_FEET_H
