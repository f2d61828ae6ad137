//! write_servo_frame: one frame of joint angles -> one tick write per servo
//! through a ServoOutput (hal_interfaces.h), with the calibrated trims.
#ifndef STRIDER_CONTROL_SERVO_FRAME_H
#define STRIDER_CONTROL_SERVO_FRAME_H

#include <stdint.h>

#include "servo_map.h"
#include "servo_tick_map.h"
#include "settings.h"

namespace strider {

//! The worse of two servo statuses.
inline ServoStatus worst(ServoStatus a, ServoStatus b) { return uint8_t(a) >= uint8_t(b) ? a : b; }

//! Writes count joints: channels[i], joint_rad[i] [rad] and
//! settings.trim_decideg[first_trim + i]; every servo within its limits.
//! Returns the worst status.
template <typename S, typename Output>
ServoStatus write_servo_frame(Output& out, const ServoChannel<S>* channels, const S* joint_rad, uint8_t count,
                              const Settings& settings, const Pca9685Timing& timing, uint8_t first_trim = 0) {
  ServoStatus status = ServoStatus::kOk;
  for (uint8_t i = 0; i < count; ++i) {
    const uint8_t t = uint8_t(first_trim + i);
    const S trim = t < kMaxServoJoints ? trim_from_decideg<S>(settings.trim_decideg[t]) : S(0);
    const ServoCommand cmd = map_joint(channels[i], joint_rad[i], trim, timing);
    out.write_ticks(cmd.channel, cmd.ticks);
    status = worst(status, cmd.status);
  }
  return status;
}

//! The same through a configured ServoTickMap: its joints [first, first + count).
template <typename S, uint8_t N, typename Output>
ServoStatus write_servo_frame(Output& out, const ServoTickMap<S, N>& map, const S* joint_rad, uint8_t count,
                              uint8_t first = 0) {
  return map.write(out, first, joint_rad, count);
}

//! Programs the PWM frequency: at boot and after a calibration change.
template <typename Output>
PwmTimingStatus configure_servo_pwm(Output& out, Pca9685Timing& timing, const Settings& settings) {
  const PwmTimingStatus s = timing.configure(settings.pca_osc_hz, settings.pwm_hz);
  if (s != PwmTimingStatus::kBadOscillator) out.set_prescale(timing.prescale());
  return s;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_FRAME_H
