// The simulator's world and scenario format: the physics body matches the
// library's kinematics, the servo model follows the pulses, scenarios parse.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "control/channel_map.h"
#include "gait/gait_params.h"
#include "kinematics/any_leg.h"
#include "robots/all_robots.h"
#include "scenario.h"
#include "world.h"

namespace {

using strider_sim::ChannelPulse;
using strider_sim::kMaxChannels;
using strider_sim::Vec;
using strider_sim::World;
using strider_sim::WorldConfig;

// The multibody built from each model puts every foot where the leg type's
// FK says, for random joints within the limits: the joint axes, zero angles
// and link offsets are right for all four leg kinds.
TEST(SimWorld, FeetMatchLibraryForwardKinematics) {
  std::mt19937 rng(7);
  for (const strider::RobotModel* model : strider::kAllRobots) {
    for (int trial = 0; trial < 5; ++trial) {
      WorldConfig cfg;
      const int dof = model->dof();
      std::vector<strider::AnyLeg<float>::Joints> q(model->leg_count);
      for (int i = 0; i < model->leg_count; ++i)
        for (int j = 0; j < dof; ++j) {
          const strider::JointRange& r = model->legs[i].joint[j];
          std::uniform_real_distribution<double> u(r.min_deg, r.max_deg);
          const double deg = u(rng);
          q[i][uint8_t(j)] = float(deg * M_PI / 180.0);
          cfg.initial_joints_rad.push_back(double(q[i][uint8_t(j)]));
        }
      World w(*model, cfg, {});
      const Vec body = w.body().pos_mm;
      for (int i = 0; i < model->leg_count; ++i) {
        strider::AnyLeg<float> leg;
        ASSERT_TRUE(strider::AnyLeg<float>::from_model(*model, uint8_t(i), leg));
        const strider::Vec3<float> want = leg.fk_body(q[i]);
        const Vec got = w.foot_mm(i);
        EXPECT_NEAR(got.x - body.x, want.x, 0.05) << model->name << " leg " << i;
        EXPECT_NEAR(got.y - body.y, want.y, 0.05) << model->name << " leg " << i;
        EXPECT_NEAR(got.z - body.z, want.z, 0.05) << model->name << " leg " << i;
        for (int j = 0; j < dof; ++j) EXPECT_NEAR(w.joint_rad(i, j), double(q[i][uint8_t(j)]), 1e-5);
      }
    }
  }
}

// A pulse becomes the joint angle the inverse servo map gives; a change
// within the dead band is ignored; a servo moves no faster than its rating.
TEST(SimWorld, ServoFollowsPulsesWithDeadbandAndSpeedLimit) {
  const strider::RobotModel& model = strider::kSprawl8;
  World w(model, WorldConfig{}, {});
  strider::ServoChannel<float> ch[strider::kMaxServoJoints];
  ASSERT_EQ(strider::make_channel_map<float>(model, ch), model.joint_count());
  ChannelPulse p[kMaxChannels];
  for (int k = 0; k < model.joint_count(); ++k) p[ch[k].channel] = ChannelPulse{true, 1500.0};
  w.set_pulses(p);
  EXPECT_NEAR(w.joint_target_rad(0, 0), strider::joint_from_pulse(ch[0], 1500.0), 1e-9);
  p[ch[0].channel].pulse_us = 1504.0;  // inside the MG90S's 5 us dead band
  w.set_pulses(p);
  EXPECT_NEAR(w.joint_target_rad(0, 0), strider::joint_from_pulse(ch[0], 1500.0), 1e-9);
  p[ch[0].channel].pulse_us = 1900.0;
  w.set_pulses(p);
  const double target = strider::joint_from_pulse(ch[0], 1900.0);
  EXPECT_NEAR(w.joint_target_rad(0, 0), target, 1e-9);
  const double start = w.joint_rad(0, 0);
  for (int s = 0; s < 100; ++s) w.step();  // 0.1 s
  const double moved = std::fabs(w.joint_rad(0, 0) - start);
  const double rated = 60.0 / double(strider::servo_spec(model.servo[0]).speed_s_per_60deg) * M_PI / 180.0;
  EXPECT_GT(moved, 0.3 * rated * 0.1);
  EXPECT_LE(moved, rated * 0.1 * 1.05);
  for (int s = 0; s < 900; ++s) w.step();
  EXPECT_NEAR(w.joint_rad(0, 0), target, 0.02);
}

// Standing, every model's CoM sits where its gait parameters assume it (the
// body's own COM is offset to balance the servos on the legs), and the
// masses add up to the model's total.
TEST(SimWorld, StandingCentreOfMassIsWhereTheGaitAssumesIt) {
  for (const strider::RobotModel* model : strider::kAllRobots) {
    World w(*model, WorldConfig{}, {});
    const strider::GaitParams* gp = strider::gait_params_for(*model);
    ASSERT_NE(gp, nullptr);
    const Vec body = w.body().pos_mm, com = w.com_mm();
    EXPECT_NEAR(com.x - body.x, double(gp->com_x_mm), 0.2) << model->name;
    EXPECT_NEAR(com.y - body.y, double(gp->com_y_mm), 0.2) << model->name;
  }
}

TEST(SimWorld, SonarSeesAWallAhead) {
  const strider::RobotModel& model = strider::kSprawl8;
  World clear(model, WorldConfig{}, {});
  EXPECT_LT(clear.sonar_mm(), 0.0);
  World wall(model, WorldConfig{}, {strider_sim::ObstacleBox{500, 0, 20, 1000, 300}});
  const double expect = 490.0 - wall.sonar_origin_body_mm().x;
  EXPECT_NEAR(wall.sonar_mm(), expect, 2.0);
  EXPECT_NEAR(wall.body_clearance_mm(), 490.0 - 0.5 * model.body.length_mm, 1.5);
}

TEST(SimScenario, ParsesTheDocumentedFormat) {
  strider_sim::Scenario s;
  std::string err;
  ASSERT_TRUE(strider_sim::parse_scenario("# a comment\nrobot sprawl8\nduration 20   # seconds\n"
                                          "obstacle box 600 0 20 800 150\n"
                                          "at 2.5 send walk 100\\n\nat 1 send F\n",
                                          &s, &err))
      << err;
  EXPECT_EQ(s.robot, "sprawl8");
  EXPECT_DOUBLE_EQ(s.duration_s, 20.0);
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_DOUBLE_EQ(s.obstacles[0].x_mm, 600.0);
  EXPECT_DOUBLE_EQ(s.obstacles[0].sz_mm, 150.0);
  ASSERT_EQ(s.sends.size(), 2u);
  EXPECT_DOUBLE_EQ(s.sends[0].at_s, 1.0);  // sorted by time
  EXPECT_EQ(s.sends[0].bytes, "F");
  EXPECT_EQ(s.sends[1].bytes, "walk 100\n");
}

TEST(SimScenario, RejectsBadLinesWithTheirNumber) {
  strider_sim::Scenario s;
  std::string err;
  EXPECT_FALSE(strider_sim::parse_scenario("robot sprawl8\nduration 5\nat x send F\n", &s, &err));
  EXPECT_EQ(err.rfind("line 3:", 0), 0u) << err;
  EXPECT_FALSE(strider_sim::parse_scenario("robot nosuch\nduration 5\n", &s, &err));
  EXPECT_FALSE(strider_sim::parse_scenario("robot sprawl8\n", &s, &err));  // no duration
  EXPECT_FALSE(strider_sim::parse_scenario("robot sprawl8\nduration 5\nobstacle box 1 2 3\n", &s, &err));
  EXPECT_FALSE(strider_sim::parse_scenario("robot sprawl8\nduration 5\nat 1 send bad\\q\n", &s, &err));
}

TEST(SimScenario, ParsesFootPads) {  // `feet pad MM`: the --foot-pad capsules
  strider_sim::Scenario s;
  std::string err;
  ASSERT_TRUE(strider_sim::parse_scenario("robot mammal8\nduration 5\nfeet pad 5\n", &s, &err)) << err;
  EXPECT_DOUBLE_EQ(s.foot_pad_half_mm, 5.0);
  EXPECT_FALSE(strider_sim::parse_scenario("robot mammal8\nduration 5\nfeet pad 0\n", &s, &err));
  EXPECT_FALSE(strider_sim::parse_scenario("robot mammal8\nduration 5\nfeet ball 5\n", &s, &err));
  EXPECT_EQ(err.rfind("line 3:", 0), 0u) << err;
}

TEST(SimScenario, ParsesRampShoveUprightAndBattery) {  // and `at T ramp`
  strider_sim::Scenario s;
  std::string err;
  ASSERT_TRUE(strider_sim::parse_scenario("robot sprawl8\nduration 9\nramp 10 30\nbattery soc 0.5 cells 3\n"
                                          "battery mah 40 ohm 0.1\nat 5 upright\nat 4 shove 0 1 -0.5\n"
                                          "at 7 ramp 12 -45\nat 8 ramp 0\n",
                                          &s, &err))
      << err;
  EXPECT_DOUBLE_EQ(s.ramp_deg, 10.0);
  EXPECT_DOUBLE_EQ(s.ramp_uphill_deg, 30.0);
  EXPECT_EQ(s.battery.cells, 3);
  EXPECT_DOUBLE_EQ(s.battery.soc, 0.5);
  EXPECT_DOUBLE_EQ(s.battery.capacity_mah, 40.0);
  EXPECT_DOUBLE_EQ(s.battery.internal_ohm, 0.1);
  ASSERT_EQ(s.events.size(), 4u);
  EXPECT_EQ(s.events[0].kind, strider_sim::TimedEvent::kShove);  // sorted by time
  EXPECT_DOUBLE_EQ(s.events[0].impulse_ns.z, -0.5);
  EXPECT_EQ(s.events[1].kind, strider_sim::TimedEvent::kUpright);
  EXPECT_EQ(s.events[2].kind, strider_sim::TimedEvent::kRamp);  // the ground tilts later on
  EXPECT_DOUBLE_EQ(s.events[2].ramp_deg, 12.0);
  EXPECT_DOUBLE_EQ(s.events[2].ramp_uphill_deg, -45.0);
  EXPECT_EQ(s.events[3].kind, strider_sim::TimedEvent::kRamp);
  EXPECT_DOUBLE_EQ(s.events[3].ramp_deg, 0.0);
  EXPECT_DOUBLE_EQ(s.events[3].ramp_uphill_deg, 0.0);
  // The command line's pack options win over the scenario's.
  strider_sim::BatteryOverrides cli;
  cli.soc = 0.2;
  const strider_sim::BatteryOverrides both = s.battery.under(cli);
  EXPECT_DOUBLE_EQ(both.soc, 0.2);
  EXPECT_EQ(both.cells, 3);
  for (const char* bad : {"ramp\n", "ramp 50\n", "ramp 10 x\n", "ramp 10 30 1\n", "battery\n", "battery cells 0\n",
                          "battery cells 2.5\n", "battery soc 1.5\n", "battery mah\n", "battery volts 7\n",
                          "at 1 shove 1 2\n", "at 1 shove 1 2 3 4\n", "at 1 upright now\n", "at 1 jump\n",
                          "at 1 ramp\n", "at 1 ramp 46\n", "at 1 ramp -1\n", "at 1 ramp 10 x\n", "at 1 ramp 10 30 1\n"}) {
    EXPECT_FALSE(strider_sim::parse_scenario(std::string("robot sprawl8\nduration 5\n") + bad, &s, &err)) << bad;
    EXPECT_EQ(err.rfind("line 3:", 0), 0u) << err;
  }
}

// A ramp tilts gravity, not the ground: a body parallel to the ground (the
// start pose) reports the slope as roll and pitch (rising ahead-left: left
// side up, nose up), and its IMU's gravity leans the same way.
TEST(SimWorld, RampTiltsGravityAndTheReportedAttitude) {
  const strider::RobotModel& model = *strider::find_robot("hexapod18");
  World w(model, WorldConfig{}, {});
  w.set_ramp(10.0, 30.0);
  const strider_sim::BodyState b = w.body();
  // up in the ground's frame: (sin 10 cos 30, sin 10 sin 30, cos 10); Z-Y-X angles of it.
  const double ux = std::sin(10 * M_PI / 180) * std::cos(30 * M_PI / 180);
  const double uy = std::sin(10 * M_PI / 180) * std::sin(30 * M_PI / 180), uz = std::cos(10 * M_PI / 180);
  EXPECT_NEAR(b.roll_deg, std::atan2(uy, uz) * 180 / M_PI, 0.01);
  EXPECT_NEAR(b.pitch_deg, -std::atan2(ux, std::hypot(uy, uz)) * 180 / M_PI, 0.01);
  EXPECT_NEAR(b.tilt_deg, 10.0, 0.01);
  for (int k = 0; k < 250; ++k) w.step();
  EXPECT_NEAR(w.body().tilt_deg, 10.0, 2.0);  // on limp servos, sagging
  const strider_sim::BodyMotion m = w.body_motion(Vec{});
  EXPECT_NEAR(m.gravity_m_s2.z, -9.81 * std::cos(10 * M_PI / 180), 1e-5);  // Bullet in float
  EXPECT_LT(m.gravity_m_s2.x, 0.0);  // downhill is behind and to the right
  EXPECT_LT(m.gravity_m_s2.y, 0.0);
}

// A shove at the top of the body tips sprawl8 over; upright() puts it back
// on its feet, level, at rest, where it lay, heading kept.
TEST(SimWorld, ShoveTipsTheRobotAndUprightSetsItBack) {
  const strider::RobotModel& model = *strider::find_robot("sprawl8");
  World w(model, WorldConfig{}, {});
  for (int k = 0; k < 100; ++k) w.step();
  EXPECT_LT(w.body().tilt_deg, 5.0);
  w.shove(Vec{0, 1.0, 0.5});
  double max_tilt = 0;
  for (int k = 0; k < 250; ++k) {
    w.step();
    max_tilt = std::max(max_tilt, w.body().tilt_deg);
  }
  EXPECT_GT(max_tilt, 60.0);
  const strider_sim::BodyState lying = w.body();
  w.upright();
  const strider_sim::BodyState up = w.body();
  EXPECT_LT(up.tilt_deg, 0.05);  // Bullet in float
  EXPECT_NEAR(up.pos_mm.x, lying.pos_mm.x, 1e-6);
  EXPECT_NEAR(up.pos_mm.y, lying.pos_mm.y, 1e-6);
  for (int k = 0; k < 250; ++k) w.step();
  EXPECT_LT(w.body().tilt_deg, 5.0);
  EXPECT_FALSE(w.body_on_ground());
}

}  // namespace
