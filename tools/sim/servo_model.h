// ServoModel: a hobby servo as the simulator drives it.
//
// What a real analog servo does with the PCA9685's pulse train, and where
// each figure comes from:
// - pulse -> angle: the servo's own linear map (servo_parts.h: 180 deg over
//   500-2500 us), turned into a joint angle by the inverse servo map
//   (control/channel_map.h joint_from_pulse);
// - PWM quantisation: the pulse is ticks * (prescale + 1) / osc_hz, so a
//   target moves in steps of one tick (4.88 us at 50 Hz, ~0.44 deg);
// - deadband: the servo's amplifier ignores a pulse change smaller than its
//   dead band (Tower Pro MG90S/MG996R/MG995 sheets: 5 us; SG90: 10 us;
//   Hitec HS-311: 5 us);
// - speed: the datasheet's no-load speed at 6 V (s per 60 deg) clamps the
//   joint velocity;
// - torque: the stall torque at 6 V (kg cm) bounds the motor's impulse per
//   step; a loaded servo slows down because the solver can only push that
//   hard;
// - stiffness: the position loop asks for 50 rad/s per rad of error
//   (velocity = 50 * error, clamped to the speed), which settles a step in
//   ~60 ms like a loaded MG996R;
// - limp (full-off channel, or before soft start): no pulse, the motor is
//   off; the gear train still resists with a friction torque of 10 % of
//   stall (estimate for metal-gear servos, which do not back-drive freely).
#pragma once

#include <cstdint>

#include "robots/servo_parts.h"

namespace strider_sim {

struct ServoModel {
  double speed_rad_s = 0;      // no-load speed [rad/s]
  double torque_nm = 0;        // stall torque [N m]
  double deadband_us = 5;      // [us]
  double limp_torque_nm = 0;   // gear friction of an unpowered servo [N m]
  double position_gain = 50;   // velocity asked per rad of error [1/s]
};

inline double servo_deadband_us(strider::ServoPart part) {
  return part == strider::ServoPart::kSg90 ? 10.0 : 5.0;
}

inline ServoModel servo_model(strider::ServoPart part) {
  const strider::ServoSpec spec = strider::servo_spec(part);
  constexpr double kKgCmToNm = 0.0980665;
  ServoModel m;
  m.speed_rad_s = 60.0 / double(spec.speed_s_per_60deg) * M_PI / 180.0;
  m.torque_nm = double(spec.stall_torque_kg_cm) * kKgCmToNm;
  m.deadband_us = servo_deadband_us(part);
  m.limp_torque_nm = 0.1 * m.torque_nm;
  return m;
}

// What one PCA9685 output currently sends.
struct ChannelPulse {
  bool on = false;       // false: full-off (no pulse, servo limp)
  double pulse_us = 0;   // pulse width when on [us]
};

constexpr int kMaxChannels = 32;  // two PCA9685 boards

}  // namespace strider_sim
