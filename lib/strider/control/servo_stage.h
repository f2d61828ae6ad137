//! ServoStage: the last step before the servo boards. Every frame it maps the
//! walker's joints to PCA9685 ticks (servo_tick_map.h, with the live trims), moves
//! each output towards its target by at most what the servo can turn in one
//! frame (so a new gait, pose or trim never makes the PCA9685 jump: the
//! board switches to a new width at once, the servo would slam), and writes
//! only the channels that changed. Output::flush() ends the frame (the driver
//! sends its changed channels in auto-increment bursts).
//!
//! Soft start: after power-up or relax every output is off (no pulse, servo
//! limp); the legs are switched on one at a time, kSoftStartStepMs apart, so
//! the servos do not all draw their start-up current at once and brown out
//! the supply (ANCHORS: the most common complaint). A servo's first pulse
//! cannot be interpolated (its position is unknown): that is what the
//! staging is for. An output that already holds a pulse (adopt_outputs():
//! after an MCU reset the boards ran through, or a board that came back)
//! is not switched off: its leg moves on from that pulse at its turn.
#ifndef STRIDER_CONTROL_SERVO_STAGE_H
#define STRIDER_CONTROL_SERVO_STAGE_H

#include <stdint.h>

#include "../gait/walker.h"
#include "channel_map.h"
#include "constant_given.h"
#include "servo_boards.h"
#include "servo_frame.h"
#include "servo_tick_map.h"

namespace strider {

constexpr uint16_t kSoftStartStepMs = 250;   //!< one leg's servos switched on per step [ms]
constexpr uint16_t kFramePeriodMs = 20;      //!< nominal frame period for the slew limit [ms] (50 Hz)

//! N: most joints (servos) it drives; a firmware for one model sizes it to
//! the model's joint count.
//!
//! RAM: the stage keeps no servo channels (servo_map.h) of its own, only
//! the tick map's constants, which a frame needs. The channels are rebuilt
//! from the model (in flash on the AVR, through a copy on the stack) when
//! the trims or the PWM change, by channel(), and in every frame only when
//! the tick map cannot hold them (map_joint(), slow; for the built-in servo
//! parts only near 400 Hz, where a joint's longest pulse reaches the period).
//! The tick map's slots (servo_tick_map.h): 0, every joint its own range;
//! a firmware whose legs have one geometry sets STRIDER_SERVO_TICK_SLOTS to
//! its legs' joint count, and the joints of a slot share their range.
#ifndef STRIDER_SERVO_TICK_SLOTS
#define STRIDER_SERVO_TICK_SLOTS 0
#endif
constexpr uint8_t kServoTickSlots = uint8_t(STRIDER_SERVO_TICK_SLOTS);
//! Whether model m's joints fit this build's tick-map slots: every joint its
//! own range, or one slot per joint of a leg when all legs have one geometry.
STRIDER_ALWAYS_INLINE constexpr bool servo_tick_slots_fit(const RobotModel& m) {
  return kServoTickSlots == 0 || (kServoTickSlots == m.dof() && leg_solver_count(m) == 1);
}

//! A stage's channels as a constant of its model (joint_channels(): a
//! firmware keeps its model's in flash): joint k's channel is range[k %
//! kRanges] with output[k] and direction[k] (legs of one geometry share
//! their ranges, kServoTickSlots).
template <typename S, uint8_t N>
struct JointChannels {
  static constexpr uint8_t kRanges = kServoTickSlots != 0 ? kServoTickSlots : N;
  ServoChannel<S> range[kRanges];
  uint8_t output[N];
  int8_t direction[N];
  uint8_t count;  // channel_map_count(), 0: the model does not fit the stage
  uint16_t step_us[kMaxLegDof];  // joint j's slew step per frame [us] (servo_step_us())
};
//! Joint j's slew step per frame [us]: a pulse change at the servo's top
//! speed over one frame (500-2500 us over 180 deg), rounded.
constexpr uint16_t servo_step_us(float speed_deg_s) {
  return uint16_t(speed_deg_s * (float(kFramePeriodMs) / 1000.0f) * (2000.0f / 180.0f) + 0.5f);
}
namespace servo_stage_detail {
template <typename S, uint8_t N, uint8_t... R, uint8_t... K>
constexpr JointChannels<S, N> joint_channels(const RobotModel& m, walker_detail::Indices<R...>, walker_detail::Indices<K...>) {
  return JointChannels<S, N>{
      {(R < m.joint_count() ? joint_channel_constant<S>(m, uint8_t(R / m.dof()), uint8_t(R % m.dof()))
                            : ServoChannel<S>{})...},
      {(K < m.joint_count() ? joint_channel(m, uint8_t(K / m.dof()), uint8_t(K % m.dof())) : uint8_t(0))...},
      {(K < m.joint_count() ? joint_direction(m, uint8_t(K / m.dof()), uint8_t(K % m.dof())) : int8_t(1))...},
      uint8_t(m.joint_count() <= N &&
                      servo_tick_slots_fit(m)
                  ? channel_map_count_constant(m)
                  : 0),
      {servo_step_us(servo_parts_detail::travel_of(m.servo[0]).speed_deg_s),
       servo_step_us(servo_parts_detail::travel_of(m.servo[1]).speed_deg_s),
       servo_step_us(servo_parts_detail::travel_of(m.servo[2]).speed_deg_s)}};
}
static_assert(kMaxLegDof == 3, "joint_channels: a step per joint of a leg");
}  // namespace servo_stage_detail
//! Model m's channels for a stage of N joints (ServoStage's kChannels).
template <typename S, uint8_t N>
constexpr JointChannels<S, N> joint_channels(const RobotModel& m) {
  return servo_stage_detail::joint_channels<S, N>(m, typename walker_detail::MakeIndices<JointChannels<S, N>::kRanges>::type(),
                                                  typename walker_detail::MakeIndices<N>::type());
}

//! kChannels: the model's channels in flash (joint_channels() of the model
//! given to configure(): a firmware's constant), nullptr: made from the
//! model when needed (make_joint_channel()).
template <typename S, uint8_t N = kMaxServoJoints, const JointChannels<S, N>* kChannels = nullptr>
class ServoStage {
  static constexpr bool kHasChannels = constant_given<const JointChannels<S, N>*, kChannels>();

 public:
  ServoStage()
      : fast_(false), unfit_(false), fitted_legs_(0), settings_(nullptr), model_(nullptr), where_(ModelMemory::kRam),
        next_leg_ms_(0), count_(0), dof_(0), legs_(0), enabled_legs_(0), soft_start_(false),
        status_(ServoStatus::kOk) {}

  //! Channel map of `model` (readable: a copy of `source` if that is in
  //! flash); every output off. The stage reads `source` again later
  //! (nullptr: `model` itself), which must outlive it. False when the model
  //! does not fit.
  bool configure(const RobotModel& model, const RobotModel* source = nullptr, ModelMemory where = ModelMemory::kRam) {
    // Joint k = leg dof + j: slot j when the tick map has dof slots, for
    // legs of one geometry (the same limits: one range per slot); fit_legs()
    // configures leg 0 first.
    const bool slots_fit = servo_tick_slots_fit(model);
    count_ = kHasChannels ? flash_u8(&kChannels->count)
             : model.joint_count() <= N && slots_fit ? channel_map_count(model) : uint8_t(0);
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

  //! Trims, oscillator and PWM frequency from the next frame on (the bus may
  //! not be up yet when settings are loaded). Keeps a pointer, not a copy (RAM):
  //! s must outlive the stage or the next call (RobotApp passes the
  //! controller's settings or its calibration's live values), and must be
  //! given before the first frame.
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

  //! What the outputs of the boards in board_mask drive now, when that is not
  //! what the stage wrote (after an MCU reset the boards kept running through,
  //! or a board that answers again): words[ch] is channel ch's OFF word, ON
  //! 0, kPcaFullOff set for no pulse. A joint whose output holds a pulse
  //! within the joint's limits goes on from it: no relax, and its leg moves
  //! from there (slew-limited) once the soft start reaches it. Any other is
  //! switched off, to get its first pulse at its leg's turn. Returns the
  //! joints that hold a pulse. Call after apply_pending() (the limits' ticks).
  template <typename Output>
  uint8_t adopt_outputs(Output& out, const uint16_t* words, uint8_t channels, uint8_t board_mask) {
    uint8_t held = 0;
    for (uint8_t k = 0; k < count_; ++k) {
      const uint8_t ch = tick_map_.channel(k);
      if (!(board_mask & board_bit(board_of_channel(ch)))) continue;
      const uint16_t w = ch < channels ? words[ch] : kPcaFullOff;
      // The limits' ticks are known when the tick map holds every joint
      // (every built-in model); otherwise nothing is taken as held.
      bool inside = false;
      if (fast_ && w < kPcaFullOff) {
        const ServoTickJoint<S> j = tick_map_.joint(k);
        inside = w >= j.lo_ticks && w <= j.hi_ticks;
      }
      if (inside) {
        ticks_[k] = w;
        ++held;
      } else {
        ticks_[k] = kOff;
        out.relax(ch);
      }
    }
    // Every board (a warm start): this replaces the relax of configure().
    // Some boards: a relax asked for meanwhile still applies to all.
    if (board_mask == 0xFF) relax_pending_ = false;
    return held;
  }

  //! Switches the legs on again one at a time from now_ms, as at power-up,
  //! without relaxing anything: a leg keeps what its outputs drive until its
  //! turn (after adopt_outputs(): a board that came back), then moves on from
  //! it. Only while the servos are on or starting (not after relax).
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
    return channel_of(m, uint8_t(k / dof_), uint8_t(k % dof_), k);
  }
  bool on(uint8_t k) const { return ticks_[k] != kOff; }
  uint16_t ticks(uint8_t k) const { return on(k) ? ticks_[k] : uint16_t(0); }   //!< last written [PCA9685 ticks], 0 off
  const Pca9685Timing& timing() const { return timing_; }
  //! The per-frame map's constants (host tools and tests).
  const ServoTickMap<S, N, kServoTickSlots>& tick_map() const { return tick_map_; }
  ServoStatus last_status() const { return status_; }

  //! Applies pending settings now (prescale to the boards, the fast map's
  //! constants), e.g. at start-up, so that no
  //! control tick pays for it. frame() does it too when settings change,
  //! the map's constants one leg per frame.
  template <typename Output>
  void apply_pending(Output& out) {
    if (pwm_pending_) apply_pwm(out);
    fit_legs(legs_);
  }

  //! One frame at now_ms: soft start, map, slew, write; ends with out.flush().
  template <typename Output>
  ServoStatus frame(const Walker<S>& walker, uint32_t now_ms, Output& out) {
    if (pwm_pending_) apply_pwm(out);
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
    // New settings: every output holds its pulse (rescaled to a new PWM
    // period at once) while the map's constants are rebuilt, a leg per frame
    // (a whole map is ~20 ms of float work on the AVR: more than a tick).
    if (fitted_legs_ < legs_) {
      fit_legs(1);
    } else {
      status_ = fast_ ? write_legs(walker, out, nullptr) : write_legs_slowly(walker, out);
    }
    out.flush();
    return status_;
  }

 private:
  static constexpr uint16_t kOff = 0xFFFF;  // ticks_ of an output that is off (no pulse)

  //! The enabled legs' joints through the tick map, or (model given: the
  //! map cannot hold them) through map_joint() with channels rebuilt from
  //! the model; slewed, written when changed. The worst status.
  template <typename Output>
  ServoStatus write_legs(const Walker<S>& walker, Output& out, const RobotModel* model) {
    ServoStatus worst_status = ServoStatus::kOk;
    for (uint8_t leg = 0; leg < enabled_legs_; ++leg) {
      const LegResult<S>& r = walker.leg(leg);
      for (uint8_t j = 0; j < dof_; ++j) {
        const uint8_t k = uint8_t(leg * dof_ + j);
        const ServoCommand cmd = model == nullptr
                                     ? tick_map_.map(k, j, r.q[j])
                                     : map_joint(channel_of(*model, leg, j, k), r.q[j],
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
  template <typename Output>
  STRIDER_NOINLINE ServoStatus write_legs_slowly(const Walker<S>& walker, Output& out) {
    return write_legs_slowly(walker, out, Given<kHasChannels>());
  }
  template <bool kOn>
  struct Given {};
  template <typename Output>
  ServoStatus write_legs_slowly(const Walker<S>& walker, Output& out, Given<false>) {
    RobotModel m;
    read_model(*model_, where_, &m);
    return write_legs(walker, out, &m);
  }
  template <typename Output>
  ServoStatus write_legs_slowly(const Walker<S>& walker, Output& out, Given<true>) {
    return write_legs(walker, out, model_);  // only a flag: the channels come from kChannels
  }

  //! Joint j's slew step per frame [us]: from kChannels, or from its servo part.
  uint16_t step_us(uint8_t j, Given<false>) const { return servo_step_us(servo_travel(part_[j]).speed_deg_s); }  // from flash
  uint16_t step_us(uint8_t j, Given<true>) const { return flash_u16(&kChannels->step_us[0], j); }

  //! Joint k = leg dof + j's channel: from kChannels, or made from m.
  ServoChannel<S> channel_of(const RobotModel& m, uint8_t leg, uint8_t j, uint8_t k) const {
    return channel_of(m, leg, j, k, Given<kHasChannels>());
  }
  ServoChannel<S> channel_of(const RobotModel& m, uint8_t leg, uint8_t j, uint8_t, Given<false>) const {
    return make_joint_channel<S>(m, leg, j);
  }
  ServoChannel<S> channel_of(const RobotModel&, uint8_t, uint8_t, uint8_t k, Given<true>) const {
    ServoChannel<S> ch;
    flash_copy(&ch, &kChannels->range[k % JointChannels<S, N>::kRanges], sizeof ch);
    ch.channel = flash_u8(&kChannels->output[k]);
    ch.direction = int8_t(flash_u8(&kChannels->direction[k]));
    return ch;
  }

  //! The tick map's constants for the timing and trims of up to n more
  //! legs, from the model (a copy, if it is in flash); after the last leg
  //! fast_ says whether the map holds every joint.
  STRIDER_NOINLINE void fit_legs(uint8_t n) {
    if (count_ == 0 || fitted_legs_ >= legs_) return;  // a model that does not fit; nothing to do
    fit_legs(n, Given<kHasChannels>());
  }
  void fit_legs(uint8_t n, Given<false>) {
    RobotModel m;
    read_model(*model_, where_, &m);
    fit_legs(n, m);
  }
  void fit_legs(uint8_t n, Given<true>) { fit_legs(n, *model_); }  // the model is not read
  void fit_legs(uint8_t n, const RobotModel& m) {
    for (; n != 0 && fitted_legs_ < legs_; --n, ++fitted_legs_)
      for (uint8_t j = 0; j < dof_; ++j) {
        const uint8_t k = uint8_t(fitted_legs_ * dof_ + j);
        const S trim = trim_from_decideg<S>(settings_->trim_decideg[k]);
        if (tick_map_.configure_joint(k, channel_of(m, fitted_legs_, j, k), trim, timing_) != ServoTickStatus::kOk)
          unfit_ = true;
      }
    if (fitted_legs_ == legs_) fast_ = !unfit_;
  }

  //! New oscillator or PWM frequency: prescale to the boards, the outputs that
  //! are on rescaled to keep their pulse widths, new slew steps.
  template <typename Output>
  void apply_pwm(Output& out) {
    pwm_pending_ = false;
    const uint32_t old_period = timing_.period_x64();
    // The map's constants again (fit_legs()), for the trims even when the
    // oscillator is refused (the timing is then kept).
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
      // Pulse change per frame at the servo's top speed (500-2500 us over 180 deg).
      const uint16_t t = timing_.pulse_ticks(step_us(j, Given<kHasChannels>()));
      step_[j] = t == 0 ? uint16_t(1) : t;
    }
  }

  ServoTickMap<S, N, kServoTickSlots> tick_map_;  // joint k's slot is k % dof_ (configure())
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
