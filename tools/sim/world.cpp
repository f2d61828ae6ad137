#include "world.h"

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

#include "control/channel_map.h"
#include "gait/gait_params.h"
#include "kinematics/any_leg.h"

namespace strider_sim {

namespace {

constexpr double kMm = 0.001;          // [m per mm]
constexpr double kSonarRangeMm = 3000; // HC-SR04: 2-300 cm (seed 000 sec 4.3)
constexpr double kSonarHalfConeDeg = 7.5;  // HC-SR04 datasheet: 15 deg measuring angle
constexpr int kSonarRays = 5;
constexpr double kContactMm = 0.5;     // a manifold point this close counts as touching
constexpr double kFar = 1e9;

btVector3 to_bt_m(const Vec& v_mm) { return btVector3(btScalar(v_mm.x * kMm), btScalar(v_mm.y * kMm), btScalar(v_mm.z * kMm)); }
Vec to_mm(const btVector3& v_m) { return Vec{v_m.x() / kMm, v_m.y() / kMm, v_m.z() / kMm}; }
Vec sub(const Vec& a, const Vec& b) { return Vec{a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec add(const Vec& a, const Vec& b) { return Vec{a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec scale(const Vec& a, double s) { return Vec{a.x * s, a.y * s, a.z * s}; }
double norm(const Vec& a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
Vec yaw_rotate(const Vec& a, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return Vec{c * a.x - s * a.y, s * a.x + c * a.y, a.z};
}

// Rotates p about the axis through `pivot` along unit `axis` by `angle` [rad].
Vec rotate_about(const Vec& p, const Vec& pivot, const Vec& axis, double angle) {
  const btVector3 v = quatRotate(btQuaternion(btVector3(btScalar(axis.x), btScalar(axis.y), btScalar(axis.z)), btScalar(angle)),
                                 btVector3(btScalar(p.x - pivot.x), btScalar(p.y - pivot.y), btScalar(p.z - pivot.z)));
  return Vec{pivot.x + double(v.x()), pivot.y + double(v.y()), pivot.z + double(v.z())};
}

// Closest distance between two convex shapes [m] (negative: penetration).
double gjk_distance(const btConvexShape* a, const btTransform& ta, const btConvexShape* b, const btTransform& tb) {
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

}  // namespace

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
};

World::World(const strider::RobotModel& model, const WorldConfig& cfg, const std::vector<ObstacleBox>& obstacles)
    : model_(model), cfg_(cfg), impl_(new Impl(cfg.solver)) {
  Impl& w = *impl_;
  w.world.setGravity(btVector3(0, 0, btScalar(-9.81)));
  w.world.getSolverInfo().m_numIterations = cfg.solver_iterations;
  w.world.getSolverInfo().m_leastSquaresResidualThreshold = btScalar(cfg.solver_residual);

  // Ground: a static plane; the feet carry the rubber's friction (Bullet
  // multiplies the two objects' coefficients).
  w.ground.reset(new btCollisionObject);
  w.ground->setCollisionShape(&w.ground_shape);
  w.ground->setFriction(1);
  w.ground->setRestitution(0);
  w.world.addCollisionObject(w.ground.get(), btBroadphaseProxy::StaticFilter,
                             btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
  for (const ObstacleBox& o : obstacles) {
    std::unique_ptr<btBoxShape> shape(
        new btBoxShape(btVector3(btScalar(o.sx_mm * 0.5 * kMm), btScalar(o.sy_mm * 0.5 * kMm), btScalar(o.sz_mm * 0.5 * kMm))));
    shape->setMargin(btScalar(0.001));
    std::unique_ptr<btCollisionObject> obj(new btCollisionObject);
    obj->setCollisionShape(shape.get());
    btTransform t;
    t.setIdentity();
    t.setOrigin(to_bt_m(Vec{o.x_mm, o.y_mm, o.sz_mm * 0.5}));
    obj->setWorldTransform(t);
    obj->setFriction(btScalar(0.5));
    w.world.addCollisionObject(obj.get(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    w.obstacle_shapes.push_back(std::move(shape));
    w.obstacles.push_back(std::move(obj));
  }

  // ---- the robot ------------------------------------------------------------
  const int legs = model.leg_count, dof = model.dof();
  joints_ = legs * dof;
  const strider::GaitParams* gp = strider::gait_params_for(model);
  w.foot_radius_mm = gp != nullptr ? std::max(3.0, double(gp->foot_radius_mm)) : 5.0;
  const double link_radius_mm = std::max(2.0, 0.5 * w.foot_radius_mm);

  // Masses: joint 0's servo sits in the body; the servo of joint j + 1 at
  // the far end of link j; links weigh link_density per mm; the body gets
  // the rest of the model's total.
  struct LinkPlan {
    Vec pivot, end, com;  // leg frame at zero [mm]
    double mass_kg = 0;
    btVector3 inertia;
  };
  std::vector<std::vector<LinkPlan>> plan(legs);
  std::vector<LegGeometry> geom(legs);
  double legs_mass = 0;
  for (int i = 0; i < legs; ++i) {
    geom[i] = leg_geometry(model, i);
    for (int j = 0; j < dof; ++j) {
      LinkPlan p;
      p.pivot = geom[i].joint[j].pivot_mm;
      p.end = geom[i].link_end_mm[j];
      const Vec d = sub(p.end, p.pivot);
      const double len = norm(d);
      const double m_link = cfg.link_density_g_mm * len * 1e-3;
      const double m_servo = j + 1 < dof ? double(strider::servo_spec(model.servo[j + 1]).mass_g) * 1e-3 : 0.0;
      p.mass_kg = m_link + m_servo;
      p.com = scale(add(scale(add(p.pivot, p.end), 0.5 * m_link), scale(p.end, m_servo)), 1.0 / p.mass_kg);
      // Inertia about the COM, link-frame diagonal: a rod plus a servo box
      // (40 x 20 x 40 mm class: m * 1.7e-4 m^2 for the MG996R size).
      const Vec mid = scale(add(p.pivot, p.end), 0.5);
      const Vec off_rod = sub(mid, p.com), off_srv = sub(p.end, p.com);
      auto axis_i = [&](double da, double db, double oa, double ob, double sa, double sb) {
        const double rod = m_link * ((da * da + db * db) / 12.0 + oa * oa + ob * ob);
        const double srv = m_servo * (sa * sa + sb * sb);
        return (rod + srv) * kMm * kMm + m_servo * 1.7e-4 + 1e-7;
      };
      p.inertia = btVector3(btScalar(axis_i(d.y, d.z, off_rod.y, off_rod.z, off_srv.y, off_srv.z)),
                            btScalar(axis_i(d.x, d.z, off_rod.x, off_rod.z, off_srv.x, off_srv.z)),
                            btScalar(axis_i(d.x, d.y, off_rod.x, off_rod.y, off_srv.x, off_srv.y)));
      legs_mass += p.mass_kg;
      plan[i].push_back(p);
    }
  }
  const double body_mass = std::max(0.1 * double(model.body.mass_kg), double(model.body.mass_kg) - legs_mass);

  // Standing joints (IK of the model's stance) and the start pose.
  std::vector<double> stand_q(size_t(joints_), 0.0), start_q;
  for (int i = 0; i < legs; ++i) {
    strider::AnyLeg<float> leg;
    strider::AnyLeg<float>::from_model(model, uint8_t(i), leg);
    strider::AnyLeg<float>::Joints q;
    strider::Vec3<float> reached;
    if (leg.ik(leg.mount().body_to_leg(model.legs[i].stand_mm), q, reached) == strider::IkStatus::kUnreachable) continue;
    for (int j = 0; j < dof; ++j) stand_q[size_t(i * dof + j)] = double(q[uint8_t(j)]);
  }
  start_q = cfg.initial_joints_rad.size() == size_t(joints_) ? cfg.initial_joints_rad : stand_q;

  // The builder balances the robot (battery placement) so that, standing,
  // its CoM is where the gait parameters assume it (com_x_mm, com_y_mm): the
  // body's own COM moves by whatever offsets the legs' servos put in.
  {
    double mx = 0, my = 0;
    for (int i = 0; i < legs; ++i) {
      const strider::LegModel& lm = model.legs[i];
      const double yaw = double(lm.mount_yaw_deg) * M_PI / 180.0;
      for (int j = 0; j < dof; ++j) {
        Vec c = plan[size_t(i)][size_t(j)].com;
        for (int k = j; k >= 0; --k)
          c = rotate_about(c, geom[size_t(i)].joint[size_t(k)].pivot_mm, geom[size_t(i)].joint[size_t(k)].axis,
                           stand_q[size_t(i * dof + k)] - geom[size_t(i)].joint[size_t(k)].zero_rad);
        c = add(Vec{lm.mount_mm.x, lm.mount_mm.y, lm.mount_mm.z}, yaw_rotate(c, yaw));
        mx += plan[size_t(i)][size_t(j)].mass_kg * c.x;
        my += plan[size_t(i)][size_t(j)].mass_kg * c.y;
      }
    }
    const double total = double(model.body.mass_kg);
    const double cx = gp != nullptr ? double(gp->com_x_mm) : 0.0, cy = gp != nullptr ? double(gp->com_y_mm) : 0.0;
    w.base_offset_mm = Vec{(total * cx - mx) / body_mass, (total * cy - my) / body_mass, 0};
  }
  const Vec& bo = w.base_offset_mm;
  const double bx = model.body.length_mm * kMm, by = model.body.width_mm * kMm, bz = model.body.height_mm * kMm;
  w.body_half_z_mm = 0.5 * model.body.height_mm;
  const btVector3 base_inertia(btScalar(body_mass / 12 * (by * by + bz * bz)), btScalar(body_mass / 12 * (bx * bx + bz * bz)),
                               btScalar(body_mass / 12 * (bx * bx + by * by)));
  w.body.reset(new btMultiBody(joints_, btScalar(body_mass), base_inertia, false, false));
  btMultiBody& mb = *w.body;
  mb.setHasSelfCollision(false);
  mb.setCanSleep(false);
  mb.setBasePos(btVector3(0, 0, 0));
  mb.setWorldToBaseRot(btQuaternion::getIdentity());

  strider::ServoChannel<float> channels[strider::kMaxServoJoints];
  strider::make_channel_map<float>(model, channels);
  w.drive.resize(size_t(joints_));
  w.foot_link.resize(size_t(legs));
  w.tip_local_mm.resize(size_t(legs));
  w.foot_touch.assign(size_t(legs), false);
  for (int i = 0; i < legs; ++i) {
    const strider::LegModel& lm = model.legs[i];
    const double yaw = double(lm.mount_yaw_deg) * M_PI / 180.0;
    const Vec mount{lm.mount_mm.x, lm.mount_mm.y, lm.mount_mm.z};
    for (int j = 0; j < dof; ++j) {
      const int link = i * dof + j;
      const LinkPlan& p = plan[i][j];
      const JointGeometry& jg = geom[i].joint[j];
      btQuaternion rot = btQuaternion::getIdentity();
      Vec parent_to_pivot;
      if (j == 0) {
        rot = btQuaternion(btVector3(0, 0, 1), btScalar(-yaw));
        parent_to_pivot = sub(add(mount, yaw_rotate(jg.pivot_mm, yaw)), bo);
      } else {
        parent_to_pivot = sub(jg.pivot_mm, plan[i][j - 1].com);
      }
      mb.setupRevolute(link, btScalar(p.mass_kg), p.inertia, j == 0 ? -1 : link - 1, rot,
                       btVector3(btScalar(jg.axis.x), btScalar(jg.axis.y), btScalar(jg.axis.z)), to_bt_m(parent_to_pivot),
                       to_bt_m(sub(p.com, jg.pivot_mm)), true);
      JointDrive& d = w.drive[size_t(link)];
      d.link = link;
      d.channel = channels[link];
      d.servo = servo_model(model.servo[j]);
      d.zero_rad = jg.zero_rad;
    }
    w.foot_link[size_t(i)] = i * dof + dof - 1;
    w.tip_local_mm[size_t(i)] = sub(geom[i].link_end_mm[size_t(dof - 1)], plan[i][size_t(dof - 1)].com);
  }
  mb.finalizeMultiDof();
  mb.setLinearDamping(0);
  mb.setAngularDamping(0);

  for (JointDrive& d : w.drive) {
    mb.setJointPos(d.link, btScalar(start_q[size_t(d.link)] - d.zero_rad));
    d.target_rad = start_q[size_t(d.link)];
  }

  // Collision shapes: the body box; each link a capsule; the last link's
  // foot a sphere whose surface passes through the foot point.
  w.world.addMultiBody(&mb);
  btAlignedObjectArray<btQuaternion> w2l;
  btAlignedObjectArray<btVector3> origin;
  w2l.resize(joints_ + 1);
  origin.resize(joints_ + 1);
  mb.forwardKinematics(w2l, origin);
  w.base_shape.reset(new btBoxShape(btVector3(btScalar(bx / 2), btScalar(by / 2), btScalar(bz / 2))));
  w.base_shape->setMargin(btScalar(0.001));
  {
    w.base_compound.reset(new btCompoundShape);
    btTransform t;
    t.setIdentity();
    t.setOrigin(to_bt_m(scale(bo, -1)));
    w.base_compound->addChildShape(t, w.base_shape.get());
    std::unique_ptr<btMultiBodyLinkCollider> col(new btMultiBodyLinkCollider(&mb, -1));
    col->setCollisionShape(w.base_compound.get());
    col->setFriction(btScalar(cfg.body_friction));
    w.world.addCollisionObject(col.get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    mb.setBaseCollider(col.get());
    w.colliders.push_back(std::move(col));
  }
  for (int i = 0; i < legs; ++i)
    for (int j = 0; j < dof; ++j) {
      const int link = i * dof + j;
      const LinkPlan& p = plan[i][j];
      const bool last = j == dof - 1;
      std::unique_ptr<btCompoundShape> compound(new btCompoundShape);
      Vec end = p.end;
      const Vec dir = sub(p.end, p.pivot);
      const double len = norm(dir);
      const Vec unit = scale(dir, 1.0 / std::max(len, 1e-9));
      if (last) end = sub(p.end, scale(unit, w.foot_radius_mm));  // the foot sphere's centre
      const double seg = norm(sub(end, p.pivot));
      if (seg > 1.0) {
        std::unique_ptr<btCapsuleShape> cap(new btCapsuleShape(btScalar(link_radius_mm * kMm), btScalar(seg * kMm)));
        cap->setMargin(btScalar(link_radius_mm * kMm));
        btTransform t;
        t.setIdentity();
        t.setOrigin(to_bt_m(sub(scale(add(p.pivot, end), 0.5), p.com)));
        t.setRotation(shortestArcQuat(btVector3(0, 1, 0), btVector3(btScalar(unit.x), btScalar(unit.y), btScalar(unit.z))));
        compound->addChildShape(t, cap.get());
        w.shapes.push_back(std::move(cap));
      }
      if (last) {
        std::unique_ptr<btSphereShape> foot(new btSphereShape(btScalar(w.foot_radius_mm * kMm)));
        btTransform t;
        t.setIdentity();
        t.setOrigin(to_bt_m(sub(end, p.com)));
        compound->addChildShape(t, foot.get());
        w.shapes.push_back(std::move(foot));
      }
      std::unique_ptr<btMultiBodyLinkCollider> col(new btMultiBodyLinkCollider(&mb, link));
      col->setCollisionShape(compound.get());
      col->setFriction(btScalar(last ? cfg.foot_friction : cfg.body_friction));
      col->setRestitution(0);
      w.world.addCollisionObject(col.get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
      mb.getLink(link).m_collider = col.get();
      w.shapes.push_back(std::move(compound));
      w.colliders.push_back(std::move(col));
    }

  // Place the robot so that its lowest point is 0.5 mm above the ground.
  mb.updateCollisionObjectWorldTransforms(w2l, origin);
  double lowest = -w.body_half_z_mm;
  for (int i = 0; i < legs; ++i) {
    const Vec tip = foot_mm(i);
    lowest = std::min(lowest, tip.z - 0.2 * w.foot_radius_mm);
  }
  for (const auto& col : w.colliders) {
    btVector3 lo, hi;
    col->getCollisionShape()->getAabb(col->getWorldTransform(), lo, hi);
    lowest = std::min(lowest, double(lo.z()) / kMm);
  }
  mb.setBasePos(btVector3(btScalar(bo.x * kMm), btScalar(bo.y * kMm), btScalar((0.5 - lowest) * kMm)));
  mb.updateCollisionObjectWorldTransforms(w2l, origin);

  // Motors, limp until the first pulse.
  for (JointDrive& d : w.drive) {
    std::unique_ptr<btMultiBodyJointMotor> m(new btMultiBodyJointMotor(&mb, d.link, 0, 0, btScalar(d.servo.limp_torque_nm * cfg.step_s)));
    d.motor = m.get();
    w.world.addMultiBodyConstraint(m.get());
    w.motors.push_back(std::move(m));
  }
  ChannelPulse off[kMaxChannels];
  set_pulses(off);
}

World::~World() {
  Impl& w = *impl_;
  for (auto& m : w.motors) w.world.removeMultiBodyConstraint(m.get());
  for (auto& c : w.colliders) w.world.removeCollisionObject(c.get());
  if (w.body) w.world.removeMultiBody(w.body.get());
  for (auto& o : w.obstacles) w.world.removeCollisionObject(o.get());
  w.world.removeCollisionObject(w.ground.get());
}

void World::set_pulses(const ChannelPulse* pulses) {
  Impl& w = *impl_;
  const double dt = cfg_.step_s;
  for (JointDrive& d : w.drive) {
    const ChannelPulse& p = pulses[d.channel.channel < kMaxChannels ? d.channel.channel : 0];
    if (!p.on) {
      d.on = false;
      d.motor->setPositionTarget(0, 0);
      d.motor->setVelocityTarget(0, 1);
      d.motor->setRhsClamp(btScalar(SIMD_INFINITY));
      d.motor->setMaxAppliedImpulse(btScalar(d.servo.limp_torque_nm * dt));
      continue;
    }
    // The servo's own travel ends its pulse range; the dead band holds the
    // last pulse it acted on until the new one differs by more.
    const double lo = std::min(d.channel.min_pulse_us, d.channel.max_pulse_us);
    const double hi = std::max(d.channel.min_pulse_us, d.channel.max_pulse_us);
    const double pulse = std::min(hi, std::max(lo, p.pulse_us));
    if (!d.on || std::fabs(pulse - d.held_pulse_us) > d.servo.deadband_us) d.held_pulse_us = pulse;
    d.on = true;
    d.target_rad = strider::joint_from_pulse(d.channel, d.held_pulse_us);
    d.motor->setPositionTarget(btScalar(d.target_rad - d.zero_rad), btScalar(d.servo.position_gain * dt));
    d.motor->setVelocityTarget(0, 1);
    d.motor->setRhsClamp(btScalar(d.servo.speed_rad_s));
    d.motor->setMaxAppliedImpulse(btScalar(d.servo.torque_nm * dt));
  }
}

void World::step() {
  Impl& w = *impl_;
  w.world.stepSimulation(btScalar(cfg_.step_s), 0, btScalar(cfg_.step_s));
  ++steps_;
  // Contacts of this step.
  std::fill(w.foot_touch.begin(), w.foot_touch.end(), false);
  w.obstacle_touch = 0;
  w.body_touch = false;
  const int n = w.dispatcher.getNumManifolds();
  for (int k = 0; k < n; ++k) {
    const btPersistentManifold* m = w.dispatcher.getManifoldByIndexInternal(k);
    bool touching = false;
    for (int c = 0; c < m->getNumContacts(); ++c)
      if (double(m->getContactPoint(c).getDistance()) < kContactMm * kMm) touching = true;
    if (!touching) continue;
    const btCollisionObject* a = m->getBody0();
    const btCollisionObject* b = m->getBody1();
    const bool a_ground = a == w.ground.get(), b_ground = b == w.ground.get();
    const btMultiBodyLinkCollider* robot = btMultiBodyLinkCollider::upcast(a_ground ? b : a);
    const btCollisionObject* other = robot == btMultiBodyLinkCollider::upcast(a) ? b : a;
    if (robot == nullptr) continue;
    if (other == w.ground.get()) {
      if (robot->m_link < 0) w.body_touch = true;
      for (size_t i = 0; i < w.foot_link.size(); ++i)
        if (robot->m_link == w.foot_link[i]) w.foot_touch[i] = true;
    } else if (!a_ground && !b_ground && btMultiBodyLinkCollider::upcast(other) == nullptr) {
      ++w.obstacle_touch;
    }
  }
}

BodyState World::body() const {
  const btMultiBody& mb = *impl_->body;
  BodyState s;
  s.pos_mm = to_mm(mb.getBasePos() - quatRotate(mb.getWorldToBaseRot().inverse(), to_bt_m(impl_->base_offset_mm)));
  s.vel_mm_s = to_mm(mb.getBaseVel());
  const btQuaternion q = mb.getWorldToBaseRot().inverse();  // body -> world
  btScalar yaw, pitch, roll;
  btMatrix3x3(q).getEulerZYX(yaw, pitch, roll);
  s.roll_deg = double(roll) * 180.0 / M_PI;
  s.pitch_deg = double(pitch) * 180.0 / M_PI;
  s.yaw_deg = double(yaw) * 180.0 / M_PI;
  const btVector3 up = quatRotate(q, btVector3(0, 0, 1));
  s.tilt_deg = std::acos(std::max(-1.0, std::min(1.0, double(up.z())))) * 180.0 / M_PI;
  return s;
}

double World::joint_rad(int leg, int j) const {
  const JointDrive& d = impl_->drive[size_t(leg * model_.dof() + j)];
  return double(impl_->body->getJointPos(d.link)) + d.zero_rad;
}

double World::joint_target_rad(int leg, int j) const { return impl_->drive[size_t(leg * model_.dof() + j)].target_rad; }

Vec World::foot_mm(int leg) const {
  const Impl& w = *impl_;
  return to_mm(w.body->localPosToWorld(w.foot_link[size_t(leg)], to_bt_m(w.tip_local_mm[size_t(leg)])));
}

bool World::foot_contact(int leg) const { return impl_->foot_touch[size_t(leg)]; }

Vec World::sonar_origin_body_mm() const { return Vec{0.5 * model_.body.length_mm + 5.0, 0, 0}; }

double World::sonar_mm() const {
  const Impl& w = *impl_;
  const btMultiBody& mb = *w.body;
  const btQuaternion q = mb.getWorldToBaseRot().inverse();
  const btVector3 from = mb.getBasePos() + quatRotate(q, to_bt_m(sub(sonar_origin_body_mm(), w.base_offset_mm)));
  double best = -1;
  for (int r = 0; r < kSonarRays; ++r) {
    const double a = (-kSonarHalfConeDeg + 2 * kSonarHalfConeDeg * r / (kSonarRays - 1)) * M_PI / 180.0;
    const btVector3 dir = quatRotate(q, btVector3(btScalar(std::cos(a)), btScalar(std::sin(a)), 0));
    const btVector3 to = from + dir * btScalar(kSonarRangeMm * kMm);
    btCollisionWorld::ClosestRayResultCallback cb(from, to);
    cb.m_collisionFilterGroup = btBroadphaseProxy::DefaultFilter;
    cb.m_collisionFilterMask = btBroadphaseProxy::StaticFilter;  // the world, not the robot
    w.world.rayTest(from, to, cb);
    if (!cb.hasHit()) continue;
    const double d = double(cb.m_closestHitFraction) * kSonarRangeMm;
    if (best < 0 || d < best) best = d;
  }
  return best;
}

double World::body_clearance_mm() const {
  const Impl& w = *impl_;
  double best = kFar;
  const btCollisionObject* base = w.colliders[0].get();
  for (size_t k = 0; k < w.obstacles.size(); ++k)
    best = std::min(best, gjk_distance(w.base_shape.get(), base->getWorldTransform() * w.base_compound->getChildTransform(0),
                                       w.obstacle_shapes[k].get(),
                                       w.obstacles[k]->getWorldTransform()) / kMm);
  return best;
}

double World::robot_clearance_mm() const {
  const Impl& w = *impl_;
  double best = body_clearance_mm();
  for (size_t c = 1; c < w.colliders.size(); ++c) {
    const btCollisionObject* col = w.colliders[c].get();
    const btCompoundShape* compound = static_cast<const btCompoundShape*>(col->getCollisionShape());
    for (int ch = 0; ch < compound->getNumChildShapes(); ++ch) {
      const btConvexShape* s = static_cast<const btConvexShape*>(compound->getChildShape(ch));
      const btTransform t = col->getWorldTransform() * compound->getChildTransform(ch);
      for (size_t k = 0; k < w.obstacles.size(); ++k)
        best = std::min(best, gjk_distance(s, t, w.obstacle_shapes[k].get(), w.obstacles[k]->getWorldTransform()) / kMm);
    }
  }
  return best;
}

int World::obstacle_contacts() const { return impl_->obstacle_touch; }

bool World::body_on_ground() const { return impl_->body_touch; }

bool World::all_servos_on() const {
  for (const JointDrive& d : impl_->drive)
    if (!d.on) return false;
  return true;
}

Vec World::com_mm() const {
  const btMultiBody& mb = *impl_->body;
  btVector3 sum = mb.getBasePos() * mb.getBaseMass();
  btScalar mass = mb.getBaseMass();
  for (int i = 0; i < mb.getNumLinks(); ++i) {
    sum += mb.localPosToWorld(i, btVector3(0, 0, 0)) * mb.getLinkMass(i);
    mass += mb.getLinkMass(i);
  }
  return to_mm(sum / mass);
}

}  // namespace strider_sim
