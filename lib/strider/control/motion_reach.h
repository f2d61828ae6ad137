//! MotionReach: the body heights and angles the legs reach from the standing
//! pose, in whole mm and degrees, for the replies that name them; found once
//! by bisection, the height with the body level and one angle at a time (in
//! combination a pose inside these may still be refused).
#ifndef STRIDER_CONTROL_MOTION_REACH_H
#define STRIDER_CONTROL_MOTION_REACH_H

#include <stdint.h>

#include "../math/fixed.h"

namespace strider {

struct MotionReach {
  int16_t height_min_mm, height_max_mm;  //!< body height, body level [mm]; 0 0: unknown
  int8_t angle_min_deg[3];               //!< roll, pitch, yaw, one at a time [deg]
  int8_t angle_max_deg[3];
};

constexpr int16_t kReachHeightMinMm = 10;   //!< command_line.h's `height` range [mm]
constexpr int16_t kReachHeightMaxMm = 400;
constexpr int8_t kReachAngleMaxDeg = 30;    //!< command_line.h's `pose` range [deg]

//! A positive length rounded to whole millimetres (no float in a Fixed build).
inline int16_t whole_mm(float mm) { return int16_t(mm + 0.5f); }
inline int16_t whole_mm(Fixed mm) { return int16_t((mm.raw() + (Fixed::kOneRaw / 2)) >> Fixed::kFracBits); }

namespace motion_reach_detail {
//! The last value from `good` toward `bad` that ok() takes, bisecting.
template <typename Ok>
int16_t edge(int16_t good, int16_t bad, Ok ok) {
  while (bad - good > 1 || good - bad > 1) {
    const int16_t mid = int16_t((good + bad) / 2);
    if (ok(mid)) good = mid; else bad = mid;
  }
  return good;
}
}  // namespace motion_reach_detail

//! height_ok(mm): the body level at that height reaches the standing feet;
//! angle_ok(axis, deg): the body turned by deg about axis (0 roll, 1 pitch,
//! 2 yaw) at the standing height does. stand_mm: the standing height.
template <typename HeightOk, typename AngleOk>
MotionReach find_motion_reach(int16_t stand_mm, HeightOk height_ok, AngleOk angle_ok) {
  using motion_reach_detail::edge;
  MotionReach r{0, 0, {0, 0, 0}, {0, 0, 0}};
  if (stand_mm >= kReachHeightMinMm && stand_mm <= kReachHeightMaxMm && height_ok(stand_mm)) {
    r.height_min_mm = edge(stand_mm, kReachHeightMinMm - 1, height_ok);
    r.height_max_mm = edge(stand_mm, kReachHeightMaxMm + 1, height_ok);
  }
  for (uint8_t axis = 0; axis < 3; ++axis) {
    auto ok = [&](int16_t deg) { return angle_ok(axis, deg); };
    r.angle_min_deg[axis] = int8_t(edge(0, -kReachAngleMaxDeg - 1, ok));
    r.angle_max_deg[axis] = int8_t(edge(0, kReachAngleMaxDeg + 1, ok));
  }
  return r;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_MOTION_REACH_H
