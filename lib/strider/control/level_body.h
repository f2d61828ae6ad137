//! LevelBody: holds the body level on a slope (`level on`): an integral
//! controller on the attitude's roll and pitch drives the body pose's, every
//! kLevelEveryTicks ticks (docs/imu.md, "Level body"). A pose the legs
//! cannot reach is refused and stays (no wind-up). It also keeps the fast
//! gains with which the filter learns the gyro's offset at power-up.
#ifndef STRIDER_CONTROL_LEVEL_BODY_H
#define STRIDER_CONTROL_LEVEL_BODY_H

#include <stdint.h>

#include "../math/scalar.h"
#include "../sensing/attitude_filter.h"

namespace strider {

constexpr double kLevelGain = 2.0;         //!< integral gain [1/s]: a 0.5 s time constant
constexpr uint8_t kLevelEveryTicks = 5;    //!< ticks between pose updates (0.1 s at 50 Hz)
constexpr double kLevelTickS = 0.02;       //!< the control tick [s] (robot_app.h's kTickPeriodUs)
constexpr double kLevelMaxRad = 30.0 * 0.017453292519943295;  //!< the `pose` command's own limit [rad]
constexpr double kLearnKp = 4.0;           //!< filter gains while learning the offset [1/s]
constexpr double kLearnKi = 4.0;           //!< ... [1/s^2]: critically damped, poles at -2/s

template <typename S>
class LevelBody {
 public:
  void set_enabled(bool on) {
    on_ = on;
    count_ = 0;
  }
  bool enabled() const { return on_; }

  //! The filter's gains g with the learning or the default kp and ki (a
  //! copy: a whole constant set would take 16 bytes of RAM on the AVR).
  static AttitudeGains<S> learning_gains(AttitudeGains<S> g, bool learning) {
    constexpr S kp = attitude_gains_default<S>().kp, ki = attitude_gains_default<S>().ki;
    g.kp = learning ? scalar<S>(kLearnKp) : kp;
    g.ki = learning ? scalar<S>(kLearnKi) : ki;
    return g;
  }
  void start_learning() { learning_ = true; }
  bool learning() const { return learning_; }
  void stop_learning() { learning_ = false; }

  //! One tick with the measured roll and pitch [rad] and the body pose's
  //! (in, out) [rad]; true when the pose changed and is to be applied.
  bool step(S roll_rad, S pitch_rad, S* pose_roll_rad, S* pose_pitch_rad) {
    if (!on_ || ++count_ < kLevelEveryTicks) return false;
    count_ = 0;
    constexpr S k = scalar<S>(kLevelGain * kLevelEveryTicks * kLevelTickS);
    constexpr S lim = scalar<S>(kLevelMaxRad);
    *pose_roll_rad = clamp(*pose_roll_rad - k * roll_rad, -lim, lim);
    *pose_pitch_rad = clamp(*pose_pitch_rad - k * pitch_rad, -lim, lim);
    return true;
  }

 private:
  bool on_ = false;
  bool learning_ = false;
  uint8_t count_ = 0;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_LEVEL_BODY_H
