//! What the walker reports per leg each tick (LegResult): joints, status and
//! contact; for host tools (a profile's kFeet) also the target, the foot
//! reached, the IK's own status and the clamp (docs/gaits.md, "2-DOF legs").
#ifndef STRIDER_GAIT_LEG_RESULT_H
#define STRIDER_GAIT_LEG_RESULT_H

#include "../kinematics/any_leg.h"

namespace strider {

//! A 2-DOF foot moved by more than this counts as clamped [mm].
constexpr double kClampToleranceMm = 0.5;

//! Where Walker::tick() keeps a leg's target and foot when its result does not (!kFeet).
template <typename S, bool kFeet>
struct LegScratch {};
template <typename S>
struct LegScratch<S, false> {
  Vec3<S> target_mm;
  Vec3<S> foot_mm;
};

//! What a LegResult keeps for host tools (kFeet); target() and foot(): the
//! leg's body-frame target and reached foot, kept here or in the scratch.
template <typename S, bool kFeet>
struct LegFeet {
  Vec3<S> target_mm;                //!< engine target, body frame [mm]
  Vec3<S> foot_mm;                  //!< foot the joints reach, body frame [mm]
  IkStatus ik_status;               //!< IK of the projected target
  S clamp_mm;                       //!< how far the projection moved the target [mm]
  Vec3<S>& target(LegScratch<S, true>&) { return target_mm; }
  Vec3<S>& foot(LegScratch<S, true>&) { return foot_mm; }
  void set_ik_status(IkStatus ik) { ik_status = ik; }
  void set_clamp(S mm) { clamp_mm = mm; }
};
template <typename S>
struct LegFeet<S, false> {
  Vec3<S>& target(LegScratch<S, false>& s) { return s.target_mm; }
  Vec3<S>& foot(LegScratch<S, false>& s) { return s.foot_mm; }
  void set_ik_status(IkStatus) {}
  void set_clamp(S) {}
};

template <typename S, bool kFeet = true>
struct LegResult : LegFeet<S, kFeet> {
  typename AnyLeg<S>::Joints q;     //!< joints, seed convention [rad]
  IkStatus status;                  //!< worst of the IK status and the clamp
  bool contact;                     //!< foot on the ground
};

}  // namespace strider

#endif  // STRIDER_GAIT_LEG_RESULT_H
