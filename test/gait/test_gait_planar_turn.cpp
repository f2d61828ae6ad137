// Planar legs turning (gait_engine_walk.h, draw_homes_for_turn(); docs/gaits.md,
// "Turning on planar legs"): while the command turns, mammal8's feet stand
// kPlanarTurnDraw of their x distance nearer the body's middle, less as the
// command goes forward too, and back where they stood once it stops; other
// leg kinds keep their homes. Float and Fixed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gait_test_util.h"
#include "robots/all_robots.h"

namespace gaittest {
namespace {

template <typename S>
class PlanarTurn : public ::testing::Test {};
TYPED_TEST_SUITE(PlanarTurn, Scalars);

constexpr double kDegToRad = kPi / 180.0;
// Fixed keeps 1/65536 mm; the homes move by sums and differences alone.
constexpr double kHomeTolMm = 1e-3;

template <typename S>
std::vector<double> home_x(Rig<S>& rig) {
  std::vector<double> x;
  for (uint8_t i = 0; i < rig.model->leg_count; ++i) x.push_back(dbl(rig.engine().config().home[i].x));
  return x;
}

template <typename S>
void expect_homes(Rig<S>& rig, const std::vector<double>& stand, double share, const char* what) {
  const std::vector<double> now = home_x(rig);
  for (size_t i = 0; i < stand.size(); ++i)
    EXPECT_NEAR(now[i], stand[i] * (1.0 - share), kHomeTolMm) << what << ", leg " << i;
}

TYPED_TEST(PlanarTurn, TurningDrawsTheFeetInAndStoppingPutsThemBack) {
  using S = TypeParam;
  Rig<S> rig(strider::kMammal8, strider::kGaitWalk);
  const std::vector<double> stand = home_x(rig);
  ASSERT_NEAR(std::fabs(stand[0]), 75.0, 1e-6);  // under the hips
  const double draw = strider::kPlanarTurnDraw;

  rig.engine().set_command(S(0), S(0), sc<S>(10.0 * kDegToRad));
  expect_homes(rig, stand, draw, "turning in place");
  std::vector<Tick> run;
  rig.run(12.0, run);
  // Feet on the ground stand about their drawn homes: within the turn's stride.
  const Tick& last = run.back();
  for (uint8_t i = 0; i < rig.model->leg_count; ++i) {
    if (!last.contact[i]) continue;
    EXPECT_NEAR(last.foot[i].x, stand[i] * (1.0 - draw), 10.0) << "leg " << int(i);
    EXPECT_EQ(last.ik[i], IkStatus::kOk) << "leg " << int(i);  // the IK of the projected point
  }

  // Forward as fast as the turn's stride at the feet (45 mm out): half the share.
  const double turn_stride = 10.0 * kDegToRad * 45.0;
  rig.engine().set_command(sc<S>(turn_stride), S(0), sc<S>(10.0 * kDegToRad));
  expect_homes(rig, stand, draw * 0.5, "forward and turning");
  rig.engine().set_command(sc<S>(20.0), S(0), S(0));
  expect_homes(rig, stand, 0.0, "forward");

  rig.engine().set_command(S(0), S(0), sc<S>(-10.0 * kDegToRad));
  expect_homes(rig, stand, draw, "turning clockwise");
  rig.run(4.0, run);
  rig.engine().set_command(S(0), S(0), S(0));
  expect_homes(rig, stand, 0.0, "stopped");
  ASSERT_TRUE(rig.run_until_standing(run, 20.0));
  for (uint8_t i = 0; i < rig.model->leg_count; ++i)
    EXPECT_NEAR(dbl(rig.engine().foot(i).x), stand[i], 0.5) << "standing, leg " << int(i);
}

TYPED_TEST(PlanarTurn, ARestartStandsOnTheStandingHomes) {
  using S = TypeParam;
  Rig<S> rig(strider::kMammal8, strider::kGaitWalk);
  const std::vector<double> stand = home_x(rig);
  rig.engine().set_command(S(0), S(0), sc<S>(10.0 * kDegToRad));
  std::vector<Tick> run;
  rig.run(3.0, run);
  // As WalkerMotion's restart (the servos went limp): the engine's own configuration.
  ASSERT_TRUE(rig.walker->restart(strider::kGaitWalk, rig.engine().config(), true));
  expect_homes(rig, stand, 0.0, "after the restart");
  for (uint8_t i = 0; i < rig.model->leg_count; ++i)
    EXPECT_NEAR(dbl(rig.engine().foot(i).x), stand[i], kHomeTolMm) << "leg " << int(i);
}

TYPED_TEST(PlanarTurn, OtherLegKindsKeepTheirHomes) {
  using S = TypeParam;
  for (const RobotModel* m : strider::kAllRobots) {
    if (m->kind == strider::LegKind::kPlanar) continue;
    Rig<S> rig(*m, strider::kGaitTrot.leg_count == m->leg_count ? strider::kGaitTrot : strider::kGaitTripod);
    const std::vector<double> stand = home_x(rig);
    rig.engine().set_command(S(0), S(0), sc<S>(20.0 * kDegToRad));
    expect_homes(rig, stand, 0.0, m->name);
  }
}

}  // namespace
}  // namespace gaittest
