//! RobotAppSink: RobotApp's MotionSink (motion_modes.h): the controller's
//! commands to the walker, servo stage, gait tuner and sensing, and
//! RobotApp's fields of `status`.
#ifndef STRIDER_CONTROL_ROBOT_APP_SINK_H
#define STRIDER_CONTROL_ROBOT_APP_SINK_H

#include <stdint.h>

#include "../gait/gait_presets.h"
#include "../gait/gait_tuning.h"
#include "gait_commands.h"
#include "gait_tuner.h"
#include "motion_reach.h"
#include "reply_texts.h"
#include "robot_mode.h"
#include "servo_map.h"
#include "settings.h"
#include "walker_motion.h"

namespace strider {

//! ` walk_vx= ...`: the command as the body speed it makes (speed_correction.h),
//! the gait, its state, IK, servos, tuning origin unless the model's own.
template <typename S, typename P, typename Stage>
void write_motion_status(ReplyWriter& w, const WalkerMotion<S, P>& motion, const Stage& stage, TuneOrigin origin) {
  const auto& e = motion.walker().engine();
  w.format(FlashText{text::kWalkFmt}, motion.body_speed(to_tenths(e.vx())), motion.body_speed(to_tenths(e.vy())),
           motion.body_speed(to_tenths(e.wz() * scalar<S>(1.0 / kDegToRad)), true));
  const FlashText servos = stage.all_on() ? FlashText{text::kOn}
                           : stage.starting() ? FlashText{text::kStarting} : FlashText{text::kOff};
  w.field_text(FlashText{text::kGaitKey}, motion.gait().name)
      .field_text(FlashText{text::kState}, text::to_flash(e.state()))
      .field_text(FlashText{text::kIk}, text::to_flash(motion.walker().worst_status()))
      .field_text(FlashText{text::kServos}, servos);
  if (stage.last_status() != ServoStatus::kOk) w.field_text(FlashText{text::kServos}, FlashText{text::kLimited});
  if (origin != TuneOrigin::kDefault) w.field_text(FlashText{text::kTune}, to_flash(origin));
}

template <typename App>
class RobotAppSink {
 public:
  explicit RobotAppSink(App& app) : app_(app) {}
  void set_velocity(const Twist& v) {
    wake();
    app_.motion_.set_velocity(v);
  }
  void stand() {
    wake();
    app_.motion_.stand();
  }
  void relax() {
    app_.stage_.relax_all();
    app_.motion_.sit_now();
  }
  //! A library gait, or one of the model's presets (gait_presets.h): its
  //! gait, then its parameters, then its own speed correction if listed.
  bool set_gait(const char* name) {
    GaitPreset preset;
    const bool is_preset = find_gait_preset<App::Profile::kModelIndex>(app_.name_, name, &preset);
    if (!app_.motion_.set_gait(is_preset ? preset.gait : name)) return false;
    app_.tuner_.use_gait(app_.motion_, app_.store_);
    app_.motion_.set_stance_motion(is_preset ? preset.stance_step_dmm : 0, is_preset && preset.on_all_feet);
    if (!is_preset) return true;
    if (!apply_gait_preset(preset, [this](TuneParam p, int32_t v) { return tune(p, v); })) return false;
    app_.motion_.correct_as_preset(preset.name);
    return true;
  }
  RcLimits pad_limits() const { return app_.motion_.pad_limits(); }
  void choose_pad_gait(const Twist& v) {
    char name[kGaitNameBytes];
    if (app_.motion_.pad_gait(v, name)) set_gait(name);
  }
  const char* gait_name() const { return app_.motion_.gait().name; }
  bool tune(TuneParam p, int32_t v) { return app_.tuner_.set(app_.motion_, p, v); }
  TuneRange tune_range(TuneParam p) const { return app_.tuner_.range(app_.motion_, p); }
  void write_tuning(ReplyWriter& w) const { app_.tuner_.write(app_.motion_, w); }
  bool save_tuning() { return app_.tuner_.save(app_.motion_, app_.store_) == SettingsStatus::kOk; }
  bool set_body_pose(int32_t r, int32_t p, int32_t y) { return app_.motion_.set_body_pose(r, p, y); }
  bool set_body_height(int32_t h) { return app_.motion_.set_body_height(h); }
  bool set_level(bool on) { return app_.sensing_.set_level(on, app_.motion_); }
  LevelCalStart start_level_cal() { return app_.sensing_.start_level_cal(app_.motion_, app_.stage_.all_on()); }
  void write_gait_names(ReplyWriter& w) const {
    w.text(FlashText{strider::gait_names(app_.motion_.walker().leg_count())});
    write_gait_presets<App::Profile::kModelIndex>(w, app_.motion_.robot());
  }
  const MotionReach& reach() const { return app_.motion_.reach(); }
  void apply_settings(const Settings& s) { app_.stage_.set_settings(s); }
  void write_status(ReplyWriter& w) {
    write_motion_status(w, app_.motion_, app_.stage_, app_.tuner_.origin());
    app_.board_watch_.write_status(w);
    app_.tick_load_.write_status(w);
    app_.sensing_.write_status(w);
  }

 private:
  //! After relax, the next motion command switches the servos on again.
  void wake() {
    if (!app_.stage_.all_on() && !app_.stage_.starting()) app_.stage_.begin_soft_start(app_.last_tick_us_ / 1000u);
  }

  App& app_;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_ROBOT_APP_SINK_H
