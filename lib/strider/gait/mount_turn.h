//! A leg mount's transforms with fewer products for the usual mounts (the
//! walker's per-leg body <-> leg frame): none when turned by 0 or +-90
//! degrees (float's cos 90 deg, 4e-8, taken as 0), two instead of four by
//! +-45 or +-135 degrees (cos = +-sin), within a rounding step of LegMount's.
#ifndef STRIDER_GAIT_MOUNT_TURN_H
#define STRIDER_GAIT_MOUNT_TURN_H

#include <stdint.h>

#include "../kinematics/leg_mount.h"

namespace strider {

enum class MountTurn : uint8_t { kTurned = 0, kStraight = 1, kLeft = 2, kRight = 3, kDiagonal = 4, kAntiDiagonal = 5 };

template <typename S>
MountTurn mount_turn_of(const LegMount<S>& m) {
  constexpr S tiny = scalar<S>(1e-6);
  if (m.sin_yaw == S(0) && m.cos_yaw == S(1)) return MountTurn::kStraight;
  if (abs(m.cos_yaw) <= tiny && m.sin_yaw == S(1)) return MountTurn::kLeft;
  if (abs(m.cos_yaw) <= tiny && m.sin_yaw == S(-1)) return MountTurn::kRight;
  // float's cos and sin of 45 or 135 degrees may differ in the last bit.
  if (abs(m.cos_yaw - m.sin_yaw) <= tiny) return MountTurn::kDiagonal;
  if (abs(m.cos_yaw + m.sin_yaw) <= tiny) return MountTurn::kAntiDiagonal;
  return MountTurn::kTurned;
}

//! A body-frame point in the frame of the leg at m (turned by `turn`);
//! inline: a call costs ~100 cycles per leg.
template <typename S>
STRIDER_ALWAYS_INLINE Vec3<S> to_leg_turned(MountTurn turn, const LegMount<S>& m, const Vec3<S>& p) {
  if (turn == MountTurn::kTurned) return m.body_to_leg(p);
  // Scalars, not a Vec3 difference (an out-of-line call on the AVR).
  const S dx = sub_inline(p.x, m.origin_mm.x), dy = sub_inline(p.y, m.origin_mm.y), dz = sub_inline(p.z, m.origin_mm.z);
  switch (turn) {
    case MountTurn::kStraight: return Vec3<S>(dx, dy, dz);
    case MountTurn::kLeft: return Vec3<S>(dy, neg_inline(dx), dz);
    case MountTurn::kRight: return Vec3<S>(neg_inline(dy), dx, dz);
    case MountTurn::kDiagonal: return Vec3<S>(m.cos_yaw * add_inline(dx, dy), m.cos_yaw * sub_inline(dy, dx), dz);
    default: return Vec3<S>(m.cos_yaw * sub_inline(dx, dy), m.cos_yaw * add_inline(dx, dy), dz);
  }
}
//! A point in the frame of the leg at m, in the body frame.
template <typename S>
Vec3<S> to_body_turned(MountTurn turn, const LegMount<S>& m, const Vec3<S>& p) {
  return turn == MountTurn::kStraight ? p + m.origin_mm : m.leg_to_body(p);
}

}  // namespace strider

#endif  // STRIDER_GAIT_MOUNT_TURN_H
