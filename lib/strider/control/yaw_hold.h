//! YawHold: with an IMU fitted, the body turns at the rate commanded (the
//! firmware: none, walking straight; robot_sensing.h). Feet slide: a
//! sprawling trot veers by a degree a second either way (docs/imu.md,
//! "Heading hold"). Proportional and integral terms on the heading error
//! (the command's turn integrated, less the measured one) give a trim to
//! the turn the gait walks; a steady veer leaves no heading behind. A
//! changed stride turns the body over the next steps, so the gains go with
//! the step rate (kp = kYawHoldKpPerHz x Hz, critically damped: ki = kp^2
//! / 4). The gyro's zero-rate offset about up is learnt standing still (the
//! attitude filter cannot see it: no compass).
#ifndef STRIDER_CONTROL_YAW_HOLD_H
#define STRIDER_CONTROL_YAW_HOLD_H

#include <stdint.h>

#include "../math/scalar.h"
#include "reply.h"

namespace strider {

constexpr double kYawHoldKpPerHz = 1.0;         //!< trim per heading error [1/s] per step rate [Hz]
constexpr double kYawHoldMaxErrorDeg = 30.0;    //!< the heading error held at most [deg]
constexpr uint8_t kYawHoldEveryTicks = 10;      //!< ticks between trims (0.2 s: a new trim plans the gait again)
constexpr uint8_t kYawHoldSettleTicks = 50;     //!< after a new command, the speed ramp's second (at least) goes unheld
constexpr double kYawHoldMaxTrimDegS = 10.0;    //!< the trim's limit either way [deg/s]
constexpr int16_t kYawHoldTrimStepTenths = 5;   //!< the least change of trim applied [0.1 deg/s]
constexpr uint8_t kYawOffsetReadings = 50;      //!< still readings that give the offset (1 s at 50 Hz)
constexpr double kYawOffsetSpreadRadS = 0.035;  //!< their spread, max - min (2 deg/s: servos holding)

template <typename S>
class YawHold {
 public:
  //! One tick [dt s]: the gyro's rates about the body's y (its offset
  //! taken off: the attitude filter's) and z [rad/s], the body's roll and
  //! pitch [rad]; the command's turn [0.1 deg/s]; whether the robot walks
  //! a command (held) or stands still with none (the offset learnt); the
  //! gait's step rate [Hz]. True when trim_tenths() changed.
  bool step(S gyro_y_rad_s, S gyro_z_rad_s, S roll_rad, S pitch_rad, int32_t command_wz_tenths, bool walking,
            bool still, S step_hz, S dt) {
    if (!finite(gyro_z_rad_s) || !finite(gyro_y_rad_s)) return false;  // a bad reading: as if none
    if (still) learn(gyro_z_rad_s);
    else readings_ = 0;
    if (!walking || !learnt_ || command_wz_tenths != command_) return restart(command_wz_tenths);
    // Unheld: the speed ramp's second, and the gait's first cycle (its
    // first steps turn the body late; a lag made up later is a turn too fast).
    if (settle_ < kYawHoldSettleTicks || (settle_ < 255 && S(int(settle_)) * dt * step_hz < S(1))) {
      ++settle_;
      return false;
    }
    constexpr S kTenthsToRad = scalar<S>(3.14159265358979323846 / 1800.0);
    constexpr S kMaxErrorRad = scalar<S>(kYawHoldMaxErrorDeg * 0.017453292519943295);
    constexpr S kMaxRadS = scalar<S>(kYawHoldMaxTrimDegS * 0.017453292519943295);
    constexpr S kMaxIntegral = scalar<S>(1000.0);  // [rad s]: in Fixed's range; the term's limit comes first
    // The heading's rate (the Z-Y-X Euler yaw's), not the body z axis's: a
    // body rocking in roll and pitch at the step rate turns its z axis about
    // up by a few tenths of a degree a second (coning). Small angles:
    // (gy sin r + gz cos r) / cos p by their series, to within r^5/120,
    // r^4/24 and 5 p^4/24 (on the AVR a sine and two cosines a tick would
    // cost more than the rest of the hold).
    const S r2 = roll_rad * roll_rad, half = scalar<S>(0.5);
    const S sin_r = roll_rad * (S(1) - r2 * scalar<S>(1.0 / 6.0)), cos_r = S(1) - half * r2;
    const S heading_rate = (gyro_y_rad_s * sin_r + (gyro_z_rad_s - offset_) * cos_r) * (S(1) + half * pitch_rad * pitch_rad);
    const S behind = (S(command_wz_tenths) * kTenthsToRad - heading_rate) * dt;
    error_rad_ = clamp(error_rad_ + behind, -kMaxErrorRad, kMaxErrorRad);
    integral_ = clamp(integral_ + error_rad_ * dt, -kMaxIntegral, kMaxIntegral);
    if (++count_ < kYawHoldEveryTicks) return false;
    count_ = 0;
    const S kp = scalar<S>(kYawHoldKpPerHz) * step_hz, ki = kp * kp * scalar<S>(0.25);
    // The integral's term within the trim's limit: no wind-up held fast.
    S from_integral = ki * integral_;
    if (kMaxRadS < abs(from_integral) && ki > S(0)) {
      from_integral = from_integral < S(0) ? -kMaxRadS : kMaxRadS;
      integral_ = from_integral / ki;
    }
    constexpr S kDegPerRad = scalar<S>(57.29577951308232);
    constexpr S kMaxDegS = scalar<S>(kYawHoldMaxTrimDegS);
    const S trim_deg_s = clamp((kp * error_rad_ + from_integral) * kDegPerRad, -kMaxDegS, kMaxDegS);
    const int16_t trim = int16_t(to_tenths(trim_deg_s));
    // Changes of less than a step are left: each plans the gait again.
    if (trim - trim_ < kYawHoldTrimStepTenths && trim_ - trim < kYawHoldTrimStepTenths) return false;
    trim_ = trim;
    return true;
  }

  //! The turn to add to the command's [0.1 deg/s].
  int16_t trim_tenths() const { return trim_; }
  //! Whether the offset is known (a second standing still since power-up).
  bool learnt() const { return learnt_; }
  //! The gyro's zero-rate offset about z [rad/s]; 0 until learnt().
  S offset_rad_s() const { return offset_; }
  //! The heading the body is behind the command's [rad] (ahead: negative).
  S error_rad() const { return error_rad_; }

 private:
  //! Not held (standing, a new command): no error, no trim; true when the
  //! trim was not zero.
  bool restart(int32_t command_wz_tenths) {
    command_ = command_wz_tenths;
    error_rad_ = integral_ = S(0);
    count_ = 0;
    settle_ = 0;
    const bool changed = trim_ != 0;
    trim_ = 0;
    return changed;
  }

  //! A still reading: kYawOffsetReadings in a row within the spread give
  //! the offset, again every such run (it drifts with the die's temperature).
  void learn(S gz) {
    if (readings_ > 0) {
      const S low = gz < low_ ? gz : low_, high = high_ < gz ? gz : high_;
      if (scalar<S>(kYawOffsetSpreadRadS) < high - low) {
        readings_ = 0;  // it moved: start again from this reading
      } else {
        low_ = low;
        high_ = high;
      }
    }
    if (readings_ == 0) low_ = high_ = gz, sum_ = S(0);
    sum_ += gz;
    if (++readings_ < kYawOffsetReadings) return;
    offset_ = sum_ * scalar<S>(1.0 / kYawOffsetReadings);
    learnt_ = true;
    readings_ = 0;
  }

  static bool finite(float v) { return detail::is_finite(v); }
  static bool finite(Fixed) { return true; }

  S offset_ = S(0), sum_ = S(0), low_ = S(0), high_ = S(0);
  S error_rad_ = S(0), integral_ = S(0);  // [rad], [rad s]
  int32_t command_ = 0;
  int16_t trim_ = 0;
  uint8_t readings_ = 0, count_ = 0, settle_ = 0;  // settle_: ticks since restart(), to 255
  bool learnt_ = false;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_YAW_HOLD_H
