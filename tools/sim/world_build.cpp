// World: the robot model built as a Bullet multibody (links, joint motors,
// colliders, masses), the ground plane and the obstacle boxes.
#include "world_impl.h"

namespace strider_sim {

using namespace world_detail;

World::World(const strider::RobotModel& model, const WorldConfig& cfg, const std::vector<ObstacleBox>& obstacles)
    : model_(model), cfg_(cfg), impl_(new Impl(cfg.solver)) {
  Impl& w = *impl_;
  w.world.setGravity(btVector3(0, 0, btScalar(-9.81)));
  w.world.getSolverInfo().m_numIterations = cfg.solver_iterations;
  w.world.getSolverInfo().m_leastSquaresResidualThreshold = btScalar(cfg.solver_residual);
  w.world.getSolverInfo().m_globalCfm = btScalar(cfg.solver_cfm);

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
  w.start_q = start_q;

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
        std::unique_ptr<btConvexInternalShape> foot;
        btTransform t;
        t.setIdentity();
        if (cfg.foot_pad_half_mm > 0) {
          // Bullet's capsule lies along its local y axis: turned onto the joint's axis.
          const Vec& axis = geom[i].joint[j].axis;
          foot.reset(new btCapsuleShape(btScalar(w.foot_radius_mm * kMm), btScalar(2 * cfg.foot_pad_half_mm * kMm)));
          t.setRotation(shortestArcQuat(btVector3(0, 1, 0), btVector3(btScalar(axis.x), btScalar(axis.y), btScalar(axis.z))));
        } else {
          foot.reset(new btSphereShape(btScalar(w.foot_radius_mm * kMm)));
        }
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
  w.start_base_z_m = (0.5 - lowest) * kMm;
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

}  // namespace strider_sim
