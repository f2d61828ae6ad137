// Double-precision reference kinematics of the robot models, built with
// Eigen from the seeds' DH tables and the leg geometry (independent of the
// closed forms in lib/strider/kinematics), plus helpers shared by the robot
// tests.
#ifndef STRIDER_TEST_ROBOTS_ROBOT_REFERENCE_H
#define STRIDER_TEST_ROBOTS_ROBOT_REFERENCE_H

#include <Eigen/Dense>
#include <cmath>

#include "kinematics/any_leg.h"
#include "robots/all_robots.h"

namespace robot_ref {

using Eigen::AngleAxisd;
using Eigen::Matrix4d;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;
inline double rad(double deg) { return deg * kPi / 180.0; }
inline double deg(double rad) { return rad * 180.0 / kPi; }

// Standard DH link transform Rz(theta) Tz(d) Tx(a) Rx(alpha).
inline Matrix4d dh(double theta, double d, double a, double alpha) {
  Matrix4d t = Matrix4d::Identity();
  t.block<3, 3>(0, 0) = (AngleAxisd(theta, Vector3d::UnitZ()) * AngleAxisd(alpha, Vector3d::UnitX())).matrix();
  t.block<3, 1>(0, 3) = AngleAxisd(theta, Vector3d::UnitZ()) * Vector3d(a, 0.0, 0.0) + Vector3d(0.0, 0.0, d);
  return t;
}

// Foot in the leg frame [mm] for joints q [rad], from the seed's own model:
// - sprawl: seed 000 table 1 (DH a1/90 deg, a2/0);
// - planar: seed 003 table 2 (DH a1, a2, all twists 0), DH (x, y) = (x, z);
// - coxa/femur/tibia: seed 002 table 2 (DH l1/d1/90 deg, l2, l3);
// - abduction: seed 001 table 3 / fig. 2 geometry: La along Rx(t1) +y, the
//   femur and tibia in the plane spanned by x and the leg's "down" w, angles
//   from the backward direction toward w.
inline Vector3d leg_fk(const strider::RobotModel& m, const strider::LegModel& leg, const double q[3]) {
  const strider::LinkLengths& l = m.links;
  switch (m.kind) {
    case strider::LegKind::kSprawl:
      return (dh(q[0], 0, l.l1_mm, kPi / 2) * dh(q[1], 0, l.l2_mm, 0)).block<3, 1>(0, 3);
    case strider::LegKind::kPlanar: {
      const Vector3d p = (dh(q[0], 0, l.l1_mm, 0) * dh(q[1], 0, l.l2_mm, 0)).block<3, 1>(0, 3);
      return Vector3d(p.x(), 0.0, p.y());
    }
    case strider::LegKind::kCoxaFemurTibia:
      return (dh(q[0], l.d1_mm, l.l1_mm, kPi / 2) * dh(q[1], 0, l.l2_mm, 0) * dh(q[2], 0, l.l3_mm, 0))
          .block<3, 1>(0, 3);
    case strider::LegKind::kAbduction: {
      const Eigen::Matrix3d r = AngleAxisd(q[0], Vector3d::UnitX()).matrix();
      const Vector3d u = r * Vector3d::UnitY();
      const Vector3d w = r * Vector3d(0.0, 0.0, leg.side == strider::BodySide::kLeft ? -1.0 : 1.0);
      const Vector3d back = -Vector3d::UnitX();
      auto dir = [&](double a) { return std::cos(a) * back + std::sin(a) * w; };
      return l.l1_mm * u + l.l2_mm * dir(q[1]) + l.l3_mm * dir(q[1] + q[2]);
    }
  }
  return Vector3d::Zero();
}

// Leg frame -> body frame through the model's mount.
inline Vector3d to_body(const strider::LegModel& leg, const Vector3d& p) {
  return AngleAxisd(rad(leg.mount_yaw_deg), Vector3d::UnitZ()) * p +
         Vector3d(leg.mount_mm.x, leg.mount_mm.y, leg.mount_mm.z);
}

inline Vector3d body_fk(const strider::RobotModel& m, const strider::LegModel& leg, const double q[3]) {
  return to_body(leg, leg_fk(m, leg, q));
}

// Signed horizontal reach of the foot from the first joint axis, in the
// direction t1 points [mm]: negative means the foot is behind that axis,
// where a solver's unique answer is the other configuration.
inline double first_axis_reach(const strider::RobotModel& m, const double q[3]) {
  const strider::LinkLengths& l = m.links;
  switch (m.kind) {
    case strider::LegKind::kSprawl: return l.l1_mm + l.l2_mm * std::cos(q[1]);
    case strider::LegKind::kPlanar: return 1e9;  // no first-axis singularity in the leg plane
    case strider::LegKind::kCoxaFemurTibia:
      return l.l1_mm + l.l2_mm * std::cos(q[1]) + l.l3_mm * std::cos(q[1] + q[2]);
    case strider::LegKind::kAbduction:
      return l.l2_mm * std::sin(q[1]) + l.l3_mm * std::sin(q[1] + q[2]);  // along w
  }
  return 0.0;
}

// a - b wrapped to (-180, 180] [deg].
inline double angle_diff_deg(double a, double b) {
  double d = std::fmod(a - b, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

template <typename S>
Vector3d to_eigen(const strider::Vec3<S>& v) {
  return Vector3d(strider::to_double(v.x), strider::to_double(v.y), strider::to_double(v.z));
}
template <typename S>
strider::Vec3<S> from_eigen(const Vector3d& v) {
  return strider::Vec3<S>(strider::scalar<S>(v.x()), strider::scalar<S>(v.y()), strider::scalar<S>(v.z()));
}

// Error bounds of the robot tests, per scalar.
template <typename S>
struct Bounds;
template <>
struct Bounds<float> {
  static constexpr double kPositionMm = 0.001;  // FK and FK(IK(p)) against the double reference
  static constexpr double kJointDeg = 0.001;    // IK(FK(q)) against q
};
template <>
struct Bounds<strider::Fixed> {
  static constexpr double kPositionMm = 0.1;
  static constexpr double kJointDeg = 0.05;
};

}  // namespace robot_ref

#endif  // STRIDER_TEST_ROBOTS_ROBOT_REFERENCE_H
