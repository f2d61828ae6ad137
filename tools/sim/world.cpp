// World: servo pulses to joint motors, stepping, and the robot's state
// (body, joints, feet, contacts) read back (see world.h).
#include "world_impl.h"

namespace strider_sim {

using namespace world_detail;

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
  if (w.shove_pending) {
    w.body->addBaseForce(w.shove_force);
    w.body->addBaseTorque(w.shove_torque);
  }
  w.world.stepSimulation(btScalar(cfg_.step_s), 0, btScalar(cfg_.step_s));
  if (w.shove_pending) {
    w.body->clearForcesAndTorques();
    w.shove_pending = false;
  }
  ++steps_;
  // A joint motor's applied impulse over the step is torque x step [N m s].
  for (const JointDrive& d : w.drive)
    servo_work_j_ += std::fabs(double(d.motor->getAppliedImpulse(0)) * double(w.body->getJointVel(d.link)));
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
  // On a ramp the attitude is against gravity: body -> level.
  const btMatrix3x3 rot = impl_->ramp ? impl_->world_to_level * btMatrix3x3(q) : btMatrix3x3(q);
  rot.getEulerZYX(yaw, pitch, roll);
  s.roll_deg = double(roll) * 180.0 / M_PI;
  s.pitch_deg = double(pitch) * 180.0 / M_PI;
  s.yaw_deg = double(yaw) * 180.0 / M_PI;
  const btVector3 up = impl_->ramp ? rot * btVector3(0, 0, 1) : quatRotate(q, btVector3(0, 0, 1));
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

long World::solver_fallbacks() const {
  if (cfg_.solver != Solver::kMlcp) return 0;
  return long(static_cast<const btMultiBodyMLCPConstraintSolver&>(*impl_->solver).getNumFallbacks());
}

bool World::foot_contact(int leg) const { return impl_->foot_touch[size_t(leg)]; }

}  // namespace strider_sim
