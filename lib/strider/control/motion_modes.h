//! MotionModes: the controller's robot mode and walking command. Motion
//! commands change the mode and go to the motion sink; every tick the
//! deadman and obstacle avoidance refine the command; a servo fault, a
//! critical battery or a fall stop the walk and refuse motion until cleared.
//!
//! MotionSink members (template concept, no virtual calls):
//!   void set_velocity(const Twist& v);   // [0.1 mm/s], [0.1 deg/s]; zero = step in place/stop;
//!                                         // a motion command, or avoidance changing it
//!   void stand();                         // stop walking and stand
//!   void relax();                         // servos limp
//!   bool set_gait(const char* name);      // false: no such gait for this robot
//!   void choose_pad_gait(const Twist& v); // an RC button's speed: the gait for it
//!   RcLimits pad_limits();                // the RC buttons' speeds at 100 %
//!   bool set_body_pose(int32_t roll, int32_t pitch, int32_t yaw);  // [0.1 deg]; false: refused
//!   bool set_body_height(int32_t height); // [0.1 mm]; false: out of the robot's range
//!   bool set_level(bool on);              // hold the body level; false: no IMU
//!   LevelCalStart start_level_cal();      // `cal level` (kStarted: level_cal_done() replies)
//!   void write_gait_names(ReplyWriter& w);  // its gaits and gait presets, space-separated
//!   const MotionReach& reach();           // heights and angles it reaches
//!   void apply_settings(const Settings& s);  // trims, oscillator, PWM frequency
//!   void write_status(ReplyWriter& w);    // appends its own ` key=value` fields to `status`
#ifndef STRIDER_CONTROL_MOTION_MODES_H
#define STRIDER_CONTROL_MOTION_MODES_H

#include <stdint.h>

#include "avoidance.h"
#include "command.h"
#include "deadman.h"
#include "reply_texts.h"
#include "robot_mode.h"
#include "settings.h"

namespace strider {

template <typename Sink>
class MotionModes {
 public:
  explicit MotionModes(Sink& sink)
      : sink_(sink), cmd_{0, 0, 0}, out_{0, 0, 0}, mode_(RobotMode::kStanding), avoid_clear_mm_(0),
        servo_fault_(false) {}

  //! The servos cannot walk (a board silent or starting again): a walk
  //! stops; motion commands are refused with err 31 until cleared.
  void set_servo_fault(bool fault) {
    if (fault && !servo_fault_ && mode_ == RobotMode::kWalking) stop();
    servo_fault_ = fault;
  }
  //! The battery is critically low: as a servo fault, with err 32.
  void set_battery_critical(bool critical) {
    if (critical && !battery_critical_ && mode_ == RobotMode::kWalking) stop();
    battery_critical_ = critical;
  }
  //! The robot tipped over: the servos go limp and motion commands are
  //! refused (err 33) until it is upright again.
  void set_fallen(bool fallen) {
    if (fallen && !fallen_ && mode_ != RobotMode::kCalibrating) {
      cmd_ = out_ = Twist{0, 0, 0};
      sink_.relax();
      mode_ = RobotMode::kRelaxed;
    }
    fallen_ = fallen;
  }
  bool fallen() const { return fallen_; }

  //! How far the body walks sideways after the way is clear (its half-width).
  void set_avoid_clear_mm(uint16_t mm) { avoid_clear_mm_ = mm; }

  RobotMode mode() const { return mode_; }
  const Twist& command() const { return cmd_; }      //!< operator's velocity
  uint8_t speed_pct() const { return speed_pct_; }

 protected:
  //! Deadman and avoidance on the walking command; true when *w holds a notice.
  bool tick_motion(uint32_t now_ms, const SonarReading& sonar, const Settings& settings, ReplyWriter& w,
                   int32_t walked_vy) {
    sonar_ = sonar;
    if (mode_ == RobotMode::kWalking && deadman_.expired(now_ms, true)) {
      stop();
      w.text(FlashText{text::kInfoDeadmanStop});
      return true;
    }
    if (mode_ != RobotMode::kWalking) return false;
    AvoidConfig cfg = default_avoid_config();
    cfg.enabled = settings.avoid_enabled != 0;
    cfg.stop_mm = settings.avoid_stop_mm;
    cfg.slow_mm = settings.avoid_slow_mm;
    cfg.clear_mm = avoid_clear_mm_;
    const AvoidState before = avoid_.state();
    // The sink hears of the velocity only when avoidance changes it: out_ is
    // what it walks (move() set it to the operator's command).
    const Twist next = avoid_.update(cmd_, sonar, now_ms, cfg, walked_vy);
    if (next.vx != out_.vx || next.vy != out_.vy || next.wz != out_.wz) {
      out_ = next;
      sink_.set_velocity(out_);
    }
    if (avoid_.state() != before && avoid_.state() != AvoidState::kPassThrough) {
      w.text(FlashText{text::kInfoAvoid_}).text(to_flash(avoid_.state()));
      return true;
    }
    return false;
  }

  void stop() {
    cmd_ = out_ = Twist{0, 0, 0};
    if (fallen_) return;  // limp until set upright (set_fallen())
    sink_.stand();
    if (mode_ == RobotMode::kWalking || mode_ == RobotMode::kRelaxed) mode_ = RobotMode::kStanding;
  }

  //! pad: an RC button, whose speed may change the gait (gait/gait_choice.h).
  void move(const Twist& t, ReplyWriter& w, bool pad = false) {
    if (mode_ == RobotMode::kCalibrating) return write_error(w, ControlError::kBusy, FlashText{text::kCalibrating});
    const bool still = t.vx == 0 && t.vy == 0 && t.wz == 0;
    if (servo_fault_ && !still) return write_error(w, ControlError::kServoFault, FlashText{text::kServoFault});
    if (battery_critical_ && !still)
      return write_error(w, ControlError::kBatteryCritical, FlashText{text::kBatteryCritical});
    if (fallen_ && !still) return write_error(w, ControlError::kFallen, FlashText{text::kFallen});
    cmd_ = t;
    if (still) {
      stop();
    } else {
      mode_ = RobotMode::kWalking;
      if (pad) sink_.choose_pad_gait(cmd_);
      out_ = cmd_;  // avoidance refines it on the next tick
      sink_.set_velocity(out_);
    }
    w.format(FlashText{text::kOkMoveFmt}, t.vx, t.vy, t.wz);
  }

  //! An RC button: its direction at the `speed` percentage, turning no
  //! slower than the gait's slowest honest turn (RcLimits::min_turn).
  void drive(const Command& c, ReplyWriter& w) {
    const RcLimits lim = sink_.pad_limits();
    const int32_t s = speed_pct_;
    int32_t wz = c.arg[2] * lim.turn * s / 100;
    if (wz != 0 && (wz < 0 ? -wz : wz) < lim.min_turn) wz = wz < 0 ? -lim.min_turn : lim.min_turn;
    move(Twist{c.arg[0] * lim.linear * s / 100, c.arg[1] * lim.linear * s / 100, wz}, w, true);
  }

  void relax(ReplyWriter& w) {
    if (mode_ == RobotMode::kCalibrating) return write_error(w, ControlError::kBusy, FlashText{text::kCalibrating});
    cmd_ = out_ = Twist{0, 0, 0};
    sink_.relax();
    mode_ = RobotMode::kRelaxed;
    w.text(FlashText{text::kOkRelax});
  }

  Sink& sink_;
  Deadman deadman_;
  Avoidance avoid_;
  SonarReading sonar_{SonarStatus::kNoData, kSonarFarMm};
  // Zero, by the constructor (but speed_pct_).
  Twist cmd_;
  Twist out_;
  RobotMode mode_;
  uint16_t avoid_clear_mm_;
  uint8_t speed_pct_ = 50;
  bool servo_fault_;
  bool battery_critical_ = false;
  bool fallen_ = false;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_MOTION_MODES_H
