//! SwingFeet: the feet in the air, each on the swing it lifted with (its
//! length, shape and apex; gait and parameter changes apply to the next
//! lift), from where it lifted toward a touch-down point that moves at a
//! limited speed when the landing stride changes.
#ifndef STRIDER_GAIT_SWING_FEET_H
#define STRIDER_GAIT_SWING_FEET_H

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

  //! Foot i at swing point (u along the way, `up` above it) toward its
  //! target, which is at ground height `ground_z`.
  STRIDER_ALWAYS_INLINE void place(uint8_t i, Vec3<S>& foot, S ground_z, S u, S up) const {
    const Vec3<S>& l = lift[i];
    // A foot that lifted from the ground line (no stance depth) keeps its
    // height but for the lift: no product for the zero difference.
    const S dz = sub_inline(ground_z, l.z);
    foot.x = add_inline(l.x, sub_inline(target[i].x, l.x) * u);
    foot.y = add_inline(l.y, sub_inline(target[i].y, l.y) * u);
    foot.z = add_inline(dz == S(0) ? l.z : add_inline(l.z, dz * u), up);
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_SWING_FEET_H
