//! mammal8: the 8-DOF mammal-type quadruped of seed 003 (Srinivas et al.
//! 2021, "Valkyrie"): hip pitch and knee per leg, legs under the body.
//!
//! Seed 003 table 1: links a1 = a2 = 70 mm, body 150 x 90 x 30 mm, 1.5 kg;
//! eq 8 uses an 11 kg cm servo torque, the MG996R's 6 V stall torque. Leg
//! frame: seed 003's DH frame in Strider's axes (kinematics/planar_leg.h):
//! origin on the hip axis, x forward, z up; the leg moves in its x-z plane,
//! t1 = -90 deg hangs the thigh straight down, t2 > 0 (eq 5's acos, the
//! default knee branch) puts the knee behind the hip-foot line.
//!
//! Legs counter-clockwise from front left: 0 front left, 1 rear left,
//! 2 rear right, 3 front right. Trot pairs {0, 2} and {1, 3}; pace pairs
//! {0, 1} and {2, 3} (seed 003 section 4.1).
#ifndef STRIDER_ROBOTS_MAMMAL8_H
#define STRIDER_ROBOTS_MAMMAL8_H

#include "model_checks.h"

namespace strider {
namespace mammal8_detail {

// Mounts [mm]: hip axes at the corners of the 150 x 90 mm body, in the
// body's mid plane; every leg frame faces forward (yaw 0).
constexpr float kHalfLength = 75.0f;
constexpr float kHalfWidth = 45.0f;

// Joint limits [deg], seed 003 convention (eq 3). Seed 003 table 1 gives
// 0 <= t1, t2 <= 20 deg: those are its PSO's search bounds (algorithm 1
// seeds the swarm in [0, 20]); in the frame of eq 3 they would hold the leg
// out horizontally, so they cannot be the mechanical limits. Chosen instead:
// - t1 (hip pitch): -170 to -40 deg: the thigh from 80 deg behind straight
//   down to 50 deg in front of it; standing -128 deg.
// - t2 (knee): +20 to +150 deg: 20 deg keeps clear of the straight-leg
//   singularity, 150 deg folds the foot to 36 mm from the hip; standing
//   +76 deg. 130 deg of the MG996R's 180 each.
constexpr JointRange kHip = {-170.0f, -40.0f};
constexpr JointRange kKnee = {20.0f, 150.0f};
constexpr JointRange kUnused = {0.0f, 0.0f};

// Standing foot, leg frame [mm]: straight under the hip, 110 mm down (79 % of
// the 140 mm leg): t1 = -128.2 deg, t2 = +76.4 deg.
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
    // MG996R (seed 003 eq 8's 11 kg cm). In a trot each knee holds 0.75 kg
    // at 43 mm, 3.2 kg cm, 30 % of its stall torque. Slot 2 is unused.
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

static_assert(model_checks::links_valid(kMammal8), "mammal8: link lengths");
static_assert(model_checks::joint_ranges_valid(kMammal8), "mammal8: joint ranges");
static_assert(model_checks::sides_consistent(kMammal8), "mammal8: sides");
static_assert(model_checks::mirror_symmetric(kMammal8), "mammal8: left/right symmetry");
static_assert(model_checks::numbered_counter_clockwise(kMammal8), "mammal8: leg order");
static_assert(model_checks::stands_in_workspace(kMammal8), "mammal8: standing pose reachable");
static_assert(model_checks::unused_slots_empty(kMammal8), "mammal8: unused leg slots");
static_assert(2.0f * mammal8_detail::kHalfLength == kMammal8.body.length_mm &&
                  2.0f * mammal8_detail::kHalfWidth == kMammal8.body.width_mm,
              "mammal8: hips at the body corners");

}  // namespace strider

#endif  // STRIDER_ROBOTS_MAMMAL8_H
