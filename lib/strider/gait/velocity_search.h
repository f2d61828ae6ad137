//! The IK search of a robot's velocity limits (velocity_limits.h), at
//! configuration time, never per tick: per leg and direction the longest
//! stride whose stance ends and swing all solve, and the servo time a step
//! takes (docs/gaits.md, "Velocity commands and limits").
#ifndef STRIDER_GAIT_VELOCITY_SEARCH_H
#define STRIDER_GAIT_VELOCITY_SEARCH_H

#include "velocity_limits.h"

namespace strider {

namespace velocity_limits_detail {

//! Swing phase samples of the stride check.
constexpr uint8_t kSwingSamples = 5;

//! Leg's joints q for a body-frame target, projected as walking does.
template <typename S>
IkStatus joints_at(const AnyLeg<S>& leg, const ReachProjection<S>& proj, const Vec3<S>& body_target,
                   typename AnyLeg<S>::Joints& q) {
  S moved;
  Vec3<S> at;
  return leg.ik(proj.apply(leg.mount().body_to_leg(body_target), moved), q, at);
}
template <typename S>
bool reaches(const AnyLeg<S>& leg, const ReachProjection<S>& proj, const Vec3<S>& body_target) {
  typename AnyLeg<S>::Joints q;
  return joints_at(leg, proj, body_target, q) == IkStatus::kOk;
}

//! The point of a stride L along unit (dx, dy) at swing phase s (s < 0,
//! s > 1: the stance ends -L/2, +L/2).
template <typename S>
Vec3<S> stride_point(const Vec3<S>& home, S dx, S dy, S L, SwingShape shape, S step_mm, S s) {
  if (s < S(0)) return Vec3<S>(home.x - dx * L * scalar<S>(0.5), home.y - dy * L * scalar<S>(0.5), home.z);
  if (s > S(1)) return Vec3<S>(home.x + dx * L * scalar<S>(0.5), home.y + dy * L * scalar<S>(0.5), home.z);
  const SwingPoint<S> sp = swing_point(shape, s);
  const S along = L * (sp.u - scalar<S>(0.5));
  return Vec3<S>(home.x + dx * along, home.y + dy * along, home.z + sp.w * swing_apex_mm(shape, L, step_mm));
}

//! Leg i's mirror image across the body's x-z plane, or i when none is.
inline uint8_t mirror_twin(const RobotModel& m, uint8_t i) {
  const LegModel& a = m.legs[i];
  auto near = [](float p, float q) { return p - q <= 1e-3f && q - p <= 1e-3f; };
  for (uint8_t j = 0; j < m.leg_count; ++j) {
    const LegModel& b = m.legs[j];
    if (j == i || !near(a.mount_mm.x, b.mount_mm.x) || !near(a.mount_mm.y, -b.mount_mm.y) ||
        !near(a.mount_mm.z, b.mount_mm.z) || !near(a.stand_mm.x, b.stand_mm.x) ||
        !near(a.stand_mm.y, -b.stand_mm.y) || !near(a.stand_mm.z, b.stand_mm.z))
      continue;
    return j;
  }
  return i;
}

template <typename S>
bool stride_ok(const AnyLeg<S>& leg, const ReachProjection<S>& proj, const Vec3<S>& home, S dx, S dy, S L,
               SwingShape shape, S step_mm) {
  if (!reaches(leg, proj, stride_point(home, dx, dy, L, shape, step_mm, -S(1)))) return false;
  if (!reaches(leg, proj, stride_point(home, dx, dy, L, shape, step_mm, S(2)))) return false;
  for (uint8_t k = 1; k <= kSwingSamples; ++k) {
    const S s = S(k) * scalar<S>(1.0 / (kSwingSamples + 1));
    if (!reaches(leg, proj, stride_point(home, dx, dy, L, shape, step_mm, s))) return false;
  }
  return true;
}

}  // namespace velocity_limits_detail

//! The limits of `model` with `legs` and standing feet home[i] [mm, body
//! frame], for a swing shape, step height and length [mm] and cycle [s].
template <typename S>
VelocityLimits<S> compute_velocity_limits(const RobotModel& model, const AnyLeg<S>* legs, const Vec3<S>* home,
                                          SwingShape shape, S step_height_mm, S step_length_mm, S cycle_s) {
  namespace d = velocity_limits_detail;
  VelocityLimits<S> lim;
  lim.set_gait(model, step_length_mm, cycle_s);
  const ReachProjection<S> proj = ReachProjection<S>::make(model);
  const S top = scalar<S>(2.0 * double(model.links.l1_mm + model.links.l2_mm + model.links.l3_mm));
  for (uint8_t i = 0; i < model.leg_count; ++i) {
    // A mirrored twin already done: its strides, direction k as -k.
    const uint8_t twin = d::mirror_twin(model, i);
    if (twin < i) {
      for (uint8_t k = 0; k < VelocityLimits<S>::kDirections; ++k)
        lim.stride_code[i][k] = lim.stride_code[twin][(VelocityLimits<S>::kDirections - k) % VelocityLimits<S>::kDirections];
      continue;
    }
    for (uint8_t k = 0; k < VelocityLimits<S>::kDirections; ++k) {
      const double deg = double(k) * 360.0 / VelocityLimits<S>::kDirections;
      const S dx = scalar<S>(model_math::cos_deg(deg)), dy = scalar<S>(model_math::sin_deg(deg));
      S lo = S(0), hi = top;
      if (!d::stride_ok(legs[i], proj, home[i], dx, dy, S(0), shape, step_height_mm)) hi = S(0);
      for (uint8_t it = 0; it < 16 && hi - lo > scalar<S>(0.5); ++it) {  // to 0.5 mm
        const S mid = (lo + hi) * scalar<S>(0.5);
        if (d::stride_ok(legs[i], proj, home[i], dx, dy, mid, shape, step_height_mm)) lo = mid;
        else hi = mid;
      }
      lim.set_stride_mm(i, k, lo * scalar<S>(kStrideShare));
      if (lo == S(0)) continue;
      // Joint rates of a swing in place and of this longest stride.
      typename AnyLeg<S>::Joints still[9], q[11];
      for (uint8_t m = 0; m < 11; ++m) {
        const S s = m == 0 ? -S(1) : m == 10 ? S(2) : S(m - 1) * scalar<S>(1.0 / 8.0);
        d::joints_at(legs[i], proj, d::stride_point(home[i], dx, dy, lo, shape, step_height_mm, s), q[m]);
        if (m >= 1 && m <= 9)
          d::joints_at(legs[i], proj, d::stride_point(home[i], dx, dy, S(0), shape, step_height_mm, s), still[m - 1]);
      }
      for (uint8_t j = 0; j < model.dof(); ++j) {
        const S w = scalar<S>(double(servo_speed_deg_s(model.servo[j])) * kServoSpeedShare * 0.017453292519943295e-3);
        S t0 = S(0), t1 = S(0);  // max |dq/ds| [rad per swing]: in place, longest stride
        for (uint8_t m = 0; m < 8; ++m) {
          t0 = max_of(t0, abs(still[m + 1][j] - still[m][j]) * S(8));
          t1 = max_of(t1, abs(q[m + 2][j] - q[m + 1][j]) * S(8));
        }
        lim.lift_ms = max_of(lim.lift_ms, t0 / w);
        lim.swing_ms_per_mm = max_of(lim.swing_ms_per_mm, max_of(t1 - t0, S(0)) / w / lo);
        lim.stance_ms_per_mm = max_of(lim.stance_ms_per_mm, abs(q[10][j] - q[0][j]) / w / lo);
      }
    }
  }
  return lim;
}

}  // namespace strider

#endif  // STRIDER_GAIT_VELOCITY_SEARCH_H
