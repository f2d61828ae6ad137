//! hexapod18: the 18-DOF hexapod of seed 002 (Qingsheng and Andika 2018).
//! Where each value comes from: docs/robots.md, "hexapod18".
#ifndef STRIDER_ROBOTS_HEXAPOD18_H
#define STRIDER_ROBOTS_HEXAPOD18_H

#include "model_checks.h"

namespace strider {
namespace hexapod18_detail {

// Mounts [mm]: corner legs at the plate's corners, middle legs at the middle
// of its long sides; the plate 20 mm under the body centre.
constexpr float kHalfLength = 87.5f;
constexpr float kHalfWidth = 77.5f;
constexpr float kPlateZ = -20.0f;

// Joint limits [deg], seed 002 convention (eqs 5-7, "t3 negative").
constexpr JointRange kCoxa = {-40.0f, 40.0f};
constexpr JointRange kFemur = {-60.0f, 90.0f};
constexpr JointRange kTibia = {-150.0f, -20.0f};

// Standing foot, leg frame [mm]: femur level, tibia vertical.
constexpr double kStandX = 120.0;
constexpr double kStandZ = -90.0;

constexpr LegModel leg(const char* name, BodySide side, float x, float y, float yaw_deg) {
  return leg_model(name, side, Vec3<float>(x, y, kPlateZ), yaw_deg, kCoxa, kFemur, kTibia, kStandX, 0.0, kStandZ);
}

}  // namespace hexapod18_detail

constexpr RobotModel kHexapod18 = {
    "hexapod18",
    2,
    LegKind::kCoxaFemurTibia,
    6,
    {30.0f, 85.0f, 125.0f, 32.0f},  // coxa, femur, tibia, d1 (seed 002 table 3)
    {175.0f, 155.0f, 40.0f, 1.8f},  // plate (seed 002); height and mass estimated
    {ServoPart::kHs311, ServoPart::kMg995, ServoPart::kMg995},  // seed 002 table 1
    {
        hexapod18_detail::leg("front_left", BodySide::kLeft, hexapod18_detail::kHalfLength,
                              hexapod18_detail::kHalfWidth, 45.0f),
        hexapod18_detail::leg("middle_left", BodySide::kLeft, 0.0f, hexapod18_detail::kHalfWidth, 90.0f),
        hexapod18_detail::leg("rear_left", BodySide::kLeft, -hexapod18_detail::kHalfLength,
                              hexapod18_detail::kHalfWidth, 135.0f),
        hexapod18_detail::leg("rear_right", BodySide::kRight, -hexapod18_detail::kHalfLength,
                              -hexapod18_detail::kHalfWidth, -135.0f),
        hexapod18_detail::leg("middle_right", BodySide::kRight, 0.0f, -hexapod18_detail::kHalfWidth, -90.0f),
        hexapod18_detail::leg("front_right", BodySide::kRight, hexapod18_detail::kHalfLength,
                              -hexapod18_detail::kHalfWidth, -45.0f),
    },
};

static_assert(model_valid(kHexapod18), "hexapod18: a model_checks.h invariant fails");
static_assert(2.0f * hexapod18_detail::kHalfLength == kHexapod18.body.length_mm &&
                  2.0f * hexapod18_detail::kHalfWidth == kHexapod18.body.width_mm,
              "hexapod18: legs on the plate's edge");

}  // namespace strider

#endif  // STRIDER_ROBOTS_HEXAPOD18_H
