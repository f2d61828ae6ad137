// The robot models as data: the seeds' numbers, the host contract of
// `strider robots`, and the compile-time invariants (which must also fail).
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>

#include "robots/all_robots.h"

using namespace strider;

namespace {

struct Expected {
  const char* name;
  uint8_t seed;
  LegKind kind;
  uint8_t legs;
  uint8_t dof;
};

// ARCHITECTURE.md's table of models.
constexpr Expected kExpected[] = {
    {"sprawl8", 0, LegKind::kSprawl, 4, 2},     {"mammal8", 3, LegKind::kPlanar, 4, 2},
    {"dog12", 1, LegKind::kAbduction, 4, 3},    {"hexapod18", 2, LegKind::kCoxaFemurTibia, 6, 3},
    {"spider12", 4, LegKind::kCoxaFemurTibia, 4, 3},
};

TEST(RobotModels, MatchTheArchitectureTable) {
  ASSERT_EQ(kRobotCount, 5);
  for (uint8_t i = 0; i < kRobotCount; ++i) {
    const RobotModel& m = *kAllRobots[i];
    const Expected& e = kExpected[i];
    EXPECT_STREQ(m.name, e.name);
    EXPECT_EQ(m.seed, e.seed) << m.name;
    EXPECT_EQ(m.kind, e.kind) << m.name;
    EXPECT_EQ(m.leg_count, e.legs) << m.name;
    EXPECT_EQ(m.dof(), e.dof) << m.name;
    EXPECT_EQ(m.joint_count(), e.legs * e.dof) << m.name;
  }
}

TEST(RobotModels, SeedGeometry) {
  // Seed 000 section 3.1.
  EXPECT_EQ(kSprawl8.links.l1_mm, 55.0f);
  EXPECT_EQ(kSprawl8.links.l2_mm, 90.0f);
  EXPECT_EQ(kSprawl8.body.length_mm, 70.0f);
  EXPECT_EQ(kSprawl8.body.width_mm, 70.0f);
  for (uint8_t i = 0; i < 4; ++i) {  // translation-only mounts at the corners (eqs 9-11)
    EXPECT_EQ(kSprawl8.legs[i].mount_yaw_deg, 0.0f);
    EXPECT_EQ(std::fabs(kSprawl8.legs[i].mount_mm.x), 35.0f);
    EXPECT_EQ(std::fabs(kSprawl8.legs[i].mount_mm.y), 35.0f);
  }
  // Seed 003 table 1.
  EXPECT_EQ(kMammal8.links.l1_mm, 70.0f);
  EXPECT_EQ(kMammal8.links.l2_mm, 70.0f);
  EXPECT_EQ(kMammal8.body.length_mm, 150.0f);
  EXPECT_EQ(kMammal8.body.width_mm, 90.0f);
  EXPECT_EQ(kMammal8.body.height_mm, 30.0f);
  EXPECT_EQ(kMammal8.body.mass_kg, 1.5f);
  // Seed 001 table 4.
  EXPECT_EQ(kDog12.links.l1_mm, 44.0f);
  EXPECT_EQ(kDog12.links.l2_mm, 280.0f);
  EXPECT_EQ(kDog12.links.l3_mm, 277.0f);
  EXPECT_EQ(kDog12.body.length_mm, 600.0f);
  EXPECT_EQ(kDog12.body.width_mm, 280.0f);
  EXPECT_EQ(kDog12.body.height_mm, 277.0f);
  // Seed 002 table 3 and section "Mechanic Design", table 1 servos.
  EXPECT_EQ(kHexapod18.links.d1_mm, 32.0f);
  EXPECT_EQ(kHexapod18.links.l1_mm, 30.0f);
  EXPECT_EQ(kHexapod18.links.l2_mm, 85.0f);
  EXPECT_EQ(kHexapod18.links.l3_mm, 125.0f);
  EXPECT_EQ(kHexapod18.body.length_mm, 175.0f);
  EXPECT_EQ(kHexapod18.body.width_mm, 155.0f);
  EXPECT_EQ(kHexapod18.servo[0], ServoPart::kHs311);
  EXPECT_EQ(kHexapod18.servo[1], ServoPart::kMg995);
  EXPECT_EQ(kHexapod18.servo[2], ServoPart::kMg995);
  // Spider sizes chosen (seed 004 gives none).
  EXPECT_EQ(kSpider12.links.l1_mm, 27.5f);
  EXPECT_EQ(kSpider12.links.l2_mm, 55.0f);
  EXPECT_EQ(kSpider12.links.l3_mm, 77.5f);
}

TEST(RobotModels, AllInvariantsHold) {
  for (const RobotModel* m : kAllRobots) {
    EXPECT_TRUE(model_valid(*m)) << m->name;
    EXPECT_TRUE(model_checks::names_unique());
    std::set<std::string> leg_names;
    for (uint8_t i = 0; i < m->leg_count; ++i) leg_names.insert(m->legs[i].name);
    EXPECT_EQ(leg_names.size(), m->leg_count) << m->name;
    EXPECT_GT(m->body.mass_kg, 0.0f);
    EXPECT_GT(m->body.height_mm, 0.0f);
  }
}

TEST(RobotModels, FindByName) {
  for (const RobotModel* m : kAllRobots) EXPECT_EQ(find_robot(m->name), m);
  EXPECT_EQ(find_robot("sprawl"), nullptr);
  EXPECT_EQ(find_robot("Sprawl8"), nullptr);
  EXPECT_EQ(find_robot(""), nullptr);
  EXPECT_EQ(find_robot(nullptr), nullptr);
}

// Each invariant must be able to fail: break one thing in a copy.
TEST(RobotModels, InvariantsCatchBrokenModels) {
  RobotModel m = kHexapod18;
  m.links.l3_mm = 0.0f;
  EXPECT_FALSE(model_checks::links_valid(m));

  m = kSprawl8;
  m.links.d1_mm = 5.0f;  // a 2-DOF kind has no d1
  EXPECT_FALSE(model_checks::links_valid(m));

  m = kSprawl8;
  m.legs[1].joint[1] = JointRange{30.0f, -110.0f};  // empty range
  EXPECT_FALSE(model_checks::joint_ranges_valid(m));

  m = kSpider12;
  m.legs[2].joint[0] = JointRange{-100.0f, 100.0f};  // wider than the MG90S's 180 deg
  EXPECT_FALSE(model_checks::joint_ranges_valid(m));

  m = kDog12;
  m.leg_count = 7;
  EXPECT_FALSE(model_checks::joint_ranges_valid(m));

  m = kMammal8;
  m.legs[0].side = BodySide::kRight;  // a left-mounted leg called right
  EXPECT_FALSE(model_checks::sides_consistent(m));

  m = kHexapod18;
  m.legs[1].mount_mm.x = 5.0f;  // middle left no longer mirrors middle right
  EXPECT_FALSE(model_checks::mirror_symmetric(m));

  m = kHexapod18;
  m.legs[5].stand_mm.z = -111.0f;
  EXPECT_FALSE(model_checks::mirror_symmetric(m));

  m = kSprawl8;
  const LegModel tmp = m.legs[1];
  m.legs[1] = m.legs[3];
  m.legs[3] = tmp;  // clockwise order
  EXPECT_FALSE(model_checks::numbered_counter_clockwise(m));

  m = kSprawl8;
  m.legs[0].stand_mm.z -= 1.0f;  // off the sprawl leg's torus
  EXPECT_FALSE(model_checks::stands_in_workspace(m));

  m = kDog12;
  m.legs[3].stand_mm.z = -600.0f;  // beyond Lb + Lc
  EXPECT_FALSE(model_checks::stands_in_workspace(m));

  m = kMammal8;
  m.legs[2].stand_mm.y += 3.0f;  // out of the planar leg's plane
  EXPECT_FALSE(model_checks::stands_in_workspace(m));

  m = kSprawl8;
  m.legs[4].name = "extra";
  EXPECT_FALSE(model_checks::unused_slots_empty(m));
}

TEST(RobotModels, CompileTimeTrigonometry) {
  for (double d = -720.0; d <= 720.0; d += 7.5) {
    EXPECT_NEAR(model_math::cos_deg(d), std::cos(d * M_PI / 180.0), 1e-12) << d;
    EXPECT_NEAR(model_math::sin_deg(d), std::sin(d * M_PI / 180.0), 1e-12) << d;
  }
  for (double v : {0.0, 1e-6, 0.25, 2.0, 12345.678, 3.1e5}) EXPECT_NEAR(model_math::sqrt(v), std::sqrt(v), 1e-12 * (1 + v));
  const Vec3<float> p = leg_point_in_body(Vec3<float>(10.0f, 20.0f, 30.0f), 90.0f, 1.0, 2.0, 3.0);
  EXPECT_NEAR(p.x, 8.0f, 1e-6f);
  EXPECT_NEAR(p.y, 21.0f, 1e-6f);
  EXPECT_NEAR(p.z, 33.0f, 1e-6f);
  const LegModel& leg = kHexapod18.legs[2];
  const Vec3<float> back = body_point_in_leg(leg, leg.stand_mm);
  EXPECT_NEAR(back.x, 120.0f, 1e-4f);
  EXPECT_NEAR(back.y, 0.0f, 1e-4f);
  EXPECT_NEAR(back.z, -90.0f, 1e-4f);
}

TEST(ServoParts, DatasheetFiguresAreSane) {
  std::set<std::string> names;
  for (uint8_t i = 0; i < kServoPartCount; ++i) {
    const ServoSpec s = servo_spec(ServoPart(i));
    names.insert(s.name);
    EXPECT_EQ(s.travel_deg, 180.0f) << s.name;
    EXPECT_LT(s.min_pulse_us, s.max_pulse_us) << s.name;
    EXPECT_GT(s.stall_torque_kg_cm, 1.0f) << s.name;
    EXPECT_GT(servo_speed_deg_s(ServoPart(i)), 300.0f) << s.name;
    EXPECT_GT(s.mass_g, 5.0f) << s.name;
  }
  EXPECT_EQ(names.size(), kServoPartCount);
  EXPECT_STREQ(servo_spec(ServoPart::kMg996r).name, "MG996R");
  EXPECT_EQ(servo_spec(ServoPart::kMg996r).stall_torque_kg_cm, 11.0f);  // seed 003 eq 8
  EXPECT_STREQ(servo_spec(ServoPart::kHs311).name, "HS-311");
}

// dog12's knees carry a quarter of the robot on a ~217 mm lever standing
// (knee to foot, horizontal), and twice that when it rolls onto one side:
// the MG996R (11 kg cm) could not stand it; the simulator measured it.
TEST(ServoParts, Dog12KneesCarryTheRobot) {
  const float standing_kg_cm = kDog12.body.mass_kg / 4.0f * 21.7f;
  EXPECT_GE(servo_spec(kDog12.servo[2]).stall_torque_kg_cm, 2.0f * standing_kg_cm);
  EXPECT_STREQ(servo_spec(ServoPart::kDs5160).name, "DS5160");
}

}  // namespace
