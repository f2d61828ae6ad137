#include "leg_geometry.h"

#include <cmath>

namespace strider_sim {

namespace {
constexpr Vec kUp{0, 0, 1};
constexpr Vec kPitch{0, -1, 0};  // positive angle turns +x toward +z
constexpr Vec kRoll{1, 0, 0};
}  // namespace

LegGeometry leg_geometry(const strider::RobotModel& model, int leg) {
  using strider::LegKind;
  const double l1 = model.links.l1_mm, l2 = model.links.l2_mm, l3 = model.links.l3_mm, d1 = model.links.d1_mm;
  LegGeometry g;
  g.dof = strider::dof_of(model.kind);
  switch (model.kind) {
    case LegKind::kSprawl:  // seed 000 eqs 4-6: yaw at the hip, knee pitch at a1
      g.joint[0] = {{0, 0, 0}, kUp, 0};
      g.joint[1] = {{l1, 0, 0}, kPitch, 0};
      g.link_end_mm = {Vec{l1, 0, 0}, Vec{l1 + l2, 0, 0}, Vec{}};
      break;
    case LegKind::kPlanar:  // seed 003 eqs 3-5: two pitch joints in the x-z plane
      g.joint[0] = {{0, 0, 0}, kPitch, 0};
      g.joint[1] = {{l1, 0, 0}, kPitch, 0};
      g.link_end_mm = {Vec{l1, 0, 0}, Vec{l1 + l2, 0, 0}, Vec{}};
      break;
    case LegKind::kCoxaFemurTibia:  // seed 002 eqs 5-7: coxa yaw, femur axis d1 up and l1 out
      g.joint[0] = {{0, 0, 0}, kUp, 0};
      g.joint[1] = {{l1, 0, d1}, kPitch, 0};
      g.joint[2] = {{l1 + l2, 0, d1}, kPitch, 0};
      g.link_end_mm = {Vec{l1, 0, d1}, Vec{l1 + l2, 0, d1}, Vec{l1 + l2 + l3, 0, d1}};
      break;
    case LegKind::kAbduction: {
      // Seed 001: abduction about +x; La points out sideways (left +y at
      // t1 = 0, right -y at t1 = pi); at t2 = t3 = 0 femur and tibia point
      // backward, and both pitch joints turn them down (about -y).
      const bool left = model.legs[leg].side == strider::BodySide::kLeft;
      const double la = left ? l1 : -l1;
      g.joint[0] = {{0, 0, 0}, kRoll, left ? 0.0 : M_PI};
      g.joint[1] = {{0, la, 0}, kPitch, 0};
      g.joint[2] = {{-l2, la, 0}, kPitch, 0};
      g.link_end_mm = {Vec{0, la, 0}, Vec{-l2, la, 0}, Vec{-l2 - l3, la, 0}};
      break;
    }
  }
  return g;
}

}  // namespace strider_sim
