//! Touchdown: where a foot lands (stance.h's touchdown_point), its leg-independent
//! terms (rotation, offset) computed once per change of the landing stride.
#ifndef STRIDER_GAIT_TOUCHDOWN_H
#define STRIDER_GAIT_TOUCHDOWN_H

#include "speed_ramp.h"
#include "stance.h"

namespace strider {

template <typename S>
struct Touchdown {
  bool fresh;  // the terms are those of the landing stride
  S cos_yaw = S(1), sin_yaw, dx, dy;

  //! x and y of the point where the foot of `home` lands for stride `land`
  //! (z is home's), into place; inline: the straight case is two sums.
  STRIDER_ALWAYS_INLINE void xy(const Vec3<S>& home, const Stride<S>& land, S duty, S& x, S& y) {
    if (!fresh) refresh(land, duty);
    if (sin_yaw == S(0) && cos_yaw == S(1)) {
      x = add_inline(home.x, dx);
      y = add_inline(home.y, dy);
    } else {
      turned(home, x, y);
    }
  }

  //! The terms for the travel of the coming stance (duty cycles); out of
  //! line: the straight path's registers stay few.
  STRIDER_NOINLINE void refresh(const Stride<S>& land, S duty) {
    if (land.yaw == S(0)) {
      // Not turning: touchdown_point() is home + the stride x duty / 2.
      constexpr S half = scalar<S>(0.5);
      const S k = duty * half;
      dx = land.x * k;
      dy = land.y * k;
      cos_yaw = S(1);
      sin_yaw = S(0);
    } else {
      touchdown_frame(land.x, land.y, land.yaw, duty, dx, dy, cos_yaw, sin_yaw);
    }
    fresh = true;
  }

  //! xy() of a turning landing stride (rotation and offset).
  STRIDER_NOINLINE void turned(const Vec3<S>& h, S& x, S& y) const {
    x = cos_yaw * h.x - sin_yaw * h.y + dx;
    y = sin_yaw * h.x + cos_yaw * h.y + dy;
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_TOUCHDOWN_H
