//! spider12: the 12-DOF quadruped of seed 004 (Essilfie-Quaye): hip yaw,
//! hip elevation and knee per leg, legs spread like a spider's. Seed 004
//! gives no sizes: those of the common open-source MG90S "spider" robot, on
//! a coxa/femur/tibia leg with d1 = 0 (docs/robots.md, "spider12").
#ifndef STRIDER_ROBOTS_SPIDER12_H
#define STRIDER_ROBOTS_SPIDER12_H

#include "model_checks.h"

namespace strider {
namespace spider12_detail {

constexpr float kHalfSide = 35.5f;  //!< half the 71 mm hip square [mm]

// Joint limits [deg], seed 002 convention (coxa t1, femur t2, tibia t3).
constexpr JointRange kHipYaw = {-40.0f, 40.0f};
constexpr JointRange kHipElevation = {-60.0f, 90.0f};
constexpr JointRange kKnee = {-150.0f, -20.0f};

// Standing foot, leg frame [mm]: 90 out, 50 down.
constexpr double kStandX = 90.0;
constexpr double kStandZ = -50.0;

constexpr LegModel leg(const char* name, BodySide side, float x, float y, float yaw_deg) {
  return leg_model(name, side, Vec3<float>(x, y, 0.0f), yaw_deg, kHipYaw, kHipElevation, kKnee, kStandX, 0.0,
                   kStandZ);
}

}  // namespace spider12_detail

constexpr RobotModel kSpider12 = {
    "spider12",
    4,
    LegKind::kCoxaFemurTibia,
    4,
    {27.5f, 55.0f, 77.5f, 0.0f},  // coxa, femur, tibia, d1 (chosen, see above)
    {71.0f, 71.0f, 30.0f, 0.45f},  // the hip square; height and mass estimated
    {ServoPart::kMg90s, ServoPart::kMg90s, ServoPart::kMg90s},
    {
        spider12_detail::leg("front_left", BodySide::kLeft, spider12_detail::kHalfSide, spider12_detail::kHalfSide,
                             45.0f),
        spider12_detail::leg("rear_left", BodySide::kLeft, -spider12_detail::kHalfSide, spider12_detail::kHalfSide,
                             135.0f),
        spider12_detail::leg("rear_right", BodySide::kRight, -spider12_detail::kHalfSide,
                             -spider12_detail::kHalfSide, -135.0f),
        spider12_detail::leg("front_right", BodySide::kRight, spider12_detail::kHalfSide,
                             -spider12_detail::kHalfSide, -45.0f),
    },
};

static_assert(model_valid(kSpider12), "spider12: a model_checks.h invariant fails");

}  // namespace strider

#endif  // STRIDER_ROBOTS_SPIDER12_H
