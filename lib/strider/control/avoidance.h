//! Avoidance: seed 000's obstacle behaviour: while walking forward, an
//! obstacle nearer than the stop distance makes the robot walk sideways
//! until the way is clear. Added: a slow-down band, hysteresis, a side
//! switch, a blocked state after both sides failed, and no forward motion
//! on a failed or stale sensor. Velocities in [0.1 mm/s], [0.1 deg/s]; [ms].
#ifndef STRIDER_CONTROL_AVOIDANCE_H
#define STRIDER_CONTROL_AVOIDANCE_H

#include <stdint.h>

#include "../robots/robot_model.h"
#include "hal_interfaces.h"
#include "reply.h"
#include "sonar_filter.h"

namespace strider {

//! Body velocity command: vx forward, vy left [0.1 mm/s], wz anticlockwise [0.1 deg/s].
struct Twist {
  int32_t vx;
  int32_t vy;
  int32_t wz;
};

struct AvoidConfig {
  bool enabled;
  uint16_t stop_mm;           //!< obstacle nearer -> sidestep [mm] (seed 000: 200)
  uint16_t slow_mm;           //!< obstacle nearer -> slow down [mm], >= stop_mm
  uint16_t hysteresis_mm;     //!< clear means >= stop_mm + this [mm]
  uint16_t clear_hold_ms;     //!< keep stepping sideways this long after clear [ms]
  uint16_t clear_mm;          //!< ... and at least this far, walked (the body's half-width) [mm]
  uint16_t side_timeout_ms;   //!< one side this long without success -> other side [ms]
  int32_t min_side_speed;     //!< sidestep speed at least this [0.1 mm/s]
};

constexpr AvoidConfig default_avoid_config() { return AvoidConfig{true, 200, 400, 50, 600, 0, 5000, 300}; }
constexpr uint8_t kAvoidMinSlowPct = 25;  //!< forward speed at the edge of the stop distance [%]

//! A model's clear_mm: the widest standing foot's distance from the body's
//! centre line plus kAvoidClearMarginMm [mm].
constexpr float kAvoidClearMarginMm = 40.0f;
constexpr uint16_t avoid_clear_mm(const RobotModel& m) {
  float w = 0.0f;
  for (uint8_t i = 0; i < m.leg_count && i < kMaxLegs; ++i) {
    const float y = m.legs[i].stand_mm.y;
    if (y > w) w = y;
    if (-y > w) w = -y;
  }
  w += kAvoidClearMarginMm;
  return w < 60000.0f ? uint16_t(w + 0.5f) : uint16_t(60000);
}

enum class AvoidState : uint8_t {
  kPassThrough = 0,  //!< disabled, or not walking forward
  kForward = 1,      //!< walking forward, way clear (possibly slowed)
  kSidestep = 2,     //!< obstacle ahead: walking sideways
  kClearing = 3,     //!< way clear: a little more sideways before resuming
  kBlocked = 4,      //!< both sides tried: standing until the command changes
  kSensorFault = 5   //!< sensor failed or stale: forward motion refused
};

constexpr char kAvoidStateNames[] STRIDER_PROGMEM = "pass\0forward\0sidestep\0clearing\0blocked\0sensor_fault";
inline FlashText to_flash(AvoidState s) { return flash_name(kAvoidStateNames, 6, uint8_t(s)); }

class Avoidance {
 public:
  //! One tick: the operator's command and the sonar -> the command to walk.
  //! walked_vy: the sideways speed really walked [0.1 mm/s], for
  //! cfg.clear_mm (kUnknownSpeed: the commanded sidestep speed).
  static constexpr int32_t kUnknownSpeed = -0x7FFFFFFF - 1;
  Twist update(const Twist& cmd, const SonarReading& sonar, uint32_t now_ms, const AvoidConfig& cfg,
               int32_t walked_vy = kUnknownSpeed) {
    if (!cfg.enabled || cmd.vx <= 0) {
      state_ = AvoidState::kPassThrough;
      reset_side();
      return cmd;
    }
    if (sonar.status == SonarStatus::kFailed || sonar.status == SonarStatus::kStale) {
      state_ = AvoidState::kSensorFault;
      return Twist{0, cmd.vy, cmd.wz};
    }
    const bool known = sonar.status == SonarStatus::kOk;
    const uint16_t d = known ? sonar.distance_mm : kSonarFarMm;
    const bool near = known && d < cfg.stop_mm;
    const bool clear = !known || uint32_t(d) >= uint32_t(cfg.stop_mm) + cfg.hysteresis_mm;
    switch (state_) {
      case AvoidState::kPassThrough:
      case AvoidState::kSensorFault:
      case AvoidState::kForward:
        if (near) enter(AvoidState::kSidestep, now_ms);
        else state_ = AvoidState::kForward;
        break;
      case AvoidState::kSidestep:
        if (clear) {
          enter(AvoidState::kClearing, now_ms);
          cleared_ = 0;
          last_ms_ = now_ms;
        } else if (elapsed(now_ms, since_ms_) >= uint32_t(cfg.side_timeout_ms) + extra_ms_) {
          if (switched_) {
            enter(AvoidState::kBlocked, now_ms);
          } else {
            // The way to the other side passes the start: give it twice the time.
            switched_ = true;
            side_ = int8_t(-side_);
            since_ms_ = now_ms;
            extra_ms_ = cfg.side_timeout_ms;
          }
        }
        break;
      case AvoidState::kClearing:
        if (near) enter(AvoidState::kSidestep, now_ms);
        else if (cleared(cmd, cfg, now_ms, walked_vy)) {
          state_ = AvoidState::kForward;
          reset_side();
        }
        break;
      case AvoidState::kBlocked:
        if (clear) {
          state_ = AvoidState::kForward;
          reset_side();
        }
        break;
    }
    return output(cmd, d, cfg);
  }

  AvoidState state() const { return state_; }
  int8_t side() const { return side_; }  //!< +1 left, -1 right

 private:
  void reset_side() {
    side_ = 1;
    switched_ = false;
    extra_ms_ = 0;
  }

  //! Clearing done: held clear_hold_ms and walked clear_mm sideways (the
  //! beam is narrower than the body), or side_timeout_ms passed.
  bool cleared(const Twist& cmd, const AvoidConfig& cfg, uint32_t now_ms, int32_t walked_vy) {
    const uint32_t dt = elapsed(now_ms, last_ms_);
    last_ms_ = now_ms;
    int32_t v = walked_vy == kUnknownSpeed ? side_speed(cmd, cfg) : walked_vy;
    if (v < 0) v = v < -kMaxSpeed ? kMaxSpeed : -v;
    if (v > kMaxSpeed) v = kMaxSpeed;
    // [0.1 mm/s] x [ms] = 1e-4 mm, the sum saturating.
    const uint32_t step = uint32_t(v) * (dt > 1000u ? 1000u : dt);
    cleared_ = step >= 0xFFFFFFFFu - cleared_ ? 0xFFFFFFFFu : cleared_ + step;
    const uint32_t held = elapsed(now_ms, since_ms_);
    if (held >= cfg.side_timeout_ms) return true;
    return held >= cfg.clear_hold_ms && cleared_ >= uint32_t(cfg.clear_mm) * 10000u;
  }

  static constexpr int32_t kMaxSpeed = 100000;  //!< 10 m/s [0.1 mm/s]: more is taken as this

  static int32_t side_speed(const Twist& cmd, const AvoidConfig& cfg) {
    return cmd.vx > cfg.min_side_speed ? cmd.vx : cfg.min_side_speed;
  }

  void enter(AvoidState s, uint32_t now_ms) {
    state_ = s;
    since_ms_ = now_ms;
  }

  Twist output(const Twist& cmd, uint16_t d, const AvoidConfig& cfg) const {
    switch (state_) {
      case AvoidState::kSidestep:
      case AvoidState::kClearing: return Twist{0, side_ * side_speed(cmd, cfg), 0};
      case AvoidState::kBlocked: return Twist{0, 0, 0};
      default: break;
    }
    if (d >= cfg.slow_mm || cfg.slow_mm <= cfg.stop_mm) return cmd;
    const int32_t span = int32_t(cfg.slow_mm) - int32_t(cfg.stop_mm);
    const int32_t into = d > cfg.stop_mm ? int32_t(d) - int32_t(cfg.stop_mm) : 0;
    const int32_t pct = kAvoidMinSlowPct + (100 - kAvoidMinSlowPct) * into / span;
    return Twist{cmd.vx * pct / 100, cmd.vy, cmd.wz};
  }

  uint32_t since_ms_ = 0;
  uint32_t extra_ms_ = 0;
  uint32_t last_ms_ = 0;  //!< clearing: the previous tick
  uint32_t cleared_ = 0;  //!< clearing: walked sideways since clear [1e-4 mm]
  AvoidState state_ = AvoidState::kPassThrough;
  int8_t side_ = 1;
  bool switched_ = false;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_AVOIDANCE_H
