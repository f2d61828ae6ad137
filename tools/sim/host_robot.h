// The firmware's hardware as the host build of its control chain sees it,
// shared by strider-sim's library driver and the gait tuner
// (tools/pso_bench/gait_tune.cpp): the PCA9685 boards behind RobotApp's
// ServoOutput, a blank EEPROM, and the pose the robot powers up in.
#ifndef STRIDER_SIM_HOST_ROBOT_H
#define STRIDER_SIM_HOST_ROBOT_H

#include <vector>

#include "control/robot_app.h"
#include "control/walker_motion.h"
#include "servo_model.h"

namespace strider_sim {

// The PCA9685 boards as the ServoOutput concept sees them: 12-bit off
// counts per channel and the prescale; pulse widths follow from the
// simulated oscillator, as on a real board.
struct PcaBoards {
  uint16_t ticks[kMaxChannels] = {};
  bool on[kMaxChannels] = {};
  uint8_t prescale = 121;
  void write_ticks(uint8_t ch, uint16_t off_ticks) {
    if (ch >= kMaxChannels) return;
    ticks[ch] = off_ticks;
    on[ch] = true;
  }
  void set_prescale(uint8_t p) { prescale = p; }
  void relax(uint8_t ch) {
    if (ch < kMaxChannels) on[ch] = false;
  }
  void flush() {}

  // What every channel sends with an oscillator of osc_hz (kMaxChannels entries).
  void pulses(double osc_hz, ChannelPulse* out) const {
    const double tick_us = (double(prescale) + 1.0) * 1e6 / osc_hz;
    for (int ch = 0; ch < kMaxChannels; ++ch) {
      out[ch].on = on[ch];
      out[ch].pulse_us = double(ticks[ch]) * tick_us;
    }
  }
};

using HostStore = strider::ArrayByteStore<4096>;
using HostApp = strider::RobotApp<float, PcaBoards, HostStore>;

// A RobotApp's boards and EEPROM, built before it (a base class of whatever
// holds the app): a new Mega, blank EEPROM and default settings.
struct HostParts {
  PcaBoards boards;
  HostStore store;
  HostParts() { store.erase(); }
};

// The pose the robot is in at power-up: the walker's sitting pose (feet
// down, body lowered), which is what its servos will first be sent to.
inline std::vector<double> sitting_joints(const strider::RobotModel& model) {
  strider::WalkerMotion<float> motion;
  std::vector<double> q;
  if (!motion.configure(model)) return q;
  for (int i = 0; i < model.leg_count; ++i)
    for (int j = 0; j < model.dof(); ++j) q.push_back(double(motion.walker().leg(uint8_t(i)).q[uint8_t(j)]));
  return q;
}

}  // namespace strider_sim

#endif  // STRIDER_SIM_HOST_ROBOT_H
