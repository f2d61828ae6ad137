//! Where a servo stage's channels come from (JointChannelSource): a constant
//! of its model (joint_channels(), in flash on a firmware) or made from the
//! model at run time; and whether a model's joints fit a stage's slots.
#ifndef STRIDER_CONTROL_JOINT_CHANNELS_H
#define STRIDER_CONTROL_JOINT_CHANNELS_H

#include <stdint.h>

#include "../gait/walker_legs.h"
#include "channel_map.h"
#include "servo_tick_map.h"

namespace strider {

constexpr uint16_t kFramePeriodMs = 20;  //!< nominal frame period for the slew limit [ms] (50 Hz)

//! Whether model m's joints fit a tick map of `slots` slots (0, or one per
//! joint of a leg for legs of one geometry).
STRIDER_ALWAYS_INLINE constexpr bool servo_tick_slots_fit(const RobotModel& m, uint8_t slots) {
  return slots == 0 || (slots == m.dof() && leg_solver_count(m) == 1);
}

//! Joint k's channel is range[k % kRanges] with output[k] and direction[k].
template <typename S, uint8_t N, uint8_t kSlots = 0>
struct JointChannels {
  static constexpr uint8_t kRanges = kSlots != 0 ? kSlots : N;
  ServoChannel<S> range[kRanges];
  uint8_t output[N];
  int8_t direction[N];
  uint8_t count;  // channel_map_count(), 0: the model does not fit the stage
  uint16_t step_us[kMaxLegDof];  // joint j's slew step per frame [us] (servo_step_us())
};
//! Joint j's slew step per frame [us]: a pulse change at the servo's top
//! speed over one frame (500-2500 us over 180 deg), rounded.
constexpr uint16_t servo_step_us(float speed_deg_s) {
  return uint16_t(speed_deg_s * (float(kFramePeriodMs) / 1000.0f) * (2000.0f / 180.0f) + 0.5f);
}
namespace servo_stage_detail {
template <typename S, uint8_t N, uint8_t kSlots, uint8_t... R, uint8_t... K>
constexpr JointChannels<S, N, kSlots> joint_channels(const RobotModel& m, walker_detail::Indices<R...>,
                                                     walker_detail::Indices<K...>) {
  return JointChannels<S, N, kSlots>{
      {(R < m.joint_count() ? joint_channel_constant<S>(m, uint8_t(R / m.dof()), uint8_t(R % m.dof()))
                            : ServoChannel<S>{})...},
      {(K < m.joint_count() ? joint_channel(m, uint8_t(K / m.dof()), uint8_t(K % m.dof())) : uint8_t(0))...},
      {(K < m.joint_count() ? joint_direction(m, uint8_t(K / m.dof()), uint8_t(K % m.dof())) : int8_t(1))...},
      uint8_t(m.joint_count() <= N && servo_tick_slots_fit(m, kSlots) ? channel_map_count_constant(m) : 0),
      {servo_step_us(servo_parts_detail::travel_of(m.servo[0]).speed_deg_s),
       servo_step_us(servo_parts_detail::travel_of(m.servo[1]).speed_deg_s),
       servo_step_us(servo_parts_detail::travel_of(m.servo[2]).speed_deg_s)}};
}
static_assert(kMaxLegDof == 3, "joint_channels: a step per joint of a leg");
}  // namespace servo_stage_detail
//! Model m's channels for a stage of N joints and kSlots tick-map slots.
template <typename S, uint8_t N, uint8_t kSlots = 0>
constexpr JointChannels<S, N, kSlots> joint_channels(const RobotModel& m) {
  using C = JointChannels<S, N, kSlots>;
  return servo_stage_detail::joint_channels<S, N, kSlots>(m, typename walker_detail::MakeIndices<C::kRanges>::type(),
                                                          typename walker_detail::MakeIndices<N>::type());
}

//! A stage's joint channels for build profile P: made from the model, or
//! (P::kStoredChannels) read from the constant P::kChannels.
template <typename S, typename P, bool kStored = P::kStoredChannels>
struct JointChannelSource {
  static uint8_t count(const RobotModel& m) {
    return m.joint_count() <= P::kJoints && servo_tick_slots_fit(m, P::kTickSlots) ? channel_map_count(m) : uint8_t(0);
  }
  static uint16_t step_us(ServoPart part, uint8_t) { return servo_step_us(servo_travel(part).speed_deg_s); }
  static ServoChannel<S> channel(const RobotModel& m, uint8_t leg, uint8_t j, uint8_t) {
    return make_joint_channel<S>(m, leg, j);
  }
};
template <typename S, typename P>
struct JointChannelSource<S, P, true> {
  static uint8_t count(const RobotModel&) { return flash_u8(&P::kChannels.count); }
  static uint16_t step_us(ServoPart, uint8_t j) { return flash_u16(&P::kChannels.step_us[0], j); }
  static ServoChannel<S> channel(const RobotModel&, uint8_t, uint8_t, uint8_t k) {
    ServoChannel<S> ch;
    flash_copy(&ch, &P::kChannels.range[k % JointChannels<S, P::kJoints, P::kTickSlots>::kRanges], sizeof ch);
    ch.channel = flash_u8(&P::kChannels.output[k]);
    ch.direction = int8_t(flash_u8(&P::kChannels.direction[k]));
    return ch;
  }
};

}  // namespace strider

#endif  // STRIDER_CONTROL_JOINT_CHANNELS_H
