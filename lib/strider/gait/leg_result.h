//! What the walker reports per leg each tick (LegResult): joints, status and
//! contact; for host tools (a profile's kFeet) also the target, the foot
//! reached, the IK's own status and the clamp (docs/gaits.md, "2-DOF legs").
#ifndef STRIDER_GAIT_LEG_RESULT_H
#define STRIDER_GAIT_LEG_RESULT_H

#include "../kinematics/any_leg.h"

namespace strider {

//! A 2-DOF foot moved by more than this counts as clamped [mm].
constexpr double kClampToleranceMm = 0.5;

//! What a LegResult keeps for host tools (kFeet).
template <typename S, bool kFeet>
struct LegFeet {
  Vec3<S> target_mm;                //!< engine target, body frame [mm]
  Vec3<S> foot_mm;                  //!< foot the joints reach, body frame [mm]
  IkStatus ik_status;               //!< IK of the projected target
  S clamp_mm;                       //!< how far the projection moved the target [mm]
};
template <typename S>
struct LegFeet<S, false> {};
//! Where Walker::tick() keeps a leg's target and foot when its result does not (!kFeet).
template <typename S, bool kFeet>
struct LegScratch {};
template <typename S>
struct LegScratch<S, false> {
  Vec3<S> target_mm;
  Vec3<S> foot_mm;
};

template <typename S, bool kFeet = true>
struct LegResult : LegFeet<S, kFeet> {
  typename AnyLeg<S>::Joints q;     //!< joints, seed convention [rad]
  IkStatus status;                  //!< worst of the IK status and the clamp
  bool contact;                     //!< foot on the ground
};

//! Where the walker keeps a leg's body-frame target and reached foot: in
//! its result (kFeet) or in the scratch; what only a result with feet keeps.
template <typename S>
Vec3<S>& target_of(LegFeet<S, true>& r, LegScratch<S, true>&) { return r.target_mm; }
template <typename S>
Vec3<S>& target_of(LegFeet<S, false>&, LegScratch<S, false>& s) { return s.target_mm; }
template <typename S>
Vec3<S>& foot_of(LegFeet<S, true>& r, LegScratch<S, true>&) { return r.foot_mm; }
template <typename S>
Vec3<S>& foot_of(LegFeet<S, false>&, LegScratch<S, false>& s) { return s.foot_mm; }
template <typename S>
void set_ik_status(LegFeet<S, true>& r, IkStatus ik) { r.ik_status = ik; }
template <typename S>
void set_ik_status(LegFeet<S, false>&, IkStatus) {}
template <typename S>
void set_clamp(LegFeet<S, true>& r, S clamp_mm) { r.clamp_mm = clamp_mm; }
template <typename S>
void set_clamp(LegFeet<S, false>&, S) {}

}  // namespace strider

#endif  // STRIDER_GAIT_LEG_RESULT_H
