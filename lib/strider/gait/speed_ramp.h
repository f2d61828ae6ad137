//! SpeedRamp: the command, its plan (velocity_limits.h) and the ramp to it
//! in stride per cycle: the velocity walked, its body step, and the stride a
//! foot landing now is placed for (docs/gaits.md, "Starting, stopping").
#ifndef STRIDER_GAIT_SPEED_RAMP_H
#define STRIDER_GAIT_SPEED_RAMP_H

#include "../kinematics/leg_ik_common.h"
#include "gait_config.h"
#include "stance.h"

namespace strider {

//! A command as the body's travel [mm] and turn [rad] per cycle, and the step rate [Hz].
template <typename S>
struct Stride {
  S x, y, yaw, hz;
};

template <typename S>
struct SpeedRamp {
  S cmd_vx, cmd_vy, cmd_wz;  // the command as set (speed percentage applied)
  VelocityPlan<S> plan;      // the command as it will be walked
  Stride<S> from, to, now, land;  // land: the mean stride over the next stance
  S t = S(1), per_cycle = S(1), cycles = S(1);  // how far along [0, 1]; cycles = 1 / per_cycle
  S vx, vy, wz, hz = S(1);  // now x hz
  bool vel_fresh;   // vx, vy, wz are now x hz
  bool land_fresh;  // the ramp is over and land is now (update_landing() has nothing to do)
  struct StepCache {
    S dt;  // the tick the step is for; 0 (no tick has it): vx, vy or wz changed since
    BodyStep<S> step;
  } step_cache;

  void reset(S rate_hz) {
    vx = vy = wz = S(0);
    hz = rate_hz;
    plan = VelocityPlan<S>{S(0), S(0), S(0), hz, false};
    from = to = now = land = Stride<S>{S(0), S(0), S(0), hz};
    land_fresh = false;
    t = S(1);
    step_cache.dt = S(0);
    vel_fresh = false;
  }

  bool command_zero() const { return plan.vx_mm_s == S(0) && plan.vy_mm_s == S(0) && plan.wz_rad_s == S(0); }
  bool at_rest() const { return t >= S(1) && vx == S(0) && vy == S(0) && wz == S(0); }

  //! Plans the command and starts the ramp to it: in phase, linear in the
  //! stride per cycle and the rate, at least one cycle and within the
  //! acceleration limits.
  template <uint8_t kL, bool kSr>
  void replan(const GaitConfig<S, kL, kSr>& cfg, S duty, S budget, bool shift_body) {
    plan = cfg.limits.plan(cfg.home, cmd_vx, cmd_vy, cmd_wz, duty, budget, shift_body);
    const S inv = S(1) / plan.step_hz;
    to = Stride<S>{plan.vx_mm_s * inv, plan.vy_mm_s * inv, plan.wz_rad_s * inv, plan.step_hz};
    from = now;
    const S dv = max_of(abs(plan.vx_mm_s - vx), abs(plan.vy_mm_s - vy));
    const S dw = abs(plan.wz_rad_s - wz);
    const S time = max_of(dv / cfg.accel_mm_s2, dw / cfg.yaw_accel_rad_s2);
    cycles = max_of(time * max_of(to.hz, from.hz), S(1));
    per_cycle = S(1) / cycles;
    t = S(0);
    land_fresh = false;
  }

  //! Cycles a stop from now takes (replan() with a zero command).
  template <uint8_t kL, bool kSr>
  S stop_cycles(const GaitConfig<S, kL, kSr>& cfg, S duty) const {
    const S rest_hz = min_of(cfg.limits.min_hz, cfg.limits.servo_hz(S(0), duty));
    const S time = max_of(max_of(abs(vx), abs(vy)) / cfg.accel_mm_s2, abs(wz) / cfg.yaw_accel_rad_s2);
    return max_of(time * max_of(rest_hz, hz), S(1));
  }

  //! Standing (no stride): the next walk starts from step rate `rate_hz`.
  void rest_at(S rate_hz) {
    if (now.x != S(0) || now.y != S(0) || now.yaw != S(0)) return;
    now.hz = rate_hz;
    hz = rate_hz;
  }

  //! A gait change from duty `was` to `duty`: each stance keeps its travel.
  void keep_travel(S was, S duty) {
    const S r = was / duty;
    now.x = now.x * r;
    now.y = now.y * r;
    now.yaw = now.yaw * r;
    if (r > S(1)) now.hz = now.hz / r;
    vel_fresh = false;
    land_fresh = false;
  }

  //! Moves the ramp on by this tick's phase; the velocity is stride x rate.
  void step(S dt) {
    if (t < S(1)) {
      t = min_of(t + dt * hz * per_cycle, S(1));
      if (t >= S(1)) {
        now = to;
      } else {
        mix_into(now, t);
      }
      vel_fresh = false;
      land_fresh = false;
    }
    if (vel_fresh) return;  // a steady command: the products of the last tick hold
    // Products into locals, then the stores (member by member, avr-gcc 5.4
    // clobbered the address register); a zero part needs no product.
    const S rate = now.hz;
    const S x = now.x * rate;
    const S y = now.y == S(0) ? now.y : now.y * rate;
    const S yaw = now.yaw == S(0) ? now.yaw : now.yaw * rate;
    hz = rate;
    vx = x;
    vy = y;
    wz = yaw;
    step_cache.dt = S(0);  // the body step is made again
    vel_fresh = true;
  }

  //! The mean stride per cycle over the next stance (duty cycles) along the
  //! ramp, which a foot landing now is placed for; true when it changed.
  bool update_landing(S duty, S inv_stance) {
    const S was_x = land.x, was_y = land.y, was_yaw = land.yaw;
    if (t >= S(1)) {
      land = now;
    } else {
      const S left = S(1) - t;  // ramp still to go
      const S finish = left * cycles;  // its length [cycles]
      // lag = (integral over the stance of (1 - ramp)) / stance
      constexpr S half = scalar<S>(0.5);
      const S lag = finish >= duty ? left - per_cycle * duty * half : left * finish * half * inv_stance;
      mix_into(land, S(1) - lag);
    }
    land_fresh = t >= S(1);
    return !(land.x == was_x && land.y == was_y && land.yaw == was_yaw);
  }

  //! out = from + (to - from) t, the four parts at their byte offsets into
  //! place (avr-gcc copies a returned Stride with a byte loop).
  STRIDER_NOINLINE void mix_into(Stride<S>& out, S at) const {
    const unsigned char* a = reinterpret_cast<const unsigned char*>(&from);
    const unsigned char* b = reinterpret_cast<const unsigned char*>(&to);
    unsigned char* o = reinterpret_cast<unsigned char*>(&out);
    for (uint8_t k = 0; k < 4; ++k, a += sizeof(S), b += sizeof(S), o += sizeof(S))
      *reinterpret_cast<S*>(o) = mix(*reinterpret_cast<const S*>(a), *reinterpret_cast<const S*>(b), at);
  }
  //! a + (b - a) t; a itself when b has a's bits (the formula's value then).
  STRIDER_ALWAYS_INLINE static S mix(S a, S b, S at) {
    return leg_ik::same_bits(a, b) ? a : add_inline(a, sub_inline(b, a) * at);
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_SPEED_RAMP_H
