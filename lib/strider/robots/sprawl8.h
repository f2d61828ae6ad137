//! sprawl8: the 8-DOF sprawling quadruped of seed 000 (Atique et al. 2018).
//!
//! Seed 000 section 3.1: thigh a1 = 55 mm, leg a2 = 90 mm, a square base of
//! 70 mm with a leg at each corner; section 2.3 eqs 9-11: leg frames are the
//! body frame translated to the hip (no rotation). Legs in the order of seed
//! 000 fig. 5 (its legs 1-4 are 0-3 here), counter-clockwise from front left:
//! 0 front left, 1 rear left, 2 rear right, 3 front right; the crawl lifts
//! the diagonal pairs {0, 2} and {1, 3} (seed 000 section 3.3, steps B and D).
//! Section 3.3's direction change (limb 4 takes the role of 1, 3 of 4, ...)
//! holds only for this counter-clockwise order.
#ifndef STRIDER_ROBOTS_SPRAWL8_H
#define STRIDER_ROBOTS_SPRAWL8_H

#include "model_checks.h"

namespace strider {

//! Half the side of the 70 mm square base [mm] (seed 000 section 3.1).
constexpr float kSprawl8HalfSide = 35.0f;

namespace sprawl8_detail {

// Standing foot, leg frame: a 54-72-90 mm right triangle puts the foot on the
// knee's circle exactly (t2 = atan2(-72, 54) = -53.13 deg, seed 000 eq 8):
// 72 mm under the hip plane and 55 + 54 = 109 mm out from the hip axis,
// along the leg's body diagonal (t1 = 45 deg + k 90 deg, eq 7).
constexpr double kStandReach = 109.0;  //!< [mm] from the hip yaw axis
constexpr double kStandZ = -72.0;      //!< [mm] below the hip plane

// Joint limits [deg], seed 000 convention (eqs 4-8):
// - t1 (hip yaw): +-40 deg about the leg's diagonal. Keeps each thigh in its
//   own quadrant, 5 deg clear of the body axes, so neighbouring legs never
//   cross (the hip servo could turn 180 deg), and keeps the rear legs clear
//   of atan2's +-180 deg cut so eq 7 never jumps across the range.
// - t2 (knee): -110 to +30 deg: from a shank pointing 20 deg inward of
//   straight down (the foot still 24 mm outside the hip axis: a1 + a2
//   cos 110 deg) to 30 deg above horizontal (45 mm foot lift over the hip
//   plane, enough to step over a cable). 140 deg of the servo's 180.
constexpr JointRange kKnee = {-110.0f, 30.0f};
constexpr JointRange kUnused = {0.0f, 0.0f};

//! A corner leg whose diagonal points at `diagonal_deg`.
constexpr LegModel corner_leg(const char* name, BodySide side, float x, float y, float diagonal_deg) {
  return leg_model(name, side, Vec3<float>(x, y, 0.0f), 0.0f, {diagonal_deg - 40.0f, diagonal_deg + 40.0f},
                   kKnee, kUnused, kStandReach * model_math::cos_deg(diagonal_deg),
                   kStandReach * model_math::sin_deg(diagonal_deg), kStandZ);
}

}  // namespace sprawl8_detail

constexpr RobotModel kSprawl8 = {
    "sprawl8",
    0,
    LegKind::kSprawl,
    4,
    {55.0f, 90.0f, 0.0f, 0.0f},  // a1 thigh, a2 leg (seed 000 section 3.1)
    // 70 mm square base (seed 000); 30 mm tall with the Mega on top and the
    // battery below (estimate). Mass 0.6 kg (estimate: 4 MG90S 54 g, 4 MG996R
    // 220 g, 1.5 mm aluminium base and brackets 150 g, Mega 37 g, 2S battery
    // 100 g, HC-05 and sensor 15 g; also the simulator's figure).
    {70.0f, 70.0f, 30.0f, 0.6f},
    // Hip yaw: MG90S (vertical axis, carries no weight). Knee: MG996R: with
    // two feet down the knee holds 0.3 kg at 54 mm, 1.6 kg cm, 15 % of its
    // stall torque (an MG90S would be at 74 %).
    {ServoPart::kMg90s, ServoPart::kMg996r, ServoPart::kMg90s},
    {
        // Mounts at the corners of the base, translation only (eqs 9-11).
        sprawl8_detail::corner_leg("front_left", BodySide::kLeft, kSprawl8HalfSide, kSprawl8HalfSide, 45.0f),
        sprawl8_detail::corner_leg("rear_left", BodySide::kLeft, -kSprawl8HalfSide, kSprawl8HalfSide, 135.0f),
        sprawl8_detail::corner_leg("rear_right", BodySide::kRight, -kSprawl8HalfSide, -kSprawl8HalfSide, -135.0f),
        sprawl8_detail::corner_leg("front_right", BodySide::kRight, kSprawl8HalfSide, -kSprawl8HalfSide, -45.0f),
    },
};

static_assert(model_checks::links_valid(kSprawl8), "sprawl8: link lengths");
static_assert(model_checks::joint_ranges_valid(kSprawl8), "sprawl8: joint ranges");
static_assert(model_checks::sides_consistent(kSprawl8), "sprawl8: sides");
static_assert(model_checks::mirror_symmetric(kSprawl8), "sprawl8: left/right symmetry");
static_assert(model_checks::numbered_counter_clockwise(kSprawl8), "sprawl8: leg order");
static_assert(model_checks::stands_in_workspace(kSprawl8), "sprawl8: standing pose reachable");
static_assert(model_checks::unused_slots_empty(kSprawl8), "sprawl8: unused leg slots");
static_assert(2.0f * kSprawl8HalfSide == kSprawl8.body.length_mm, "sprawl8: legs at the base corners");

}  // namespace strider

#endif  // STRIDER_ROBOTS_SPRAWL8_H
