//! ServoMap: joint angle -> servo angle -> pulse width [us] -> PCA9685 ticks,
//! with the zero, direction, trim and limits of each joint.
//!
//! servo angle = centre + direction * (joint - zero) + trim, clamped to the
//! servo's [min, max]; pulse = min_pulse + angle * us_per_rad, where
//! us_per_rad = (max - min pulse) / travel.
//! A joint angle that is NaN or infinite never reaches a servo: the output
//! holds the centre (clamped into the limits) and the status says so.
#ifndef STRIDER_CONTROL_SERVO_MAP_H
#define STRIDER_CONTROL_SERVO_MAP_H

#include <stdint.h>

#include "../math/scalar.h"
#include "pca9685_timing.h"

namespace strider {

enum class ServoStatus : uint8_t {
  kOk = 0,
  kLimited = 1,   //!< servo angle was outside [min, max]: clamped to the limit
  kNotFinite = 2  //!< joint angle was NaN or infinite: centre sent instead
};

//! Calibration-independent description of one joint's servo.
template <typename S>
struct ServoChannel {
  uint8_t channel;         //!< PCA9685 output (board * 16 + pin)
  int8_t direction;        //!< +1: servo turns with the joint; -1: mirrored
  S zero_rad;              //!< joint angle at which the servo sits at its centre [rad]
  S centre_rad;            //!< servo angle of the centre, from the pulse-range start [rad]
  S min_rad;               //!< lowest allowed servo angle [rad]
  S max_rad;               //!< highest allowed servo angle [rad]
  S us_per_rad;            //!< pulse change per servo radian, (max - min pulse) / travel [us/rad]
  uint16_t min_pulse_us;   //!< pulse at servo angle 0 [us]
  uint16_t max_pulse_us;   //!< pulse at the end of the travel [us]
};

//! A 180-degree 500-2500 us servo centred at 90 deg with the given limits [deg]
//! around its centre (SG90, MG90S, MG996R: see robots/servo_parts.h).
template <typename S>
constexpr ServoChannel<S> make_servo_channel(uint8_t channel, int8_t direction, double zero_deg,
                                             double below_deg = 90.0, double above_deg = 90.0) {
  return ServoChannel<S>{channel,
                         direction,
                         scalar<S>(zero_deg * kDegToRad),
                         scalar<S>(90.0 * kDegToRad),
                         scalar<S>((90.0 - below_deg) * kDegToRad),
                         scalar<S>((90.0 + above_deg) * kDegToRad),
                         scalar<S>(2000.0 / (180.0 * kDegToRad)),
                         500,
                         2500};
}

namespace detail {
inline bool is_finite(Fixed) { return true; }  // float: float_math.h
inline int32_t round_to_int(float v) { return v >= 0.0f ? int32_t(v + 0.5f) : -int32_t(-v + 0.5f); }
inline int32_t round_to_int(Fixed v) { return (v + Fixed::from_raw(Fixed::kOneRaw / 2)).raw() >> Fixed::kFracBits; }
}  // namespace detail

struct ServoCommand {
  uint8_t channel;      //!< PCA9685 output
  uint16_t pulse_us;    //!< pulse width [us], inside the channel's pulse range
  uint16_t ticks;       //!< PCA9685 off-count for an on-count of 0
  ServoStatus status;
};

//! Servo angle [rad] for a joint angle [rad] and a trim [rad]; clamped to the
//! channel's limits. NaN/inf -> centre (clamped), kNotFinite.
template <typename S>
ServoStatus servo_angle(const ServoChannel<S>& ch, S joint_rad, S trim_rad, S* angle_rad) {
  const S lo = ch.min_rad;
  const S hi = ch.max_rad;
  if (!detail::is_finite(joint_rad) || !detail::is_finite(trim_rad)) {
    *angle_rad = clamp(ch.centre_rad, lo, hi);
    return ServoStatus::kNotFinite;
  }
  const S delta = joint_rad - ch.zero_rad;
  const S a = ch.centre_rad + (ch.direction < 0 ? -delta : delta) + trim_rad;
  if (!detail::is_finite(a)) {  // float overflow of huge but finite inputs
    *angle_rad = clamp(ch.centre_rad, lo, hi);
    return ServoStatus::kNotFinite;
  }
  if (a < lo || hi < a) {
    *angle_rad = clamp(a, lo, hi);
    return ServoStatus::kLimited;
  }
  *angle_rad = a;
  return ServoStatus::kOk;
}

//! Pulse width [us] of a servo angle [rad] already inside the limits; the
//! result is clamped to the channel's pulse range whatever the input.
template <typename S>
uint16_t servo_pulse_us(const ServoChannel<S>& ch, S angle_rad) {
  // A precomputed slope: an AVR division costs 3 to 5 multiplications.
  const int32_t lo = ch.min_pulse_us < ch.max_pulse_us ? ch.min_pulse_us : ch.max_pulse_us;
  const int32_t hi = ch.min_pulse_us < ch.max_pulse_us ? ch.max_pulse_us : ch.min_pulse_us;
  const S offset = clamp(angle_rad * ch.us_per_rad, S(int(lo - ch.min_pulse_us)), S(int(hi - ch.min_pulse_us)));
  int32_t us = int32_t(ch.min_pulse_us) + detail::round_to_int(offset);
  us = us < lo ? lo : (us > hi ? hi : us);
  return uint16_t(us);
}

//! The on-time ticks of a channel's two joint limits, rounded toward the
//! inside of its range; *lo_ticks <= *hi_ticks.
template <typename S>
void limit_ticks(const ServoChannel<S>& ch, const Pca9685Timing& timing, uint16_t* lo_ticks, uint16_t* hi_ticks) {
  const uint16_t a = servo_pulse_us(ch, ch.min_rad), b = servo_pulse_us(ch, ch.max_rad);
  const uint16_t lo_us = a < b ? a : b, hi_us = a < b ? b : a;
  *lo_ticks = timing.pulse_ticks_toward(lo_us, true);
  *hi_ticks = timing.pulse_ticks_toward(hi_us, false);
  if (*hi_ticks < *lo_ticks) *hi_ticks = *lo_ticks = timing.pulse_ticks(lo_us);  // a range within one tick
}

//! The whole mapping of one joint, joint angle [rad] + trim [rad] -> command;
//! the ticks within the limits' ticks (limit_ticks()).
template <typename S>
ServoCommand map_joint(const ServoChannel<S>& ch, S joint_rad, S trim_rad, const Pca9685Timing& timing) {
  S angle = ch.centre_rad;
  const ServoStatus status = servo_angle(ch, joint_rad, trim_rad, &angle);
  ServoCommand cmd;
  cmd.channel = ch.channel;
  cmd.pulse_us = servo_pulse_us(ch, angle);
  uint16_t lo, hi;
  limit_ticks(ch, timing, &lo, &hi);
  const uint16_t t = timing.pulse_ticks(cmd.pulse_us);
  cmd.ticks = t < lo ? lo : t > hi ? hi : t;
  cmd.status = status;
  return cmd;
}

//! Trim stored in settings [0.1 deg] -> [rad].
template <typename S>
S trim_from_decideg(int16_t decideg) {
  return S(int(decideg)) * scalar<S>(kDegToRad / 10.0);
}

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_MAP_H
