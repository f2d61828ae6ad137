//! GaitTuner: the live gait parameters of the gait walked now (gait_tuning.h)
//! applied to a WalkerMotion, checked against what its walker was built for,
//! kept per gait in the store (gait_tuning_record.h). A gait switch takes the
//! gait's saved set or the model's defaults; a change applies at the next
//! stride (docs/protocol.md, "Live gait parameters").
#ifndef STRIDER_CONTROL_GAIT_TUNER_H
#define STRIDER_CONTROL_GAIT_TUNER_H

#include <stdint.h>

#include "../gait/gait_tuning.h"
#include "gait_tuning_record.h"
#include "walker_motion.h"

namespace strider {

//! Where the parameters walked now came from (`status`: tune=...).
enum class TuneOrigin : uint8_t { kDefault = 0, kSaved = 1, kChanged = 2 };
constexpr char kTuneOriginNames[] STRIDER_PROGMEM = "default\0saved\0changed";
inline FlashText to_flash(TuneOrigin o) { return flash_name(kTuneOriginNames, 3, uint8_t(o)); }

namespace gait_tuner_detail {
//! v x 100, rounded half up (v >= 0, v x 100 < 2^31).
inline int32_t hundredths(float v) { return int32_t(v * 100.0f + 0.5f); }
inline int32_t hundredths(Fixed v) { return int32_t((int64_t(v.raw()) * 100 + 32768) >> 16); }
//! n / 100 in the scalar.
template <typename S>
S from_hundredths(int32_t n) { return S(n) / S(100); }
}  // namespace gait_tuner_detail

template <typename S, typename P = HostProfile<S>>
class GaitTuner {
 public:
  //! Takes the model's defaults from a walker just configured at them.
  void configure(WalkerMotion<S, P>& motion) {
    const auto& c = motion.walker().engine().config();
    own_ = Own{c.step_height_mm, c.limits.preferred_stride_mm, c.limits.min_hz, c.limits.lift_ms, c.shape};
    live_ = gait_defaults(motion, duty_pct_of(motion.gait()));
    origin_ = TuneOrigin::kDefault;
  }

  //! After a gait switch (and at start-up): the gait's saved parameters
  //! when the walker allows them, or the defaults.
  template <typename Store>
  void use_gait(WalkerMotion<S, P>& motion, const Store& store) {
    live_ = gait_defaults(motion, own_duty_pct(motion));
    origin_ = TuneOrigin::kDefault;
    GaitTuning saved;
    if (read_gait_tuning(store, gait_index(motion.walker().leg_count(), motion.gait().name), &saved)) {
      // Checked against the ranges the saved set makes itself (cycle and duty).
      const GaitTuning own = live_;
      live_ = saved;
      if (tuning_allowed(bounds(motion), saved)) {
        origin_ = TuneOrigin::kSaved;
      } else {
        live_ = own;
      }
    }
    apply(motion);
    if (live_.height_dmm > 0) motion.set_body_height(live_.height_dmm);
  }

  //! Parameter p to v (its unit / 100; kSwing: a SwingShape); false: out of bounds().
  bool set(WalkerMotion<S, P>& motion, TuneParam p, int32_t v) {
    if (!in_tune_range(range(motion, p), p, v)) return false;
    switch (p) {
      case TuneParam::kStepHeight: live_.step_height_cmm = uint16_t(v); break;
      case TuneParam::kStepLength: live_.step_length_cmm = uint16_t(v); break;
      case TuneParam::kCycle: live_.cycle_cs = uint16_t(v); break;
      case TuneParam::kDuty: live_.duty_pct = uint8_t(v); break;
      case TuneParam::kSwing: live_.shape = uint8_t(v); break;
    }
    origin_ = TuneOrigin::kChanged;
    apply(motion);
    return true;
  }

  //! Writes the gait's parameters and the body height into the store.
  template <typename Store>
  SettingsStatus save(const WalkerMotion<S, P>& motion, Store& store) {
    live_.height_dmm = int16_t(body_height_dmm(motion));
    const SettingsStatus st = save_gait_tuning(store, gait_index(motion.walker().leg_count(), motion.gait().name), live_);
    if (st == SettingsStatus::kOk) origin_ = TuneOrigin::kSaved;
    return st;
  }

  //! What parameter p may be for the gait walked now (docs/protocol.md,
  //! "Live gait parameters"; kSwing: lo is a mask).
  TuneRange range(const WalkerMotion<S, P>& motion, TuneParam p) const {
    using namespace gait_tuner_detail;
    const VelocityLimits<S, P::kSearch>& lim = motion.walker().engine().config().limits;
    const GaitTuning mine = own_tuning();
    switch (p) {
      case TuneParam::kStepHeight: return TuneRange{kMinStepHeightCmm, mine.step_height_cmm};
      case TuneParam::kStepLength: {
        S longest = S(0);
        for (uint8_t i = 0; i < motion.walker().leg_count(); ++i)
          for (uint8_t k = 0; k < kStrideDirections; ++k) longest = max_of(longest, lim.stride_mm(i, k));
        const int32_t hi = hundredths(longest);
        return TuneRange{kMinStepLengthCmm, hi > mine.step_length_cmm ? hi : int32_t(mine.step_length_cmm)};
      }
      case TuneParam::kCycle: return TuneRange{shortest_cycle_cs(lim, live_.duty_pct), kMaxCycleCs};
      case TuneParam::kDuty: {
        GaitTable own;
        load_gait(motion.walker().leg_count(), motion.gait().name, &own);
        TuneRange r = duty_range(own);
        // At most 1 - lift / cycle, then the cycle's own test.
        const int32_t most = 100 - (hundredths(lim.lift_ms / S(int32_t(live_.cycle_cs))) + 9) / 10;
        const int32_t gait_most = r.hi;
        if (most < r.hi) r.hi = most;
        while (r.hi > r.lo && shortest_cycle_cs(lim, r.hi) > live_.cycle_cs) --r.hi;
        while (r.hi < gait_most && shortest_cycle_cs(lim, r.hi + 1) <= live_.cycle_cs) ++r.hi;
        return r;
      }
      case TuneParam::kSwing: break;
    }
    return TuneRange{swings_within(own_.shape), 0};
  }
  TuneBounds bounds(const WalkerMotion<S, P>& motion) const {
    return TuneBounds{range(motion, TuneParam::kStepHeight), range(motion, TuneParam::kStepLength),
                      range(motion, TuneParam::kCycle), range(motion, TuneParam::kDuty), uint8_t(swings_within(own_.shape))};
  }

  //! `step_height=20.00 step_length=40.00 cycle=0.80 duty=0.75 swing=ellipse height=85.0`
  void write(const WalkerMotion<S, P>& motion, ReplyWriter& w) const {
    const int32_t v[4] = {live_.step_height_cmm, live_.step_length_cmm, live_.cycle_cs, live_.duty_pct};
    for (uint8_t p = 0; p < 4; ++p)
      w.ch(' ').text(flash_name(kTuneParamNames, kTuneParamCount, p)).ch('=').hundredths(v[p]);
    w.ch(' ').text(flash_name(kTuneParamNames, kTuneParamCount, uint8_t(TuneParam::kSwing))).ch('=');
    w.text(flash_name(kSwingShapeNames, kSwingShapeCount, live_.shape));
    w.ch(' ').text(FlashText{kHeightName}).ch('=').tenths(body_height_dmm(motion));
  }

  const GaitTuning& live() const { return live_; }
  TuneOrigin origin() const { return origin_; }
  //! The shortest cycle [0.01 s] the servos step at with duty_pct, rounded up.
  static int32_t shortest_cycle_cs(const VelocityLimits<S, P::kSearch>& lim, int32_t duty_pct) {
    using namespace gait_tuner_detail;
    const int32_t lo = hundredths(S(1) / lim.servo_hz(S(0), from_hundredths<S>(duty_pct))) + 1;
    return lo > kMinCycleCs ? lo : kMinCycleCs;
  }

  //! The model's own parameters (duty and height 0).
  GaitTuning own_tuning() const {
    using namespace gait_tuner_detail;
    return GaitTuning{uint16_t(hundredths(own_.step_height_mm)), uint16_t(hundredths(own_.stride_mm)),
                      uint16_t(hundredths(S(1) / own_.min_hz)), 0, uint8_t(own_.shape), 0};
  }

 private:
  //! The model's own values, bit for bit, for a parameter set back to them.
  struct Own {
    S step_height_mm, stride_mm, min_hz, lift_ms;
    SwingShape shape;
  };
  static constexpr char kHeightName[] STRIDER_PROGMEM = "height";

  //! The model's defaults at duty_pct, the cycle no shorter than the servos step at.
  GaitTuning gait_defaults(const WalkerMotion<S, P>& motion, uint8_t duty_pct) const {
    GaitTuning t = own_tuning();
    t.duty_pct = duty_pct;
    const int32_t shortest = shortest_cycle_cs(motion.walker().engine().config().limits, duty_pct);
    if (t.cycle_cs < shortest) t.cycle_cs = uint16_t(shortest);
    return t;
  }

  static uint8_t own_duty_pct(const WalkerMotion<S, P>& motion) {
    GaitTable own;
    return load_gait(motion.walker().leg_count(), motion.gait().name, &own) ? duty_pct_of(own) : duty_pct_of(motion.gait());
  }

  //! The body's height above the ground now [0.1 mm].
  static int32_t body_height_dmm(const WalkerMotion<S, P>& motion) {
    const S mm = motion.stand_height_mm() + motion.offsets().translation_mm.z;
    return (gait_tuner_detail::hundredths(mm) + 5) / 10;
  }

  //! live_ into the walker, what differs from what it walks.
  void apply(WalkerMotion<S, P>& motion) {
    using namespace gait_tuner_detail;
    auto& e = motion.walker().engine();
    const auto& c = e.config();
    const GaitTuning mine = own_tuning();
    const S height = live_.step_height_cmm == mine.step_height_cmm ? own_.step_height_mm
                                                                   : from_hundredths<S>(live_.step_height_cmm);
    const S stride = live_.step_length_cmm == mine.step_length_cmm ? own_.stride_mm
                                                                   : from_hundredths<S>(live_.step_length_cmm);
    // The model's cycle, or the servos' longer shortest one at this duty.
    const bool own_cycle = live_.cycle_cs == mine.cycle_cs ||
                           (live_.cycle_cs > mine.cycle_cs && live_.cycle_cs == shortest_cycle_cs(c.limits, live_.duty_pct));
    const S hz = own_cycle ? own_.min_hz : S(100) / S(int32_t(live_.cycle_cs));
    // A lower apex lifts in less servo time: the joints' travel of a lift in
    // place grows with its height (velocity_search.h's lift_ms), so the
    // step rate the servos allow rises with a lower step.
    if (!(height == c.step_height_mm) || SwingShape(live_.shape) != c.shape)
      e.set_swing(height, SwingShape(live_.shape), height == own_.step_height_mm ? own_.lift_ms : own_.lift_ms * height / own_.step_height_mm);
    if (!(stride == c.limits.preferred_stride_mm) || !(hz == c.limits.min_hz)) e.set_step(stride, hz);
    if (live_.duty_pct != duty_pct_of(motion.gait())) motion.set_duty(live_.duty_pct);
    // The speed correction holds for the gait's own parameters only.
    const GaitTuning own = gait_defaults(motion, own_duty_pct(motion));
    motion.correct_speeds(live_.step_height_cmm == own.step_height_cmm &&
                          live_.step_length_cmm == own.step_length_cmm && live_.cycle_cs == own.cycle_cs &&
                          live_.duty_pct == own.duty_pct && live_.shape == own.shape);
  }

  Own own_{};
  GaitTuning live_{};
  TuneOrigin origin_ = TuneOrigin::kDefault;
};

template <typename S, typename P>
constexpr char GaitTuner<S, P>::kHeightName[];

}  // namespace strider

#endif  // STRIDER_CONTROL_GAIT_TUNER_H
