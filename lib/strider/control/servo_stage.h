//! ServoStage: the last step before the servo boards. Every frame it maps the
//! legs' joint angles to PCA9685 ticks (servo_tick_map.h, with the live
//! trims), moves each output towards its target by at most what the servo
//! turns in one frame (a new gait, pose or trim never makes a servo slam),
//! and writes only the channels that changed; Output::flush() ends the frame.
//!
//! Soft start: after power-up or relax every output is off; the legs are
//! switched on one at a time, kSoftStartStepMs apart, so that the servos'
//! start-up currents do not brown out the supply (a first pulse cannot be
//! slewed). An output that holds a pulse (adopt_outputs()) stays on.
#ifndef STRIDER_CONTROL_SERVO_STAGE_H
#define STRIDER_CONTROL_SERVO_STAGE_H

#include <stdint.h>

#include "../gait/walker_legs.h"
#include "../robots/build_profile.h"
#include "channel_map.h"
#include "servo_boards.h"
#include "servo_frame.h"
#include "servo_tick_map.h"
#include "servo_warm_start.h"

namespace strider {

constexpr uint16_t kSoftStartStepMs = 250;   //!< one leg's servos switched on per step [ms]
constexpr uint16_t kFramePeriodMs = 20;  //!< nominal frame period for the slew limit [ms] (50 Hz)

//! A joint's slew step per frame [us]: a pulse change at the servo's top
//! speed over one frame (500-2500 us over 180 deg), rounded.
inline uint16_t servo_step_us(ServoPart part) {
  return uint16_t(servo_travel(part).speed_deg_s * (float(kFramePeriodMs) / 1000.0f) * (2000.0f / 180.0f) + 0.5f);
}

//! P (robots/build_profile.h): the most joints and the tick map's slots.
//! RAM: no servo channels kept, only the tick map's constants; channels are
//! rebuilt from the model (a stack copy) when trims or PWM change, and every
//! frame only when the map cannot hold them (near 400 Hz: map_joint(), slow).
template <typename S, typename P = HostProfile<S>>
class ServoStage {
  static constexpr uint8_t N = P::kJoints;
  static constexpr uint8_t kSlots = P::kTickSlots;

 public:
  ServoStage()
      : fast_(false), unfit_(false), fitted_legs_(0), settings_(nullptr), model_(nullptr), where_(ModelMemory::kRam),
        next_leg_ms_(0), count_(0), dof_(0), legs_(0), enabled_legs_(0), soft_start_(false),
        status_(ServoStatus::kOk) {}

  //! Every output off; `model` is a readable copy of `source` (nullptr:
  //! `model`), which must outlive the stage. False when it does not fit.
  bool configure(const RobotModel& model, const RobotModel* source = nullptr, ModelMemory where = ModelMemory::kRam) {
    // Joint k = leg dof + j: slot j when the tick map has dof slots, for
    // legs of one geometry (the same limits: one range per slot), else none;
    // fit_legs() configures leg 0 first.
    const bool fits = model.joint_count() <= N && (kSlots == 0 || (kSlots == model.dof() && leg_solver_count(model) == 1));
    count_ = fits ? channel_map_count(model) : uint8_t(0);
    model_ = source != nullptr ? source : &model;
    where_ = where;
    dof_ = model.dof();
    legs_ = model.leg_count;
    for (uint8_t j = 0; j < dof_; ++j) part_[j] = model.servo[j];
    for (uint8_t k = 0; k < N; ++k) ticks_[k] = kOff;
    for (uint8_t k = 0; k < count_; ++k) tick_map_.set_channel(k, joint_channel(model, uint8_t(k / dof_), uint8_t(k % dof_)));
    enabled_legs_ = 0;
    relax_pending_ = true;
    pwm_pending_ = true;  // the tick map's constants with the settings
    return count_ != 0;
  }

  //! Trims, oscillator and PWM from the next frame on. Keeps a pointer (RAM):
  //! s must outlive the next call; needed before the first frame.
  void set_settings(const Settings& s) {
    settings_ = &s;
    pwm_pending_ = true;
  }

  //! Every output off at the next frame; the soft start must run again.
  void relax_all() {
    enabled_legs_ = 0;
    relax_pending_ = true;
    soft_start_ = false;
  }

  //! Starts switching legs on, the first at now_ms.
  void begin_soft_start(uint32_t now_ms) {
    soft_start_ = true;
    next_leg_ms_ = now_ms;
  }

  //! Takes over the pulses held by the boards in board_mask
  //! (servo_warm_start.h); call after apply_pending().
  template <typename Output>
  uint8_t adopt_outputs(Output& out, const uint16_t* words, uint8_t channels, uint8_t board_mask) {
    const uint8_t held = adopt_held_outputs(tick_map_, fast_, count_, ticks_, kOff, out, words, channels, board_mask);
    // A warm start (every board) replaces configure()'s relax.
    if (board_mask == 0xFF) relax_pending_ = false;
    return held;
  }

  //! The soft start again from now_ms without relaxing: a leg holds its
  //! outputs until its turn. Only while the servos are on or starting.
  void restart_soft_start(uint32_t now_ms) {
    if (!all_on() && !starting()) return;
    enabled_legs_ = 0;
    begin_soft_start(now_ms);
  }

  bool all_on() const { return enabled_legs_ == legs_; }
  bool starting() const { return soft_start_ && !all_on(); }
  uint8_t joint_count() const { return count_; }
  //! Joint k's channel, rebuilt from the model (host tools and tests).
  ServoChannel<S> channel(uint8_t k) const {
    RobotModel m;
    read_model(*model_, where_, &m);
    return make_joint_channel<S>(m, uint8_t(k / dof_), uint8_t(k % dof_));
  }
  bool on(uint8_t k) const { return ticks_[k] != kOff; }
  uint16_t ticks(uint8_t k) const { return on(k) ? ticks_[k] : uint16_t(0); }   //!< last written [PCA9685 ticks], 0 off
  const Pca9685Timing& timing() const { return timing_; }
  //! The per-frame map's constants (host tools and tests).
  const ServoTickMap<S, N, kSlots>& tick_map() const { return tick_map_; }
  ServoStatus last_status() const { return status_; }

  //! Applies pending settings now (start-up), so that no control tick pays
  //! for it; frame() does it one leg per frame.
  template <typename Output>
  void apply_pending(Output& out) {
    if (pwm_pending_) apply_pwm(out);
    fit_legs(legs_);
  }

  //! One frame of legs[i].q[j] [rad] (Walker::results()): soft start, map,
  //! slew, write, out.flush().
  template <typename Leg, typename Output>
  ServoStatus frame(const Leg* legs, uint32_t now_ms, Output& out) {
    const bool new_pwm = pwm_pending_;
    if (new_pwm) apply_pwm(out);
    if (relax_pending_) {
      for (uint8_t k = 0; k < count_; ++k) {
        out.relax(tick_map_.channel(k));
        ticks_[k] = kOff;
      }
      relax_pending_ = false;
    }
    if (soft_start_ && enabled_legs_ < legs_ && int32_t(now_ms - next_leg_ms_) >= 0) {
      ++enabled_legs_;
      next_leg_ms_ = now_ms + kSoftStartStepMs;
    }
    // New settings: outputs hold their pulses while the map is rebuilt a
    // leg per frame (a whole map is ~20 ms of float work on the AVR).
    if (fitted_legs_ < legs_) {
      if (!new_pwm) fit_legs(1);
    } else {
      status_ = fast_ ? write_legs(legs, out, nullptr) : write_legs_slowly(legs, out);
    }
    out.flush();
    return status_;
  }

 private:
  static constexpr uint16_t kOff = 0xFFFF;  // ticks_ of an output that is off (no pulse)

  //! The enabled legs' joints through the tick map (model given: through
  //! map_joint()), slewed, written when changed; the worst status.
  template <typename Leg, typename Output>
  ServoStatus write_legs(const Leg* legs, Output& out, const RobotModel* model) {
    ServoStatus worst_status = ServoStatus::kOk;
    for (uint8_t leg = 0; leg < enabled_legs_; ++leg) {
      const Leg& r = legs[leg];
      for (uint8_t j = 0; j < dof_; ++j) {
        const uint8_t k = uint8_t(leg * dof_ + j);
        const ServoCommand cmd = model == nullptr
                                     ? tick_map_.map(k, j, r.q[j])
                                     : map_joint(make_joint_channel<S>(*model, leg, j), r.q[j],
                                                 trim_from_decideg<S>(settings_->trim_decideg[k]), timing_);
        worst_status = worst(worst_status, cmd.status);
        uint16_t next = cmd.ticks;
        const uint16_t now = ticks_[k];
        if (now != kOff) {
          if (next > now + step_[j]) next = uint16_t(now + step_[j]);
          else if (now > next + step_[j]) next = uint16_t(now - step_[j]);
          if (next == now) continue;
        }
        ticks_[k] = next;
        out.write_ticks(cmd.channel, next);
      }
    }
    return worst_status;
  }
  template <typename Leg, typename Output>
  STRIDER_NOINLINE ServoStatus write_legs_slowly(const Leg* legs, Output& out) {
    RobotModel m;
    read_model(*model_, where_, &m);
    return write_legs(legs, out, &m);
  }

  //! The tick map's constants for up to n more legs; after the last one
  //! fast_ says whether the map holds every joint.
  STRIDER_NOINLINE void fit_legs(uint8_t n) {
    if (count_ == 0 || fitted_legs_ >= legs_) return;  // a model that does not fit; nothing to do
    RobotModel m;
    read_model(*model_, where_, &m);
    for (; n != 0 && fitted_legs_ < legs_; --n, ++fitted_legs_)
      for (uint8_t j = 0; j < dof_; ++j) {
        const uint8_t k = uint8_t(fitted_legs_ * dof_ + j);
        const S trim = trim_from_decideg<S>(settings_->trim_decideg[k]);
        if (tick_map_.configure_joint(k, make_joint_channel<S>(m, fitted_legs_, j), trim, timing_) != ServoTickStatus::kOk)
          unfit_ = true;
      }
    if (fitted_legs_ == legs_) fast_ = !unfit_;
  }

  //! New oscillator or PWM: prescale, outputs rescaled to keep their pulse widths.
  template <typename Output>
  void apply_pwm(Output& out) {
    pwm_pending_ = false;
    const uint32_t old_period = timing_.period_x64();
    // Refit even for a refused oscillator (new trims).
    fitted_legs_ = 0;
    unfit_ = false;
    if (configure_servo_pwm(out, timing_, *settings_) == PwmTimingStatus::kBadOscillator) return;
    for (uint8_t k = 0; k < count_; ++k) {
      if (ticks_[k] == kOff) continue;
      // ticks * old / new period, in two 16-bit halves of the period (no 64-bit).
      const uint32_t us_x64 = uint32_t(ticks_[k]) * (old_period >> 12);
      ticks_[k] = timing_.pulse_ticks(uint16_t(us_x64 >> 6));
      out.write_ticks(tick_map_.channel(k), ticks_[k]);
    }
    for (uint8_t j = 0; j < dof_; ++j) {
      const uint16_t t = timing_.pulse_ticks(servo_step_us(part_[j]));
      step_[j] = t == 0 ? uint16_t(1) : t;
    }
  }

  ServoTickMap<S, N, kSlots> tick_map_;  // joint k's slot is k % dof_ (configure())
  // Members without a default here are zero, by the constructors.
  bool fast_;
  bool unfit_;           // fit_legs() met a joint the map cannot hold
  uint8_t fitted_legs_;  // legs whose map constants fit the settings
  uint16_t ticks_[N];  // last written, kOff: off
  uint16_t step_[kMaxLegDof] = {1, 1, 1};
  ServoPart part_[kMaxLegDof] = {ServoPart::kSg90, ServoPart::kSg90, ServoPart::kSg90};  // of joint j
  Pca9685Timing timing_;
  const Settings* settings_;  // set_settings()
  const RobotModel* model_;   // configure(): the channels' source
  ModelMemory where_;
  uint32_t next_leg_ms_;
  uint8_t count_;
  uint8_t dof_;
  uint8_t legs_;
  uint8_t enabled_legs_;
  bool soft_start_;
  bool relax_pending_ = true;
  bool pwm_pending_ = true;
  ServoStatus status_;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_STAGE_H
