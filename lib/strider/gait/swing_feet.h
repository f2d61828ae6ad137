//! SwingFeet: the feet in the air, each on the swing it lifted with (gait
//! and parameter changes apply to the next lift), toward a touch-down point
//! that moves at a limited speed when the landing stride changes.
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

  //! Moves foot i's target toward (wx, wy) by at most max_step.
  STRIDER_ALWAYS_INLINE void settle(uint8_t i, S wx, S wy, S max_step) {
    Vec3<S>& t = target[i];
    const S lo = neg_inline(max_step);
    t.x = add_inline(t.x, clamp(sub_inline(wx, t.x), lo, max_step));
    t.y = add_inline(t.y, clamp(sub_inline(wy, t.y), lo, max_step));
    settled[i] = t.x == wx && t.y == wy;
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_SWING_FEET_H
