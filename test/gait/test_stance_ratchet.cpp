// StanceRatchet (gait/stance_ratchet.h): the stance feet in steps, all at
// once, and only while every foot is down; what is walked is what the feet
// take in the end, in float and Fixed. The engine with it: test_gait_walk.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gait/stance_ratchet.h"
#include "gait_test_util.h"

namespace gaittest {
namespace {

using strider::BodyStep;
using strider::StanceRatchet;

template <typename S>
class StanceRatchetTest : public ::testing::Test {};
TYPED_TEST_SUITE(StanceRatchetTest, Scalars);

template <typename S>
BodyStep<S> straight(double dx, double dy = 0.0) {
  return BodyStep<S>{sc<S>(dx), sc<S>(dy), S(0), S(1), S(0)};
}

// One tick: what the stance feet take of `walked`.
template <typename S>
BodyStep<S> take(StanceRatchet<S>& r, BodyStep<S> walked, bool flush, bool now) {
  r.take(walked, flush, now);
  return walked;
}

// Fixed: each tick's step is rounded to 1/65536 mm; over a few thousand
// ticks the sums differ by that much at most.
template <typename S>
double sum_tolerance(int ticks) {
  return strider::ScalarTraits<S>::kIsFixed ? ticks * 2.0 / 65536.0 : 1e-3;
}

TYPED_TEST(StanceRatchetTest, OffTakesEveryTickAsWalked) {
  using S = TypeParam;
  StanceRatchet<S> r;
  for (int k = 0; k < 50; ++k) {
    const BodyStep<S> out = take(r, straight<S>(0.084, -0.02), true, true);
    EXPECT_NEAR(dbl(out.dx_mm), 0.084, 1e-4);
    EXPECT_NEAR(dbl(out.dy_mm), -0.02, 1e-4);
  }
  r.set(S(0), true);  // on all feet needs steps: still off
  EXPECT_FALSE(r.on_all_feet());
  EXPECT_NEAR(dbl(take(r, straight<S>(0.5), true, false).dx_mm), 0.5, 1e-4);
}

// mammal8's seed trot: 4.2 mm/s at the 50 Hz tick is 0.084 mm a tick. In
// 1.3 mm steps the feet do not move for 15 ticks, then take the 16th tick's
// 1.344 mm at once; a stop takes the rest; the sum is what was walked.
TYPED_TEST(StanceRatchetTest, StepsOfTheSetLengthAndTheRestAtAStop) {
  using S = TypeParam;
  StanceRatchet<S> r;
  r.set(sc<S>(1.3), false);
  double walked = 0, taken = 0;
  int moves = 0;
  const int ticks = 200;
  for (int k = 0; k < ticks; ++k) {
    const BodyStep<S> out = take(r, straight<S>(0.084), true, true);
    walked += 0.084;
    taken += dbl(out.dx_mm);
    if (dbl(out.dx_mm) != 0.0) {
      ++moves;
      EXPECT_GE(dbl(out.dx_mm), 1.3 - 1e-3) << k;  // never less than a step
      EXPECT_LT(dbl(out.dx_mm), 1.3 + 0.084 + 1e-3) << k;
      EXPECT_EQ((k + 1) % 16, 0) << k;
    }
  }
  EXPECT_EQ(moves, 200 / 16);
  EXPECT_GT(walked - taken, 0.0);
  EXPECT_LT(walked - taken, 1.3);
  // Stopped: the rest (under a step) at once.
  taken += dbl(take(r, BodyStep<S>::none(), true, true).dx_mm);
  EXPECT_NEAR(taken, walked, sum_tolerance<S>(ticks + 1));
  // Nothing more held.
  EXPECT_EQ(dbl(take(r, BodyStep<S>::none(), true, true).dx_mm), 0.0);
}

// A foot at its edge holds the body (flush false): a stop takes nothing.
TYPED_TEST(StanceRatchetTest, AFootAtItsEdgeKeepsWhatIsHeld) {
  using S = TypeParam;
  StanceRatchet<S> r;
  r.set(sc<S>(1.3), false);
  for (int k = 0; k < 10; ++k) take(r, straight<S>(0.084), true, true);
  for (int k = 0; k < 50; ++k) EXPECT_EQ(dbl(take(r, BodyStep<S>::none(), false, true).dx_mm), 0.0);
  double taken = 0;
  for (int k = 0; k < 50; ++k) taken += dbl(take(r, BodyStep<S>::none(), true, true).dx_mm);
  EXPECT_NEAR(taken, 0.84, sum_tolerance<S>(70));
}

// A turn takes what is held and this tick's step at once, its rotation as
// walked: the ground point moves as by the held translation, then the step.
TYPED_TEST(StanceRatchetTest, ATurnTakesTheHeldTranslationWithIt) {
  using S = TypeParam;
  StanceRatchet<S> r;
  r.set(sc<S>(1.3), false);
  for (int k = 0; k < 10; ++k) take(r, straight<S>(0.08, 0.02), true, true);
  const BodyStep<S> turn = BodyStep<S>::make(sc<S>(4.0), S(0), sc<S>(0.05), sc<S>(kDt));
  const BodyStep<S> out = take(r, turn, true, true);
  EXPECT_NEAR(dbl(out.dx_mm), 0.8 + dbl(turn.dx_mm), 1e-3);
  EXPECT_NEAR(dbl(out.dy_mm), 0.2 + dbl(turn.dy_mm), 1e-3);
  EXPECT_EQ(dbl(out.sin_yaw), dbl(turn.sin_yaw));
  EXPECT_EQ(dbl(out.cos_yaw), dbl(turn.cos_yaw));
  EXPECT_EQ(dbl(take(r, BodyStep<S>::none(), true, true).dx_mm), 0.0);
}

// On all feet: a trot at duty 0.8 has two four-foot windows of 0.3 of a
// cycle. With a foot up nothing moves; in the windows the feet catch up a
// step a tick (1.5 steps at most at once), then step as walked, each
// window ending with less than a step held; a stop takes the rest, a step
// a tick.
TYPED_TEST(StanceRatchetTest, OnAllFeetMovesOnlyInFourFootWindows) {
  using S = TypeParam;
  StanceRatchet<S> r;
  r.set(sc<S>(1.3), true);
  EXPECT_TRUE(r.on_all_feet());
  const int cycle = 119;  // 2.38 s at 50 Hz
  double walked = 0, taken = 0;
  int ticks = 0;
  for (int c = 0; c < 8; ++c) {
    for (int k = 0; k < cycle; ++k, ++ticks) {
      // Windows [0, 0.3) and [0.5, 0.8) of the cycle: every foot down.
      const double ph = double(k) / cycle;
      const bool all_down = ph < 0.3 || (ph >= 0.5 && ph < 0.8);
      const BodyStep<S> out = take(r, straight<S>(0.084), true, all_down);
      walked += 0.084;
      taken += dbl(out.dx_mm);
      if (!all_down) {
        EXPECT_EQ(dbl(out.dx_mm), 0.0) << c << " " << k;
      }
      if (dbl(out.dx_mm) != 0.0) {
        EXPECT_LE(dbl(out.dx_mm), 1.5 * 1.3 + 1e-3) << c << " " << k;
      }
      const bool window_ends = (ph < 0.3 && double(k + 1) / cycle >= 0.3) || (ph < 0.8 && double(k + 1) / cycle >= 0.8);
      if (all_down && window_ends && c > 0) {
        EXPECT_LT(walked - taken, 1.3 + 1e-3) << c << " " << k;
      }
    }
  }
  // The last swing's walk is held (0.2 of a cycle, 2 mm): two ticks.
  for (int k = 0; k < 2; ++k, ++ticks) {
    const double d = dbl(take(r, BodyStep<S>::none(), true, true).dx_mm);
    EXPECT_GT(d, 0.0) << k;
    EXPECT_LE(d, 1.5 * 1.3 + 1e-3) << k;
    taken += d;
  }
  EXPECT_NEAR(taken, walked, sum_tolerance<S>(ticks));
}

// The engine walking mammal8's trot at seed 003's point with a preset's
// stance motion (duty 0.8, 10 mm strides, 2.38 s cycle, 1.3 mm steps on
// all feet; trot10 walks 0.85): while a foot is up no stance foot moves; the stance
// feet move together, by at least a step (the stop's rest excepted); their
// motion adds up to the engine's odometry once it stands.
TYPED_TEST(StanceRatchetTest, TheEngineMovesTheStanceOnAllFeetInSteps) {
  using S = TypeParam;
  strider::GaitTable trot = strider::kGaitTrot;
  trot.duty = 0.8f;
  Rig<S> rig(strider::kMammal8, trot);
  GaitEngine<S>& e = rig.engine();
  e.set_step(sc<S>(10.0), sc<S>(1.0 / 2.38));
  e.set_stance_motion(sc<S>(1.3), true);
  e.set_command(sc<S>(4.2), S(0), S(0));
  std::vector<Tick> run;
  rig.run(30.0, run);
  e.set_command(S(0), S(0), S(0));
  ASSERT_TRUE(rig.run_until_standing(run, 10.0));
  double stance_x = 0;
  int moves = 0, small = 0;
  for (size_t k = 1; k < run.size(); ++k) {
    const Tick &a = run[k - 1], &b = run[k];
    bool all_down = true;
    for (bool c : a.contact) all_down = all_down && c;
    std::vector<double> dx;
    for (size_t i = 0; i < b.foot.size(); ++i)
      if (a.contact[i] && b.contact[i]) dx.push_back(b.foot[i].x - a.foot[i].x);
    if (dx.empty()) continue;
    for (double d : dx) {
      EXPECT_NEAR(d, dx[0], 1e-3) << b.t;  // together
      if (!all_down) {
        EXPECT_EQ(d, 0.0) << b.t;
      }
    }
    if (dx[0] != 0.0) {
      ++moves;
      stance_x -= dx[0];
      if (-dx[0] < 1.3 - 1e-3) ++small;
    }
  }
  EXPECT_GT(moves, 50);
  EXPECT_LE(small, 1);  // the stop's rest
  EXPECT_NEAR(stance_x, dbl(e.odometry_x()), strider::ScalarTraits<S>::kIsFixed ? 0.05 : 1e-3);
  EXPECT_NEAR(dbl(e.odometry_x()), 4.2 * 30.0, 4.2 * 3.0);  // the ramps' share
}

}  // namespace
}  // namespace gaittest
