//! Odometry: the body's position [mm] and heading [rad] summed from its
//! steps (stance.h's BodyStep), the heading kept as cos/sin too (no trig).
#ifndef STRIDER_GAIT_ODOMETRY_H
#define STRIDER_GAIT_ODOMETRY_H

#include "stance.h"

namespace strider {

template <typename S>
struct Odometry {
  S x, y, yaw, c = S(1), s;
  // The last step in the world frame (w), kept while the body does not
  // turn and the step (d) repeats.
  S dx, dy, wx, wy;

  void reset() {
    x = y = yaw = S(0);
    c = S(1);
    s = S(0);
    dx = dy = wx = wy = S(0);
  }

  STRIDER_ALWAYS_INLINE void add(const BodyStep<S>& step) {
    if (!(step.dyaw == S(0) && step.dx_mm == dx && step.dy_mm == dy)) {
      dx = step.dx_mm;
      dy = step.dy_mm;
      wx = c * step.dx_mm - s * step.dy_mm;
      wy = s * step.dx_mm + c * step.dy_mm;
    }
    x = add_inline(x, wx);
    y = add_inline(y, wy);
    yaw = add_inline(yaw, step.dyaw);
    if (step.dyaw != S(0)) {
      dx = dy = S(0);  // the heading changes: recompute next tick
      // Renormalised by one Newton step.
      const S nc = c * step.cos_yaw - s * step.sin_yaw;
      const S ns = s * step.cos_yaw + c * step.sin_yaw;
      constexpr S half = scalar<S>(0.5);
      const S k = (S(3) - (nc * nc + ns * ns)) * half;
      c = nc * k;
      s = ns * k;
    }
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_ODOMETRY_H
