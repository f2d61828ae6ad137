//! The leg models the benchmark and the bit-exact test exercise, one factory
//! per leg type that exists in lib/strider/kinematics (leg types added later
//! are picked up by __has_include), plus the shared joint grid and targets.
#ifndef STRIDER_TOOLS_BENCH_LEGS_H
#define STRIDER_TOOLS_BENCH_LEGS_H

#include <stdint.h>

#include "bench_inputs.h"
#include "kinematics/joints.h"
#include "kinematics/sprawl_leg.h"
#include "math/vec3.h"

#if __has_include("kinematics/planar_leg.h")
#include "kinematics/planar_leg.h"
#define STRIDER_BENCH_HAS_PLANAR_LEG 1
#else
#define STRIDER_BENCH_HAS_PLANAR_LEG 0
#endif
#if __has_include("kinematics/coxa_femur_tibia_leg.h")
#include "kinematics/coxa_femur_tibia_leg.h"
#define STRIDER_BENCH_HAS_CFT_LEG 1
#else
#define STRIDER_BENCH_HAS_CFT_LEG 0
#endif
#if __has_include("kinematics/abduction_leg.h")
#include "kinematics/abduction_leg.h"
#define STRIDER_BENCH_HAS_ABDUCTION_LEG 1
#else
#define STRIDER_BENCH_HAS_ABDUCTION_LEG 0
#endif

namespace strider_bench {

//! A raw Q16.16 value in scalar S (exact for Fixed; for float exact below 2^24).
template <class S> S from_raw(int32_t raw);
template <> inline float from_raw<float>(int32_t raw) { return float(raw) * (1.0f / 65536.0f); }
template <> inline strider::Fixed from_raw<strider::Fixed>(int32_t raw) { return strider::Fixed::from_raw(raw); }

//! Target i of the seed 002 table [mm].
template <class S>
strider::Vec3<S> hex_target(uint8_t i) {
  return strider::Vec3<S>(from_raw<S>(qmm_to_raw(read_i16(&kHexTargetsQmm[i][0]))),
                          from_raw<S>(qmm_to_raw(read_i16(&kHexTargetsQmm[i][1]))),
                          from_raw<S>(qmm_to_raw(read_i16(&kHexTargetsQmm[i][2]))));
}

//! Grid point i (0..47) as joint angles [rad]; 2-DOF legs take the first two
//! angles and spread the third over the second (+0.1 rad steps).
template <class S, uint8_t N>
void grid_joints(uint8_t i, strider::JointVector<S, N>& q) {
  int32_t raw[3];
  grid_joints_raw(i, raw);
  if (N == 2) raw[1] += int32_t(i % 3) * 6554;
  for (uint8_t j = 0; j < N; ++j) q[j] = from_raw<S>(raw[j < 3 ? j : 2]);
}

// Seed 000 sprawl8: thigh a1 = 55 mm, leg a2 = 90 mm.
template <class S>
strider::SprawlLeg<S> make_sprawl_leg() {
  return strider::SprawlLeg<S>{strider::scalar<S>(55.0), strider::scalar<S>(90.0),
                               strider::JointLimits<S, 2>::unlimited()};
}

#if STRIDER_BENCH_HAS_PLANAR_LEG
// Seed 003 mammal8: a1 = a2 = 70 mm.
template <class S>
strider::PlanarLeg<S> make_planar_leg() {
  return strider::PlanarLeg<S>::make(strider::scalar<S>(70.0), strider::scalar<S>(70.0),
                                     strider::JointLimits<S, 2>::unlimited());
}
#endif

#if STRIDER_BENCH_HAS_CFT_LEG
// Seed 002 hexapod18: d1 32, coxa 30, femur 85, tibia 125 mm.
template <class S>
strider::CoxaFemurTibiaLeg<S> make_hexapod_leg() {
  return strider::CoxaFemurTibiaLeg<S>::make(
      strider::scalar<S>(double(kHexD1Mm)), strider::scalar<S>(double(kHexCoxaMm)),
      strider::scalar<S>(double(kHexFemurMm)), strider::scalar<S>(double(kHexTibiaMm)),
      strider::JointLimits<S, 3>::unlimited());
}
#endif

//! IK target i (0..47) of a leg: its own FK over the joint grid, so every
//! leg type gets points of its workspace in its own convention.
template <class Leg>
auto workspace_target(const Leg& leg, uint8_t i) -> decltype(leg.fk(typename Leg::Joints())) {
  typename Leg::Joints q;
  grid_joints(i, q);
  return leg.fk(q);
}

#if STRIDER_BENCH_HAS_CFT_LEG
//! The hexapod leg uses the seed 002 table, independent of the code under test.
template <class S>
strider::Vec3<S> workspace_target(const strider::CoxaFemurTibiaLeg<S>&, uint8_t i) {
  return hex_target<S>(i);
}
#endif

#if STRIDER_BENCH_HAS_ABDUCTION_LEG
// Seed 001 dog12: La 44, Lb 280, Lc 277 mm.
template <class S>
strider::AbductionLeg<S> make_abduction_leg() {
  return strider::AbductionLeg<S>::make(strider::scalar<S>(44.0), strider::scalar<S>(280.0),
                                        strider::scalar<S>(277.0), strider::JointLimits<S, 3>::unlimited());
}
#endif

}  // namespace strider_bench

#endif  // STRIDER_TOOLS_BENCH_LEGS_H
