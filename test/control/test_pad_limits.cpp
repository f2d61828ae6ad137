// The RC pad's 100 %: 155 mm/s and 60 deg/s (seed 000), or the top speed of
// the gait the pad walks where that is less (gait/speed_correction.h), so
// that the slider's 100 % is a speed the model really makes. The command
// the robot took is read back from `status` (vx=, wz=), as a user sees it.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <string>

#include "fakes/app_rig.h"
#include "gait/speed_correction.h"
#include "robots/all_robots.h"

namespace {

// The value of ` key=` in a status line; NaN when absent.
double field(const std::string& status, const char* key) {
  const std::string k = std::string(" ") + key + "=";
  const size_t at = status.find(k);
  return at == std::string::npos ? std::nan("") : std::strtod(status.c_str() + at + k.size(), nullptr);
}

struct PadCase {
  const strider::RobotModel* model;
  double forward_mm_s, turn_deg_s;  // at the slider's 100 %
};

// The tops measured in the simulator, firmware mode (docs/results.md,
// "Phone pad per model"), under which each pad's 100 % sits.
const PadCase kCases[] = {
    {&strider::kSprawl8, 155.0, 60.0},    // the pad trots at 100 % (gait_choice.h), which makes both
    {&strider::kHexapod18, 155.0, 36.0},  // tripod: 161 mm/s, turns at most 37.4 deg/s
    {&strider::kSpider12, 26.2, 12.0},    // walk: 26.2 mm/s over 30 s, 12.5 deg/s at most
    {&strider::kMammal8, 17.0, 3.5},      // walk: 16.2-16.4 mm/s over 30 s; turns 3.2-3.8 deg/s
    {&strider::kDog12, 120.0, 20.0},      // crawl: 116-135 mm/s, turns at most ~21 deg/s
};

TEST(PadLimits, FullSliderIsTheSpeedTheModelMakes) {
  for (const PadCase& c : kCases) {
    SCOPED_TRACE(c.model->name);
    strider_test::AppRig rig(*c.model);
    ASSERT_TRUE(rig.began);
    rig.run_ms(3000);  // soft start, stand
    rig.bytes("q");
    rig.bytes("F");
    rig.run_ms(200);
    const std::string forward = rig.reply("status");
    EXPECT_DOUBLE_EQ(field(forward, "vx"), c.forward_mm_s) << forward;
    rig.bytes("G");
    rig.run_ms(200);
    const std::string turn = rig.reply("status");
    EXPECT_DOUBLE_EQ(field(turn, "wz"), c.turn_deg_s) << turn;
    rig.bytes("5");  // the slider scales the model's own 100 %
    rig.bytes("G");
    rig.run_ms(200);
    EXPECT_NEAR(field(rig.reply("status"), "wz"), c.turn_deg_s / 2, 0.05 + 1e-9);  // in whole 0.1 deg/s
    rig.bytes("S");
  }
}

TEST(PadLimits, AGaitNotListedKeepsThePadsDefaults) {
  int32_t linear = 1550, turn = 600, min_turn = -1;
  strider::pad_top_of("spider12", "limp", &linear, &turn, &min_turn);
  EXPECT_EQ(min_turn, 0);
  min_turn = -1;
  strider::pad_top_of("no_such", "walk", &linear, &turn, &min_turn);
  EXPECT_EQ(linear, 1550);
  EXPECT_EQ(turn, 600);
  EXPECT_EQ(min_turn, 0);
  strider::pad_top_of("hexapod18", "tripod", &linear, &turn, &min_turn);  // only its turn is under the default
  EXPECT_EQ(linear, 1550);
  EXPECT_EQ(turn, 360);
  EXPECT_EQ(min_turn, 0);
  strider::pad_top_of("mammal8", "walk", &linear, &turn, &min_turn);
  EXPECT_EQ(min_turn, 17);
}

// mammal8's walk turns its planar feet by sliding them: under 1.7 deg/s they
// stick and slip (docs/results.md, "Phone pad per model"), so the slider's
// 10 and 20 % turn at 1.7 deg/s, either way, and `status` says so; 50 % is
// over it and scales as usual; walking straight is not raised. A model
// without a slowest turn (spider12) scales down to its 10 %.
TEST(PadLimits, TheSliderTurnsNoSlowerThanTheGaitsSlowestHonestTurn) {
  strider_test::AppRig rig(strider::kMammal8);
  ASSERT_TRUE(rig.began);
  rig.run_ms(3000);
  const struct {
    const char* slider;
    const char* button;
    const char* key;
    double expected;
  } cases[] = {{"1", "G", "wz", 1.7}, {"2", "G", "wz", 1.7}, {"2", "I", "wz", -1.7},
               {"5", "G", "wz", 1.7}, {"q", "G", "wz", 3.5}, {"1", "F", "vx", 1.7}};
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.slider) + c.button);
    rig.bytes(c.slider);
    rig.bytes(c.button);
    rig.run_ms(200);
    EXPECT_NEAR(field(rig.reply("status"), c.key), c.expected, 0.05 + 1e-9);
    rig.bytes("S");
    rig.run_ms(200);
  }
  strider_test::AppRig spider(strider::kSpider12);
  ASSERT_TRUE(spider.began);
  spider.run_ms(3000);
  spider.bytes("1");
  spider.bytes("G");
  spider.run_ms(200);
  EXPECT_NEAR(field(spider.reply("status"), "wz"), 1.2, 0.05 + 1e-9);
}

// A commanded body speed through the correction and back is itself (to a
// rounding step), both ways from zero, on a ratio, a ratio less a loss and
// a curve of several points; zero stays zero (standing still is not
// corrected into stepping), and no curve is the same speed. Back to the
// body it is a step off at most where the body gains a step or less per
// step of the gait, two where it gains more (the curve's 1.34).
TEST(SpeedCorrection, CommandAndBodySpeedRoundTrip) {
  const struct {
    strider::SpeedCurve c;
    int32_t step;
  } cases[] = {{strider::affine(10000), 1},
               {strider::affine(9270, 33), 1},
               {strider::affine(4697), 1},
               {{4, {{106, 41}, {239, 146}, {306, 236}, {1372, 1277}}}, 2}};
  for (const auto& k : cases) {
    const strider::SpeedCurve& c = k.c;
    EXPECT_EQ(strider::speed_corrected(0, &c), 0);
    for (int32_t v = -3000; v <= 3000; v += 7) {
      if (v == 0) continue;
      const int32_t g = strider::speed_corrected(v, &c);
      EXPECT_EQ(g > 0, v > 0) << v;
      EXPECT_EQ(strider::speed_corrected(-v, &c), -g) << v;
      EXPECT_LE(std::abs(strider::body_speed_of(g, &c) - v), k.step) << v << " curve of " << int(c.count);
    }
  }
  EXPECT_EQ(strider::speed_corrected(-123, nullptr), -123);
  EXPECT_EQ(strider::body_speed_of(-123, nullptr), -123);
}

// A ratio less a loss: (v + loss) / ratio, rounded to the nearest step; the
// gait under the loss moves the body not at all.
TEST(SpeedCorrection, RatioAndLoss) {
  const strider::SpeedCurve c = strider::affine(9270, 33);
  EXPECT_EQ(strider::speed_corrected(155, &c), 203);  // (155 + 33) / 0.927 = 202.8
  EXPECT_EQ(strider::speed_corrected(-155, &c), -203);
  EXPECT_EQ(strider::body_speed_of(20, &c), 0);  // under the loss: the body does not move
  EXPECT_EQ(strider::body_speed_of(-20, &c), 0);
  EXPECT_EQ(strider::body_speed_of(1000, &c), 894);  // 927 - 33
}

// A curve's points are met exactly, between them it is linear, and beyond
// its ends the end segments go on: below the first the body slows to zero
// along the first segment, above the last it follows the last.
TEST(SpeedCorrection, CurveInterpolatesAndExtends) {
  const strider::SpeedCurve c{3, {{100, 40}, {200, 140}, {1200, 1100}}};
  EXPECT_EQ(strider::speed_corrected(40, &c), 100);
  EXPECT_EQ(strider::speed_corrected(140, &c), 200);
  EXPECT_EQ(strider::speed_corrected(1100, &c), 1200);
  EXPECT_EQ(strider::speed_corrected(90, &c), 150);    // half way along the first segment
  EXPECT_EQ(strider::speed_corrected(620, &c), 700);   // half way along the second
  EXPECT_EQ(strider::speed_corrected(10, &c), 70);     // the first segment extended
  EXPECT_EQ(strider::speed_corrected(1196, &c), 1300);  // the last extended
  EXPECT_EQ(strider::body_speed_of(60, &c), 0);        // the first segment crosses zero at 60
  EXPECT_EQ(strider::body_speed_of(150, &c), 90);
  EXPECT_EQ(strider::body_speed_of(-150, &c), -90);
}

// Every listed curve can be inverted and is a slip the robot can have:
// gait and body speeds rising from point to point, and any positive command
// asks the gait to step forward.
TEST(SpeedCorrection, ListedCurvesRise) {
  for (const strider::SpeedCorrection& e : strider::kSpeedCorrections) {
    for (const strider::SpeedCurve* c : {&e.linear, &e.turn}) {
      SCOPED_TRACE(std::string(e.robot) + " " + e.gait);
      ASSERT_GE(c->count, 2);
      ASSERT_LE(c->count, strider::kSpeedPointsMax);
      for (uint8_t i = 1; i < c->count; ++i) {
        EXPECT_GT(c->at[i].gait, c->at[i - 1].gait) << int(i);
        EXPECT_GT(c->at[i].body, c->at[i - 1].body) << int(i);
      }
      EXPECT_GT(strider::speed_corrected(1, c), 0);
    }
  }
}

}  // namespace
