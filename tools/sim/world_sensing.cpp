// World: what sensors and metrics see: the HC-SR04 ray-cast cone, body and
// robot clearance to the obstacles, the centre of mass.
#include "world_impl.h"

namespace strider_sim {

using namespace world_detail;

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
