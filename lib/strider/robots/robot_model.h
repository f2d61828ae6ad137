//! RobotModel: the constant description of one robot (legs, mounts, joint
//! limits, standing pose, body, servos) in float, mm and degrees. The
//! conventions every model follows: docs/robots.md, "What a model holds".
#ifndef STRIDER_ROBOTS_ROBOT_MODEL_H
#define STRIDER_ROBOTS_ROBOT_MODEL_H

#include <stdint.h>

#include "../math/vec3.h"
#include "servo_parts.h"

namespace strider {

//! The leg types of kinematics/ (one analytic solver each).
enum class LegKind : uint8_t {
  kSprawl = 0,          //!< SprawlLeg: hip yaw t1, knee t2 (seed 000)
  kPlanar = 1,          //!< PlanarLeg: hip pitch t1, knee t2 (seed 003)
  kCoxaFemurTibia = 2,  //!< CoxaFemurTibiaLeg: coxa t1, femur t2, tibia t3 (seed 002)
  kAbduction = 3        //!< AbductionLeg: abduction t1, hip t2, knee t3 (seed 001)
};

//! Joints per leg of a kind.
constexpr uint8_t dof_of(LegKind kind) {
  return (kind == LegKind::kSprawl || kind == LegKind::kPlanar) ? 2 : 3;
}

//! The kind's name as used in docs and the CLI.
constexpr const char* to_string(LegKind kind) {
  return kind == LegKind::kSprawl           ? "sprawl"
         : kind == LegKind::kPlanar         ? "planar"
         : kind == LegKind::kCoxaFemurTibia ? "coxa_femur_tibia"
                                            : "abduction";
}

//! Which side of the body a leg is on (x forward, y left).
enum class BodySide : uint8_t { kLeft = 0, kRight = 1 };

constexpr const char* to_string(BodySide side) { return side == BodySide::kLeft ? "left" : "right"; }

//! Most legs a model (and a gait table) may have, and most joints per leg;
//! the walking state holds its build profile's kLegs (build_profile.h).
constexpr uint8_t kMaxLegs = 6;
constexpr uint8_t kMaxLegDof = 3;

//! Link lengths of a leg [mm]; the meaning of each slot depends on the kind.
struct LinkLengths {
  float l1_mm;  //!< sprawl/planar a1, coxa-femur-tibia coxa l1, abduction La
  float l2_mm;  //!< sprawl/planar a2, coxa-femur-tibia femur l2, abduction Lb
  float l3_mm;  //!< coxa-femur-tibia tibia l3, abduction Lc; 0 for 2-DOF kinds
  float d1_mm;  //!< coxa-femur-tibia d1 (femur axis above the leg frame); else 0
};

//! One joint's mechanical range, in the leg type's seed convention [deg].
struct JointRange {
  float min_deg = 0.0f;
  float max_deg = 0.0f;
};

//! One leg: where it sits, what it can do, where it stands.
struct LegModel {
  // Member initializers make unused slots constexpr-constructible (gcc 5).
  const char* name = nullptr;          //!< e.g. "front_left"; nullptr for an unused slot
  BodySide side = BodySide::kLeft;
  Vec3<float> mount_mm;                //!< leg frame origin in the body frame [mm]
  float mount_yaw_deg = 0.0f;          //!< leg frame rotation about body z [deg]
  JointRange joint[kMaxLegDof];        //!< limits; unused slots {0, 0}
  Vec3<float> stand_mm;                //!< default standing foot position, body frame [mm]
};

//! The body as a box, with the robot's total mass.
struct BodyModel {
  float length_mm;  //!< along x
  float width_mm;   //!< along y
  float height_mm;  //!< along z
  float mass_kg;    //!< whole robot, legs, servos and battery included (estimate)
};

//! A whole robot.
struct RobotModel {
  const char* name;   //!< CLI name, e.g. "sprawl8"
  uint8_t seed;       //!< the seed document it comes from (0..4)
  LegKind kind;       //!< every leg of a model is of one kind
  uint8_t leg_count;  //!< 4 or 6
  LinkLengths links;  //!< shared by all legs
  BodyModel body;
  ServoPart servo[kMaxLegDof];  //!< part driving joint j of every leg
  LegModel legs[kMaxLegs];      //!< legs [0, leg_count); the rest zero

  constexpr uint8_t dof() const { return dof_of(kind); }
  constexpr uint8_t joint_count() const { return uint8_t(leg_count * dof()); }
};

//! The model without its legs' names, which only the host tools print (their
//! strings would otherwise take AVR RAM).
constexpr RobotModel without_leg_names(RobotModel m) {
  for (uint8_t i = 0; i < kMaxLegs; ++i) m.legs[i].name = nullptr;
  return m;
}

namespace model_math {

//! cos and sin of an angle [deg] at compile time (Taylor series after
//! reducing to [-180, 180]; error below 1e-12). Not for run-time use.
constexpr double cos_deg(double deg) {
  while (deg > 180.0) deg -= 360.0;
  while (deg < -180.0) deg += 360.0;
  const double x = deg * 0.017453292519943295;
  double term = 1.0, sum = 1.0;
  for (int k = 1; k < 16; ++k) {
    term *= -x * x / double((2 * k - 1) * (2 * k));
    sum += term;
  }
  return sum;
}
constexpr double sin_deg(double deg) { return cos_deg(deg - 90.0); }

//! Square root at compile time (Newton's method; exact to double rounding).
constexpr double sqrt(double v) {
  if (v <= 0.0) return 0.0;
  double r = v < 1.0 ? 1.0 : v;
  for (int i = 0; i < 64; ++i) r = 0.5 * (r + v / r);
  return r;
}

}  // namespace model_math

//! A leg-frame point [mm] in the body frame (leg_to_body at compile time).
constexpr Vec3<float> leg_point_in_body(const Vec3<float>& origin_mm, float yaw_deg, double x, double y,
                                        double z) {
  return Vec3<float>(float(origin_mm.x + model_math::cos_deg(yaw_deg) * x - model_math::sin_deg(yaw_deg) * y),
                     float(origin_mm.y + model_math::sin_deg(yaw_deg) * x + model_math::cos_deg(yaw_deg) * y),
                     float(origin_mm.z + z));
}

//! A leg whose standing foot is given in its own leg frame [mm].
constexpr LegModel leg_model(const char* name, BodySide side, const Vec3<float>& mount_mm, float yaw_deg,
                             JointRange j0, JointRange j1, JointRange j2, double stand_x, double stand_y,
                             double stand_z) {
  return LegModel{name, side, mount_mm, yaw_deg, {j0, j1, j2},
                  leg_point_in_body(mount_mm, yaw_deg, stand_x, stand_y, stand_z)};
}

//! A body-frame point [mm] in a leg's frame (body_to_leg at compile time).
constexpr Vec3<float> body_point_in_leg(const LegModel& leg, const Vec3<float>& p) {
  return Vec3<float>(
      float(model_math::cos_deg(leg.mount_yaw_deg) * (p.x - leg.mount_mm.x) +
            model_math::sin_deg(leg.mount_yaw_deg) * (p.y - leg.mount_mm.y)),
      float(-model_math::sin_deg(leg.mount_yaw_deg) * (p.x - leg.mount_mm.x) +
            model_math::cos_deg(leg.mount_yaw_deg) * (p.y - leg.mount_mm.y)),
      float(p.z - leg.mount_mm.z));
}

}  // namespace strider

#endif  // STRIDER_ROBOTS_ROBOT_MODEL_H
