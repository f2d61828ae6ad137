//! spider12: the 12-DOF quadruped of seed 004 (Essilfie-Quaye): hip yaw,
//! hip elevation and knee per leg, legs spread like a spider's.
//!
//! Seed 004 gives the joint order and the IK but no sizes. Strider takes the
//! sizes of the common open-source MG90S/SG90 "spider" quadruped (the
//! Instructables/GitHub Arduino spider robot): coxa 27.5 mm, femur 55 mm,
//! tibia 77.5 mm, hip yaw axes on a 71 mm square, standing foot about
//! 88 mm out from the hip axis and 50 mm down. The leg type is the coxa/femur/
//! tibia leg (seed 002 frame, eqs 5-7) with d1 = 0: the hip elevation axis is
//! level with the leg frame origin. Seed 004's own angles (knee measured
//! from the femur, hip elevation from the vertical) map onto it one to one
//! (docs/kinematics.md).
//!
//! Legs counter-clockwise from front left: 0 front left, 1 rear left,
//! 2 rear right, 3 front right; each points out along its body diagonal.
#ifndef STRIDER_ROBOTS_SPIDER12_H
#define STRIDER_ROBOTS_SPIDER12_H

#include "model_checks.h"

namespace strider {
namespace spider12_detail {

constexpr float kHalfSide = 35.5f;  //!< half the 71 mm hip square [mm]

// Joint limits [deg], seed 002 convention (coxa t1, femur t2, tibia t3):
// - t1 (hip yaw): +-40 deg about the diagonal: the legs 90 deg apart never
//   meet, and a crawl's 40-60 mm stride needs about +-20 deg.
// - t2 (hip elevation): -60 to +90 deg; standing needs +28 deg.
// - t3 (knee): -150 to -20 deg; standing -108 deg; -150 is the bracket
//   stop, -20 keeps clear of the straight-leg singularity.
// 150 and 130 deg of the MG90S's 180 deg travel.
constexpr JointRange kHipYaw = {-40.0f, 40.0f};
constexpr JointRange kHipElevation = {-60.0f, 90.0f};
constexpr JointRange kKnee = {-150.0f, -20.0f};

// Standing foot, leg frame [mm]: 90 out, 50 down (t2 = +28.45 deg,
// t3 = -107.93 deg); the open-source spider stands at 88 out, 50 down.
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
    // Body: the 71 mm hip square, 30 mm tall (estimate). Mass 0.45 kg
    // (estimate: 12 MG90S 161 g, printed body and legs 120 g, Mega 37 g,
    // PCA9685 10 g, 2S 800 mAh battery 50 g, wiring and sensor 40 g).
    {71.0f, 71.0f, 30.0f, 0.45f},
    // MG90S on every joint (the open-source spider's part). In a creep gait
    // (three feet down) each hip elevation servo holds 0.15 kg at 62.5 mm,
    // 0.94 kg cm, 43 % of its 2.2 kg cm stall torque; the knee 0.2 kg cm.
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

static_assert(model_checks::links_valid(kSpider12), "spider12: link lengths");
static_assert(model_checks::joint_ranges_valid(kSpider12), "spider12: joint ranges");
static_assert(model_checks::sides_consistent(kSpider12), "spider12: sides");
static_assert(model_checks::mirror_symmetric(kSpider12), "spider12: left/right symmetry");
static_assert(model_checks::numbered_counter_clockwise(kSpider12), "spider12: leg order");
static_assert(model_checks::stands_in_workspace(kSpider12), "spider12: standing pose reachable");
static_assert(model_checks::unused_slots_empty(kSpider12), "spider12: unused leg slots");

}  // namespace strider

#endif  // STRIDER_ROBOTS_SPIDER12_H
