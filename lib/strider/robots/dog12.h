//! dog12: the 12-DOF quadruped of seed 001 (Shahriar): abduction, hip and
//! knee per leg. Where each value comes from: docs/robots.md, "dog12".
#ifndef STRIDER_ROBOTS_DOG12_H
#define STRIDER_ROBOTS_DOG12_H

#include "model_checks.h"

namespace strider {
namespace dog12_detail {

// Mounts [mm]: the body's corners, in its mid plane; every leg faces forward.
constexpr float kHalfLength = 300.0f;
constexpr float kHalfWidth = 140.0f;

// Standing foot, leg frame [mm]: straight under the hip, La outward, 350 mm down.
constexpr double kStandZ = -350.0;
constexpr double kLa = 44.0;

// Joint limits [deg], seed 001 convention; t1 is +-70 deg about the standing
// value (left 0, right 180).
constexpr JointRange kHip = {-40.0f, 120.0f};
constexpr JointRange kKnee = {15.0f, 160.0f};

constexpr LegModel leg(const char* name, BodySide side, float x, float y) {
  return side == BodySide::kLeft
             ? leg_model(name, side, Vec3<float>(x, y, 0.0f), 0.0f, {-70.0f, 70.0f}, kHip, kKnee, 0.0, kLa,
                         kStandZ)
             : leg_model(name, side, Vec3<float>(x, y, 0.0f), 0.0f, {110.0f, 250.0f}, kHip, kKnee, 0.0, -kLa,
                         kStandZ);
}

}  // namespace dog12_detail

constexpr RobotModel kDog12 = {
    "dog12",
    1,
    LegKind::kAbduction,
    4,
    {44.0f, 280.0f, 277.0f, 0.0f},  // La, Lb, Lc (seed 001 table 4)
    {600.0f, 280.0f, 277.0f, 5.2f},  // bl x bw x bh (seed 001 table 4); mass estimated
    {ServoPart::kDs5160, ServoPart::kDs5160, ServoPart::kDs5160},
    {
        dog12_detail::leg("front_left", BodySide::kLeft, dog12_detail::kHalfLength, dog12_detail::kHalfWidth),
        dog12_detail::leg("rear_left", BodySide::kLeft, -dog12_detail::kHalfLength, dog12_detail::kHalfWidth),
        dog12_detail::leg("rear_right", BodySide::kRight, -dog12_detail::kHalfLength, -dog12_detail::kHalfWidth),
        dog12_detail::leg("front_right", BodySide::kRight, dog12_detail::kHalfLength, -dog12_detail::kHalfWidth),
    },
};

static_assert(model_valid(kDog12), "dog12: a model_checks.h invariant fails");
static_assert(kDog12.links.l1_mm == float(dog12_detail::kLa), "dog12: stance uses La");

}  // namespace strider

#endif  // STRIDER_ROBOTS_DOG12_H
