//! A build's profile: the compile-time choices that size its walker, servo
//! stage and RobotApp; HostProfile is every host build's default (a
//! firmware's: control/firmware_profile.h).
#ifndef STRIDER_ROBOTS_BUILD_PROFILE_H
#define STRIDER_ROBOTS_BUILD_PROFILE_H

#include <stdint.h>

#include "robot_model.h"

namespace strider {

//! A build for every model (the host's), where a firmware names its own.
constexpr uint8_t kEveryModel = 0xff;

//! The host's profile, for any model.
template <typename S>
struct HostProfile {
  using Scalar = S;
  static constexpr uint8_t kLegs = kMaxLegs;
  //! Leg solvers: one per leg, or fewer shared by legs of one geometry.
  static constexpr uint8_t kSolvers = kLegs;
  //! The leg results keep each leg's target, foot, IK status and clamp.
  static constexpr bool kFeet = true;
  //! Servo tick-map ranges shared by a slot's joints (0: one per joint).
  static constexpr uint8_t kTickSlots = 0;
  static constexpr uint8_t kJoints = kMaxLegs * kMaxLegDof;  //!< most servos driven
  //! Velocity limits by the IK search, strides in RAM (else stored, in flash).
  static constexpr bool kSearch = true;
  //! The model the build is for: per-model tables keep its entries only
  //! (robots/model_entries.h); kEveryModel keeps them all.
  static constexpr uint8_t kModelIndex = kEveryModel;
};

}  // namespace strider

#endif  // STRIDER_ROBOTS_BUILD_PROFILE_H
