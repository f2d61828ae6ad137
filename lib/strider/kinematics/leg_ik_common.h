//! Building blocks shared by the analytic leg solvers: bounds of a sane
//! target, cheap comparisons, joint limits, and the common end of ik().
#ifndef STRIDER_KINEMATICS_LEG_IK_COMMON_H
#define STRIDER_KINEMATICS_LEG_IK_COMMON_H

#include "../math/vec3.h"
#include "../math/working_units.h"
#include "ik_status.h"
#include "joints.h"

namespace strider {

namespace leg_ik {

//! |v| <= bound [mm] (bound >= 0), false for NaN and infinities; float on the bits.
inline bool within(float v, float bound) { return detail::magnitude_bits(v) <= detail::float_bits(bound); }
inline bool within(Fixed v, Fixed bound) { return abs(v) <= bound; }

//! a < b and v == 0, on the bits for float (NaN never passes within()).
STRIDER_ALWAYS_INLINE bool lt(float a, float b) { return detail::float_less(a, b); }
STRIDER_ALWAYS_INLINE bool lt(Fixed a, Fixed b) { return a < b; }
STRIDER_ALWAYS_INLINE bool is_zero(float v) { return detail::float_is_zero(v); }
STRIDER_ALWAYS_INLINE bool is_zero(Fixed v) { return v.raw() == 0; }
//! Same bits, so the same value (for float not the only way: +0 and -0).
STRIDER_ALWAYS_INLINE bool same_bits(float a, float b) { return detail::float_bits(a) == detail::float_bits(b); }
STRIDER_ALWAYS_INLINE bool same_bits(Fixed a, Fixed b) { return a == b; }

//! A sum of squares [unit^2] too small for Fixed's sqrt (then units::norm()).
constexpr bool tiny_square(float) { return false; }
constexpr bool tiny_square(Fixed sq) { return sq < Fixed(0.0625); }

//! Scales a Fixed pair by 2^k so that its larger magnitude is >= 1: the same
//! angle, and products that keep ~16 significant bits.
inline void lift_pair(float&, float&) {}
inline void lift_pair(Fixed& a, Fixed& b) {
  uint32_t m = Fixed::abs_raw(a.raw());
  if (Fixed::abs_raw(b.raw()) > m) m = Fixed::abs_raw(b.raw());
  if (m == 0 || m >= uint32_t(Fixed::kOneRaw)) return;
  int k = 0;
  while (m < uint32_t(Fixed::kOneRaw)) { m <<= 1; ++k; }
  a = a.scaled_pow2(k);
  b = b.scaled_pow2(k);
}

//! The status of a target missed by miss_mm: kOk, kClamped or kUnreachable.
template <typename S>
IkStatus miss_status(S miss_mm, const IkOptions<S>& opt) {
  if (!(miss_mm <= opt.max_clamp_mm)) return IkStatus::kUnreachable;
  return miss_mm > opt.tolerance_mm ? IkStatus::kClamped : IkStatus::kOk;
}

//! Each joint's angle +-2 pi inside the limits if one is; else clamped to
//! the limit nearer around the circle. True when any joint was clamped.
template <typename S, uint8_t N>
bool fit_into_limits(const JointLimits<S, N>& lim, JointVector<S, N>& q) {
  bool moved = false;
  for (uint8_t i = 0; i < N; ++i) {
    S a = q[i];
    if (leg_ik::lt(a, lim.lo[i])) {
      a += two_pi<S>();
      if (lim.hi[i] < a) a = q[i];
    } else if (leg_ik::lt(lim.hi[i], a)) {
      a -= two_pi<S>();
      if (a < lim.lo[i]) a = q[i];
    } else {
      continue;  // the common case: inside
    }
    if (a < lim.lo[i] || lim.hi[i] < a) {
      const S past_hi = wrap_two_pi(a - lim.hi[i]);
      const S below_lo = wrap_two_pi(lim.lo[i] - a);
      a = past_hi < below_lo ? lim.hi[i] : lim.lo[i];
      moved = true;
    }
    q[i] = a;
  }
  return moved;
}

//! lim.contains(q) with the comparisons of lt().
template <typename S, uint8_t N>
bool within_limits(const JointLimits<S, N>& lim, const JointVector<S, N>& q) {
  for (uint8_t i = 0; i < N; ++i)
    if (leg_ik::lt(q[i], lim.lo[i]) || leg_ik::lt(lim.hi[i], q[i])) return false;
  return true;
}

//! JointLimits::contains unrolled (avr-gcc's loop reloads every joint just stored).
template <uint8_t I, uint8_t N>
struct LimitsFrom {
  template <typename S>
  STRIDER_ALWAYS_INLINE static bool contain(const JointLimits<S, N>& lim, const JointVector<S, N>& q) {
    return !(q[I] < lim.lo[I] || lim.hi[I] < q[I]) && LimitsFrom<I + 1, N>::contain(lim, q);
  }
};
template <uint8_t N>
struct LimitsFrom<N, N> {
  template <typename S>
  STRIDER_ALWAYS_INLINE static bool contain(const JointLimits<S, N>&, const JointVector<S, N>&) {
    return true;
  }
};
template <typename S, uint8_t N>
STRIDER_ALWAYS_INLINE bool limits_contain(const JointLimits<S, N>& lim, const JointVector<S, N>& q) {
  return LimitsFrom<0, N>::contain(lim, q);
}

//! reached = p field by field: avr-gcc copies a whole Vec3 with a byte loop.
template <typename S>
STRIDER_ALWAYS_INLINE void copy_point(const Vec3<S>& p, Vec3<S>& reached) {
  reached.x = p.x;
  reached.y = p.y;
  reached.z = p.z;
}

//! A free angle (yaw with the foot on the yaw axis), not a joint-limit hit.
template <typename S, uint8_t N>
S free_angle(const JointLimits<S, N>& lim, uint8_t i, S preferred) {
  return clamp(preferred, lim.lo[i], lim.hi[i]);
}

//! Clamps sol into the limits and then sets at = fk(sol); kJointLimit only
//! when that moved the foot by more than the tolerance.
template <typename Leg, typename S>
IkStatus apply_limits(const Leg& leg, const Vec3<S>& target, typename Leg::Joints& sol, Vec3<S>& at,
                      IkStatus status, const IkOptions<S>& opt) {
  if (!leg_ik::fit_into_limits(leg.limits, sol)) return status;
  const Vec3<S> before = at;
  at = leg.fk(sol);
  const bool moved = units::distance(at, before) > opt.tolerance_mm ||
                     (status == IkStatus::kOk && units::distance(at, target) > opt.tolerance_mm);
  return moved ? worst(status, IkStatus::kJointLimit) : status;
}

//! The common end of every analytic ik(): sol solves the nearest reachable
//! point (measured through fk when clamped); outputs untouched on kUnreachable.
template <typename Leg, typename S>
IkStatus finish(const Leg& leg, const Vec3<S>& target, typename Leg::Joints sol, bool clamped,
                const IkOptions<S>& opt, typename Leg::Joints& q, Vec3<S>& reached) {
  if (!clamped && leg_ik::within_limits(leg.limits, sol)) {  // the common case, without copies
    q = sol;
    leg_ik::copy_point(target, reached);
    return IkStatus::kOk;
  }
  IkStatus status = IkStatus::kOk;
  Vec3<S> at = target;
  if (clamped) {
    at = leg.fk(sol);
    status = leg_ik::miss_status(units::distance(at, target), opt);
    if (status == IkStatus::kUnreachable) return status;
  }
  status = leg_ik::apply_limits(leg, target, sol, at, status, opt);
  q = sol;
  reached = at;
  return status;
}

}  // namespace leg_ik
}  // namespace strider

#endif  // STRIDER_KINEMATICS_LEG_IK_COMMON_H
