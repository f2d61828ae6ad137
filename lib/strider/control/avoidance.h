//! Avoidance: seed 000's obstacle behaviour (sec 4.3, results): while walking
//! forward, an obstacle nearer than the stop distance (20 cm) ahead makes the
//! robot walk sideways until the way is clear, then forward again.
//! Additions: a slow-down band (forward speed falls linearly from 100 % at
//! the slow distance to kAvoidMinSlowPct at the stop distance), hysteresis,
//! a side switch when one side takes too long, a blocked state after both
//! sides failed, and a sensor-failure policy: no forward motion on a failed
//! or stale sensor (backwards, sideways and turning stay allowed).
//! Velocities are in the Command units: [0.1 mm/s], [0.1 deg/s]. Time [ms].
#ifndef STRIDER_CONTROL_AVOIDANCE_H
#define STRIDER_CONTROL_AVOIDANCE_H

#include <stdint.h>

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

enum class AvoidState : uint8_t {
  kPassThrough = 0,  //!< disabled, or not walking forward
  kForward = 1,      //!< walking forward, way clear (possibly slowed)
  kSidestep = 2,     //!< obstacle ahead: walking sideways
  kClearing = 3,     //!< way clear: a little more sideways before resuming
  kBlocked = 4,      //!< both sides tried: standing until the command changes
  kSensorFault = 5   //!< sensor failed or stale: forward motion refused
};

inline const char* to_string(AvoidState s) {
  switch (s) {
    case AvoidState::kPassThrough: return "pass";
    case AvoidState::kForward: return "forward";
    case AvoidState::kSidestep: return "sidestep";
    case AvoidState::kClearing: return "clearing";
    case AvoidState::kBlocked: return "blocked";
    case AvoidState::kSensorFault: return "sensor_fault";
  }
  return "unknown";
}

constexpr char kAvoidStateNames[] STRIDER_PROGMEM = "pass\0forward\0sidestep\0clearing\0blocked\0sensor_fault";
//! to_string() with the text in flash (for replies on the AVR).
inline FlashText to_flash(AvoidState s) { return flash_name(kAvoidStateNames, 6, uint8_t(s)); }

class Avoidance {
 public:
  Avoidance() : since_ms_(0), extra_ms_(0), last_ms_(0), cleared_(0), state_(AvoidState::kPassThrough), switched_(false) {}

  //! One control tick: the operator's command, the sonar, the time -> the
  //! command to walk. Seed 000 only avoids while walking forward.
  //! walked_vy: the sideways speed the body really walks [0.1 mm/s] (the
  //! gait's, after its limits and ramp), for cfg.clear_mm; kUnknownSpeed:
  //! taken as the commanded sidestep speed.
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
  //! sensor's beam is narrow: the way is clear for the sensor before it is
  //! for the body and its feet), or side_timeout_ms passed (a gait that
  //! cannot walk sideways must not hold this state for ever).
  bool cleared(const Twist& cmd, const AvoidConfig& cfg, uint32_t now_ms, int32_t walked_vy) {
    const uint32_t dt = elapsed(now_ms, last_ms_);
    last_ms_ = now_ms;
    int32_t v = walked_vy == kUnknownSpeed ? side_speed(cmd, cfg) : walked_vy;
    if (v < 0) v = v < -kMaxSpeed ? kMaxSpeed : -v;
    if (v > kMaxSpeed) v = kMaxSpeed;
    // [0.1 mm/s] x [ms] = 1e-4 mm: at most 1e5 x 1e3 per tick, and the sum
    // saturates instead of wrapping.
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
    // Linear from kAvoidMinSlowPct at stop_mm to 100 % at slow_mm.
    const int32_t span = int32_t(cfg.slow_mm) - int32_t(cfg.stop_mm);
    const int32_t into = d > cfg.stop_mm ? int32_t(d) - int32_t(cfg.stop_mm) : 0;
    const int32_t pct = kAvoidMinSlowPct + (100 - kAvoidMinSlowPct) * into / span;
    return Twist{cmd.vx * pct / 100, cmd.vy, cmd.wz};
  }

  // Zero (but side_), by the constructors.
  uint32_t since_ms_;
  uint32_t extra_ms_;
  uint32_t last_ms_;  //!< clearing: the previous tick
  uint32_t cleared_;  //!< clearing: walked sideways since clear [1e-4 mm]
  AvoidState state_;
  int8_t side_ = 1;
  bool switched_;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_AVOIDANCE_H
