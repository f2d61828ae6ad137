//! sprawl8: the 8-DOF sprawling quadruped of seed 000 (Atique et al. 2018).
//! Where each value comes from: docs/robots.md, "sprawl8".
#ifndef STRIDER_ROBOTS_SPRAWL8_H
#define STRIDER_ROBOTS_SPRAWL8_H

#include "model_checks.h"

namespace strider {

//! Half the side of the 70 mm square base [mm] (seed 000 section 3.1).
constexpr float kSprawl8HalfSide = 35.0f;

namespace sprawl8_detail {

// Standing foot, leg frame: along the leg's body diagonal, on the knee's
// circle exactly (a 54-72-90 mm right triangle).
constexpr double kStandReach = 109.0;  //!< [mm] from the hip yaw axis
constexpr double kStandZ = -72.0;      //!< [mm] below the hip plane

// Joint limits [deg], seed 000 convention (eqs 4-8); t1 is +-40 deg about
// the leg's diagonal.
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
    {70.0f, 70.0f, 30.0f, 0.6f},  // 70 mm square base (seed 000); height and mass estimated
    {ServoPart::kMg90s, ServoPart::kMg996r, ServoPart::kMg90s},
    {
        sprawl8_detail::corner_leg("front_left", BodySide::kLeft, kSprawl8HalfSide, kSprawl8HalfSide, 45.0f),
        sprawl8_detail::corner_leg("rear_left", BodySide::kLeft, -kSprawl8HalfSide, kSprawl8HalfSide, 135.0f),
        sprawl8_detail::corner_leg("rear_right", BodySide::kRight, -kSprawl8HalfSide, -kSprawl8HalfSide, -135.0f),
        sprawl8_detail::corner_leg("front_right", BodySide::kRight, kSprawl8HalfSide, -kSprawl8HalfSide, -45.0f),
    },
};

static_assert(model_valid(kSprawl8), "sprawl8: a model_checks.h invariant fails");
static_assert(2.0f * kSprawl8HalfSide == kSprawl8.body.length_mm, "sprawl8: legs at the base corners");

}  // namespace strider

#endif  // STRIDER_ROBOTS_SPRAWL8_H
