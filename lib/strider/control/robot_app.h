//! RobotApp: the whole robot behind its hardware seams. The firmware's main
//! loop and the simulator's library mode both run exactly this:
//!
//!   link bytes -> one CommandParser per port -> Controller (deadman, avoidance)
//!   -> WalkerMotion (gait engine, body pose, IK) -> ServoStage (servo map,
//!   slew limit, soft start) -> ServoOutput
//!
//! The caller owns the hardware and the clock (now_us, wrapping): it passes
//! bytes and sonar echoes in and calls tick() every kTickPeriodUs. Output: a
//! ServoOutput (hal_interfaces.h); Store: a ByteStore; Link: link_ports.h.
#ifndef STRIDER_CONTROL_ROBOT_APP_H
#define STRIDER_CONTROL_ROBOT_APP_H

#include <stdint.h>

#include "control_tick.h"
#include "controller.h"
#include "gait_tuner.h"
#include "link_ports.h"
#include "robot_app_sink.h"
#include "robot_sensing.h"
#include "servo_board_watch.h"
#include "servo_stage.h"
#include "sonar_filter.h"

namespace strider {

//! P: the build profile (robots/build_profile.h). The model may be in flash
//! (ModelMemory: no RAM copy of its ~370 bytes; read through a stack copy).
template <typename S, typename Output, typename Store, typename P = HostProfile<S>>
class RobotApp {
  class Sink;

 public:
  using Profile = P;
  //! Reads the settings from store but touches no other hardware. Out of
  //! line: the settings' copy is off the stack before begin() runs.
  STRIDER_NOINLINE RobotApp(const RobotModel& model, Output& out, Store& store, ModelMemory where = ModelMemory::kRam)
      : model_(model),
        model_in_flash_(where == ModelMemory::kFlash),
        boards_(0),
        out_(out),
        store_(store),
        sink_(*this),
        controller_(sink_, store, LoadedSettings(store)),
        last_tick_us_(0),
        ok_(false) {}

  //! Power-up: walker (sitting), servo map, boot notices, soft start. False
  //! (and an `err` notice) when the model does not fit. held (a warm start):
  //! `channels` OFF words (ServoStage::adopt_outputs()); see hold().
  template <typename Link>
  bool begin(uint32_t now_us, Link& link, const uint16_t* held = nullptr, uint8_t channels = 0) {
    // The deepest stack of the firmware: nothing else is on it meanwhile.
    const char* error = configure_from_model();  // in flash; nullptr: configured
    ok_ = error == nullptr;
    if (ok_) {
      motion_.walker().refresh();  // the legs' IK, with the model's copy off the stack
      motion_.find_reach();        // what `help` and err 24 name
      tuner_.configure(motion_);
      tuner_.use_gait(motion_, store_);  // the default gait's saved parameters
    }
    announce(link, error);
    if (!ok_) return false;
    stage_.set_settings(controller_.settings());
    stage_.apply_pending(out_);
    if (held != nullptr) hold(held, channels, link);
    stage_.begin_soft_start(now_us / 1000u);
    last_tick_us_ = now_us;
    return true;
  }

  //! The servo boards as their driver sees them, before each tick()
  //! (servo_board_watch.h: a silent board stops the walk, err 31).
  template <typename Link>
  STRIDER_NOINLINE void servo_boards(const ServoBoardReport& r, uint32_t now_us, Link& link) {
    controller_.set_servo_fault(board_watch_.report(r, now_us / 1000u, stage_, out_, link));
  }

  //! Other gait parameters (host tools: tried on a copy of the walker, too
  //! big for the AVR stack), after begin(); false: refused, nothing changed.
  bool set_gait_params(const GaitParams& params) {
    WalkerMotion<S, P> trial = motion_;
    RobotModel model;
    copy_model(&model);
    if (!trial.configure(model, params)) return false;
    trial.find_reach();
    motion_ = trial;
    tuner_.configure(motion_);
    return true;
  }

  //! The battery divider's ADC reading, once a tick (robot_sensing.h).
  template <typename Link>
  void battery(uint16_t adc_code, Link& link) { sensing_.battery_reading(adc_code, controller_, motion_, link); }
  void set_battery_config(const BatteryConfig& c) { sensing_.battery = BatteryMonitor(c); }
  void set_imu_present(bool present) { sensing_.set_imu_present(present); }
  //! One IMU sample per tick, before tick() (robot_sensing.h).
  template <typename Link>
  STRIDER_NOINLINE void imu(const ImuSample<S>* sample, Link& link) {
    sensing_.imu_sample(sample, controller_, motion_, stage_.all_on(), ports_, link);
  }
  const AttitudeFilter<S>& attitude() const { return sensing_.attitude(); }
  const LevelBody<S>& level() const { return sensing_.level(); }
  const YawHold<S>& yaw_hold() const { return sensing_.yaw_hold(); }

  //! One byte from link `port` (0 or 1) at now_us; a reply goes back to that port.
  template <typename Link>
  void on_byte(uint8_t port, uint8_t b, uint32_t now_us, Link& link) {
    ports_.on_byte(port, b, now_us, controller_, sensing_.level_cal(), link);
  }
  //! The receiver of link `port` may have dropped bytes before the next one (link_ports.h).
  template <typename Link>
  void on_bytes_lost(uint8_t port, uint32_t now_us, Link& link) {
    ports_.on_bytes_lost(port, now_us, controller_, sensing_.level_cal(), link);
  }

  //! One control tick: controller, walker, servo frame. period_us: what the
  //! gait advances by (the firmware: whole scheduled periods, so that start
  //! jitter does not move the gait); 0: the time since the last tick.
  template <typename Link>
  void tick(uint32_t now_us, Link& link, uint32_t period_us = 0) {
    if (!ok_) return;
    const uint32_t now_ms = now_us / 1000u;
    tick_controller(now_us, now_ms, link);
    const S dt_s = tick_seconds<S>(now_us, &last_tick_us_, period_us);
    if (stage_.all_on() && motion_.sitting() && controller_.mode() != RobotMode::kRelaxed && !sensing_.battery.critical())
      motion_.stand_up();
    if (board_watch_.restored(stage_.starting())) controller_.set_servo_fault(board_watch_.faulted != 0);
    motion_.walker().tick(dt_s);
    stage_.frame(motion_.walker().results(), now_ms, out_);
  }

  //! The tick's time [us], skipped ticks, stack probe: `status` (control_tick.h).
  void record_tick_time(uint32_t took_us) { tick_load_.record(took_us); }
  void record_missed_ticks(uint16_t n) { tick_load_.record_missed(n); }
  void set_stack_probe(uint16_t (*probe)()) { tick_load_.stack_probe = probe; }

  SonarFilter& sonar() { return sonar_; }
  const Controller<Sink, Store, false>& controller() const { return controller_; }
  const WalkerMotion<S, P>& motion() const { return motion_; }
  //! What each live gait parameter may be for the gait walked now (gait_tuner.h).
  TuneBounds tune_bounds() const { return tuner_.bounds(motion_); }
  //! The walker, for host tools that change it between ticks (the simulator's gait overrides).
  WalkerMotion<S, P>& motion() { return motion_; }
  const ServoStage<S, P>& servos() const { return stage_; }
  uint16_t overruns() const { return tick_load_.overruns; }
  uint32_t tick_max_us() const { return tick_load_.max_us; }

 private:
  class Sink : public RobotAppSink<RobotApp> { using RobotAppSink<RobotApp>::RobotAppSink; };  // the controller's
  friend class RobotAppSink<RobotApp>;

  void copy_model(RobotModel* to) const {
    read_model(model_, where(), to);
  }

  //! Walker and servo stage from a copy of the model; the error line, or
  //! nullptr when configured.
  STRIDER_NOINLINE const char* configure_from_model() {
    RobotModel model;
    copy_model(&model);
    name_ = model.name;
    boards_ = pca_board_count(model);
    controller_.set_avoid_clear_mm(avoid_clear_mm(model));  // the copy: model_ may be in flash
    const char* error = configure_walker(model);
    return error != nullptr ? error : configure_stage(model) ? nullptr : text::kErrServos;
  }
  const char* configure_walker(const RobotModel& model) {
    GaitParams params;
    if (!gait_params_of(model, &params)) return text::kErrGait;
    return motion_.configure(model, params, false) ? nullptr : text::kErrModel;
  }
  // Not inlined: the stage's temporaries are not on the stack with the
  // walker's configuration. The stage reads the model again (model_, not
  // this copy) when the settings change.
  STRIDER_NOINLINE bool configure_stage(const RobotModel& model) { return stage_.configure(model, &model_, where()); }
  ModelMemory where() const { return model_in_flash_ ? ModelMemory::kFlash : ModelMemory::kRam; }

  template <typename Link>
  void announce(Link& link, const char* error) {
    send_boot_notices(error, name_, stage_.joint_count(), boards_, controller_.settings_record(), link);
  }

  //! Warm start (begin()): the joints whose outputs hold a pulse keep it and
  //! the walker stands, so that no leg drops to the sitting pose first.
  template <typename Link>
  STRIDER_NOINLINE void hold(const uint16_t* held, uint8_t channels, Link& link) {
    const uint8_t n = stage_.adopt_outputs(out_, held, channels, 0xFF);
    if (n == 0) return;
    motion_.stand_now();
    ReplyLine line;
    line.w.text(FlashText{text::kInfoHeld}).field(FlashText{text::kJoints}, n);
    link.send_line(kAllPorts, line.buf);
  }

  //! The tick's link and controller part: partial lines time out, deadman and avoidance.
  //! Not inlined: its reply buffer is off the stack again before the walker runs.
  template <typename Link>
  STRIDER_NOINLINE void tick_controller(uint32_t now_us, uint32_t now_ms, Link& link) {
    ports_.time_out(now_ms, controller_, sensing_.level_cal(), link);
    ReplyLine line;
    const int32_t walked_vy = motion_.body_speed(to_tenths(motion_.walker().engine().vy()));
    if (controller_.tick(now_ms, sonar_.reading(now_us), line.w, walked_vy)) link.send_line(kAllPorts, line.buf);
  }

  const RobotModel& model_;  // in RAM or flash (model_in_flash_): read through copy_model() only
  bool model_in_flash_;
  const char* name_ = "";    // the model's name (the string is in RAM either way)
  uint8_t boards_;           // PCA9685 boards the model uses
  Output& out_;
  Store& store_;
  WalkerMotion<S, P> motion_;
  GaitTuner<S, P> tuner_;
  RobotSensing<S, P> sensing_;
  ServoStage<S, P> stage_;
  Sink sink_;
  Controller<Sink, Store, false> controller_;  // input from ports_
  LinkPorts<Controller<Sink, Store, false>, LevelCalibration<S>> ports_;
  SonarFilter sonar_;
  // Zero, by the constructors (as boards_).
  uint32_t last_tick_us_;
  TickLoad tick_load_;
  bool ok_;
  ServoBoardWatch board_watch_;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_ROBOT_APP_H
