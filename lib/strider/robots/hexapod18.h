//! hexapod18: the 18-DOF hexapod of seed 002 (Qingsheng and Andika 2018).
//!
//! Seed 002 table 3 and fig. 2: d1 = 32 mm (bottom plate to the femur
//! axis), coxa 30 mm, femur 85 mm, tibia 125 mm; a rectangular body of
//! 175 x 155 mm with six leg joints; table 1: 12 MG995 (femur, tibia: they
//! carry the weight) and 6 HS-311 (coxa: swings only). Leg frame: DH frame 0
//! of seed 002 (table 2, eqs 5-7), origin on the coxa axis in the plane of
//! the bottom plate, x along the leg at t1 = 0, z up.
//!
//! Legs counter-clockwise from front left: 0 front left, 1 middle left,
//! 2 rear left, 3 rear right, 4 middle right, 5 front right (seed 002's legs
//! 1-6; its tables 5 and 8, the middle legs 2 and 5, test feet on both sides
//! of the leg axis, y = -30..40 mm). Tripods: {0, 2, 4} and {1, 3, 5}.
#ifndef STRIDER_ROBOTS_HEXAPOD18_H
#define STRIDER_ROBOTS_HEXAPOD18_H

#include "model_checks.h"

namespace strider {
namespace hexapod18_detail {

// Mounts [mm]: corner legs at the corners of the 175 x 155 mm plate, middle
// legs at the middle of the long sides (the seed gives no joint coordinates).
// The bottom plate, the leg frames' plane, is 20 mm under the body centre
// (body 40 mm tall, estimate), so the femur axes sit 12 mm above it.
constexpr float kHalfLength = 87.5f;
constexpr float kHalfWidth = 77.5f;
constexpr float kPlateZ = -20.0f;

// Joint limits [deg], seed 002 convention (eqs 5-7, "t3 negative"):
// - t1 (coxa, HS-311): +-40 deg about the leg's mount direction. Covers
//   every foot of seed 002 tables 4-9 (-23 to +28 deg) and keeps a corner
//   leg and its middle neighbour (45 deg apart) from sweeping through
//   each other's home.
// - t2 (femur, MG995): -60 to +90 deg. Tables 4-9 need up to +74 deg
//   (foot at z = +20 mm); standing needs +2 deg; -60 lets the foot reach
//   under the body when climbing down.
// - t3 (tibia, MG995): -150 to -20 deg. The tables need -115 to -136 deg,
//   standing -90 deg; -150 is where the tibia bracket meets the femur and
//   -20 keeps the knee off the straight-leg singularity (acos near 1).
constexpr JointRange kCoxa = {-40.0f, 40.0f};
constexpr JointRange kFemur = {-60.0f, 90.0f};
constexpr JointRange kTibia = {-150.0f, -20.0f};

// Standing foot, leg frame [mm]: femur level, tibia vertical: 120 mm out
// from the coxa axis, 90 mm under the bottom plate (t2 = +1.95 deg,
// t3 = -89.64 deg): body 90 mm off the ground.
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
    // 175 x 155 mm plate (seed 002); 40 mm tall (estimate). Mass 1.8 kg
    // (estimate: 12 MG995 660 g, 6 HS-311 258 g, aluminium plates and 18
    // brackets 450 g, 2S 3300 mAh battery 200 g, Mega, 3 UBECs, servo boards).
    {175.0f, 155.0f, 40.0f, 1.8f},
    // Seed 002 table 1. In a tripod gait each femur servo holds 0.6 kg at
    // 90 mm, 5.4 kg cm, 54 % of the MG995's 10 kg cm stall torque.
    {ServoPart::kHs311, ServoPart::kMg995, ServoPart::kMg995},
    {
        // Corner legs point out along 45 deg diagonals, middle legs sideways.
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

static_assert(model_checks::links_valid(kHexapod18), "hexapod18: link lengths");
static_assert(model_checks::joint_ranges_valid(kHexapod18), "hexapod18: joint ranges");
static_assert(model_checks::sides_consistent(kHexapod18), "hexapod18: sides");
static_assert(model_checks::mirror_symmetric(kHexapod18), "hexapod18: left/right symmetry");
static_assert(model_checks::numbered_counter_clockwise(kHexapod18), "hexapod18: leg order");
static_assert(model_checks::stands_in_workspace(kHexapod18), "hexapod18: standing pose reachable");
static_assert(model_checks::unused_slots_empty(kHexapod18), "hexapod18: unused leg slots");
static_assert(2.0f * hexapod18_detail::kHalfLength == kHexapod18.body.length_mm &&
                  2.0f * hexapod18_detail::kHalfWidth == kHexapod18.body.width_mm,
              "hexapod18: legs on the plate's edge");

}  // namespace strider

#endif  // STRIDER_ROBOTS_HEXAPOD18_H
