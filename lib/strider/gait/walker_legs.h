//! The walker's leg storage: an AnyLeg per leg, or one IK solver per leg
//! geometry with each leg's mount and side (the profile's kSolvers).
#ifndef STRIDER_GAIT_WALKER_LEGS_H
#define STRIDER_GAIT_WALKER_LEGS_H

#include "../kinematics/any_leg.h"

namespace strider {

//! Legs i and j of `model` solve alike: same joint limits (and side).
constexpr bool same_leg_solver(const RobotModel& model, uint8_t i, uint8_t j) {
  const LegModel& a = model.legs[i];
  const LegModel& b = model.legs[j];
  if (model.kind == LegKind::kAbduction && a.side != b.side) return false;
  for (uint8_t k = 0; k < kMaxLegDof; ++k)
    if (!(a.joint[k].min_deg == b.joint[k].min_deg) || !(a.joint[k].max_deg == b.joint[k].max_deg)) return false;
  return true;
}
//! The first leg of `model` that solves like leg i.
constexpr uint8_t leg_solver_of(const RobotModel& model, uint8_t i) {
  uint8_t j = 0;
  while (j < i && !same_leg_solver(model, i, j)) ++j;
  return j;
}
//! How many distinct leg solvers the legs before leg `end` of `model` need.
constexpr uint8_t leg_solver_count(const RobotModel& model, uint8_t end = kMaxLegs) {
  uint8_t n = 0;
  for (uint8_t i = 0; i < model.leg_count && i < end; ++i)
    if (leg_solver_of(model, i) == i) ++n;
  return n;
}
//! The index of leg i's solver among `model`'s leg solvers.
constexpr uint8_t leg_solver_index(const RobotModel& model, uint8_t i) {
  return leg_solver_count(model, leg_solver_of(model, i));
}
//! The first leg of `model`'s leg solver n (model.leg_count when there is none).
constexpr uint8_t leg_of_solver(const RobotModel& model, uint8_t n) {
  for (uint8_t i = 0; i < model.leg_count && i < kMaxLegs; ++i)
    if (leg_solver_of(model, i) == i && n-- == 0) return i;
  return model.leg_count;
}

namespace walker_detail {

//! The legs of a model: an AnyLeg per leg.
template <typename S, uint8_t kLegs, uint8_t kSolvers, bool kShared = (kSolvers < kLegs)>
struct LegSolvers {
  static_assert(kSolvers >= 1 && kSolvers <= kLegs, "kSolvers: 1 to kLegs");
  static bool fits(const RobotModel& model) { return model.leg_count <= kLegs; }
  void build(const RobotModel& model) {  // legs past the model's are left as they are, unused
    for (uint8_t i = 0; i < model.leg_count; ++i) AnyLeg<S>::from_model(model, i, legs[i]);
  }
  const AnyLeg<S>& solver(uint8_t i) const { return legs[i]; }
  const LegMount<S>& mount(uint8_t i) const { return legs[i].mount(); }
  AnyLeg<S> leg(uint8_t i) const { return legs[i]; }
  const AnyLeg<S>* per_leg() const { return legs; }

  AnyLeg<S> legs[kLegs];
};
//! The legs of a model whose legs share kSolvers geometries: a solver per
//! geometry, each leg's mount and side.
template <typename S, uint8_t kLegs, uint8_t kSolvers>
struct LegSolvers<S, kLegs, kSolvers, true> {
  static bool fits(const RobotModel& model) { return model.leg_count <= kLegs && leg_solver_count(model) <= kSolvers; }
  void build(const RobotModel& model) {
    for (uint8_t n = 0; n < kSolvers; ++n) AnyLeg<S>::from_model(model, leg_of_solver(model, n), solvers[n]);
    for (uint8_t i = 0; i < kLegs; ++i) {
      const bool used = i < model.leg_count;
      mounts[i] = used ? AnyLeg<S>::mount_of(model, i) : LegMount<S>::make(Vec3<S>(), S(0));
      sides[i] = used ? model.legs[i].side : BodySide::kLeft;
      of[i] = used ? leg_solver_index(model, i) : uint8_t(0);
    }
  }
  const AnyLeg<S>& solver(uint8_t i) const { return solvers[of[i]]; }
  const LegMount<S>& mount(uint8_t i) const { return mounts[i]; }
  AnyLeg<S> leg(uint8_t i) const { return solvers[of[i]].placed(mounts[i], sides[i]); }
  const AnyLeg<S>* per_leg() const { return nullptr; }  // none kept

  AnyLeg<S> solvers[kSolvers];  // the mount each holds is its first leg's, never read
  LegMount<S> mounts[kLegs];
  BodySide sides[kLegs] = {};
  uint8_t of[kLegs] = {};  // leg -> its solver
};

}  // namespace walker_detail

}  // namespace strider

#endif  // STRIDER_GAIT_WALKER_LEGS_H
