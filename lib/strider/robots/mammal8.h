//! mammal8: the 8-DOF mammal-type quadruped of seed 003 (Srinivas et al.
//! 2021, "Valkyrie"): hip pitch and knee per leg, legs under the body.
//! Where each value comes from: docs/robots.md, "mammal8".
#ifndef STRIDER_ROBOTS_MAMMAL8_H
#define STRIDER_ROBOTS_MAMMAL8_H

#include "model_checks.h"

namespace strider {
namespace mammal8_detail {

// Mounts [mm]: the body's corners, in its mid plane; every leg faces forward.
constexpr float kHalfLength = 75.0f;
constexpr float kHalfWidth = 45.0f;

// Joint limits [deg], seed 003 convention (eq 3).
constexpr JointRange kHip = {-170.0f, -40.0f};
constexpr JointRange kKnee = {20.0f, 150.0f};
constexpr JointRange kUnused = {0.0f, 0.0f};

// Standing foot, leg frame [mm]: straight under the hip, 110 mm down.
constexpr double kStandZ = -110.0;

constexpr LegModel leg(const char* name, BodySide side, float x, float y) {
  return leg_model(name, side, Vec3<float>(x, y, 0.0f), 0.0f, kHip, kKnee, kUnused, 0.0, 0.0, kStandZ);
}

}  // namespace mammal8_detail

constexpr RobotModel kMammal8 = {
    "mammal8",
    3,
    LegKind::kPlanar,
    4,
    {70.0f, 70.0f, 0.0f, 0.0f},  // a1, a2 (seed 003 table 1)
    {150.0f, 90.0f, 30.0f, 1.5f},  // seed 003 table 1
    // MG996R (seed 003 eq 8's 11 kg cm). Slot 2 is unused.
    {ServoPart::kMg996r, ServoPart::kMg996r, ServoPart::kMg996r},
    {
        mammal8_detail::leg("front_left", BodySide::kLeft, mammal8_detail::kHalfLength, mammal8_detail::kHalfWidth),
        mammal8_detail::leg("rear_left", BodySide::kLeft, -mammal8_detail::kHalfLength, mammal8_detail::kHalfWidth),
        mammal8_detail::leg("rear_right", BodySide::kRight, -mammal8_detail::kHalfLength,
                            -mammal8_detail::kHalfWidth),
        mammal8_detail::leg("front_right", BodySide::kRight, mammal8_detail::kHalfLength,
                            -mammal8_detail::kHalfWidth),
    },
};

static_assert(model_valid(kMammal8), "mammal8: a model_checks.h invariant fails");
static_assert(2.0f * mammal8_detail::kHalfLength == kMammal8.body.length_mm &&
                  2.0f * mammal8_detail::kHalfWidth == kMammal8.body.width_mm,
              "mammal8: hips at the body corners");

}  // namespace strider

#endif  // STRIDER_ROBOTS_MAMMAL8_H
