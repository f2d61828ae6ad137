// World: what a scenario does to the robot besides the link: a sloping
// ground, a shove, setting a fallen robot back on its feet (see world.h).
#include "world_impl.h"

namespace strider_sim {

using namespace world_detail;

void World::set_ramp(double slope_deg, double uphill_deg) {
  Impl& w = *impl_;
  const double th = slope_deg * M_PI / 180.0, az = uphill_deg * M_PI / 180.0;
  // Ground rising toward d = (cos az, sin az, 0) by th: in the ground's frame
  // the true vertical leans toward d, up = (sin th d, cos th), and a ball
  // rolls toward -d. The level frame turns up onto z: about (sin az, -cos az, 0) by th.
  const btVector3 up(btScalar(std::sin(th) * std::cos(az)), btScalar(std::sin(th) * std::sin(az)), btScalar(std::cos(th)));
  w.world.setGravity(up * btScalar(-9.81));
  w.world_to_level.setRotation(btQuaternion(btVector3(btScalar(std::sin(az)), btScalar(-std::cos(az)), 0), btScalar(th)));
  w.ramp = slope_deg != 0;
}

void World::shove(const Vec& impulse_ns) {
  Impl& w = *impl_;
  const btMultiBody& mb = *w.body;
  const btQuaternion q = mb.getWorldToBaseRot().inverse();  // body -> world
  // The top face's centre relative to the base (the body's own COM).
  const btVector3 arm = quatRotate(q, to_bt_m(sub(Vec{0, 0, w.body_half_z_mm}, w.base_offset_mm)));
  const btVector3 f = btVector3(btScalar(impulse_ns.x), btScalar(impulse_ns.y), btScalar(impulse_ns.z)) /
                      btScalar(cfg_.step_s);
  w.shove_force = f;
  w.shove_torque = arm.cross(f);
  w.shove_pending = true;
}

void World::upright() {
  Impl& w = *impl_;
  btMultiBody& mb = *w.body;
  const BodyState b = body();
  const btQuaternion q = mb.getWorldToBaseRot().inverse();  // body -> world
  // The heading: where body x points, on the ground.
  const btVector3 fwd = quatRotate(q, btVector3(1, 0, 0));
  const double yaw = std::atan2(double(fwd.y()), double(fwd.x()));
  const btQuaternion heading(btVector3(0, 0, 1), btScalar(yaw));
  for (JointDrive& d : w.drive) {
    mb.setJointPos(d.link, btScalar(w.start_q[size_t(d.link)] - d.zero_rad));
    mb.setJointVel(d.link, 0);
  }
  const btVector3 offset = quatRotate(heading, to_bt_m(Vec{w.base_offset_mm.x, w.base_offset_mm.y, 0}));
  mb.setWorldToBaseRot(heading.inverse());
  mb.setBasePos(btVector3(btScalar(b.pos_mm.x * kMm), btScalar(b.pos_mm.y * kMm), btScalar(w.start_base_z_m)) + offset);
  mb.setBaseVel(btVector3(0, 0, 0));
  mb.setBaseOmega(btVector3(0, 0, 0));
  btAlignedObjectArray<btQuaternion> w2l;
  btAlignedObjectArray<btVector3> origin;
  w2l.resize(joints_ + 1);
  origin.resize(joints_ + 1);
  mb.forwardKinematics(w2l, origin);
  mb.updateCollisionObjectWorldTransforms(w2l, origin);
}

}  // namespace strider_sim
