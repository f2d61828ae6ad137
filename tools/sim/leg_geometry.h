// LegGeometry: the joints and links of one leg of a RobotModel at its zero
// configuration, in the leg frame, for building the physics body.
//
// Every link frame is aligned with the leg frame when all joints sit at
// their zero angle, so a physics joint angle is the seed-convention joint
// angle minus zero_rad, about the axis given here. The axes follow from each
// leg type's FK (lib/strider/kinematics): a pitch joint whose positive angle
// lifts a link pointing along +x turns about -y.
#pragma once

#include <array>

#include "robots/robot_model.h"

namespace strider_sim {

struct Vec {
  double x = 0, y = 0, z = 0;
};

struct JointGeometry {
  Vec pivot_mm;    // joint axis point, leg frame at the zero configuration [mm]
  Vec axis;        // unit axis, leg frame
  double zero_rad; // seed-convention angle of the zero configuration [rad]
};

struct LegGeometry {
  int dof = 0;
  std::array<JointGeometry, 3> joint{};
  // Link j runs from joint j's pivot to link_end_mm[j] (the next pivot, or
  // the foot for the last link), leg frame at the zero configuration [mm].
  std::array<Vec, 3> link_end_mm{};
};

// The geometry of leg `leg` of `model` (links from model.links).
LegGeometry leg_geometry(const strider::RobotModel& model, int leg);

}  // namespace strider_sim
