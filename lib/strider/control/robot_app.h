//! RobotApp: the whole robot behind its hardware seams. The firmware's main
//! loop and the simulator's library mode both run exactly this:
//!
//!   link bytes -> one CommandParser per port -> Controller (deadman, avoidance)
//!   -> WalkerMotion (gait engine, body pose, IK) -> ServoStage (servo map,
//!   slew limit, soft start) -> ServoOutput
//!
//! The caller owns the hardware: it passes bytes in, pings the sonar when
//! sonar().ping_due() says so and hands the echo samples back, calls tick()
//! every kTickPeriodUs and reports how long the tick took. Time is a parameter:
//! now_us, a wrapping microsecond count that the caller reads from its clock.
//!
//! Template parameters: S the scalar (float or Fixed); Output a ServoOutput
//! (hal_interfaces.h) with `void flush()` ending a frame; Store a ByteStore;
//! P the build profile (below).
//! Link (per call): `void send_line(uint8_t port, const char* line)`, line
//! without its ending; port kAllPorts means every port (notices).
#ifndef STRIDER_CONTROL_ROBOT_APP_H
#define STRIDER_CONTROL_ROBOT_APP_H

#include <stdint.h>

#include "battery_monitor.h"
#include "controller.h"
#include "fall_detector.h"
#include "gait_tuner.h"
#include "level_body.h"
#include "../sensing/attitude_filter.h"
#include "model_constants.h"
#include "servo_boards.h"
#include "servo_stage.h"
#include "settings_store.h"
#include "sonar_filter.h"
#include "walker_motion.h"

namespace strider {

constexpr uint32_t kTickPeriodUs = 20000;  //!< control tick, 50 Hz [us]
constexpr uint8_t kLinkPorts = 2;          //!< 0 = USB serial, 1 = Bluetooth (HC-05)
constexpr uint8_t kAllPorts = 0xFF;        //!< send_line(): every port
constexpr uint16_t kLineIdleMs = 300;      //!< a partial line older than this is dropped [ms]
static_assert(kLevelTickS * 1e6 == double(kTickPeriodUs), "level_body.h's tick is RobotApp's");
static_assert(kLinkPorts <= 2, "cal level keeps the port in one bit (RobotApp::level_cal())");

namespace app_text {
constexpr char kInfoStrider[] STRIDER_PROGMEM = "info strider ";
constexpr char kReady[] STRIDER_PROGMEM = " ready";
constexpr char kJoints[] STRIDER_PROGMEM = "joints";
constexpr char kBoards[] STRIDER_PROGMEM = "boards";
constexpr char kInfoEeprom[] STRIDER_PROGMEM = "info eeprom ";
constexpr char kDefaults[] STRIDER_PROGMEM = ", defaults";
constexpr char kSlot[] STRIDER_PROGMEM = "slot";
constexpr char kSeq[] STRIDER_PROGMEM = "seq";
constexpr char kOther[] STRIDER_PROGMEM = "other";
constexpr char kVersion[] STRIDER_PROGMEM = "version";
// The start-up configuration's errors (RobotApp::begin()).
constexpr char kErrModel[] STRIDER_PROGMEM = "err 30 model does not fit the firmware: build it for this model";
constexpr char kErrServos[] STRIDER_PROGMEM = "err 37 servos do not fit the firmware: build it for this model";
constexpr char kErrGait[] STRIDER_PROGMEM = "err 38 no gait defaults for the model: add its row to gait_params.h";
constexpr char kGait[] STRIDER_PROGMEM = "gait";
constexpr char kState[] STRIDER_PROGMEM = "state";
constexpr char kIk[] STRIDER_PROGMEM = "ik";
constexpr char kServos[] STRIDER_PROGMEM = "servos";
constexpr char kOn[] STRIDER_PROGMEM = "on";
constexpr char kOff[] STRIDER_PROGMEM = "off";
constexpr char kStarting[] STRIDER_PROGMEM = "starting";
constexpr char kLimited[] STRIDER_PROGMEM = "limited";
constexpr char kStackPeak[] STRIDER_PROGMEM = "stack_peak";
constexpr char kPca9685[] STRIDER_PROGMEM = "pca9685";
constexpr char kOk[] STRIDER_PROGMEM = "ok";
constexpr char kI2cErrors[] STRIDER_PROGMEM = "i2c_errors";
constexpr char kInfoFaultPca[] STRIDER_PROGMEM = "info fault pca9685 ";
constexpr char kInfoFaultI2c[] STRIDER_PROGMEM = "info fault i2c timeout";
constexpr char kInfoPca[] STRIDER_PROGMEM = "info pca9685 ";
constexpr char kRestored[] STRIDER_PROGMEM = " restored";
constexpr char kNothing[] STRIDER_PROGMEM = "";
constexpr char kInfoHeld[] STRIDER_PROGMEM = "info servos held";
constexpr char kInfoBattery[] STRIDER_PROGMEM = "info battery ";
constexpr char kBatteryMv[] STRIDER_PROGMEM = "battery_mv";
constexpr char kImu[] STRIDER_PROGMEM = "imu";
constexpr char kNone[] STRIDER_PROGMEM = "none";
constexpr char kFallen[] STRIDER_PROGMEM = "fallen";
constexpr char kLevel[] STRIDER_PROGMEM = "level";
constexpr char kImuFmt[] STRIDER_PROGMEM = " roll=" "\2" " pitch=" "\2";  // ReplyWriter::format()
constexpr char kInfoFall[] STRIDER_PROGMEM = "info fall";
constexpr char kInfoUpright[] STRIDER_PROGMEM = "info fall cleared";
constexpr char kMv[] STRIDER_PROGMEM = "mv";
constexpr char kBatteryLevelNames[] STRIDER_PROGMEM = "absent\0ok\0low\0critical";
inline FlashText to_flash(BatteryLevel l) { return flash_name(kBatteryLevelNames, 4, uint8_t(l)); }
constexpr char kWalkFmt[] STRIDER_PROGMEM = " walk_vx=" "\2" " walk_vy=" "\2" " walk_wz=" "\2";  // ReplyWriter::format()
constexpr char kOverrunsFmt[] STRIDER_PROGMEM = " overruns=" "\1" " tick_max_us=" "\1";
// The IK's states' names (to_string() in ik_status.h), in flash; a test
// keeps them equal. The gait states' names: kGaitStateNames (gait_state.h).
constexpr char kIkStatusNames[] STRIDER_PROGMEM = "ok\0clamped\0joint_limit\0unreachable";
inline FlashText to_flash(GaitState s) { return flash_name(kGaitStateNames, kGaitStateCount, uint8_t(s)); }
inline FlashText to_flash(IkStatus s) { return flash_name(kIkStatusNames, 4, uint8_t(s)); }
}  // namespace app_text

//! Microseconds (<= 1e6) -> seconds, without a division.
inline void to_seconds(uint32_t us, float* s) { *s = float(us) * 1e-6f; }
inline void to_seconds(uint32_t us, Fixed* s) { *s = Fixed::from_raw(int32_t((us * 4295ul) >> 16)); }  // 2^16 / 1e6 = 4295 / 2^16 (+1e-5)

//! A value -> tenths, rounded half away from zero (|v| < 200,000).
inline int32_t to_tenths(float v) { return v >= 0.0f ? int32_t(v * 10.0f + 0.5f) : -int32_t(-v * 10.0f + 0.5f); }
inline int32_t to_tenths(Fixed v) {
  const int32_t t = v.raw() * 10;  // |v| < 3276.7: no overflow
  return t >= 0 ? (t + 32768) >> 16 : -((-t + 32768) >> 16);
}

// Where RobotApp's model is (ModelMemory, channel_map.h): in RAM, or in
// flash (the firmware: no RAM copy of its ~370 bytes; the configuration
// reads a copy on the stack in begin(), the servo stage when the PWM or the
// trims change).

//! P: the build profile (robots/build_profile.h): the walker's and the
//! servo stage's shape, and which of the model's constants it holds in
//! flash (a firmware's, control/firmware_profile.h); the others are built
//! from the model at start-up.
template <typename S, typename Output, typename Store, typename P = HostProfile<S>>
class RobotApp {
  class Sink;

 public:
  //! Reads the settings from store (EEPROM) but touches no other hardware.
  //! The model is read at start-up (begin(), set_gait_params()) only.
  RobotApp(const RobotModel& model, Output& out, Store& store, ModelMemory where = ModelMemory::kRam)
      : model_(model),
        model_in_flash_(where == ModelMemory::kFlash),
        boards_(0),
        out_(out),
        store_(store),
        sink_(*this),
        controller_(sink_, store, LoadedSettings(store)),
        last_byte_ms_(),
        last_tick_us_(0),
        tick_max_us_(0),
        overruns_(0),
        stack_probe_(nullptr),
        ok_(false),
        boards_faulted_(0),
        bus_stuck_(false),
        restoring_(false),
        i2c_errors_(0),
        reply_buf_() {}

  //! Power-up: walker (sitting), servo map, boot notices; the soft start
  //! begins with the first tick. False (and an `err` notice) when the model
  //! does not fit. Takes the velocity-limit search's time (gait_config.h).
  //! held (a warm start: an MCU reset the servo boards ran through): what
  //! every output drives, `channels` OFF words (ServoStage::adopt_outputs());
  //! the joints that hold a pulse keep it, the walker starts standing and
  //! the soft start moves each leg from its pulses to the standing pose
  //! (`info servos held joints=N`).
  template <typename Link>
  bool begin(uint32_t now_us, Link& link, const uint16_t* held = nullptr, uint8_t channels = 0) {
    // The walker's configuration needs the deepest stack of the whole
    // firmware: nothing else (no line buffer) is on the stack meanwhile,
    // and its copy of the model is gone before announce() runs.
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

  //! The servo boards as their driver sees them (the caller owns the bus:
  //! call it before each tick()). A board that stops answering (or none at
  //! power-up) is reported once, `info fault pca9685 0x41`, and a bus that
  //! hangs, `info fault i2c timeout`; the walk stops (the robot stands) and
  //! walking is refused (err 31) until every board answers again. A board
  //! that answers again is reported (`info pca9685 0x41 restored`); the
  //! driver has set it up again if it had lost power, and its legs are
  //! switched on one at a time (the soft start: each leg from the pulses its
  //! outputs drive), walking allowed again once they all are. `status`
  //! reports the boards (`pca9685=ok` or the addresses of the silent ones)
  //! and the failed transfers (`i2c_errors`).
  template <typename Link>
  STRIDER_NOINLINE void servo_boards(const ServoBoardReport& r, uint32_t now_us, Link& link) {
    // A board may have failed and come back since the last report: both notices.
    const uint8_t lost = uint8_t((r.faulted | r.restored) & ~boards_faulted_);
    const uint8_t back = uint8_t((boards_faulted_ | r.restored) & ~r.faulted);
    for (uint8_t b = 0; b < kMaxPcaBoards; ++b)
      if (lost & board_bit(b)) board_notice(FlashText{app_text::kInfoFaultPca}, b, FlashText{app_text::kNothing}, link);
    if (r.bus_stuck && !bus_stuck_) notice(FlashText{app_text::kInfoFaultI2c}, link);
    for (uint8_t b = 0; b < kMaxPcaBoards; ++b)
      if (back & board_bit(b)) board_notice(FlashText{app_text::kInfoPca}, b, FlashText{app_text::kRestored}, link);
    if (r.restored != 0 && r.outputs != nullptr) {
      stage_.adopt_outputs(out_, r.outputs, r.channels, r.restored);
      if (stage_.all_on() || stage_.starting()) {
        stage_.restart_soft_start(now_us / 1000u);
        restoring_ = true;
      }
    }
    boards_faulted_ = r.faulted;
    bus_stuck_ = r.bus_stuck;
    i2c_errors_ = r.errors;
    controller_.set_servo_fault(boards_faulted_ != 0 || restoring_);
  }

  //! Other gait parameters than the model's defaults (e.g. tuned ones), after
  //! begin() and before the robot stands up: the robot starts over sitting.
  //! False (nothing changed) when the walker refuses them. Works on a copy of
  //! the walker first: meant for host tools (the AVR stack has no room for it).
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

  //! The battery divider's ADC reading (the firmware: once a tick). A new
  //! level is a notice, `info battery low mv=6950`; a critical pack stops a
  //! walk and sits the robot down, and walking is refused (err 32) until it
  //! recovers (battery_monitor.h: its hold and hysteresis). `status` has
  //! `battery_mv` while a pack is seen.
  template <typename Link>
  STRIDER_NOINLINE void battery(uint16_t adc_code, Link& link) {
    if (!battery_.add(adc_code)) return;
    ReplyLine line;
    line.w.text(FlashText{app_text::kInfoBattery}).text(app_text::to_flash(battery_.level()));
    line.w.field(FlashText{app_text::kMv}, battery_.mv());
    link.send_line(kAllPorts, line.buf);
    controller_.set_battery_critical(battery_.critical());
    if (battery_.critical()) motion_.walker().engine().sit_down();
  }
  const BatteryMonitor& battery_monitor() const { return battery_; }
  //! Whether an MPU-6050 answered at start-up (the firmware probes the bus):
  //! `status` then has `imu=none`, or `imu=ok` (`imu=fallen`, `imu=level`)
  //! with roll and pitch [deg]. Not called (the host tools): no imu field.
  //! With an IMU the filter learns the gyro's offset with fast gains until
  //! the robot first stands (level_body.h).
  void set_imu_present(bool present) {
    imu_probed_ = true, imu_present_ = present;
    if (!present) return;
    attitude_.set_gains(LevelBody<S>::learning_gains(attitude_.gains(), true));
    level_.start_learning();
  }
  //! One IMU sample per tick, before tick() (nullptr: the read failed, the
  //! attitude holds). The attitude filter (sensing/attitude_filter.h) runs at
  //! the tick's period; a tilt past 50 deg for 0.2 s is a fall: `info fall`,
  //! the servos go limp and walking is refused (err 33) until the robot has
  //! stood upright (under 20 deg) for 1 s: `info fall cleared`. With
  //! `level on` the body's roll and pitch follow (level_body.h). The
  //! accelerometer's x and y offsets (`cal level`, kept in the settings) are
  //! taken from every sample first.
  template <typename Link>
  STRIDER_NOINLINE void imu(const ImuSample<S>* sample, Link& link) {
    if (level_cal_.running() && imu_present_) level_cal(sample, link);  // a failed read (nullptr) ends it
    if (sample == nullptr || !imu_present_) return;
    ImuSample<S> s = *sample;
    constexpr S kMs2PerMg = scalar<S>(kStandardGravity / 1000.0);
    s.accel_m_s2.x -= S(int(controller_.settings().accel_x_mg)) * kMs2PerMg;
    s.accel_m_s2.y -= S(int(controller_.settings().accel_y_mg)) * kMs2PerMg;
    attitude_.update(s, scalar<S>(double(kTickPeriodUs) * 1e-6));
    if (!attitude_.has_attitude()) return;
    level_body();
    if (!fall_.update(attitude_.tilt_rad())) return;
    notice(FlashText{fall_.fallen() ? app_text::kInfoFall : app_text::kInfoUpright}, link);
    controller_.set_fallen(fall_.fallen());
  }
  const AttitudeFilter<S>& attitude() const { return attitude_; }
  const LevelBody<S>& level() const { return level_; }
  //! The divider and thresholds (the firmware: from its board file).
  void set_battery_config(const BatteryConfig& c) { battery_ = BatteryMonitor(c); }

  //! One byte from link `port` (0 or 1) at now_us; a reply goes back to that port.
  template <typename Link>
  void on_byte(uint8_t port, uint8_t b, uint32_t now_us, Link& link) {
    if (port >= kLinkPorts) return;
    const uint32_t now_ms = now_us / 1000u;
    last_byte_ms_[port] = now_ms;
    Command c;
    const ParseResult r = parsers_[port].feed(b, &c);
    reply(port, r, c, now_ms, link);
  }

  //! The receiver of link `port` may have dropped bytes before the next one
  //! (its buffer was full), which comes at now_us: the line they damage is
  //! answered `err 10` at its end and never runs (CommandParser::lost()).
  //! After kLineIdleMs of silence since the last byte, the bytes were lost at
  //! the end of what was sent: the line they belonged to is abandoned as the
  //! idle timeout does (`err 8`), and the next byte starts afresh.
  template <typename Link>
  void on_bytes_lost(uint8_t port, uint32_t now_us, Link& link) {
    if (port >= kLinkPorts) return;
    const uint32_t now_ms = now_us / 1000u;
    if (elapsed(now_ms, last_byte_ms_[port]) < kLineIdleMs) {
      parsers_[port].lost();
      return;
    }
    Command c;
    reply(port, parsers_[port].idle_timeout(&c), c, now_ms, link);
  }

  //! One control tick (call every kTickPeriodUs): partial lines time out,
  //! controller (deadman, avoidance), walker, servo frame.
  template <typename Link>
  //! period_us: the time the gait advances by, when the caller schedules the
  //! ticks (the firmware: whole periods since the last tick's scheduled time,
  //! so that the start's jitter does not move the gait); 0: the time since
  //! the last tick.
  void tick(uint32_t now_us, Link& link, uint32_t period_us = 0) {
    if (!ok_) return;
    const uint32_t now_ms = now_us / 1000u;
    tick_controller(now_us, now_ms, link);
    // Elapsed time, at most five ticks: a stalled loop must not make the gait leap.
    uint32_t dt_us = period_us != 0 ? period_us : elapsed(now_us, last_tick_us_);
    last_tick_us_ = now_us;
    if (dt_us > 5 * kTickPeriodUs) dt_us = 5 * kTickPeriodUs;
    if (stage_.all_on() && motion_.sitting() && controller_.mode() != RobotMode::kRelaxed && !battery_.critical())
      motion_.stand_up();
    if (restoring_ && !stage_.starting()) {  // a board's legs are on again
      restoring_ = false;
      controller_.set_servo_fault(boards_faulted_ != 0);
    }
    S dt_s;
    to_seconds(dt_us, &dt_s);
    motion_.walker().tick(dt_s);
    stage_.frame(motion_.walker(), now_ms, out_);
  }

  //! How long the last tick took [us] (the caller measures); longer than a
  //! period counts as an overrun (reported by `status`).
  void record_tick_time(uint32_t took_us) {
    if (took_us > tick_max_us_) tick_max_us_ = took_us;
    if (took_us > kTickPeriodUs && overruns_ < 0xFFFF) ++overruns_;
  }
  //! Ticks the caller had to skip (it fell behind by whole periods).
  void record_missed_ticks(uint16_t n) {
    const uint32_t sum = uint32_t(overruns_) + n;
    overruns_ = sum > 0xFFFFu ? uint16_t(0xFFFF) : uint16_t(sum);
  }

  //! A board-specific probe for `status`: the deepest stack use since
  //! power-up [bytes] (the firmware paints the free RAM at start-up and
  //! counts what was overwritten; the scan runs only when status is asked).
  void set_stack_probe(uint16_t (*probe)()) { stack_probe_ = probe; }

  SonarFilter& sonar() { return sonar_; }
  const Controller<Sink, Store, false>& controller() const { return controller_; }
  const WalkerMotion<S, P>& motion() const { return motion_; }
  //! What each live gait parameter may be for the gait walked now (gait_tuner.h).
  TuneBounds tune_bounds() const { return tuner_.bounds(motion_); }
  //! The walker, for host tools that change it between ticks (the simulator's gait overrides).
  WalkerMotion<S, P>& motion() { return motion_; }
  const ServoStage<S, P>& servos() const { return stage_; }
  SettingsStatus load_status() const { return controller_.load_status(); }
  uint16_t overruns() const { return overruns_; }
  uint32_t tick_max_us() const { return tick_max_us_; }

 private:
  //! The controller's MotionSink: motion commands to the walker, servo power
  //! and settings to the stage.
  class Sink {
   public:
    explicit Sink(RobotApp& app) : app_(app) {}
    void set_velocity(const Twist& v) {
      app_.wake();
      app_.motion_.set_velocity(v);
    }
    void stand() {
      app_.wake();
      app_.motion_.stand();
    }
    void relax() {
      app_.stage_.relax_all();
      app_.motion_.sit_now();
    }
    bool set_gait(const char* name) {
      if (!app_.motion_.set_gait(name)) return false;
      app_.tuner_.use_gait(app_.motion_, app_.store_);
      return true;
    }
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
    bool set_level(bool on) { return app_.set_level(on); }
    LevelCalStart start_level_cal() { return app_.start_level_cal(); }
    const char* gait_names() const { return strider::gait_names(app_.motion_.walker().leg_count()); }
    const MotionReach& reach() const { return app_.motion_.reach(); }
    void apply_settings(const Settings& s) { app_.stage_.set_settings(s); }
    void write_status(ReplyWriter& w) { app_.write_status(w); }

   private:
    RobotApp& app_;
  };

  void copy_model(RobotModel* to) const {
    read_model(model_, where(), to);
  }

  //! Walker (legs' IK not yet solved) and servo stage from (a copy of) the
  //! model; keeps its name and board count for announce(). The error line
  //! (app_text), nullptr when configured.
  STRIDER_NOINLINE const char* configure_from_model() {
    RobotModel model;
    copy_model(&model);
    name_ = model.name;
    boards_ = pca_board_count(model);
    controller_.set_avoid_clear_mm(P::kAvoidClearMm != 0 ? P::kAvoidClearMm : avoid_clear_mm(model));  // the copy: model_ may be in flash
    const char* error = configure_walker(model, Stored<P::kStoredConfig>());
    return error != nullptr ? error : configure_stage(model) ? nullptr : app_text::kErrServos;
  }
  // The walker from the model (only the one called is built).
  template <bool kOn>
  struct Stored {};
  const char* configure_walker(const RobotModel& model, Stored<false>) {
    GaitParams params;
    if (!gait_params_of(model, &params)) return app_text::kErrGait;
    return motion_.configure(model, params, false) ? nullptr : app_text::kErrModel;
  }
  // A stored configuration needs only the default gait's name.
  const char* configure_walker(const RobotModel& model, Stored<true>) {
    GaitName gait;
    if (!default_gait(model, &gait, Stored<P::kStoredGait>())) return app_text::kErrGait;
    return configure_walker(model, gait.text, Stored<P::kStoredLegs>()) ? nullptr : app_text::kErrModel;
  }
  static bool default_gait(const RobotModel&, GaitName* gait, Stored<true>) {
    flash_copy(gait, &P::kDefaultGait, sizeof *gait);
    return true;
  }
  static bool default_gait(const RobotModel& model, GaitName* gait, Stored<false>) {
    GaitParams params;
    if (!gait_params_of(model, &params)) return false;
    for (uint8_t i = 0; i < kGaitNameBytes; ++i) gait->text[i] = params.default_gait[i];
    return true;
  }
  bool configure_walker(const RobotModel& model, const char* gait, Stored<false>) {
    return motion_.configure_stored(model, gait, &P::kGaitConfig, false);
  }
  bool configure_walker(const RobotModel& model, const char* gait, Stored<true>) {
    return motion_.configure_stored(model, gait, &P::kGaitConfig, &P::kWalkerLegsInFlash, false);
  }
  // Not inlined: the stage's temporaries are not on the stack with the
  // walker's configuration. The stage reads the model again (model_, not
  // this copy) when the settings change.
  STRIDER_NOINLINE bool configure_stage(const RobotModel& model) { return stage_.configure(model, &model_, where()); }
  ModelMemory where() const { return model_in_flash_ ? ModelMemory::kFlash : ModelMemory::kRam; }

  //! The boot notices: model and boards, how the settings loaded; or the
  //! start-up configuration's error line (in flash).
  template <typename Link>
  STRIDER_NOINLINE void announce(Link& link, const char* error) {
    ReplyLine line;
    ReplyWriter& w = line.w;
    char* const buf = line.buf;
    if (error != nullptr) {
      w.text(FlashText{error});
      link.send_line(kAllPorts, buf);
      return;
    }
    w.text(FlashText{app_text::kInfoStrider}).text(name_).text(FlashText{app_text::kReady});
    w.field(FlashText{app_text::kJoints}, stage_.joint_count()).field(FlashText{app_text::kBoards}, boards_);
    link.send_line(kAllPorts, buf);
    ReplyWriter e(buf, sizeof line.buf);
    e.text(FlashText{app_text::kInfoEeprom}).text(to_flash(load_status()));
    if (load_status() != SettingsStatus::kOk) {
      e.text(FlashText{app_text::kDefaults});
    } else {
      describe_record(e, controller_.settings_record());
    }
    link.send_line(kAllPorts, buf);
  }

  //! Which record the settings came from: ` slot=1 seq=7`, or ` version=1`
  //! (the single record before the slots); ` other=corrupt` (old_version,
  //! invalid) when the other slot holds neither a record nor erased bytes.
  static void describe_record(ReplyWriter& w, const SettingsRecord& r) {
    if (r.version == kSettingsSingleRecordVersion) {
      w.field(FlashText{app_text::kVersion}, r.version);
    } else {
      w.field(FlashText{app_text::kSlot}, r.slot).field(FlashText{app_text::kSeq}, r.seq);
    }
    if (r.other != SettingsStatus::kOk && r.other != SettingsStatus::kEmpty)
      w.field_text(FlashText{app_text::kOther}, to_flash(r.other));
  }

  //! Warm start (begin()): the joints whose outputs hold a pulse keep it and
  //! the walker stands, so that no leg drops to the sitting pose first.
  template <typename Link>
  STRIDER_NOINLINE void hold(const uint16_t* held, uint8_t channels, Link& link) {
    const uint8_t n = stage_.adopt_outputs(out_, held, channels, 0xFF);
    if (n == 0) return;
    motion_.stand_now();
    ReplyLine line;
    line.w.text(FlashText{app_text::kInfoHeld}).field(FlashText{app_text::kJoints}, n);
    link.send_line(kAllPorts, line.buf);
  }

  template <typename Link>
  STRIDER_NOINLINE static void notice(FlashText text, Link& link) {
    ReplyLine line;
    line.w.text(text);
    link.send_line(kAllPorts, line.buf);
  }
  //! `<head>0x41<tail>` for board b.
  template <typename Link>
  STRIDER_NOINLINE static void board_notice(FlashText head, uint8_t b, FlashText tail, Link& link) {
    ReplyLine line;
    write_board(line.w.text(head), b).text(tail);
    link.send_line(kAllPorts, line.buf);
  }
  //! Board b's I2C address, `0x41`.
  static ReplyWriter& write_board(ReplyWriter& w, uint8_t b) {
    const uint8_t a = uint8_t(kPcaFirstAddress + b);
    const char lo = char(a & 15u);
    return w.ch('0').ch('x').ch(char('0' + (a >> 4))).ch(char(lo < 10 ? '0' + lo : 'a' + lo - 10));
  }

  //! The tick's link and controller part: partial lines time out, deadman and
  //! avoidance. Not inlined: its reply buffer is off the stack again before
  //! the walker (the deepest call chain) runs.
  template <typename Link>
  STRIDER_NOINLINE void tick_controller(uint32_t now_us, uint32_t now_ms, Link& link) {
    for (uint8_t p = 0; p < kLinkPorts; ++p) {
      if (elapsed(now_ms, last_byte_ms_[p]) < kLineIdleMs) continue;
      Command c;
      reply(p, parsers_[p].idle_timeout(&c), c, now_ms, link);
    }
    ReplyLine line;
    ReplyWriter& w = line.w;
    const int32_t walked_vy = motion_.body_speed(to_tenths(motion_.walker().engine().vy()));
    if (controller_.tick(now_ms, sonar_.reading(now_us), w, walked_vy)) link.send_line(kAllPorts, line.buf);
  }

  //! `level on|off`; false without an IMU. Off puts the body's roll and
  //! pitch back to 0 (parallel to the feet), yaw and height kept.
  bool set_level(bool on) {
    if (!imu_present_) return false;
    level_.set_enabled(on);
    if (!on) motion_.set_body_tilt(S(0), S(0));
    return true;
  }
  //! `cal level`: measuring starts when the robot stands still with its
  //! servos on, the body parallel to its feet (level off, no pose); the
  //! reply follows after kLevelCalSamples samples (reply_line() keeps its
  //! port in the measurement's tag).
  LevelCalStart start_level_cal() {
    if (!imu_present_) return LevelCalStart::kNoImu;
    if (level_cal_.running() || !attitude_.has_attitude() || fall_.fallen() || !stage_.all_on() ||
        level_.enabled() || level_.learning() || motion_.walker().engine().state() != GaitState::kStanding ||
        motion_.offsets().roll_rad != S(0) || motion_.offsets().pitch_rad != S(0))
      return LevelCalStart::kNotStill;
    level_cal_.start();  // again with the reply's port in reply_line()
    return LevelCalStart::kStarted;
  }
  //! One raw sample into the `cal level` measurement; a robot that leaves
  //! its stand meanwhile ends it (moving). At the end, the deferred reply.
  template <typename Link>
  STRIDER_NOINLINE void level_cal(const ImuSample<S>* sample, Link& link) {
    int8_t x = 0, y = 0;
    const LevelCalStatus st = sample == nullptr ? (level_cal_.stop(), LevelCalStatus::kNoReading)
                              : motion_.walker().engine().state() != GaitState::kStanding || !stage_.all_on()
                                  ? (level_cal_.stop(), LevelCalStatus::kMoving)
                                  : level_cal_.add(*sample, attitude_.gyro_bias_rad_s(), &x, &y);
    if (st == LevelCalStatus::kCollecting) return;
    const bool checked = (level_cal_.tag() & kLevelCalChecked) != 0;
    ReplyWriter w(reply_buf_, uint16_t(sizeof reply_buf_ - (checked ? kLineCheckBytes : 0)));
    controller_.level_cal_done(st, x, y, w);
    if (st == LevelCalStatus::kDone) {
      // The attitude again from the corrected accelerometer (the next
      // sample), the gyro's bias kept: the offset's step would otherwise
      // take the filter's 2 s time constant and overshoot.
      const Vec3<S> bias = attitude_.gyro_bias_rad_s();
      attitude_.reset();
      attitude_.set_gyro_bias(bias);
    }
    if (checked) append_line_check(reply_buf_, w.length());
    link.send_line(uint8_t(level_cal_.tag() & ~kLevelCalChecked), reply_buf_);
  }

  //! The IMU's part of a tick, with an attitude: the learning gains end once
  //! the robot first stands; the level acts while it stands or walks, servos on.
  void level_body() {
    const GaitState st = motion_.walker().engine().state();
    if (level_.learning() && st == GaitState::kStanding) {
      level_.stop_learning();
      attitude_.set_gains(LevelBody<S>::learning_gains(attitude_.gains(), false));
    }
    if (fall_.fallen() || !stage_.all_on() || st == GaitState::kSitting || st == GaitState::kStandingUp ||
        st == GaitState::kSittingDown)
      return;
    S roll = motion_.offsets().roll_rad, pitch = motion_.offsets().pitch_rad;
    if (level_.step(attitude_.roll_rad(), attitude_.pitch_rad(), &roll, &pitch)) motion_.set_body_tilt(roll, pitch);
  }

  //! After relax, the next motion command switches the servos on again.
  void wake() {
    if (!stage_.all_on() && !stage_.starting()) stage_.begin_soft_start(last_tick_us_ / 1000u);
  }

  // The command's reply is written into a member, not a stack buffer: a
  // command may reconfigure the walker (a gait, a height), the deepest
  // call chain there is, and the soak's random input took the stack past
  // its 1 KB budget (1,029 B on sprawl8) with the 320-byte line of then under it.
  template <typename Link>
  void reply(uint8_t port, ParseResult r, const Command& c, uint32_t now_ms, Link& link) {
    if (r == ParseResult::kNothing) return;
    if (c.source == CommandSource::kBareByte) {  // an RC byte: no reply, so none is written
      char none;
      ReplyWriter nowhere(&none, 1);
      controller_.on_parsed(r, c, now_ms, nowhere);
      return;
    }
    reply_line(port, r, c, now_ms, link);
  }
  template <typename Link>
  STRIDER_NOINLINE void reply_line(uint8_t port, ParseResult r, const Command& c, uint32_t now_ms, Link& link) {
    // A checked line gets a checked reply: room for its `*hhhh` kept free.
    const bool checked = c.source == CommandSource::kCheckedLine;
    ReplyWriter w(reply_buf_, uint16_t(sizeof reply_buf_ - (checked ? kLineCheckBytes : 0)));
    if (!controller_.on_parsed(r, c, now_ms, w)) return;
    if (w.length() == 0) {  // `cal level` measuring: the reply follows (level_cal())
      level_cal_.start(uint8_t(port | (checked ? kLevelCalChecked : 0)));
      return;
    }
    if (checked) append_line_check(reply_buf_, w.length());
    link.send_line(port, reply_buf_);
  }

  void write_status(ReplyWriter& w) {
    // What the gait engine walks: the command after avoidance and the robot's
    // limits, as the body speed it makes (speed_correction.h).
    const GaitEngine<S>& e = motion_.walker().engine();
    w.format(FlashText{app_text::kWalkFmt}, motion_.body_speed(to_tenths(e.vx())),
             motion_.body_speed(to_tenths(e.vy())),
             motion_.body_speed(to_tenths(e.wz() * scalar<S>(1.0 / kDegToRad)), true));
    const FlashText servos = stage_.all_on() ? FlashText{app_text::kOn}
                             : stage_.starting() ? FlashText{app_text::kStarting} : FlashText{app_text::kOff};
    w.field_text(FlashText{app_text::kGait}, motion_.gait().name)
        .field_text(FlashText{app_text::kState}, app_text::to_flash(motion_.walker().engine().state()))
        .field_text(FlashText{app_text::kIk}, app_text::to_flash(motion_.walker().worst_status()))
        .field_text(FlashText{app_text::kServos}, servos);
    if (stage_.last_status() != ServoStatus::kOk) w.field_text(FlashText{app_text::kServos}, FlashText{app_text::kLimited});
    // Live gait parameters (gait_tuner.h) other than the model's own: saved or changed.
    if (tuner_.origin() != TuneOrigin::kDefault) w.field_text(FlashText{text::kTune}, to_flash(tuner_.origin()));
    w.ch(' ').text(FlashText{app_text::kPca9685}).ch('=');
    if (boards_faulted_ == 0) w.text(FlashText{app_text::kOk});
    for (uint8_t b = 0, n = 0; b < kMaxPcaBoards; ++b)
      if (boards_faulted_ & board_bit(b)) write_board(n++ != 0 ? w.ch(',') : w, b);
    w.field(FlashText{app_text::kI2cErrors}, i2c_errors_);
    w.format(FlashText{app_text::kOverrunsFmt}, overruns_, int32_t(tick_max_us_));
    if (stack_probe_ != nullptr) w.field(FlashText{app_text::kStackPeak}, stack_probe_());
    if (battery_.present()) w.field(FlashText{app_text::kBatteryMv}, battery_.mv());
    if (imu_probed_) {
      w.field_text(FlashText{app_text::kImu}, !imu_present_ ? FlashText{app_text::kNone}
                                              : fall_.fallen() ? FlashText{app_text::kFallen}
                                              : level_.enabled() ? FlashText{app_text::kLevel} : FlashText{app_text::kOk});
      constexpr S kDeg = scalar<S>(57.29577951308232);
      if (imu_present_ && attitude_.has_attitude())
        w.format(FlashText{app_text::kImuFmt}, to_tenths(attitude_.roll_rad() * kDeg), to_tenths(attitude_.pitch_rad() * kDeg));
    }
  }

  const RobotModel& model_;  // in RAM or flash (model_in_flash_): read through copy_model() only
  bool model_in_flash_;
  const char* name_ = "";    // the model's name (the string is in RAM either way)
  uint8_t boards_;           // PCA9685 boards the model uses
  Output& out_;
  Store& store_;
  WalkerMotion<S, P> motion_;
  GaitTuner<S, P> tuner_;
  BatteryMonitor battery_;
  AttitudeFilter<S> attitude_;
  FallDetector<S> fall_;
  LevelBody<S> level_;
  LevelCalibration<S> level_cal_;
  static constexpr uint8_t kLevelCalChecked = 2;  // level_cal_'s tag: the port (bit 0), a checked reply (bit 1)
  bool imu_probed_ = false;
  bool imu_present_ = false;
  ServoStage<S, P> stage_;
  Sink sink_;
  Controller<Sink, Store, false> controller_;  // input from parsers_
  CommandParser parsers_[kLinkPorts];
  uint32_t last_byte_ms_[kLinkPorts];
  SonarFilter sonar_;
  // Zero, by the constructors (as boards_ and last_byte_ms_).
  uint32_t last_tick_us_;
  uint32_t tick_max_us_;
  uint16_t overruns_;
  uint16_t (*stack_probe_)();
  bool ok_;
  uint8_t boards_faulted_;  // servo_boards(): boards not answering
  bool bus_stuck_;
  bool restoring_;          // a board came back: its legs are being switched on again
  uint16_t i2c_errors_;
  char reply_buf_[kMaxReplyBytes];  // reply(): a command's reply line
};

}  // namespace strider

#endif  // STRIDER_CONTROL_ROBOT_APP_H
