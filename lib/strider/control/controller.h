//! Controller: dispatches parsed commands to a MotionSink (motion_modes.h)
//! and answers each text line with exactly one reply; keeps the settings in
//! force, their calibration and their saving (a ByteStore).
#ifndef STRIDER_CONTROL_CONTROLLER_H
#define STRIDER_CONTROL_CONTROLLER_H

#include <stdint.h>

#include "calibration.h"
#include "command_parser.h"
#include "error_hints.h"
#include "gait_commands.h"
#include "motion_modes.h"
#include "motion_reach.h"
#include "../sensing/level_calibration.h"

namespace strider {

namespace controller_detail {
//! The controller's own parser; none (no RAM) for a caller with its own.
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
class Controller : private controller_detail::ParserSlot<kOwnParser>, public MotionModes<Sink> {
  using Modes = MotionModes<Sink>;
  using Modes::sink_;
  using Modes::mode_;
  using Modes::stop;
  using Modes::deadman_;

 public:
  //! record: where `loaded` came from; the next save goes to the other slot.
  Controller(Sink& sink, Store& store, const Settings& loaded, SettingsStatus load_status,
             const SettingsRecord& record = SettingsRecord())
      : Modes(sink), store_(store), settings_(loaded), cal_(loaded), record_(record) {
    record_.load_status = load_status;
    apply_loaded();
  }
  Controller(Sink& sink, Store& store, const LoadedSettings& loaded)
      : Controller(sink, store, loaded.settings, loaded.record.load_status, loaded.record) {}

  //! One received byte; true when *w holds a reply line (no line ending).
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

  //! A parse result from one of the caller's parsers (one per port).
  bool on_parsed(ParseResult r, const Command& c, uint32_t now_ms, ReplyWriter& w) {
    return handle(r, c, now_ms, w);
  }

  //! Deadman and avoidance; walked_vy [0.1 mm/s] (Avoidance::update).
  //! True when *w holds a notice.
  bool tick(uint32_t now_ms, const SonarReading& sonar, ReplyWriter& w,
            int32_t walked_vy = Avoidance::kUnknownSpeed) {
    return this->tick_motion(now_ms, sonar, settings_, w, walked_vy);
  }

  //! The end of a `cal level` measurement: the offsets [mg] saved and
  //! applied, or why it failed (nothing changed).
  void level_cal_done(LevelCalStatus st, int8_t x_mg, int8_t y_mg, ReplyWriter& w) {
    if (st == LevelCalStatus::kMoving) return write_error(w, ControlError::kNotStill, FlashText{text::kNotStill});
    if (st == LevelCalStatus::kNoReading) return write_error(w, ControlError::kNoImu, FlashText{text::kNoImu});
    if (st != LevelCalStatus::kDone) return write_error(w, ControlError::kNotLevel, FlashText{text::kNotLevel});
    Settings s = settings_;
    s.accel_x_mg = x_mg;
    s.accel_y_mg = y_mg;
    if (save_settings(store_, s, &record_) != SettingsStatus::kOk)
      return write_error(w, ControlError::kStoreFailed, FlashText{text::kStoreFailed});
    settings_.accel_x_mg = x_mg;
    settings_.accel_y_mg = y_mg;
    w.format(FlashText{text::kOkCalLevelFmt}, int32_t(x_mg), int32_t(y_mg));
  }

  const Settings& settings() const { return settings_; }
  //! The record the settings in force came from, or the last one saved.
  const SettingsRecord& settings_record() const { return record_; }

 private:
  // Not inlined: the writer is then addressed through a register, not at
  // the far end of the caller's frame (flash).
  STRIDER_NOINLINE bool handle(ParseResult r, const Command& c, uint32_t now_ms, ReplyWriter& w) {
    if (r == ParseResult::kNothing) return false;
    if (r == ParseResult::kError) {
      write_parse_error(w, c, &sink_);
      return true;
    }
    if (c.kind != CommandKind::kRcEcho) deadman_.feed(now_ms);
    apply(c, w);
    return c.source != CommandSource::kBareByte;
  }

  //! err 24 with what the legs reach (pose: one angle at a time).
  void refused(ReplyWriter& w, bool pose) {
    const MotionReach& r = sink_.reach();
    write_error(w, ControlError::kRefused, pose ? FlashText{text::kPoseRefused_} : FlashText{text::kHeightRefused_});
    if (!pose) {
      w.format(FlashText{text::kHeightRangeFmt}, r.height_min_mm, r.height_max_mm);
      return;
    }
    w.format(FlashText{text::kPoseRangesFmt}, r.angle_min_deg[0], r.angle_max_deg[0], r.angle_min_deg[1]);
    w.format(FlashText{text::kPoseRanges2Fmt}, r.angle_max_deg[1], r.angle_min_deg[2], r.angle_max_deg[2]);
  }

  void apply(const Command& c, ReplyWriter& w) {
    switch (c.kind) {
      case CommandKind::kDrive: return this->drive(c, w);
      case CommandKind::kMove: return this->move(Twist{c.arg[0], c.arg[1], c.arg[2]}, w);
      case CommandKind::kStop: stop(); w.text(FlashText{text::kOkStop}); return;
      case CommandKind::kRelax: return this->relax(w);
      case CommandKind::kSpeed:
        this->speed_pct_ = uint8_t(c.arg[0]);
        w.format(FlashText{text::kOkSpeedFmt}, c.arg[0]);
        return;
      case CommandKind::kGait: return apply_gait(sink_, c, w);
      case CommandKind::kPose:
        if (!sink_.set_body_pose(c.arg[0], c.arg[1], c.arg[2])) return refused(w, true);
        w.format(FlashText{text::kOkPoseFmt}, c.arg[0], c.arg[1], c.arg[2]);
        return;
      case CommandKind::kHeight:
        if (!sink_.set_body_height(c.arg[0])) return refused(w, false);
        w.format(FlashText{text::kOkHeightFmt}, c.arg[0]);
        return;
      case CommandKind::kLevel:
        if (!sink_.set_level(c.arg[0] != 0)) return write_error(w, ControlError::kNoImu, FlashText{text::kNoImu});
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
        if (s != CalStatus::kOk) return write_error(w, ControlError::kNotCalibrating, FlashText{text::kCalStartFirst});
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
        if (mode_ == RobotMode::kCalibrating) return write_error(w, ControlError::kBusy, FlashText{text::kCalibrating});
        switch (mode_ != RobotMode::kStanding ? LevelCalStart::kNotStill : sink_.start_level_cal()) {
          case LevelCalStart::kNoImu: return write_error(w, ControlError::kNoImu, FlashText{text::kNoImu});
          case LevelCalStart::kNotStill: return write_error(w, ControlError::kNotStill, FlashText{text::kNotStill});
          default: return;  // measuring: no reply yet (level_cal_done())
        }
      case CommandKind::kCalSave: {
        if (!cal_.active()) return write_error(w, ControlError::kNotCalibrating, FlashText{text::kCalStartFirst});
        if (cal_.save(store_, settings_, &record_) != CalStatus::kOk) return write_error(w, ControlError::kStoreFailed, FlashText{text::kStoreFailed});
        settings_ = cal_.live();  // what was saved
        mode_ = RobotMode::kStanding;
        w.text(FlashText{text::kOkCalSaved});
        return;
      }
      case CommandKind::kCalAbort:
        if (!cal_.active()) return write_error(w, ControlError::kNotCalibrating, FlashText{text::kCalStartFirst});
        cal_.abort(settings_);
        sink_.apply_settings(cal_.live());
        mode_ = RobotMode::kStanding;
        w.text(FlashText{text::kOkCalAborted});
        return;
      case CommandKind::kSave: {
        Settings s = settings_;
        s.speed_pct = this->speed_pct_;
        if (save_settings(store_, s, &record_) != SettingsStatus::kOk || !sink_.save_tuning())
          return write_error(w, ControlError::kStoreFailed, FlashText{text::kStoreFailed});
        settings_ = s;
        w.text(FlashText{text::kOkSaved});
        return;
      }
      case CommandKind::kStatus: return status(w);
      case CommandKind::kHelp: {
        const MotionReach& r = sink_.reach();
        w.text(FlashText{text::kOkHelp_}).text(FlashText{text::kCommandList});
        sink_.write_gait_names(w.text(FlashText{text::kHelpGaits_}));
        w.format(FlashText{text::kHelpHeightFmt}, r.height_min_mm, r.height_max_mm);
        return;
      }
      case CommandKind::kSet:
        if (mode_ == RobotMode::kCalibrating) return write_error(w, ControlError::kBusy, FlashText{text::kCalibrating});
        return set_tuning(sink_, c, w);
      case CommandKind::kGet: return get_tuning(sink_, w);
      case CommandKind::kLight: w.text(FlashText{text::kOkLightIgnored}); return;
      case CommandKind::kRcEcho: w.text(FlashText{text::kOkRc_}).ch(char(c.arg[0])); return;
      default: w.text(FlashText{text::kOk}); return;
    }
  }

  void status(ReplyWriter& w) {
    w.text(FlashText{text::kOkStatus}).field_text(FlashText{text::kMode}, to_flash(mode_));
    const Twist& out = this->out_;
    const SonarReading& sonar = this->sonar_;
    w.format(FlashText{text::kStatusSpeedFmt}, this->speed_pct_, out.vx, out.vy).field_tenths(FlashText{text::kWz}, out.wz);
    w.field_text(FlashText{text::kAvoid}, settings_.avoid_enabled ? to_flash(this->avoid_.state()) : FlashText{text::kOff});
    w.field_text(FlashText{text::kSonar}, flash_name(text::kSonarStatusNames, 4, uint8_t(sonar.status)));
    if (sonar.status == SonarStatus::kOk && sonar.distance_mm != kSonarFarMm) w.field(FlashText{text::kDistMm}, sonar.distance_mm);
    w.field(FlashText{text::kDeadmanMs}, settings_.deadman_ms).field_text(FlashText{text::kEeprom}, to_flash(record_.load_status));
    sink_.write_status(w);
  }

  Store& store_;
  Settings settings_;
  Calibration cal_;
  SettingsRecord record_;  // and how the settings loaded at start-up
  void apply_loaded() {
    deadman_.set_timeout(settings_.deadman_ms);
    this->speed_pct_ = settings_.speed_pct;
    sink_.apply_settings(settings_);
  }
};

}  // namespace strider

#endif  // STRIDER_CONTROL_CONTROLLER_H
