//! ChannelMap: which PCA9685 output drives which joint of a robot model, and
//! how its servo is mounted; one rule for every built-in model (docs/wiring.md):
//! joint k = leg * dof + j on one board up to 16 joints, else the left legs
//! on 0x40 and the rest on 0x41; the servo's centre at the middle of the
//! joint's range; a right leg's horizontal-axis servos turn the other way.
#ifndef STRIDER_CONTROL_CHANNEL_MAP_H
#define STRIDER_CONTROL_CHANNEL_MAP_H

#include <stdint.h>

#include "../math/flash_table.h"
#include "../robots/robot_model.h"
#include "servo_map.h"
#include "settings.h"

namespace strider {

constexpr uint8_t kPcaChannelsPerBoard = 16;
constexpr uint8_t kPcaFirstAddress = 0x40;  //!< 7-bit address of board 0 (A0-A5 open)
constexpr uint8_t kMaxPcaBoards = 2;

constexpr uint8_t pca_board_count(const RobotModel& m) {
  return m.joint_count() > kPcaChannelsPerBoard ? uint8_t(2) : uint8_t(1);
}

//! Global channel (board * 16 + pin) of joint j of leg `leg`.
constexpr uint8_t joint_channel(const RobotModel& m, uint8_t leg, uint8_t j) {
  return pca_board_count(m) == 1
             ? uint8_t(leg * m.dof() + j)
             : uint8_t((leg / ((m.leg_count + 1) / 2)) * kPcaChannelsPerBoard + (leg % ((m.leg_count + 1) / 2)) * m.dof() + j);
}

constexpr bool joint_axis_vertical(LegKind kind, uint8_t j) {
  return j == 0 && (kind == LegKind::kSprawl || kind == LegKind::kCoxaFemurTibia);
}

//! +1 or -1: how the servo of joint j of leg `leg` is mounted (file comment).
constexpr int8_t joint_direction(const RobotModel& m, uint8_t leg, uint8_t j) {
  return m.legs[leg].side == BodySide::kRight && !joint_axis_vertical(m.kind, j) ? int8_t(-1) : int8_t(1);
}

//! The servo channel of joint j of leg `leg` in scalar S.
template <typename S>
ServoChannel<S> make_joint_channel(const RobotModel& m, uint8_t leg, uint8_t j) {
  const ServoTravel spec = servo_travel(m.servo[j]);
  return ServoChannel<S>{
      joint_channel(m, leg, j),
      joint_direction(m, leg, j),
      scalar<S>(0.5 * (double(m.legs[leg].joint[j].min_deg) + double(m.legs[leg].joint[j].max_deg)) * kDegToRad),
      scalar<S>(0.5 * double(spec.travel_deg) * kDegToRad),
      scalar<S>((0.5 * double(spec.travel_deg) -
                 0.5 * (double(m.legs[leg].joint[j].max_deg) - double(m.legs[leg].joint[j].min_deg))) *
                kDegToRad),
      scalar<S>((0.5 * double(spec.travel_deg) +
                 0.5 * (double(m.legs[leg].joint[j].max_deg) - double(m.legs[leg].joint[j].min_deg))) *
                kDegToRad),
      scalar<S>(double(spec.max_pulse_us - spec.min_pulse_us) / (double(spec.travel_deg) * kDegToRad)),
      spec.min_pulse_us,
      spec.max_pulse_us};
}

//! The model's joint count when make_channel_map() can map it, else 0 (more
//! joints than kMaxServoJoints, or a joint range wider than its servo's
//! travel).
inline uint8_t channel_map_count(const RobotModel& m) {
  if (m.joint_count() > kMaxServoJoints) return 0;
  for (uint8_t leg = 0; leg < m.leg_count; ++leg)
    for (uint8_t j = 0; j < m.dof(); ++j) {
      const JointRange& r = m.legs[leg].joint[j];
      if (r.max_deg - r.min_deg > servo_travel(m.servo[j]).travel_deg) return 0;
    }
  return m.joint_count();
}

//! Where a model is kept: in RAM (host tools, the simulator), or in flash
//! (the firmware: STRIDER_PROGMEM, read through a copy).
enum class ModelMemory : uint8_t { kRam = 0, kFlash = 1 };

inline void read_model(const RobotModel& from, ModelMemory where, RobotModel* to) {
  if (where == ModelMemory::kFlash) flash_copy(to, &from, sizeof *to);
  else *to = from;
}

//! Fills out[k] for every joint k = leg * dof + j; returns channel_map_count().
template <typename S>
uint8_t make_channel_map(const RobotModel& m, ServoChannel<S>* out) {
  const uint8_t n = channel_map_count(m);
  for (uint8_t k = 0; k < n; ++k) out[k] = make_joint_channel<S>(m, uint8_t(k / m.dof()), uint8_t(k % m.dof()));
  return n;
}

//! The joint angle [rad] a servo on `ch` holds for a pulse [us] with zero
//! trim (the simulators' inverse of servo_pulse_us()).
inline double joint_from_pulse(const ServoChannel<float>& ch, double pulse_us) {
  const double servo_rad = (pulse_us - double(ch.min_pulse_us)) / double(ch.us_per_rad);
  const double delta = servo_rad - double(ch.centre_rad);
  return double(ch.zero_rad) + (ch.direction < 0 ? -delta : delta);
}

}  // namespace strider

#endif  // STRIDER_CONTROL_CHANNEL_MAP_H
