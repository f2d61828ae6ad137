//! dog12: the 12-DOF quadruped of seed 001 (Shahriar): abduction, hip and
//! knee per leg.
//!
//! Seed 001 table 4: La = 44 mm, Lb = 280 mm, Lc = 277 mm, body length bl =
//! 600 mm, width bw = 280 mm, height bh = 277 mm; body poses tested over roll
//! -28..28 deg, pitch -21..21 deg, yaw -21..21 deg. Leg frame: seed 001's
//! (kinematics/abduction_leg.h): origin on the abduction axis (x forward),
//! t1 the angle of La from +y about +x in [0, 360) deg, t2 the femur angle
//! from backward, t3 the knee flexion; standing, left legs have t1 = 0 and
//! right legs t1 = 180 deg.
//!
//! Legs counter-clockwise from front left: 0 front left, 1 rear left,
//! 2 rear right, 3 front right (trot pairs {0, 2} and {1, 3}).
#ifndef STRIDER_ROBOTS_DOG12_H
#define STRIDER_ROBOTS_DOG12_H

#include "model_checks.h"

namespace strider {
namespace dog12_detail {

// Mounts [mm]: abduction axes at the corners of the 600 x 280 mm body, in
// its mid plane (the body centre, about which seed 001 rotates the body);
// every leg frame faces forward (yaw 0).
constexpr float kHalfLength = 300.0f;
constexpr float kHalfWidth = 140.0f;

// Standing foot, leg frame [mm]: straight under the hip, La outward and
// 350 mm down (63 % of Lb + Lc): t1 = 0 / 180 deg, t2 = 39.3 deg,
// t3 = 102.1 deg. Chosen so that every pose of seed 001 table 4 (each axis
// alone and all eight corners roll +-28, pitch +-21, yaw +-21 deg together)
// stays reachable: the longest hip-foot distance then is 548 mm of 557.
constexpr double kStandZ = -350.0;
constexpr double kLa = 44.0;

// Joint limits [deg], seed 001 convention. Over seed 001's poses at this
// stance the joints span t1 -50..58 deg (left; right 122..230), t2 -24..101
// deg and t3 27..137 deg; each limit adds 12-23 deg of margin:
// - t1 (abduction): -70 to +70 deg about the standing value (left 0, right
//   180). Wide for a dog (real ones use +-30-45 deg): the seed's corner
//   poses stack roll and yaw. Left limits straddle 0, so a left leg reports
//   -10 deg rather than 350 (the solver picks the representative).
// - t2 (hip): -40 to +120 deg (backward 0, down 90).
// - t3 (knee): +15 to +160 deg: 15 deg keeps clear of the straight leg,
//   160 deg is where the tibia meets the femur.
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
    // bl x bw x bh (seed 001 table 4). Mass 5.2 kg (estimate: 12 DS5160
    // servos 1.86 kg, aluminium body and 560 mm legs 2.2 kg, battery and
    // electronics 1.1 kg; seed 001 gives none).
    {600.0f, 280.0f, 277.0f, 5.2f},
    // Seed 001 names no servo part (its prototype leg drives the joints
    // through capstan pulleys). Standing, a knee carries a quarter of the
    // robot at a ~217 mm lever (~28 kg cm), and far more when the robot
    // rolls onto one side or rises from its power-up crouch: an MG996R
    // (11 kg cm) cannot stand it, and in simulation a 35 kg cm DS3235 sags
    // onto one side; the 60 kg cm class DS5160 (58 kg cm at 6 V,
    // servo_parts.h) is what robot dogs of this size use.
    {ServoPart::kDs5160, ServoPart::kDs5160, ServoPart::kDs5160},
    {
        dog12_detail::leg("front_left", BodySide::kLeft, dog12_detail::kHalfLength, dog12_detail::kHalfWidth),
        dog12_detail::leg("rear_left", BodySide::kLeft, -dog12_detail::kHalfLength, dog12_detail::kHalfWidth),
        dog12_detail::leg("rear_right", BodySide::kRight, -dog12_detail::kHalfLength, -dog12_detail::kHalfWidth),
        dog12_detail::leg("front_right", BodySide::kRight, dog12_detail::kHalfLength, -dog12_detail::kHalfWidth),
    },
};

static_assert(model_checks::links_valid(kDog12), "dog12: link lengths");
static_assert(model_checks::joint_ranges_valid(kDog12), "dog12: joint ranges");
static_assert(model_checks::sides_consistent(kDog12), "dog12: sides");
static_assert(model_checks::mirror_symmetric(kDog12), "dog12: left/right symmetry");
static_assert(model_checks::numbered_counter_clockwise(kDog12), "dog12: leg order");
static_assert(model_checks::stands_in_workspace(kDog12), "dog12: standing pose reachable");
static_assert(model_checks::unused_slots_empty(kDog12), "dog12: unused leg slots");
static_assert(kDog12.links.l1_mm == float(dog12_detail::kLa), "dog12: stance uses La");

}  // namespace strider

#endif  // STRIDER_ROBOTS_DOG12_H
