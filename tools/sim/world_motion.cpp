// World: the body's motion at a point (for the IMU model) and each servo's
// torque and speed (for the battery model).
#include "world_impl.h"

namespace strider_sim {

using namespace world_detail;

BodyMotion World::body_motion(const Vec& point_body_mm) const {
  const Impl& w = *impl_;
  const btMultiBody& mb = *w.body;
  const btQuaternion q = mb.getWorldToBaseRot().inverse();  // body -> world
  const btMatrix3x3 r(q);
  const btVector3 omega = mb.getBaseOmega();  // world frame
  // The base is the body's own centre of mass, base_offset_mm from its centre.
  const btVector3 arm = quatRotate(q, to_bt_m(sub(point_body_mm, w.base_offset_mm)));
  BodyMotion m;
  m.vel_mm_s = to_mm(mb.getBaseVel() + omega.cross(arm));
  const btVector3 omega_body = quatRotate(q.inverse(), omega);
  m.omega_body_rad_s = Vec{double(omega_body.x()), double(omega_body.y()), double(omega_body.z())};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.rot[i][j] = double(r[i][j]);
  const btVector3 g = w.world.getGravity();
  m.gravity_m_s2 = Vec{double(g.x()), double(g.y()), double(g.z())};
  return m;
}

double World::joint_torque_nm(int leg, int j) const {
  if (steps_ == 0) return 0;  // the motor's rows exist from the first step on
  const JointDrive& d = impl_->drive[size_t(leg * model_.dof() + j)];
  return double(d.motor->getAppliedImpulse(0)) / cfg_.step_s;
}

double World::joint_speed_rad_s(int leg, int j) const {
  const JointDrive& d = impl_->drive[size_t(leg * model_.dof() + j)];
  return double(impl_->body->getJointVel(d.link));
}

bool World::joint_on(int leg, int j) const { return impl_->drive[size_t(leg * model_.dof() + j)].on; }

}  // namespace strider_sim
