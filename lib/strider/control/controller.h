//! Controller: applies parsed commands to a motion sink, answers each text
//! line with exactly one reply, and runs the deadman and obstacle avoidance
//! every tick. It knows nothing of the gait engine: the firmware binds a
//! MotionSink (gait engine), a ByteStore (EEPROM) and feeds it bytes, sonar
//! readings and the time [ms].
//!
//! MotionSink members (template concept, no virtual calls):
//!   void set_velocity(const Twist& v);   // [0.1 mm/s], [0.1 deg/s]; zero = step in place/stop
//!   void stand();                         // stop walking and stand
//!   void relax();                         // servos limp
//!   bool set_gait(const char* name);      // false: no such gait for this robot
//!   void choose_pad_gait(const Twist& v); // an RC button's speed: the gait for it (gait/gait_choice.h)
//!   RcLimits pad_limits();                // the RC buttons' speeds at 100 % (walker_motion.h)
//!   bool set_body_pose(int32_t roll, int32_t pitch, int32_t yaw);  // [0.1 deg]; false: refused
//!   bool set_body_height(int32_t height); // [0.1 mm]; false: out of the robot's range
//!   bool set_level(bool on);              // hold the body level (level_body.h); false: no IMU
//!   LevelCalStart start_level_cal();      // `cal level`: measure the accelerometer's offsets
//!                                         // (kStarted: the reply follows, level_cal_done())
//!   const char* gait_names();             // the robot's gaits, space-separated, in flash
//!   const MotionReach& reach();           // heights and angles it reaches (motion_reach.h)
//!   void apply_settings(const Settings& s);  // trims, oscillator, PWM frequency
//!   void write_status(ReplyWriter& w);    // appends its own ` key=value` fields to `status`
#ifndef STRIDER_CONTROL_CONTROLLER_H
#define STRIDER_CONTROL_CONTROLLER_H

#include <stdint.h>

#include "avoidance.h"
#include "calibration.h"
#include "command_parser.h"
#include "deadman.h"
#include "error_hints.h"
#include "motion_reach.h"
#include "reply.h"
#include "reply_texts.h"
#include "robot_mode.h"
#include "../sensing/level_calibration.h"

namespace strider {

namespace controller_detail {
//! The controller's own parser (on_byte(), on_idle()); none for a caller
//! with parsers of its own (on_parsed() only): no RAM for an unused line.
template <bool kOwn>
struct ParserSlot {
  ParserSlot() = default;
  CommandParser parser_;
};
template <>
struct ParserSlot<false> {
  ParserSlot() = default;
};
}  // namespace controller_detail

//! kOwnParser false: only on_parsed() takes input (RobotApp, one parser per port).
template <typename Sink, typename Store, bool kOwnParser = true>
class Controller : private controller_detail::ParserSlot<kOwnParser> {
 public:
  //! record: where `loaded` came from (load_settings()); the next save
  //! goes to the other slot.
  Controller(Sink& sink, Store& store, const Settings& loaded, SettingsStatus load_status,
             const SettingsRecord& record = SettingsRecord())
      : sink_(sink), store_(store), settings_(loaded), cal_(loaded), record_(record), cmd_{0, 0, 0},
        out_{0, 0, 0}, mode_(RobotMode::kStanding), avoid_clear_mm_(0), servo_fault_(false) {
    record_.load_status = load_status;
    apply_loaded();
  }
  //! The same from the settings the store gave (settings_store.h).
  Controller(Sink& sink, Store& store, const LoadedSettings& loaded)
      : Controller(sink, store, loaded.settings, loaded.record.load_status, loaded.record) {}

  //! One received byte at now_ms. Returns true when *w holds a reply line
  //! (without line ending) to send.
  bool on_byte(uint8_t b, uint32_t now_ms, ReplyWriter& w) {
    Command c;
    const ParseResult r = this->parser_.feed(b, &c);
    return handle(r, c, now_ms, w);
  }

  //! No byte for a while: abandons a partial line (reply on true).
  bool on_idle(uint32_t now_ms, ReplyWriter& w) {
    Command c;
    return handle(this->parser_.idle_timeout(&c), c, now_ms, w);
  }

  //! A parse result from a parser of the caller's (one per serial port, so
  //! two links never mix their bytes). Returns true when *w holds a reply.
  bool on_parsed(ParseResult r, const Command& c, uint32_t now_ms, ReplyWriter& w) {
    return handle(r, c, now_ms, w);
  }

  //! One control tick: deadman and avoidance; sends the walking command.
  //! walked_vy: the sideways speed the gait really walks [0.1 mm/s]
  //! (Avoidance::update). Returns true when *w holds a notice (`info ...`).
  bool tick(uint32_t now_ms, const SonarReading& sonar, ReplyWriter& w,
            int32_t walked_vy = Avoidance::kUnknownSpeed) {
    sonar_ = sonar;
    if (mode_ == RobotMode::kWalking && deadman_.expired(now_ms, true)) {
      stop();
      w.text(FlashText{text::kInfoDeadmanStop});
      return true;
    }
    if (mode_ != RobotMode::kWalking) return false;
    AvoidConfig cfg = default_avoid_config();
    cfg.enabled = settings_.avoid_enabled != 0;
    cfg.stop_mm = settings_.avoid_stop_mm;
    cfg.slow_mm = settings_.avoid_slow_mm;
    cfg.clear_mm = avoid_clear_mm_;
    const AvoidState before = avoid_.state();
    out_ = avoid_.update(cmd_, sonar, now_ms, cfg, walked_vy);
    sink_.set_velocity(out_);
    if (avoid_.state() != before && avoid_.state() != AvoidState::kPassThrough) {
      w.text(FlashText{text::kInfoAvoid_}).text(to_flash(avoid_.state()));
      return true;
    }
    return false;
  }

  //! The servos cannot walk (RobotApp: a servo board does not answer, or
  //! its legs are being switched on again): a walk stops and the robot
  //! stands; motion commands are refused with err 31 until cleared. Stop,
  //! relax and everything else still work.
  void set_servo_fault(bool fault) {
    if (fault && !servo_fault_ && mode_ == RobotMode::kWalking) stop();
    servo_fault_ = fault;
  }
  bool servo_fault() const { return servo_fault_; }
  //! The battery is critically low (RobotApp): like a servo fault, a walk
  //! stops and motion commands are refused, with err 32, until it recovers.
  void set_battery_critical(bool critical) {
    if (critical && !battery_critical_ && mode_ == RobotMode::kWalking) stop();
    battery_critical_ = critical;
  }
  bool battery_critical() const { return battery_critical_; }
  //! The robot tipped over (RobotApp, from the IMU): the servos go limp
  //! (relaxed, so that no leg fights the ground) and motion commands are
  //! refused, with err 33, until it is upright again; then a motion command
  //! wakes it as after `relax`.
  void set_fallen(bool fallen) {
    if (fallen && !fallen_ && mode_ != RobotMode::kCalibrating) {
      cmd_ = out_ = Twist{0, 0, 0};
      sink_.relax();
      mode_ = RobotMode::kRelaxed;
    }
    fallen_ = fallen;
  }
  bool fallen() const { return fallen_; }

  //! How far the body walks sideways after the sensor sees the way clear:
  //! the robot's half-width with its feet (RobotApp sets it from the model).
  void set_avoid_clear_mm(uint16_t mm) { avoid_clear_mm_ = mm; }

  //! The end of a `cal level` measurement (RobotApp, after start_level_cal()
  //! said kStarted): done, the offsets [mg] saved with the settings in force
  //! and applied; or why it failed (nothing changed). *w: the reply.
  void level_cal_done(LevelCalStatus st, int8_t x_mg, int8_t y_mg, ReplyWriter& w) {
    if (st == LevelCalStatus::kMoving) return fail(w, ControlError::kNotStill, FlashText{text::kNotStill});
    if (st == LevelCalStatus::kNoReading) return fail(w, ControlError::kNoImu, FlashText{text::kNoImu});
    if (st != LevelCalStatus::kDone) return fail(w, ControlError::kNotLevel, FlashText{text::kNotLevel});
    Settings s = settings_;
    s.accel_x_mg = x_mg;
    s.accel_y_mg = y_mg;
    if (save_settings(store_, s, &record_) != SettingsStatus::kOk)
      return fail(w, ControlError::kStoreFailed, FlashText{text::kStoreFailed});
    settings_.accel_x_mg = x_mg;
    settings_.accel_y_mg = y_mg;
    w.format(FlashText{text::kOkCalLevelFmt}, int32_t(x_mg), int32_t(y_mg));
  }

  RobotMode mode() const { return mode_; }
  const Twist& command() const { return cmd_; }      //!< operator's velocity
  const Twist& output() const { return out_; }       //!< after avoidance
  const Settings& settings() const { return settings_; }
  SettingsStatus load_status() const { return record_.load_status; }
  //! The record the settings in force came from, or the last one saved.
  const SettingsRecord& settings_record() const { return record_; }
  uint8_t speed_pct() const { return speed_pct_; }

 private:
  // Not inlined into the callers: they keep a reply buffer on the stack, and
  // the replies' code addresses the writer through a register here instead
  // of at the far end of the caller's frame (flash).
  STRIDER_NOINLINE bool handle(ParseResult r, const Command& c, uint32_t now_ms, ReplyWriter& w) {
    if (r == ParseResult::kNothing) return false;
    if (r == ParseResult::kError) {
      write_parse_error(w, c, sink_.gait_names());
      return true;
    }
    if (c.kind != CommandKind::kRcEcho) deadman_.feed(now_ms);
    apply(c, w);
    return c.source != CommandSource::kBareByte;
  }

  void fail(ReplyWriter& w, ControlError e, FlashText reason) { write_error(w, uint8_t(e), reason); }

  //! err 24 with what the legs reach (pose: one angle at a time).
  void refused(ReplyWriter& w, bool pose) {
    const MotionReach& r = sink_.reach();
    fail(w, ControlError::kRefused, pose ? FlashText{text::kPoseRefused_} : FlashText{text::kHeightRefused_});
    if (!pose) {
      w.format(FlashText{text::kHeightRangeFmt}, r.height_min_mm, r.height_max_mm);
      return;
    }
    w.format(FlashText{text::kPoseRangesFmt}, r.angle_min_deg[0], r.angle_max_deg[0], r.angle_min_deg[1]);
    w.format(FlashText{text::kPoseRanges2Fmt}, r.angle_max_deg[1], r.angle_min_deg[2], r.angle_max_deg[2]);
  }

  void stop() {
    cmd_ = out_ = Twist{0, 0, 0};
    if (fallen_) return;  // limp until set upright (set_fallen())
    sink_.stand();
    if (mode_ == RobotMode::kWalking || mode_ == RobotMode::kRelaxed) mode_ = RobotMode::kStanding;
  }

  //! pad: an RC button, whose speed may change the gait (gait/gait_choice.h).
  void move(const Twist& t, ReplyWriter& w, bool pad = false) {
    if (mode_ == RobotMode::kCalibrating) return fail(w, ControlError::kBusy, FlashText{text::kCalibrating});
    const bool still = t.vx == 0 && t.vy == 0 && t.wz == 0;
    if (servo_fault_ && !still) return fail(w, ControlError::kServoFault, FlashText{text::kServoFault});
    if (battery_critical_ && !still) return fail(w, ControlError::kBatteryCritical, FlashText{text::kBatteryCritical});
    if (fallen_ && !still) return fail(w, ControlError::kFallen, FlashText{text::kFallen});
    cmd_ = t;
    if (still) {
      stop();
    } else {
      mode_ = RobotMode::kWalking;
      if (pad) sink_.choose_pad_gait(cmd_);
      sink_.set_velocity(cmd_);  // avoidance refines it on the next tick
    }
    w.format(FlashText{text::kOkMoveFmt}, t.vx, t.vy, t.wz);
  }

  void apply(const Command& c, ReplyWriter& w) {
    switch (c.kind) {
      case CommandKind::kDrive: {
        const RcLimits lim = sink_.pad_limits();
        const int32_t s = speed_pct_;
        return move(Twist{c.arg[0] * lim.linear * s / 100, c.arg[1] * lim.linear * s / 100,
                          c.arg[2] * lim.turn * s / 100}, w, true);
      }
      case CommandKind::kMove: return move(Twist{c.arg[0], c.arg[1], c.arg[2]}, w);
      case CommandKind::kStop: stop(); w.text(FlashText{text::kOkStop}); return;
      case CommandKind::kRelax:
        if (mode_ == RobotMode::kCalibrating) return fail(w, ControlError::kBusy, FlashText{text::kCalibrating});
        cmd_ = out_ = Twist{0, 0, 0};
        sink_.relax();
        mode_ = RobotMode::kRelaxed;
        w.text(FlashText{text::kOkRelax});
        return;
      case CommandKind::kSpeed:
        speed_pct_ = uint8_t(c.arg[0]);
        w.format(FlashText{text::kOkSpeedFmt}, c.arg[0]);
        return;
      case CommandKind::kGait:
        if (!sink_.set_gait(c.word)) {
          fail(w, ControlError::kUnknownGait, FlashText{text::kUnknownGait_});
          w.text(FlashText{sink_.gait_names()});
          return;
        }
        w.text(FlashText{text::kOkGait_}).text(c.word);
        return;
      case CommandKind::kPose:
        if (!sink_.set_body_pose(c.arg[0], c.arg[1], c.arg[2])) return refused(w, true);
        w.format(FlashText{text::kOkPoseFmt}, c.arg[0], c.arg[1], c.arg[2]);
        return;
      case CommandKind::kHeight:
        if (!sink_.set_body_height(c.arg[0])) return refused(w, false);
        w.format(FlashText{text::kOkHeightFmt}, c.arg[0]);
        return;
      case CommandKind::kLevel:
        if (!sink_.set_level(c.arg[0] != 0)) return fail(w, ControlError::kNoImu, FlashText{text::kNoImu});
        w.text(FlashText{text::kOkLevel_}).text(c.arg[0] ? FlashText{text::kOn} : FlashText{text::kOff});
        return;
      case CommandKind::kAvoidEnable:
        settings_.avoid_enabled = uint8_t(c.arg[0]);
        w.text(FlashText{text::kOkAvoid_}).text(c.arg[0] ? FlashText{text::kOn} : FlashText{text::kOff});
        return;
      case CommandKind::kAvoidLimits:
        settings_.avoid_stop_mm = uint16_t(c.arg[0]);
        settings_.avoid_slow_mm = uint16_t(c.arg[1]);
        w.format(FlashText{text::kOkAvoidFmt}, c.arg[0], c.arg[1]);
        return;
      case CommandKind::kDeadman:
        settings_.deadman_ms = uint16_t(c.arg[0]);
        deadman_.set_timeout(settings_.deadman_ms);
        if (c.arg[0] == 0) w.text(FlashText{text::kOkDeadmanOff});
        else w.format(FlashText{text::kOkDeadmanFmt}, c.arg[0]);
        return;
      case CommandKind::kBaud:
        settings_.baud = uint32_t(c.arg[0]);
        w.format(FlashText{text::kOkBaudFmt}, c.arg[0]);
        return;
      default: return apply_cal(c, w);
    }
  }

  void apply_cal(const Command& c, ReplyWriter& w) {
    switch (c.kind) {
      case CommandKind::kCalStart:
        stop();
        cal_.start(settings_);
        mode_ = RobotMode::kCalibrating;
        w.text(FlashText{text::kOkCalStart});
        return;
      case CommandKind::kCalTrim:
      case CommandKind::kCalOsc:
      case CommandKind::kCalPwm: {
        const CalStatus s = c.kind == CommandKind::kCalTrim ? cal_.set_trim(uint8_t(c.arg[0]), int16_t(c.arg[1]))
                            : c.kind == CommandKind::kCalOsc ? cal_.set_oscillator(uint32_t(c.arg[0]))
                                                             : cal_.set_pwm(uint16_t(c.arg[0]));
        if (s != CalStatus::kOk) return fail(w, ControlError::kNotCalibrating, FlashText{text::kCalStartFirst});
        sink_.apply_settings(cal_.live());
        w.format(c.kind == CommandKind::kCalTrim ? FlashText{text::kOkCalTrimFmt}
                 : c.kind == CommandKind::kCalOsc ? FlashText{text::kOkCalOscFmt} : FlashText{text::kOkCalPwmFmt},
                 c.arg[0], c.arg[1]);
        return;
      }
      case CommandKind::kCalShow:
        w.format(FlashText{text::kOkCalShowFmt}, int32_t(cal_.live().pca_osc_hz));
        for (uint8_t i = 0; i < kMaxServoJoints; ++i) {
          if (i) w.ch(',');
          w.tenths(cal_.live().trim_decideg[i]);
        }
        w.format(FlashText{text::kLevelMgFmt}, int32_t(settings_.accel_x_mg), int32_t(settings_.accel_y_mg));
        return;
      case CommandKind::kCalLevel:
        if (mode_ == RobotMode::kCalibrating) return fail(w, ControlError::kBusy, FlashText{text::kCalibrating});
        switch (mode_ != RobotMode::kStanding ? LevelCalStart::kNotStill : sink_.start_level_cal()) {
          case LevelCalStart::kNoImu: return fail(w, ControlError::kNoImu, FlashText{text::kNoImu});
          case LevelCalStart::kNotStill: return fail(w, ControlError::kNotStill, FlashText{text::kNotStill});
          default: return;  // measuring: no reply yet (level_cal_done())
        }
      case CommandKind::kCalSave: {
        if (!cal_.active()) return fail(w, ControlError::kNotCalibrating, FlashText{text::kCalStartFirst});
        if (cal_.save(store_, settings_, &record_) != CalStatus::kOk) return fail(w, ControlError::kStoreFailed, FlashText{text::kStoreFailed});
        settings_ = cal_.live();  // what was saved
        mode_ = RobotMode::kStanding;
        w.text(FlashText{text::kOkCalSaved});
        return;
      }
      case CommandKind::kCalAbort:
        if (!cal_.active()) return fail(w, ControlError::kNotCalibrating, FlashText{text::kCalStartFirst});
        cal_.abort(settings_);
        sink_.apply_settings(cal_.live());
        mode_ = RobotMode::kStanding;
        w.text(FlashText{text::kOkCalAborted});
        return;
      case CommandKind::kSave: {
        Settings s = settings_;
        s.speed_pct = speed_pct_;
        if (save_settings(store_, s, &record_) != SettingsStatus::kOk || !sink_.save_tuning())
          return fail(w, ControlError::kStoreFailed, FlashText{text::kStoreFailed});
        settings_ = s;
        w.text(FlashText{text::kOkSaved});
        return;
      }
      case CommandKind::kStatus: return status(w);
      case CommandKind::kHelp: {
        const MotionReach& r = sink_.reach();
        w.text(FlashText{text::kOkHelp_}).text(FlashText{text::kCommandList});
        w.text(FlashText{text::kHelpGaits_}).text(FlashText{sink_.gait_names()});
        w.format(FlashText{text::kHelpHeightFmt}, r.height_min_mm, r.height_max_mm);
        return;
      }
      case CommandKind::kSet: return set_tuning(c, w);
      case CommandKind::kGet:
        w.text(FlashText{text::kOkGet}).field_text(FlashText{text::kGaitKey}, sink_.gait_name());
        sink_.write_tuning(w);
        return;
      case CommandKind::kLight: w.text(FlashText{text::kOkLightIgnored}); return;
      case CommandKind::kRcEcho: w.text(FlashText{text::kOkRc_}).ch(char(c.arg[0])); return;
      default: w.text(FlashText{text::kOk}); return;
    }
  }

  //! `set PARAM VALUE`: `ok set step_height 15.00`, or err 25 with the
  //! parameter's range (the swing: the shapes allowed).
  void set_tuning(const Command& c, ReplyWriter& w) {
    if (mode_ == RobotMode::kCalibrating) return fail(w, ControlError::kBusy, FlashText{text::kCalibrating});
    const TuneParam p = TuneParam(c.arg[0]);
    const FlashText name = flash_name(kTuneParamNames, kTuneParamCount, uint8_t(p));
    if (!sink_.tune(p, c.arg[1])) {
      const TuneRange r = sink_.tune_range(p);
      write_error(w, uint8_t(ControlError::kTuneRefused), name);
      if (p != TuneParam::kSwing) {
        w.text(FlashText{text::kOutOfRange_}).hundredths(r.lo).ch('.').ch('.').hundredths(r.hi);
        return;
      }
      w.text(FlashText{text::kNotWithin_});
      for (uint8_t k = 0, n = 0; k < kSwingShapeCount; ++k)
        if ((r.lo >> k) & 1) (n++ != 0 ? w.ch(' ') : w).text(flash_name(kSwingShapeNames, kSwingShapeCount, k));
      return;
    }
    w.text(FlashText{text::kOkSet_}).text(name).ch(' ');
    if (p == TuneParam::kSwing) w.text(flash_name(kSwingShapeNames, kSwingShapeCount, uint8_t(c.arg[1])));
    else w.hundredths(c.arg[1]);
  }

  void status(ReplyWriter& w) {
    w.text(FlashText{text::kOkStatus}).field_text(FlashText{text::kMode}, to_flash(mode_));
    w.format(FlashText{text::kStatusSpeedFmt}, speed_pct_, out_.vx, out_.vy).field_tenths(FlashText{text::kWz}, out_.wz);
    w.field_text(FlashText{text::kAvoid}, settings_.avoid_enabled ? to_flash(avoid_.state()) : FlashText{text::kOff});
    w.field_text(FlashText{text::kSonar}, flash_name(text::kSonarStatusNames, 4, uint8_t(sonar_.status)));
    if (sonar_.status == SonarStatus::kOk && sonar_.distance_mm != kSonarFarMm) w.field(FlashText{text::kDistMm}, sonar_.distance_mm);
    w.field(FlashText{text::kDeadmanMs}, settings_.deadman_ms).field_text(FlashText{text::kEeprom}, to_flash(record_.load_status));
    sink_.write_status(w);
  }

  Sink& sink_;
  Store& store_;
  Settings settings_;
  Calibration cal_;
  SettingsRecord record_;  // and how the settings loaded at start-up
  // Both constructors: the loaded settings into the deadman, the speed and the sink.
  void apply_loaded() {
    deadman_.set_timeout(settings_.deadman_ms);
    speed_pct_ = settings_.speed_pct;
    sink_.apply_settings(settings_);
  }

  Deadman deadman_;
  Avoidance avoid_;
  SonarReading sonar_{SonarStatus::kNoData, kSonarFarMm};
  // Zero, by the constructors (but speed_pct_).
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

#endif  // STRIDER_CONTROL_CONTROLLER_H
