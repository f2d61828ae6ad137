//! BodyPosture: the body's height between sitting and standing, the user's
//! pose offsets (BodyOffsets) moving to their goal at a limited rate, and
//! the body pose they and the body shift make.
#ifndef STRIDER_GAIT_BODY_POSTURE_H
#define STRIDER_GAIT_BODY_POSTURE_H

#include "../kinematics/body_pose.h"
#include "../kinematics/leg_ik_common.h"
#include "body_shift.h"
#include "gait_config.h"

namespace strider {

//! The user's body pose offsets (applied while standing and walking).
template <typename S>
struct BodyOffsets {
  Vec3<S> translation_mm;  //!< body shift x, y and height change z [mm]
  S roll_rad, pitch_rad, yaw_rad;
  static BodyOffsets zero() { return BodyOffsets{Vec3<S>(), S(0), S(0), S(0)}; }
};
// BodyPosture::step_pose() walks the six offsets as an array.
static_assert(sizeof(BodyOffsets<float>) == 6 * sizeof(float) && sizeof(BodyOffsets<Fixed>) == 6 * sizeof(Fixed),
              "BodyOffsets: six scalars, no padding");

template <typename S>
struct BodyPosture {
  S progress = S(1);  // 0 sitting .. 1 standing
  BodyOffsets<S> pose, goal;
  bool at_goal = true;  // pose == goal known: step_pose() has nothing to do

  void reset(bool sitting) {
    progress = sitting ? S(0) : S(1);
    pose = goal = BodyOffsets<S>::zero();
    at_goal = true;
  }

  //! The body in the stance frame: shift + offsets + sit/stand height.
  template <uint8_t kL, bool kSr>
  BodyPose<S> body_pose(const BodyShift<S>& shift, const GaitConfig<S, kL, kSr>& cfg) const {
    return BodyPose<S>::make(translation(shift, cfg), pose.roll_rad, pose.pitch_rad, pose.yaw_rad);
  }
  //! body_pose()'s translation (sums in place; inline: the walker's level tick).
  template <uint8_t kL, bool kSr>
  STRIDER_ALWAYS_INLINE Vec3<S> translation(const BodyShift<S>& shift, const GaitConfig<S, kL, kSr>& cfg) const {
    // How far the body is below standing height [mm] (standing: no products).
    const S drop = progress >= S(1) ? S(0) : cfg.sit_drop_mm * (S(1) - BodyShift<S>::smoothstep(progress));
    const Vec3<S>& t = pose.translation_mm;
    return Vec3<S>(add_inline(shift.x_mm(), t.x), add_inline(shift.y_mm(), t.y), sub_inline(t.z, drop));
  }

  //! All of roll, pitch and yaw zero (integer tests of float bits).
  bool level() const {
    return leg_ik::is_zero(pose.roll_rad) && leg_ik::is_zero(pose.pitch_rad) && leg_ik::is_zero(pose.yaw_rad);
  }

  //! Moves progress by d toward standing (up) or sitting; true when there.
  bool step_progress(bool up, S d) {
    if (up) {
      progress = min_of(progress + d, S(1));
      return progress >= S(1);
    }
    progress = max_of(progress - d, S(0));
    return progress <= S(0);
  }

  //! Every offset moves by at most its rate; when all were at the goal
  //! already (none moved), the pose is there.
  template <uint8_t kL, bool kSr>
  void step_pose(const GaitConfig<S, kL, kSr>& cfg, S dt) {
    if (at_goal) return;
    const S dp = cfg.pose_speed_mm_s * dt, da = cfg.pose_rate_rad_s * dt;
    // The six offsets (x, y, z, roll, pitch, yaw) at their byte offsets, one
    // call site: the lengths at dp, the angles at da.
    unsigned char* v = reinterpret_cast<unsigned char*>(&pose);
    const unsigned char* g = reinterpret_cast<const unsigned char*>(&goal);
    bool there = true;
    for (uint8_t k = 0; k < 6; ++k, v += sizeof(S), g += sizeof(S))
      there &= move_toward(*reinterpret_cast<S*>(v), *reinterpret_cast<const S*>(g), k < 3 ? dp : da);
    at_goal = there;
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_BODY_POSTURE_H
