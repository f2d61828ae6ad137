//! FirmwareProfile: a firmware's build profile (robots/build_profile.h),
//! derived from its model, a compile-time constant: walking state for the
//! model's legs, an IK solver per leg geometry, leg results without the
//! feet, the tick map's ranges shared by legs of one geometry, and the
//! model's constants in flash, so that start-up converts no float model,
//! looks no limits up and keeps no RAM copy of them.
#ifndef STRIDER_CONTROL_FIRMWARE_PROFILE_H
#define STRIDER_CONTROL_FIRMWARE_PROFILE_H

#include "../gait/gait_config.h"
#include "../math/fixed.h"
#include "../robots/all_robots.h"
#include "../robots/build_profile.h"
#include "joint_channels.h"
#include "model_constants.h"

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
  static constexpr bool kStoredConfig = true;
  static constexpr bool kStoredLegs = true;
  static constexpr bool kStoredChannels = true;
  static constexpr bool kStoredGait = true;
  static constexpr uint16_t kAvoidClearMm = avoid_clear_mm(kModel);
  static_assert(kAvoidClearMm != 0, "avoid_clear_mm: a distance");

  //! The model's strides alone of the stored table, and its gait
  //! configuration at its defaults with the ramps (stored_gait_config()).
  static constexpr StrideTable<true> kStrides STRIDER_PROGMEM = stored_strides(r);
  static constexpr GaitConfig<S, kLegs, kSearch> kGaitConfig STRIDER_PROGMEM =
      stored_gait_config<S, kLegs, kSearch>(r, &kStrides.stride_code[0][0]);
  //! The walker's legs, but for the mounts' cos and sin (walker_legs()).
  static constexpr WalkerLegs<S, kLegs, kSolvers> kWalkerLegsInFlash STRIDER_PROGMEM =
      walker_legs<S, kLegs, kSolvers>(kModel);
  static constexpr JointChannels<S, kJoints, kTickSlots> kChannels STRIDER_PROGMEM =
      joint_channels<S, kJoints, kTickSlots>(kModel);
  static constexpr GaitName kDefaultGait STRIDER_PROGMEM = default_gait_name(r);
  static_assert(kWalkerLegsInFlash.ok, "the model's legs fit the walker");
  static_assert(kChannels.count == kJoints, "the model's channels fit the servo stage");
};
template <uint8_t r, typename S>
constexpr StrideTable<true> FirmwareProfile<r, S>::kStrides;
template <uint8_t r, typename S>
constexpr GaitConfig<S, FirmwareProfile<r, S>::kLegs, false> FirmwareProfile<r, S>::kGaitConfig;
template <uint8_t r, typename S>
constexpr WalkerLegs<S, FirmwareProfile<r, S>::kLegs, FirmwareProfile<r, S>::kSolvers> FirmwareProfile<r, S>::kWalkerLegsInFlash;
template <uint8_t r, typename S>
constexpr JointChannels<S, FirmwareProfile<r, S>::kJoints, FirmwareProfile<r, S>::kTickSlots> FirmwareProfile<r, S>::kChannels;
template <uint8_t r, typename S>
constexpr GaitName FirmwareProfile<r, S>::kDefaultGait;

}  // namespace strider

#endif  // STRIDER_CONTROL_FIRMWARE_PROFILE_H
