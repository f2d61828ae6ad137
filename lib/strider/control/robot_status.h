//! The motion fields RobotApp adds to `status` (after the controller's): what
//! the gait walks, the gait and its state, the IK's and the servos' state,
//! the live tuning's origin.
#ifndef STRIDER_CONTROL_ROBOT_STATUS_H
#define STRIDER_CONTROL_ROBOT_STATUS_H

#include <stdint.h>

#include "gait_tuner.h"
#include "reply_texts.h"
#include "servo_map.h"
#include "walker_motion.h"

namespace strider {

//! A value -> tenths, rounded half away from zero (|v| < 200,000).
inline int32_t to_tenths(float v) { return v >= 0.0f ? int32_t(v * 10.0f + 0.5f) : -int32_t(-v * 10.0f + 0.5f); }
inline int32_t to_tenths(Fixed v) {
  const int32_t t = v.raw() * 10;  // |v| < 3276.7: no overflow
  return t >= 0 ? (t + 32768) >> 16 : -((-t + 32768) >> 16);
}

//! ` walk_vx= walk_vy= walk_wz=`: the command after avoidance and the
//! robot's limits, as the body speed it makes (speed_correction.h); the
//! gait, its state, the IK's, the servos' and the live tuning's origin
//! unless the model's own.
template <typename S, typename Stage>
void write_motion_status(ReplyWriter& w, const WalkerMotion<S>& motion, const Stage& stage, TuneOrigin origin) {
  const GaitEngine<S>& e = motion.walker().engine();
  w.format(FlashText{text::kWalkFmt}, motion.body_speed(to_tenths(e.vx())), motion.body_speed(to_tenths(e.vy())),
           motion.body_speed(to_tenths(e.wz() * scalar<S>(1.0 / kDegToRad)), true));
  const FlashText servos = stage.all_on() ? FlashText{text::kOn}
                           : stage.starting() ? FlashText{text::kStarting} : FlashText{text::kOff};
  w.field_text(FlashText{text::kGaitKey}, motion.gait().name)
      .field_text(FlashText{text::kState}, text::to_flash(e.state()))
      .field_text(FlashText{text::kIk}, text::to_flash(motion.walker().worst_status()))
      .field_text(FlashText{text::kServos}, servos);
  if (stage.last_status() != ServoStatus::kOk) w.field_text(FlashText{text::kServos}, FlashText{text::kLimited});
  if (origin != TuneOrigin::kDefault) w.field_text(FlashText{text::kTune}, to_flash(origin));
}

}  // namespace strider

#endif  // STRIDER_CONTROL_ROBOT_STATUS_H
