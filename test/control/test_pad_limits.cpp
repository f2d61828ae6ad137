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
    {&strider::kSpider12, 27.0, 12.0},    // walk: 28.0-28.4 mm/s, 12.5 deg/s at most
    {&strider::kMammal8, 20.0, 60.0},     // walk: 21.3-21.5 mm/s at most; turning not listed
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
    EXPECT_DOUBLE_EQ(field(rig.reply("status"), "wz"), c.turn_deg_s / 2);
    rig.bytes("S");
  }
}

TEST(PadLimits, AGaitNotListedKeepsThePadsDefaults) {
  int32_t linear = 1550, turn = 600;
  strider::pad_top_of("spider12", "limp", &linear, &turn);
  strider::pad_top_of("no_such", "walk", &linear, &turn);
  EXPECT_EQ(linear, 1550);
  EXPECT_EQ(turn, 600);
  strider::pad_top_of("hexapod18", "tripod", &linear, &turn);  // only its turn is under the default
  EXPECT_EQ(linear, 1550);
  EXPECT_EQ(turn, 360);
}

// A commanded body speed through the correction and back is itself (to a
// rounding step), both ways from zero, with and without an offset; zero
// stays zero (standing still is not corrected into stepping).
TEST(SpeedCorrection, CommandAndBodySpeedRoundTrip) {
  const uint16_t cases[][2] = {{10000, 0}, {9270, 33}, {9480, 6}, {4697, 0}};
  for (const auto& c : cases) {
    EXPECT_EQ(strider::speed_corrected(0, c[0], c[1]), 0);
    for (int32_t v = -3000; v <= 3000; v += 7) {
      if (v == 0) continue;
      const int32_t g = strider::speed_corrected(v, c[0], c[1]);
      EXPECT_EQ(g > 0, v > 0) << v;
      EXPECT_LE(std::abs(strider::body_speed_of(g, c[0], c[1]) - v), 1) << v << " per10k " << c[0];
    }
  }
  EXPECT_EQ(strider::body_speed_of(20, 9270, 33), 0);  // under the offset: the body does not move
  EXPECT_EQ(strider::body_speed_of(-20, 9270, 33), 0);
}

}  // namespace
