//! FirmwareProfile: a firmware's build profile (robots/build_profile.h),
//! derived from its model, a compile-time constant: walking state for the
//! model's legs, an IK solver per leg geometry, leg results without the
//! feet, the tick map's ranges shared by legs of one geometry, the stored
//! velocity limits instead of the IK search. Everything else is built from
//! the model at start-up, as on the host.
#ifndef STRIDER_CONTROL_FIRMWARE_PROFILE_H
#define STRIDER_CONTROL_FIRMWARE_PROFILE_H

#include "../gait/walker_legs.h"
#include "../math/fixed.h"
#include "../robots/all_robots.h"
#include "../robots/build_profile.h"

namespace strider {

//! m's index among the built-in models, kAllRobots (kRobotCount: not one of them).
constexpr uint8_t robot_index(const RobotModel& m) {
  uint8_t r = 0;
  while (r < kRobotCount && kAllRobots[r] != &m) ++r;
  return r;
}

//! r: the built-in model's index, robot_index(kSprawl8) (its velocity
//! limits are stored); S: the scalar (fixed point: the shorter tick on the
//! AVR, docs/benchmarks.md).
template <uint8_t r, typename S = Fixed>
struct FirmwareProfile : HostProfile<S> {
  static_assert(r < kRobotCount, "a built-in model (stored velocity limits)");
  static constexpr uint8_t kModelIndex = r;
  static constexpr const RobotModel& kModel = *kAllRobots[r];
  static constexpr uint8_t kLegs = kModel.leg_count;
  static constexpr uint8_t kSolvers = leg_solver_count(kModel);
  static constexpr bool kFeet = false;
  static constexpr uint8_t kTickSlots = kSolvers == 1 ? kModel.dof() : 0;
  static constexpr uint8_t kJoints = kModel.joint_count();
  static constexpr bool kSearch = false;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_FIRMWARE_PROFILE_H
