// World's implementation state (see world.h), shared by its parts:
// world_build.cpp (the robot, ground and obstacles built in Bullet),
// world.cpp (servo pulses in, stepping, the robot's state out) and
// world_sensing.cpp (sonar ray cast, clearances, centre of mass).
#pragma once

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyMLCPConstraintSolver.h>
#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "control/channel_map.h"
#include "gait/gait_params.h"
#include "kinematics/any_leg.h"

#include "world.h"

namespace strider_sim {
namespace world_detail {

constexpr double kMm = 0.001;          // [m per mm]
constexpr double kSonarRangeMm = 3000; // HC-SR04: 2-300 cm (seed 000 sec 4.3)
constexpr double kSonarHalfConeDeg = 7.5;  // HC-SR04 datasheet: 15 deg measuring angle
constexpr int kSonarRays = 5;
constexpr double kContactMm = 0.5;     // a manifold point this close counts as touching
constexpr double kFar = 1e9;

inline btVector3 to_bt_m(const Vec& v_mm) { return btVector3(btScalar(v_mm.x * kMm), btScalar(v_mm.y * kMm), btScalar(v_mm.z * kMm)); }
inline Vec to_mm(const btVector3& v_m) { return Vec{v_m.x() / kMm, v_m.y() / kMm, v_m.z() / kMm}; }
inline Vec sub(const Vec& a, const Vec& b) { return Vec{a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec add(const Vec& a, const Vec& b) { return Vec{a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec scale(const Vec& a, double s) { return Vec{a.x * s, a.y * s, a.z * s}; }
inline double norm(const Vec& a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
inline Vec yaw_rotate(const Vec& a, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return Vec{c * a.x - s * a.y, s * a.x + c * a.y, a.z};
}

// Rotates p about the axis through `pivot` along unit `axis` by `angle` [rad].
inline Vec rotate_about(const Vec& p, const Vec& pivot, const Vec& axis, double angle) {
  const btVector3 v = quatRotate(btQuaternion(btVector3(btScalar(axis.x), btScalar(axis.y), btScalar(axis.z)), btScalar(angle)),
                                 btVector3(btScalar(p.x - pivot.x), btScalar(p.y - pivot.y), btScalar(p.z - pivot.z)));
  return Vec{pivot.x + double(v.x()), pivot.y + double(v.y()), pivot.z + double(v.z())};
}

// Closest distance between two convex shapes [m] (negative: penetration).
inline double gjk_distance(const btConvexShape* a, const btTransform& ta, const btConvexShape* b, const btTransform& tb) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector gjk(a, b, &simplex, &epa);
  btGjkPairDetector::ClosestPointInput in;
  in.m_transformA = ta;
  in.m_transformB = tb;
  btPointCollector out;
  gjk.getClosestPoints(in, out, nullptr);
  return out.m_hasResult ? double(out.m_distance) : kFar;
}

}  // namespace world_detail

struct JointDrive {
  int link = 0;                 // multibody link index
  strider::ServoChannel<float> channel{};
  ServoModel servo;
  double zero_rad = 0;          // seed angle of physics angle 0 [rad]
  bool on = false;              // a pulse is arriving
  double held_pulse_us = 0;     // pulse the servo acts on (after the deadband)
  double target_rad = 0;        // seed convention [rad]
  btMultiBodyJointMotor* motor = nullptr;
};

struct World::Impl {
  explicit Impl(Solver kind)
      : solver(kind == Solver::kMlcp ? new btMultiBodyMLCPConstraintSolver(&dantzig) : new btMultiBodyConstraintSolver),
        world(&dispatcher, &broadphase, solver.get(), &config) {}

  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  // Constraint solver: Bullet's projected Gauss-Seidel, or the exact mixed
  // LCP (Dantzig; Bullet falls back to PGS for a step it cannot solve).
  btDantzigSolver dantzig;
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
  btMultiBodyDynamicsWorld world;

  btStaticPlaneShape ground_shape{btVector3(0, 0, 1), 0};
  std::unique_ptr<btCollisionObject> ground;
  std::vector<std::unique_ptr<btBoxShape>> obstacle_shapes;
  std::vector<std::unique_ptr<btCollisionObject>> obstacles;

  std::unique_ptr<btMultiBody> body;
  std::unique_ptr<btBoxShape> base_shape;
  std::unique_ptr<btCompoundShape> base_compound;
  Vec base_offset_mm;  // the base frame (the body's own COM) from the body centre [mm]
  std::vector<std::unique_ptr<btCollisionShape>> shapes;  // link shapes and children
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;  // [0] base, then links
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors;
  std::vector<JointDrive> drive;  // joint k = leg * dof + j
  std::vector<Vec> tip_local_mm;  // per leg: foot tip relative to the last link's COM, link frame [mm]
  std::vector<int> foot_link;     // per leg
  std::vector<bool> foot_touch;   // per leg, this step
  int obstacle_touch = 0;
  bool body_touch = false;
  double foot_radius_mm = 5;
  double body_half_z_mm = 15;
  // world_events.cpp: the ramp (world -> level, a rotation that takes
  // gravity's up to z), a pending shove, the start pose for upright().
  bool ramp = false;
  btMatrix3x3 world_to_level = btMatrix3x3::getIdentity();
  bool shove_pending = false;
  btVector3 shove_force{0, 0, 0}, shove_torque{0, 0, 0};
  std::vector<double> start_q;  // joint k [rad], seed convention
  double start_base_z_m = 0;
};

}  // namespace strider_sim
