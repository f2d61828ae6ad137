// The rules of the live gait parameters (gait/gait_tuning.h), each against an
// independent computation: the duties a gait allows against the gait
// tables' own float checks (sampled support, separated swings), the table
// of swing shapes under each other against their paths sampled densely in
// double, and the duty's integer-built float against the float division.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gait/gait_library.h"
#include "gait/gait_tuning.h"
#include "math/float_bits.h"

namespace {

const strider::GaitTable* const kGaits[] = {&strider::kGaitWalk,   &strider::kGaitTrot,   &strider::kGaitPace,
                                            &strider::kGaitCrawl,  &strider::kGaitTripod, &strider::kGaitRipple,
                                            &strider::kGaitWave};

// The fewest feet down of t, sampled as gait_table::keeps_support() does.
uint8_t sampled_fewest_down(const strider::GaitTable& t) {
  uint8_t fewest = t.leg_count;
  for (uint8_t k = 0; k <= t.leg_count; ++k)
    if (strider::gait_table::keeps_support(t, k)) fewest = k;
  return fewest;
}

TEST(GaitTuning, DutiesAllowedMatchTheTablesOwnChecks) {
  for (const strider::GaitTable* g : kGaits) {
    SCOPED_TRACE(g->name);
    const uint8_t own = sampled_fewest_down(*g);
    EXPECT_EQ(strider::fewest_feet_down(*g, strider::table_fraction::swing_span(g->duty)), own);
    for (uint8_t d = 1; d <= strider::kMaxDutyPct; ++d) {
      strider::GaitTable t = *g;
      t.duty = float(d) / 100.0f;
      const bool expect = strider::gait_table::keeps_support(t, own) &&
                          (!t.shift_body || strider::gait_table::swings_separated(t));
      EXPECT_EQ(strider::duty_allowed(*g, d), expect) << "duty " << int(d);
    }
    EXPECT_FALSE(strider::duty_allowed(*g, strider::kMaxDutyPct + 1));
    EXPECT_FALSE(strider::duty_allowed(*g, 0));
  }
}

// The ranges `set duty` names (docs/protocol.md); each gait's own duty in them.
TEST(GaitTuning, DutyRangesPerGait) {
  struct Row {
    const strider::GaitTable* gait;
    int32_t lo;
  };
  const Row rows[] = {{&strider::kGaitWalk, 76},   {&strider::kGaitTrot, 50},   {&strider::kGaitPace, 50},
                      {&strider::kGaitCrawl, 51},  {&strider::kGaitTripod, 50}, {&strider::kGaitRipple, 67},
                      {&strider::kGaitWave, 84}};
  for (const Row& r : rows) {
    SCOPED_TRACE(r.gait->name);
    const strider::TuneRange range = strider::duty_range(*r.gait);
    EXPECT_EQ(range.lo, r.lo);
    EXPECT_EQ(range.hi, strider::kMaxDutyPct);
    const uint8_t own = strider::duty_pct_of(*r.gait);
    EXPECT_NEAR(own, r.gait->duty * 100.0f, 1.0f);
    EXPECT_GE(own + 0.01f, r.gait->duty * 100.0f);
    EXPECT_TRUE(strider::duty_allowed(*r.gait, own));
    std::printf("%-6s duty %.2f, allowed %.2f..%.2f\n", r.gait->name, double(r.gait->duty), range.lo / 100.0,
                range.hi / 100.0);
  }
}

// Shape c is under shape o when no point of c's path rises above o's path at
// the same horizontal progress (the semicircle's apex: half the step height
// at its lowest, all of it at its highest).
double envelope(strider::SwingShape o, double u) {
  double best = -1.0;
  constexpr int kN = 20000;
  for (int k = 0; k <= kN; ++k) {
    const auto p = strider::swing_point(o, float(k) / kN);
    if (std::fabs(double(p.u) - u) < 2e-3) best = std::fmax(best, double(p.w));
  }
  return best;
}

TEST(GaitTuning, SwingsWithinMatchTheSampledPaths) {
  for (uint8_t o = 0; o < strider::kSwingShapeCount; ++o) {
    uint8_t mask = 0;
    for (uint8_t c = 0; c < strider::kSwingShapeCount; ++c) {
      bool under = true;
      const double own_apex = o == uint8_t(strider::SwingShape::kSemicircle) ? 0.5 : 1.0;
      for (int k = 0; k <= 400 && under; ++k) {
        const auto p = strider::swing_point(strider::SwingShape(c), float(k) / 400);
        if (p.w <= 1e-6f) continue;
        under = double(p.w) <= own_apex * envelope(strider::SwingShape(o), double(p.u)) + 1e-3;
      }
      if (under || c == o) mask = uint8_t(mask | (1u << c));
    }
    EXPECT_EQ(strider::swings_within(strider::SwingShape(o)), mask) << strider::to_string(strider::SwingShape(o));
  }
}

TEST(GaitTuning, RatioFloatIsTheNearestFloat) {
  for (uint32_t den = 2; den <= 1000; ++den)
    for (uint32_t num = 1; num < den; ++num)
      ASSERT_EQ(strider::detail::ratio_float(num, den), float(num) / float(den)) << num << "/" << den;
  EXPECT_EQ(strider::detail::ratio_float(67, 100), 0.67f);
  EXPECT_EQ(strider::detail::ratio_float(16777215, 16777216), 16777215.0f / 16777216.0f);
}

TEST(GaitTuning, BoundsCheckEveryParameter) {
  const strider::TuneBounds b{{100, 2000}, {500, 8000}, {30, 500}, {51, 95}, 0x1E};
  using P = strider::TuneParam;
  EXPECT_TRUE(strider::tune_value_allowed(b, P::kStepHeight, 100));
  EXPECT_TRUE(strider::tune_value_allowed(b, P::kStepHeight, 2000));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kStepHeight, 99));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kStepHeight, 2001));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kStepLength, 8001));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kCycle, 29));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kDuty, 50));
  EXPECT_TRUE(strider::tune_value_allowed(b, P::kSwing, uint8_t(strider::SwingShape::kCycloid)));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kSwing, uint8_t(strider::SwingShape::kRectangle)));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kSwing, strider::kSwingShapeCount));
  EXPECT_FALSE(strider::tune_value_allowed(b, P::kSwing, -1));
  const strider::GaitTuning good{1500, 3000, 80, 67, uint8_t(strider::SwingShape::kEllipse), 0};
  EXPECT_TRUE(strider::tuning_allowed(b, good));
  strider::GaitTuning bad = good;
  bad.shape = uint8_t(strider::SwingShape::kBezier);
  EXPECT_FALSE(strider::tuning_allowed(b, bad));
  bad = good;
  bad.cycle_cs = 501;
  EXPECT_FALSE(strider::tuning_allowed(b, bad));
}

}  // namespace
