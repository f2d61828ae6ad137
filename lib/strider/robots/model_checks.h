//! Compile-time invariants of a RobotModel: each robot file static_asserts
//! them, so a typo in a model fails the build instead of a walk.
#ifndef STRIDER_ROBOTS_MODEL_CHECKS_H
#define STRIDER_ROBOTS_MODEL_CHECKS_H

#include "robot_model.h"

namespace strider {
namespace model_checks {

//! Positive link lengths for the slots the kind uses, zero for the others.
constexpr bool links_valid(const RobotModel& m) {
  const LinkLengths& l = m.links;
  if (!(l.l1_mm > 0.0f && l.l2_mm > 0.0f)) return false;
  if (m.kind == LegKind::kSprawl || m.kind == LegKind::kPlanar) return l.l3_mm == 0.0f && l.d1_mm == 0.0f;
  if (!(l.l3_mm > 0.0f)) return false;
  return m.kind == LegKind::kCoxaFemurTibia || l.d1_mm == 0.0f;
}

//! Leg count in range, and every used joint range non-empty and no wider
//! than the travel of the servo that drives it.
constexpr bool joint_ranges_valid(const RobotModel& m) {
  if (m.leg_count == 0 || m.leg_count > kMaxLegs) return false;
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    for (uint8_t j = 0; j < m.dof(); ++j) {
      const JointRange& r = m.legs[i].joint[j];
      if (!(r.min_deg < r.max_deg)) return false;
      if (r.max_deg - r.min_deg > servo_spec(m.servo[j]).travel_deg) return false;
      if (r.min_deg < -360.0f || r.max_deg > 360.0f) return false;
    }
  }
  return true;
}

//! Left legs mounted at y > 0, right legs at y < 0.
constexpr bool sides_consistent(const RobotModel& m) {
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    const LegModel& leg = m.legs[i];
    if (leg.side == BodySide::kLeft ? !(leg.mount_mm.y > 0.0f) : !(leg.mount_mm.y < 0.0f)) return false;
  }
  return true;
}

constexpr bool near(float a, float b, float tol) { return a - b <= tol && b - a <= tol; }

//! Two names equal (strcmp at compile time).
constexpr bool same_name(const char* a, const char* b) {
  while (*a != '\0' && *a == *b) ++a, ++b;
  return *a == *b;
}

//! Every leg has a mirror twin across the body's x-z plane: mount (x, -y, z),
//! yaw -yaw, standing foot (x, -y, z). Legs on the x axis are their own twin.
constexpr bool mirror_symmetric(const RobotModel& m) {
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    const LegModel& a = m.legs[i];
    bool found = false;
    for (uint8_t k = 0; k < m.leg_count && !found; ++k) {
      const LegModel& b = m.legs[k];
      found = near(a.mount_mm.x, b.mount_mm.x, 1e-3f) && near(a.mount_mm.y, -b.mount_mm.y, 1e-3f) &&
              near(a.mount_mm.z, b.mount_mm.z, 1e-3f) &&
              (near(a.mount_yaw_deg, -b.mount_yaw_deg, 1e-3f) ||
               near(a.mount_yaw_deg, 360.0f - b.mount_yaw_deg, 1e-3f) ||
               near(a.mount_yaw_deg, -360.0f - b.mount_yaw_deg, 1e-3f)) &&
              near(a.stand_mm.x, b.stand_mm.x, 1e-3f) && near(a.stand_mm.y, -b.stand_mm.y, 1e-3f) &&
              near(a.stand_mm.z, b.stand_mm.z, 1e-3f);
    }
    if (!found) return false;
  }
  return true;
}

//! Legs numbered counter-clockwise seen from above (the mount bearing from
//! the body centre increases with the index, one turn in all).
constexpr bool numbered_counter_clockwise(const RobotModel& m) {
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    const Vec3<float>& a = m.legs[i].mount_mm;
    const Vec3<float>& b = m.legs[(i + 1) % m.leg_count].mount_mm;
    if (a.x * b.y - a.y * b.x <= 0.0f) return false;
  }
  return m.legs[0].side == BodySide::kLeft && m.legs[0].mount_mm.x > 0.0f;
}

//! The standing foot lies in the leg's workspace, tested geometrically in the
//! leg frame (seed 000 eqs 4-6, seed 003 eq 3, seed 002 eqs 5-7, seed 001
//! eqs 4.1 and 4.12-4.16).
constexpr bool stand_in_workspace(const RobotModel& m, const LegModel& leg) {
  using model_math::sqrt;
  const Vec3<float> p = body_point_in_leg(leg, leg.stand_mm);
  const LinkLengths& l = m.links;
  const double tol = 0.005;  // [mm] below the float solver's tolerance
  const double rho = sqrt(double(p.x) * p.x + double(p.y) * p.y);
  if (m.kind == LegKind::kSprawl) {
    const double d = sqrt((rho - l.l1_mm) * (rho - l.l1_mm) + double(p.z) * p.z);
    return d - l.l2_mm <= tol && l.l2_mm - d <= tol;
  }
  double r = 0.0;
  if (m.kind == LegKind::kPlanar) {
    if (p.y > tol || -p.y > tol) return false;  // a planar leg cannot leave its plane
    r = sqrt(double(p.x) * p.x + double(p.z) * p.z);
  } else if (m.kind == LegKind::kCoxaFemurTibia) {
    r = sqrt((rho - l.l1_mm) * (rho - l.l1_mm) + (double(p.z) - l.d1_mm) * (double(p.z) - l.d1_mm));
  } else {
    const double a2 = double(p.y) * p.y + double(p.z) * p.z;
    if (a2 <= double(l.l1_mm) * l.l1_mm) return false;
    r = sqrt(double(p.x) * p.x + a2 - double(l.l1_mm) * l.l1_mm);
  }
  // r spans the two links that fold (a1, a2 of a planar leg; else l2, l3).
  const double a = m.kind == LegKind::kPlanar ? l.l1_mm : l.l2_mm;
  const double b = m.kind == LegKind::kPlanar ? l.l2_mm : l.l3_mm;
  return r > (a > b ? a - b : b - a) + 1.0 && r < a + b - 1.0;  // 1 mm clear of a straight or folded leg
}

constexpr bool stands_in_workspace(const RobotModel& m) {
  for (uint8_t i = 0; i < m.leg_count; ++i)
    if (!stand_in_workspace(m, m.legs[i])) return false;
  return true;
}

//! Unused leg slots are zero, so a loop that forgets leg_count finds nothing.
constexpr bool unused_slots_empty(const RobotModel& m) {
  for (uint8_t i = m.leg_count; i < kMaxLegs; ++i)
    if (m.legs[i].name != nullptr) return false;
  return true;
}

}  // namespace model_checks

constexpr bool model_valid(const RobotModel& m) {
  return model_checks::links_valid(m) && model_checks::joint_ranges_valid(m) &&
         model_checks::sides_consistent(m) && model_checks::mirror_symmetric(m) &&
         model_checks::numbered_counter_clockwise(m) && model_checks::stands_in_workspace(m) &&
         model_checks::unused_slots_empty(m);
}

}  // namespace strider

#endif  // STRIDER_ROBOTS_MODEL_CHECKS_H
