//! Velocity limits of a robot: each leg's longest stride per direction (its
//! reach at the standing pose), how fast it can step (its servos' speed), and
//! the planner of a command's stride and step rate (docs/gaits.md, "Velocity
//! commands and limits"; the search: velocity_search.h).
#ifndef STRIDER_GAIT_VELOCITY_LIMITS_H
#define STRIDER_GAIT_VELOCITY_LIMITS_H

#include "../kinematics/any_leg.h"
#include "../math/flash_table.h"
#include "gait_table.h"
#include "reach_projection.h"
#include "swing_trajectory.h"
#include "velocity_limit_encoding.h"

namespace strider {

//! Share of a servo's no-load speed a step may use.
constexpr double kServoSpeedShare = 0.75;
//! Share of the longest reachable stride a gait may use (the rest absorbs
//! overshoot at lift-off, stance.h's turning approximations, command changes).
constexpr double kStrideShare = 0.9;
//! Most the body may turn during one stance [rad] (docs/gaits.md).
constexpr double kMaxStanceTurnRad = 0.4;

template <typename S>
struct VelocityPlan {
  S vx_mm_s, vy_mm_s, wz_rad_s;  //!< the command as it will be walked
  S step_hz;                     //!< cycles per second
  bool limited;                  //!< the command was scaled down
};

//! Direction k of a stride table is k * 22.5 deg from forward.
constexpr uint8_t kStrideDirections = 16;

//! A robot's stride table (the longest stride of leg i along direction k,
//! in 1/32 mm, velocity_limit_encoding.h): in RAM (kInRam), or a pointer to
//! the stored table in flash (a firmware).
template <bool kInRam>
struct StrideTable {
  uint16_t stride_code[kMaxLegs][kStrideDirections] = {};
  uint16_t code(uint8_t leg, uint8_t k) const { return stride_code[leg][k]; }
  template <typename S>
  void set_stride_mm(uint8_t leg, uint8_t k, S mm) { stride_code[leg][k] = velocity_limit_encoding::stride_code(mm); }
};
template <>
struct StrideTable<false> {
  //! [kMaxLegs][kStrideDirections] in flash (nullptr: no stride at all).
  const uint16_t* flash_codes = nullptr;
  uint16_t code(uint8_t leg, uint8_t k) const {
    return flash_codes == nullptr ? uint16_t(0) : flash_u16(flash_codes, uint16_t(leg * kStrideDirections + k));
  }
};

template <typename S, bool kSearch = true>
struct VelocityLimits : StrideTable<kSearch> {
  static constexpr uint8_t kDirections = kStrideDirections;

  constexpr VelocityLimits() : leg_count(0), preferred_stride_mm(), lift_ms(), swing_ms_per_mm(), stance_ms_per_mm() {}

  uint8_t leg_count;
  //! False for planar legs: a sideways command is dropped (limited).
  bool sideways = true;
  S min_hz = S(1);                     //!< default step rate, 1 / cycle_s [Hz]
  S preferred_stride_mm;               //!< step_length_mm [mm]
  S lift_ms;                           //!< servo time of a swing's lift alone [ms]
  S swing_ms_per_mm;                   //!< servo time of a swing per mm of stride [ms/mm]
  S stance_ms_per_mm;                  //!< servo time of a stance per mm of stride [ms/mm]

  //! The fields of the gait defaults and the model's kind.
  constexpr void set_gait(const RobotModel& model, S step_length_mm, S cycle_s) {
    leg_count = model.leg_count;
    sideways = model.kind != LegKind::kPlanar;
    min_hz = S(1) / cycle_s;
    preferred_stride_mm = step_length_mm;
  }

  //! Leg i's longest stride along direction k [mm].
  S stride_mm(uint8_t leg, uint8_t k) const { return velocity_limit_encoding::stride_of(this->code(leg, k), S()); }

  //! Leg i's longest stride along (dx, dy) (not both 0) [mm], interpolated
  //! between the two nearest directions, less twice the body-shift budget.
  S leg_stride(uint8_t leg, S dx, S dy, S budget_mm = S(0)) const {
    S a = atan2(dy, dx);  // (-pi, pi]
    if (a < S(0)) a += two_pi<S>();
    const S x = a * scalar<S>(double(kDirections) / 6.283185307179586);
    uint8_t k = 0;
    while (k + 1 < kDirections && S(k + 1) <= x) ++k;
    const S f = clamp(x - S(k), S(0), S(1));
    const S lo = stride_mm(leg, k), hi = stride_mm(leg, uint8_t((k + 1) % kDirections));
    return max_of(lo + (hi - lo) * f - budget_mm * S(2), S(0));
  }

  //! The fastest step rate the servos allow for a stride [mm] [Hz].
  S servo_hz(S length_mm, S duty) const {
    const S swing = lift_ms + swing_ms_per_mm * length_mm;
    S f = swing > S(0) ? scalar<S>(1000.0) * (S(1) - duty) / swing : scalar<S>(100.0);
    const S stance = stance_ms_per_mm * length_mm;
    if (stance > S(0)) f = smaller(f, scalar<S>(1000.0) * duty / stance);
    return smaller(f, scalar<S>(100.0));
  }

  //! The command (vx, vy [mm/s], wz [rad/s]) as the robot can walk it with
  //! its feet at home[i] [mm, body frame] in a gait of this duty; gaits that
  //! shift the body pass their budget [mm] and keep_stride (preferred length).
  VelocityPlan<S> plan(const Vec3<S>* home, S vx, S vy, S wz, S duty, S budget_mm = S(0),
                       bool keep_stride = false) const {
    VelocityPlan<S> p{vx, vy, wz, smaller(min_hz, servo_hz(S(0), duty)), false};
    if (!sideways && vy != S(0)) {
      p.vy_mm_s = S(0);
      p.limited = true;
    }
    S rate_lo;  // step rate the stride limits need [Hz]
    const S fastest = stride_need(home, p, duty, budget_mm, keep_stride, &rate_lo);  // largest R_i [mm/s]
    if (fastest != S(0)) fit(p, rate_lo, fastest, duty);
    return p;
  }

  //! Top speed along (dx, dy) without turning [mm/s].
  S max_speed_mm_s(const Vec3<S>* home, S dx, S dy, S duty, S budget_mm = S(0), bool keep_stride = false) const {
    const S n = hypot(dx, dy);
    if (n == S(0)) return S(0);
    const S big = scalar<S>(5000.0);
    const VelocityPlan<S> p = plan(home, dx / n * big, dy / n * big, S(0), duty, budget_mm, keep_stride);
    return hypot(p.vx_mm_s, p.vy_mm_s);
  }

  //! Top yaw rate turning in place [rad/s].
  S max_yaw_rate(const Vec3<S>* home, S duty, S budget_mm = S(0), bool keep_stride = false) const {
    return plan(home, S(0), S(0), scalar<S>(20.0), duty, budget_mm, keep_stride).wz_rad_s;
  }

  // plan()'s two halves: a short stack frame each on the AVR.
  //! The largest R_i (0: no leg moves); *rate_lo the rate the strides need.
  STRIDER_NOINLINE S stride_need(const Vec3<S>* home, const VelocityPlan<S>& p, S duty, S budget_mm,
                                 bool keep_stride, S* rate_lo) const {
    S lo = S(0), fastest = S(0);
    for (uint8_t i = 0; i < leg_count; ++i) {
      // A planar leg strides along x alone: a turn's sideways part is dropped
      // (reach_projection.h), the body's feet slide instead of stepping it.
      const S rx = p.vx_mm_s - p.wz_rad_s * home[i].y;
      const S ry = sideways ? p.vy_mm_s + p.wz_rad_s * home[i].x : S(0);
      const S r = hypot(rx, ry) * duty;
      if (r == S(0)) continue;
      S room = leg_stride(i, rx, ry, budget_mm);
      if (keep_stride) room = smaller(room, preferred_stride_mm);
      lo = room > S(0) ? larger(lo, r / room) : scalar<S>(1000.0);
      fastest = larger(fastest, r);
    }
    *rate_lo = larger(lo, abs(p.wz_rad_s) * duty * scalar<S>(1.0 / kMaxStanceTurnRad));
    return fastest;
  }

  //! The step rate for p's command, scaled down if the servos need it.
  STRIDER_NOINLINE void fit(VelocityPlan<S>& p, S rate_lo, S fastest, S duty) const {
    // The largest k with a rate f >= k rate_lo inside the servo limits.
    const S swing_room = scalar<S>(1000.0) * (S(1) - duty);
    S k = S(1);
    const S swing_need = lift_ms * rate_lo + swing_ms_per_mm * fastest;
    if (swing_need > swing_room) k = swing_room / swing_need;
    const S stance_need = stance_ms_per_mm * fastest;
    const S stance_room = scalar<S>(1000.0) * duty;
    if (stance_need > stance_room) k = smaller(k, stance_room / stance_need);
    S hi = scalar<S>(100.0);
    if (lift_ms > S(0)) hi = (swing_room - swing_ms_per_mm * k * fastest) / lift_ms;
    const S f = larger(min_hz, preferred_stride_mm > S(0) ? k * fastest / preferred_stride_mm : S(0));
    p.step_hz = larger(smaller(f, hi), k * rate_lo);
    if (k < S(1)) {
      p.vx_mm_s = p.vx_mm_s * k;
      p.vy_mm_s = p.vy_mm_s * k;
      p.wz_rad_s = p.wz_rad_s * k;
      p.limited = true;
    }
  }

  // Calls, not inline comparisons: less flash on the AVR, off the tick path.
  static STRIDER_NOINLINE S larger(S a, S b) { return max_of(a, b); }
  static STRIDER_NOINLINE S smaller(S a, S b) { return min_of(a, b); }
};

}  // namespace strider

#endif  // STRIDER_GAIT_VELOCITY_LIMITS_H
