// The gait engine's parts: gait tables (seed 000, 003), phase clock, swing
// shapes (seed 001), stance motion, support polygon and margin (seed 003
// section 3) against double-precision references.
#include <Eigen/Dense>
#include <map>
#include <random>

#include "gait/body_shift.h"
#include "gait/gait_choice.h"
#include "gait/gait_library.h"
#include "gait/gait_params.h"
#include "gait/phase.h"
#include "gait/stability.h"
#include "gait/stance.h"
#include "gait/swing_trajectory.h"
#include "gait_test_util.h"

namespace gaittest {
namespace {

using strider::GaitList;
using strider::Phase16;
using strider::PhaseClock;
using strider::SupportPolygon;
using strider::SwingPoint;
using strider::SwingShape;

// ---- gait tables ---------------------------------------------------------------

// Legs in lift-off order (stable for equal offsets: by index).
std::vector<int> lift_order(const GaitTable& t) {
  std::vector<int> legs;
  for (int i = 0; i < t.leg_count; ++i) legs.push_back(i);
  std::stable_sort(legs.begin(), legs.end(), [&](int a, int b) { return t.offset[a] < t.offset[b]; });
  return legs;
}

TEST(GaitTable, NamesPerArchitecture) {
  const char* quad[] = {"walk", "trot", "pace", "crawl"};
  const char* hexa[] = {"tripod", "ripple", "wave"};
  for (const RobotModel* m : strider::kAllRobots) {
    const GaitList list = strider::gaits_for(*m);
    ASSERT_EQ(list.count, m->leg_count == 4 ? 4 : 3) << m->name;
    for (uint8_t i = 0; i < list.count; ++i) {
      EXPECT_STREQ(list.items[i]->name, m->leg_count == 4 ? quad[i] : hexa[i]);
      EXPECT_EQ(list.items[i]->leg_count, m->leg_count);
      EXPECT_EQ(strider::find_gait(*m, list.items[i]->name), list.items[i]);
    }
    EXPECT_EQ(strider::find_gait(*m, "gallop"), nullptr);
    EXPECT_EQ(strider::find_gait(*m, nullptr), nullptr);
    EXPECT_NE(strider::find_gait(*m, strider::gait_params_for(*m)->default_gait), nullptr) << m->name;
  }
}

TEST(GaitTable, WalkIsSeed003Order) {
  // Seed 003 section 5: right hind, left front, right front, left hind.
  EXPECT_EQ(lift_order(strider::kGaitWalk), (std::vector<int>{2, 0, 3, 1}));
  for (int i = 0; i < 4; ++i)  // evenly spaced beats
    EXPECT_NEAR(std::fmod(strider::kGaitWalk.offset[lift_order(strider::kGaitWalk)[i]], 1.0), i * 0.25, 1e-6);
  EXPECT_GE(strider::kGaitWalk.duty, 0.75f);  // one leg at a time
  EXPECT_TRUE(strider::kGaitWalk.shift_body);
}

TEST(GaitTable, TrotPaceCrawlPairs) {
  const GaitTable& trot = strider::kGaitTrot;  // diagonals: LF + RH, LH + RF
  EXPECT_EQ(trot.offset[0], trot.offset[2]);
  EXPECT_EQ(trot.offset[1], trot.offset[3]);
  EXPECT_NEAR(std::fabs(trot.offset[0] - trot.offset[1]), 0.5, 1e-6);
  const GaitTable& pace = strider::kGaitPace;  // laterals: LF + LH, RH + RF
  EXPECT_EQ(pace.offset[0], pace.offset[1]);
  EXPECT_EQ(pace.offset[2], pace.offset[3]);
  EXPECT_NEAR(std::fabs(pace.offset[0] - pace.offset[2]), 0.5, 1e-6);
  // Seed 000's crawl: the diagonal pair with limbs 1 and 3 (legs 0, 2) first.
  const GaitTable& crawl = strider::kGaitCrawl;
  EXPECT_EQ(crawl.offset[0], 0.0f);
  EXPECT_EQ(crawl.offset[2], 0.0f);
  EXPECT_EQ(crawl.offset[1], crawl.offset[3]);
  EXPECT_NEAR(crawl.offset[1], 0.5, 1e-6);
  // Six steps: A stand, B+C pair one up, D both down, E pair two up, F down.
  int phases_all_down = 0, phases_pair = 0;
  for (int k = 0; k < 600; ++k) {
    const float ph = (float(k) + 0.5f) / 600.0f;
    int up = 0;
    for (uint8_t i = 0; i < 4; ++i) up += strider::gait_table::in_swing(crawl, i, ph) ? 1 : 0;
    ASSERT_TRUE(up == 0 || up == 2) << ph;
    (up == 0 ? phases_all_down : phases_pair)++;
  }
  EXPECT_NEAR(phases_all_down / 600.0, 1.0 / 3.0, 0.01);  // two windows of 1/6
}

TEST(GaitTable, HexapodGroups) {
  const GaitTable& tri = strider::kGaitTripod;
  for (int i = 0; i < 6; ++i) EXPECT_EQ(tri.offset[i], tri.offset[(i + 2) % 6]);
  EXPECT_NE(tri.offset[0], tri.offset[1]);
  for (const GaitTable* t : {&strider::kGaitRipple, &strider::kGaitWave}) {
    const int most_up = t == &strider::kGaitWave ? 1 : 2;
    for (int k = 0; k < 720; ++k) {
      const float ph = (float(k) + 0.5f) / 720.0f;
      int up = 0;
      for (uint8_t i = 0; i < 6; ++i) up += strider::gait_table::in_swing(*t, i, ph) ? 1 : 0;
      ASSERT_EQ(up, most_up) << t->name << " " << ph;
    }
  }
  // Wave: rear to front on each side.
  EXPECT_EQ(lift_order(strider::kGaitWave), (std::vector<int>{2, 1, 0, 3, 4, 5}));
}

TEST(GaitTable, DutyIsTheSwingFraction) {
  for (const Case& c : all_cases()) {
    for (uint8_t i = 0; i < c.gait->leg_count; ++i) {
      int down = 0;
      const int n = 6000;
      for (int k = 0; k < n; ++k) down += strider::gait_table::in_swing(*c.gait, i, (float(k) + 0.5f) / float(n)) ? 0 : 1;
      EXPECT_NEAR(double(down) / n, c.gait->duty, 1.0 / n + 1e-6) << c.name() << " leg " << int(i);
    }
  }
}

TEST(GaitTable, RelabelLikeSeed000) {
  // Walking right: "limb 4 will be 1, 3 will be 4, 2 will be 3 and 1 will be 2".
  const GaitTable& w = strider::kGaitWalk;
  const GaitTable r = strider::gait_table::relabeled(w, -1);
  EXPECT_EQ(r.offset[3], w.offset[0]);
  EXPECT_EQ(r.offset[2], w.offset[3]);
  EXPECT_EQ(r.offset[1], w.offset[2]);
  EXPECT_EQ(r.offset[0], w.offset[1]);
  const GaitTable back = strider::gait_table::relabeled(r, 1);
  const GaitTable full = strider::gait_table::relabeled(w, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(back.offset[i], w.offset[i]);
    EXPECT_EQ(full.offset[i], w.offset[i]);
  }
  // The crawl's first pair changes with a quarter turn.
  const GaitTable c = strider::gait_table::relabeled(strider::kGaitCrawl, 1);
  EXPECT_EQ(c.offset[1], 0.0f);
  EXPECT_EQ(c.offset[0], 0.5f);
  const GaitTable h = strider::gait_table::relabeled(strider::kGaitTripod, 1);  // 6 legs: unchanged
  for (int i = 0; i < 6; ++i) EXPECT_EQ(h.offset[i], strider::kGaitTripod.offset[i]);
}

// ---- phase clock -----------------------------------------------------------------

// The pad's gait for sprawl8: crawl -> trot above 25 mm/s or 25 deg/s,
// back below 18 mm/s and 18 deg/s; between, the gait walked stays.
// Sideways speed does not count (trot drifts sideways; the crawl does not).
TEST(GaitChoice, Sprawl8ChangesUpAndDownWithHysteresis) {
  char to[strider::kGaitNameBytes] = "";
  using strider::gait_choice_for;
  EXPECT_FALSE(gait_choice_for("sprawl8", "crawl", 155, 0, 0, to));  // 10 %: crawl
  EXPECT_FALSE(gait_choice_for("sprawl8", "crawl", 250, 0, 0, to));  // at the change: still crawl
  EXPECT_TRUE(gait_choice_for("sprawl8", "crawl", 310, 0, 0, to));   // 20 %: trot
  EXPECT_STREQ(to, "trot");
  EXPECT_TRUE(gait_choice_for("sprawl8", "crawl", -1550, 1550, 0, to));  // back and left: trot
  EXPECT_FALSE(gait_choice_for("sprawl8", "crawl", 0, -1550, 0, to));  // sideways: crawl
  EXPECT_TRUE(gait_choice_for("sprawl8", "crawl", 0, 0, -300, to));  // turning at 50 %
  EXPECT_FALSE(gait_choice_for("sprawl8", "crawl", 0, 0, 240, to));
  EXPECT_FALSE(gait_choice_for("sprawl8", "trot", 200, 0, 0, to));   // in the band: stays trot
  EXPECT_FALSE(gait_choice_for("sprawl8", "trot", 100, 0, 200, to)); // turning too fast for crawl
  EXPECT_TRUE(gait_choice_for("sprawl8", "trot", -155, 0, 60, to));  // 10 %: back to crawl
  EXPECT_STREQ(to, "crawl");
  EXPECT_TRUE(gait_choice_for("sprawl8", "trot", 0, 1550, 0, to));   // sideways: back to crawl
  EXPECT_FALSE(gait_choice_for("sprawl8", "trot", 0, 0, 0, to));     // standing still keeps it
  EXPECT_FALSE(gait_choice_for("sprawl8", "pace", 1550, 0, 0, to));  // a gait the user chose
  EXPECT_FALSE(gait_choice_for("dog12", "walk", 1550, 0, 0, to));    // a model not listed
}

TEST(Phase, CrossingAndWrap) {
  PhaseClock clock;
  clock.reset(strider::phase16(0.9));
  int crossings0 = 0, crossings_half = 0, wraps = 0;
  for (int k = 0; k < 1000; ++k) {  // 0.013 cycle per tick: 13 cycles
    wraps += clock.advance(0.013f) ? 1 : 0;
    crossings0 += clock.crossed(0) ? 1 : 0;
    crossings_half += clock.crossed(strider::phase16(0.5)) ? 1 : 0;
  }
  EXPECT_EQ(wraps, 13);
  EXPECT_EQ(crossings0, 13);
  EXPECT_EQ(crossings_half, 13);
  // A mark exactly at the previous phase is not crossed again.
  clock.reset(100);
  clock.advance(0.01f);
  EXPECT_FALSE(clock.crossed(100));
  EXPECT_TRUE(clock.crossed(101));
}

TEST(Phase, FloatAndFixedIncrementsAgree) {
  for (double c : {0.0, 1e-5, 0.004, 0.02, 0.1234, 0.5, 0.9}) {
    const uint32_t f = strider::cycles_to_q32(float(c));
    const uint32_t x = strider::cycles_to_q32(Fixed(c));
    EXPECT_LE(std::fabs(double(f) - double(x)), 65536.0 * 1.01) << c;  // one Fixed LSB of a cycle
  }
  EXPECT_EQ(strider::cycles_to_q32(-1.0f), 0u);
  EXPECT_EQ(strider::cycles_to_q32(Fixed(-1.0)), 0u);
  EXPECT_EQ(strider::phase_to<float>(32768), 0.5f);
  EXPECT_EQ(strider::phase_to<Fixed>(32768), Fixed(0.5));
}

// The Fixed engine takes a table's float duty and offsets from their bits
// (integers only): the same values as the double path (phase16(),
// phase_span(), Fixed(double)) bit for bit, over every float k 2^-20 in
// [0, 1], random floats in [2^-8, 1), and the library's tables, whose values
// are also those of single precision (the AVR's double).
struct TableUnits {
  uint32_t q16, swing;
  int32_t inv, inv_rest;
};
TableUnits double_units(float f) {
  return {uint32_t(Fixed(double(f)).raw()), strider::phase_span(1.0 - double(f)), Fixed(1.0 / double(f)).raw(),
          Fixed(1.0 / (1.0 - double(f))).raw()};
}
void expect_integer_units(float f) {
  namespace tf = strider::table_fraction;
  const TableUnits want = double_units(f);
  ASSERT_EQ(tf::q16(f), want.q16) << f;
  ASSERT_EQ(Phase16(tf::q16(f) & 0xFFFFu), strider::phase16(double(f))) << f;
  ASSERT_EQ(tf::swing_span(f), want.swing) << f;
  if (f > 0.0f) {
    ASSERT_EQ(tf::inverse(f).raw(), want.inv) << f;
  }
  if (f < 1.0f) {
    ASSERT_EQ(tf::inverse_of_rest(f).raw(), want.inv_rest) << f;
  }
}

TEST(Phase, TableFractionsFromTheBitsMatchTheDoublePath) {
  for (uint32_t k = 0; k <= (uint32_t(1) << 20); ++k) expect_integer_units(float(k) / 1048576.0f);
  std::mt19937 rng(5);
  std::uniform_int_distribution<uint32_t> bits(0x3B800000u, 0x3F7FFFFFu);  // [2^-8, 1)
  for (int n = 0; n < 2000000; ++n) expect_integer_units(strider::detail::bits_float(bits(rng)));
  // Single precision (the AVR's double) gives the same for the library.
  const strider::GaitTable* tables[] = {&strider::kGaitWalk,   &strider::kGaitTrot,   &strider::kGaitPace,
                                        &strider::kGaitCrawl,  &strider::kGaitTripod, &strider::kGaitRipple,
                                        &strider::kGaitWave};
  for (const strider::GaitTable* t : tables) {
    const volatile float d = t->duty;  // single precision throughout
    const float rest = 1.0f - d, inv = 1.0f / d, inv_rest = 1.0f / rest;
    EXPECT_EQ(strider::table_fraction::swing_span(t->duty), uint32_t(rest * 65536.0f + 0.5f)) << t->name;
    EXPECT_EQ(strider::table_fraction::inverse(t->duty).raw(), int32_t(inv * 65536.0f + 0.5f)) << t->name;
    EXPECT_EQ(strider::table_fraction::inverse_of_rest(t->duty).raw(), int32_t(inv_rest * 65536.0f + 0.5f))
        << t->name;
    for (int i = 0; i < t->leg_count; ++i) {
      expect_integer_units(t->offset[i]);
      EXPECT_EQ(strider::table_fraction::q16(t->offset[i]), uint32_t(t->offset[i] * 65536.0f + 0.5f)) << t->name;
    }
    expect_integer_units(t->duty);
  }
}

TEST(Phase, TableFractionsOfTinyDutiesWithinOneUnit) {
  // Below 2^-8 the rest 1 - duty is rounded to 2^-31 first: within one
  // Fixed unit of the double path; the other values stay exact.
  namespace tf = strider::table_fraction;
  for (uint32_t u = 0x00000001u; u < 0x3B800000u; u += 997u) {
    const float f = strider::detail::bits_float(u);
    const TableUnits want = double_units(f);
    ASSERT_EQ(tf::q16(f), want.q16) << f;
    ASSERT_EQ(tf::swing_span(f), want.swing) << f;
    ASSERT_EQ(tf::inverse(f).raw(), want.inv) << f;
    ASSERT_LE(std::abs(tf::inverse_of_rest(f).raw() - want.inv_rest), 1) << f;
  }
  EXPECT_EQ(tf::inverse(0.0f).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(tf::inverse_of_rest(1.0f).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(tf::inverse_of_rest(0.0f).raw(), Fixed::kOneRaw);
}

// ---- swing shapes ------------------------------------------------------------------

const SwingShape kShapes[] = {SwingShape::kRectangle, SwingShape::kSemicircle, SwingShape::kEllipse,
                              SwingShape::kCycloid,   SwingShape::kParabola,   SwingShape::kBezier};

template <typename S>
class SwingTest : public ::testing::Test {};
TYPED_TEST_SUITE(SwingTest, Scalars);

// Scalar error of the shapes: float ~1e-6, Fixed's trig and steps ~1e-4.
template <typename S>
double shape_tol() {
  return strider::ScalarTraits<S>::kIsFixed ? 2e-4 : 2e-6;
}

TYPED_TEST(SwingTest, EndsAndApex) {
  using S = TypeParam;
  for (SwingShape shape : kShapes) {
    const SwingPoint<S> a = strider::swing_point(shape, S(0));
    const SwingPoint<S> b = strider::swing_point(shape, S(1));
    EXPECT_NEAR(dbl(a.u), 0.0, shape_tol<S>()) << to_string(shape);
    EXPECT_NEAR(dbl(a.w), 0.0, shape_tol<S>()) << to_string(shape);
    EXPECT_NEAR(dbl(b.u), 1.0, shape_tol<S>()) << to_string(shape);
    EXPECT_NEAR(dbl(b.w), 0.0, shape_tol<S>()) << to_string(shape);
    double top = 0.0, umin = 1.0, umax = 0.0;
    for (int k = 0; k <= 4096; ++k) {
      const SwingPoint<S> p = strider::swing_point(shape, sc<S>(k / 4096.0));
      top = std::max(top, dbl(p.w));
      umin = std::min(umin, dbl(p.u));
      umax = std::max(umax, dbl(p.u));
      ASSERT_GE(dbl(p.w), -shape_tol<S>()) << to_string(shape);
    }
    EXPECT_NEAR(top, 1.0, 2e-4) << to_string(shape);
    EXPECT_NEAR(umin, strider::swing_u_min(shape), 2e-3) << to_string(shape);
    EXPECT_NEAR(umax, strider::swing_u_max(shape), 2e-3) << to_string(shape);
  }
}

TYPED_TEST(SwingTest, KnownAnswers) {
  using S = TypeParam;
  const double t = shape_tol<S>() * 5;
  auto at = [](SwingShape shape, double s) { return strider::swing_point(shape, sc<S>(s)); };
  // Rectangle (seed 001 section 3.2): lift, carry, lower on thirds.
  EXPECT_NEAR(dbl(at(SwingShape::kRectangle, 1.0 / 6).u), 0.0, t);
  EXPECT_NEAR(dbl(at(SwingShape::kRectangle, 1.0 / 6).w), 0.5, t);
  EXPECT_NEAR(dbl(at(SwingShape::kRectangle, 0.5).u), 0.5, t);
  EXPECT_NEAR(dbl(at(SwingShape::kRectangle, 0.5).w), 1.0, t);
  EXPECT_NEAR(dbl(at(SwingShape::kRectangle, 5.0 / 6).w), 0.5, t);
  // Ellipse / semicircle: (1 - cos pi s)/2, sin pi s.
  EXPECT_NEAR(dbl(at(SwingShape::kEllipse, 0.5).u), 0.5, t);
  EXPECT_NEAR(dbl(at(SwingShape::kEllipse, 0.5).w), 1.0, t);
  EXPECT_NEAR(dbl(at(SwingShape::kEllipse, 0.25).u), (1 - std::cos(kPi / 4)) / 2, t);
  EXPECT_NEAR(dbl(at(SwingShape::kSemicircle, 0.25).w), std::sin(kPi / 4), t);
  // Cycloid: s - sin(2 pi s)/(2 pi), (1 - cos 2 pi s)/2.
  EXPECT_NEAR(dbl(at(SwingShape::kCycloid, 0.25).u), 0.25 - 1 / (2 * kPi), t);
  EXPECT_NEAR(dbl(at(SwingShape::kCycloid, 0.25).w), 0.5, t);
  // Parabola: s, 4 s (1 - s).
  EXPECT_NEAR(dbl(at(SwingShape::kParabola, 0.3).u), 0.3, t);
  EXPECT_NEAR(dbl(at(SwingShape::kParabola, 0.3).w), 0.84, t);
  // Semicircle apex: L/2 within [h/2, h].
  EXPECT_NEAR(dbl(strider::swing_apex_mm(SwingShape::kSemicircle, sc<S>(30), sc<S>(20))), 15.0, 1e-3);
  EXPECT_NEAR(dbl(strider::swing_apex_mm(SwingShape::kSemicircle, sc<S>(4), sc<S>(20))), 10.0, 1e-3);
  EXPECT_NEAR(dbl(strider::swing_apex_mm(SwingShape::kSemicircle, sc<S>(90), sc<S>(20))), 20.0, 1e-3);
  EXPECT_NEAR(dbl(strider::swing_apex_mm(SwingShape::kCycloid, sc<S>(90), sc<S>(20))), 20.0, 1e-3);
}

// The 12-point Bezier with CHAMP's control points, exactly, in double.
Eigen::Vector2d bezier_exact(double s) {
  const double x[12] = {-0.15, -0.2805, -0.3, -0.3, -0.3, 0.0, 0.0, 0.0, 0.3032, 0.3032, 0.2826, 0.15};
  const double y[12] = {-0.5, -0.5, -0.3611, -0.3611, -0.3611, -0.3611, -0.3611, -0.3214, -0.3214, -0.3214, -0.5, -0.5};
  double u[12], w[12];
  for (int i = 0; i < 12; ++i) {
    u[i] = i == 0 ? 0.0 : i == 11 ? 1.0 : x[i] / 0.4 + 0.5;
    w[i] = (y[i] + 0.5) / 0.15;
  }
  for (int n = 11; n > 0; --n)  // de Casteljau
    for (int i = 0; i < n; ++i) {
      u[i] = u[i] + (u[i + 1] - u[i]) * s;
      w[i] = w[i] + (w[i + 1] - w[i]) * s;
    }
  return Eigen::Vector2d(u[0], w[0]);
}

TYPED_TEST(SwingTest, BezierMatchesChampCurve) {
  using S = TypeParam;
  double apex = 0.0;
  for (int k = 0; k <= 20000; ++k) apex = std::max(apex, bezier_exact(k / 20000.0).y());
  EXPECT_NEAR(apex, 1.03339, 1e-4);  // CHAMP's curve tops 3.3 % above its nominal height
  // Named bound: 65 nodes, linear interpolation (tools/gen_bezier_table.py).
  const double kBezierTableError = 0.0036;
  double worst = 0.0;
  for (int k = 0; k <= 5000; ++k) {
    const double s = k / 5000.0;
    const SwingPoint<S> p = strider::swing_point(SwingShape::kBezier, sc<S>(s));
    const Eigen::Vector2d e = bezier_exact(s);
    worst = std::max({worst, std::fabs(dbl(p.u) - e.x()), std::fabs(dbl(p.w) - e.y() / apex)});
  }
  std::printf("[ measured ] Bezier table error %.5f (bound %.4f)\n", worst, kBezierTableError);
  EXPECT_LT(worst, kBezierTableError);
}

TYPED_TEST(SwingTest, ContinuousWithBoundedSlopes) {
  // |du/ds| <= 3 and |dw/ds| <= 5 for every shape: the engine's per-tick
  // step bound (gait_test_util.h) rests on these.
  using S = TypeParam;
  const int n = 2000;
  for (SwingShape shape : kShapes) {
    double du = 0.0, dw = 0.0;
    SwingPoint<S> prev = strider::swing_point(shape, S(0));
    for (int k = 1; k <= n; ++k) {
      const SwingPoint<S> p = strider::swing_point(shape, sc<S>(double(k) / n));
      du = std::max(du, std::fabs(dbl(p.u) - dbl(prev.u)) * n);
      dw = std::max(dw, std::fabs(dbl(p.w) - dbl(prev.w)) * n);
      prev = p;
    }
    EXPECT_LE(du, 3.0 + 0.05) << to_string(shape);
    EXPECT_LE(dw, 5.0 + 0.05) << to_string(shape);
    std::printf("[ measured ] %-10s max |du/ds| %.3f, max |dw/ds| %.3f\n", to_string(shape), du, dw);
  }
}

TEST(Swing, NamesRoundTrip) {
  for (SwingShape shape : kShapes) {
    SwingShape back = SwingShape::kRectangle;
    EXPECT_TRUE(strider::parse_swing_shape(strider::to_string(shape), back));
    EXPECT_EQ(back, shape);
  }
  SwingShape s = SwingShape::kCycloid;
  EXPECT_FALSE(strider::parse_swing_shape("circle", s));
  EXPECT_FALSE(strider::parse_swing_shape(nullptr, s));
  EXPECT_EQ(s, SwingShape::kCycloid);
}

// ---- stance --------------------------------------------------------------------------

template <typename S>
class StanceTest : public ::testing::Test {};
TYPED_TEST_SUITE(StanceTest, Scalars);

// The exact motion of a body at constant body-frame velocity v turning at w
// for dt: the arc D = [[sin t, -(1 - cos t)], [1 - cos t, sin t]] v / w.
Eigen::Vector3d arc(double vx, double vy, double wz, double dt) {
  const double t = wz * dt;
  if (std::fabs(t) < 1e-9) return Eigen::Vector3d(vx * dt, vy * dt, 0);
  return Eigen::Vector3d(std::sin(t) * vx - (1 - std::cos(t)) * vy, (1 - std::cos(t)) * vx + std::sin(t) * vy, 0) / wz;
}

TYPED_TEST(StanceTest, GroundPointMovesByTheInverseStep) {
  using S = TypeParam;
  // Fixed: dt = 0.02 s is 1311 / 65536 (2e-4 relative), on steps up to 11 mm.
  const double tol = strider::ScalarTraits<S>::kIsFixed ? 1e-2 : 1e-4;  // [mm]
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-250, 250), vel(-400, 400), yaw(-3, 3);
  double worst = 0.0;
  for (int n = 0; n < STRIDER_RANDOM_CASES; ++n) {
    const double vx = vel(rng), vy = vel(rng), wz = yaw(rng), dt = 0.02;
    const strider::BodyStep<S> step = strider::BodyStep<S>::make(sc<S>(vx), sc<S>(vy), sc<S>(wz), sc<S>(dt));
    const Eigen::Vector3d p(pos(rng), pos(rng), -100);
    const Vec3<S> q = step.move_ground_point(Vec3<S>(sc<S>(p.x()), sc<S>(p.y()), sc<S>(p.z())));
    const Eigen::Vector3d ref = Eigen::AngleAxisd(-wz * dt, Eigen::Vector3d::UnitZ()) * (p - arc(vx, vy, wz, dt));
    worst = std::max({worst, std::fabs(dbl(q.x) - ref.x()), std::fabs(dbl(q.y) - ref.y())});
    ASSERT_NEAR(dbl(q.x), ref.x(), tol);
    ASSERT_NEAR(dbl(q.y), ref.y(), tol);
    ASSERT_EQ(dbl(q.z), -100.0);
  }
  std::printf("[ measured ] stance step error %.2e mm (bound %.0e)\n", worst, tol);
}

TYPED_TEST(StanceTest, SmallAngleSeriesBound) {
  using S = TypeParam;
  const double bound = strider::ScalarTraits<S>::kIsFixed ? 1e-4 : 3e-5;  // named: |a| <= 0.5
  double worst = 0.0;
  for (int k = -500; k <= 500; ++k) {
    const double a = k / 1000.0;
    S c, s;
    strider::small_angle_cos_sin(sc<S>(a), c, s);
    worst = std::max({worst, std::fabs(dbl(c) - std::cos(a)), std::fabs(dbl(s) - std::sin(a))});
  }
  EXPECT_LT(worst, bound);
}

// Fixed's touchdown_frame() computes the offset and the rotation directly:
// the bits must be those of the generic version's two touchdown_point()s.
TEST(Stance, FixedTouchdownFrameIsTheTwoPoints) {
  using strider::Fixed;
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> stride(-400.0, 400.0), turn(-1.6, 1.6), duty(0.05, 0.95);
  for (int k = 0; k < 4 * STRIDER_RANDOM_CASES; ++k) {
    const Fixed vx(k % 7 == 0 ? 0.0 : stride(rng)), vy(k % 5 == 0 ? 0.0 : stride(rng));
    const Fixed wz(k % 11 == 0 ? 1e-4 : turn(rng)), ts(duty(rng));
    const Vec3<Fixed> o = strider::touchdown_point(Vec3<Fixed>(), vx, vy, wz, ts);
    const Vec3<Fixed> e = strider::touchdown_point(Vec3<Fixed>(Fixed(1), Fixed(0), Fixed(0)), vx, vy, wz, ts);
    Fixed dx, dy, c, s;
    strider::touchdown_frame(vx, vy, wz, ts, dx, dy, c, s);
    ASSERT_EQ(dx.raw(), o.x.raw()) << k;
    ASSERT_EQ(dy.raw(), o.y.raw()) << k;
    ASSERT_EQ(c.raw(), (e.x - o.x).raw()) << k;
    ASSERT_EQ(s.raw(), (e.y - o.y).raw()) << k;
  }
}

TYPED_TEST(StanceTest, TouchdownCentresTheStance) {
  using S = TypeParam;
  const double tol = strider::ScalarTraits<S>::kIsFixed ? 0.02 : 1e-3;  // [mm]
  const Eigen::Vector3d home(120, 80, -90);
  for (double wz : {0.0, 0.5, -1.2}) {
    const double ts = 0.6, vx = 100, vy = -40;
    const Vec3<S> td = strider::touchdown_point(Vec3<S>(sc<S>(home.x()), sc<S>(home.y()), sc<S>(home.z())),
                                                sc<S>(vx), sc<S>(vy), sc<S>(wz), sc<S>(ts));
    // March the stance; it ends at home turned the other way about the
    // turning centre (for a translation: mirrored through home).
    Vec3<S> p = td;
    const int n = 30;
    const strider::BodyStep<S> step = strider::BodyStep<S>::make(sc<S>(vx), sc<S>(vy), sc<S>(wz), sc<S>(ts / n));
    for (int k = 0; k < n; ++k) p = step.move_ground_point(p);
    Eigen::Vector3d start, end;
    if (wz == 0.0) {
      start = home + Eigen::Vector3d(vx, vy, 0) * ts / 2;
      end = home - Eigen::Vector3d(vx, vy, 0) * ts / 2;
    } else {
      const Eigen::Vector3d c(-vy / wz, vx / wz, 0);
      start = Eigen::AngleAxisd(wz * ts / 2, Eigen::Vector3d::UnitZ()) * (home - c) + c;
      end = Eigen::AngleAxisd(-wz * ts / 2, Eigen::Vector3d::UnitZ()) * (home - c) + c;
    }
    EXPECT_NEAR(dbl(td.x), start.x(), tol) << wz;
    EXPECT_NEAR(dbl(td.y), start.y(), tol) << wz;
    EXPECT_NEAR(dbl(p.x), end.x(), tol * 5) << wz;
    EXPECT_NEAR(dbl(p.y), end.y(), tol * 5) << wz;
    EXPECT_EQ(dbl(td.z), -90.0);
  }
  EXPECT_EQ(dbl(strider::stance_sink_mm(sc<S>(5), S(0))), 0.0);
  EXPECT_EQ(dbl(strider::stance_sink_mm(sc<S>(5), S(1))), 0.0);
  EXPECT_NEAR(dbl(strider::stance_sink_mm(sc<S>(5), sc<S>(0.5))), 5.0, 1e-3);
}

// ---- support polygon and margin (seed 003 section 3) --------------------------------

// Double reference: signed distance of p to the convex hull of `pts`
// (brute force: hull edges are the pairs with every point on one side).
double ref_signed_distance(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& p) {
  auto seg = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& x) {
    const Eigen::Vector2d e = b - a;
    const double l2 = e.squaredNorm();
    const double t = l2 > 0 ? std::clamp((x - a).dot(e) / l2, 0.0, 1.0) : 0.0;
    return (a + t * e - x).norm();
  };
  if (pts.size() == 1) return -(pts[0] - p).norm();
  double out = 1e9, in = 1e9;
  bool inside = pts.size() >= 3, any_edge = false;
  for (size_t i = 0; i < pts.size(); ++i)
    for (size_t j = 0; j < pts.size(); ++j) {
      if (i == j) continue;
      const Eigen::Vector2d e = pts[j] - pts[i];
      if (e.norm() < 1e-9) continue;
      bool hull = true;
      for (size_t k = 0; k < pts.size() && hull; ++k) {
        const Eigen::Vector2d r = pts[k] - pts[i];
        if (e.x() * r.y() - e.y() * r.x() < -1e-9) hull = false;
      }
      if (!hull) continue;
      any_edge = true;
      out = std::min(out, seg(pts[i], pts[j], p));
      const Eigen::Vector2d r = p - pts[i];
      const double d = (e.x() * r.y() - e.y() * r.x()) / e.norm();
      if (pts.size() >= 3) {
        if (d < 0) inside = false;
        in = std::min(in, d);
      }
    }
  if (!any_edge) return -(pts[0] - p).norm();
  return inside ? in : -out;
}

template <typename S>
class StabilityTest : public ::testing::Test {};
TYPED_TEST_SUITE(StabilityTest, Scalars);

TYPED_TEST(StabilityTest, KnownAnswers) {
  using S = TypeParam;
  // A 200 mm square, pads of 10 mm, CoM at the centre: 100 + 10.
  Vec3<S> f[5] = {Vec3<S>(sc<S>(100), sc<S>(100), S(0)), Vec3<S>(sc<S>(-100), sc<S>(100), S(0)),
                  Vec3<S>(sc<S>(-100), sc<S>(-100), S(0)), Vec3<S>(sc<S>(100), sc<S>(-100), S(0)),
                  Vec3<S>(sc<S>(0), sc<S>(50), S(0))};
  bool all[5] = {true, true, true, true, true};
  SupportPolygon<S> poly;
  poly.build(f, all, 5, sc<S>(10), strider::units::unit_shift(sc<S>(400)));
  EXPECT_EQ(poly.size(), 4);  // the inner foot is not a vertex
  EXPECT_NEAR(dbl(poly.margin(f, S(0), S(0))), 110.0, 0.01);
  EXPECT_NEAR(dbl(poly.margin(f, sc<S>(90), S(0))), 20.0, 0.01);
  EXPECT_NEAR(dbl(poly.margin(f, sc<S>(130), S(0))), -20.0, 0.01);  // outside: negative
  EXPECT_NEAR(dbl(poly.margin(f, sc<S>(130), sc<S>(140))), 10.0 - 50.0, 0.01);  // nearest is a corner
  // Three feet (seed 003's walk): the triangle without the rear right foot.
  bool three[5] = {true, true, false, true, false};
  poly.build(f, three, 5, S(0), strider::units::unit_shift(sc<S>(400)));
  EXPECT_EQ(poly.size(), 3);
  EXPECT_NEAR(dbl(poly.margin(f, S(0), S(0))), 0.0, 0.01);  // on the diagonal
  EXPECT_NEAR(dbl(poly.margin(f, sc<S>(10), sc<S>(10))), 20.0 / std::sqrt(2.0), 0.01);
  // Two feet (seed 000's crawl): a strip of half-width r around the diagonal.
  bool two[5] = {true, false, true, false, false};
  poly.build(f, two, 5, sc<S>(10), strider::units::unit_shift(sc<S>(400)));
  EXPECT_EQ(poly.size(), 2);
  EXPECT_NEAR(dbl(poly.margin(f, S(0), S(0))), 10.0, 0.01);
  EXPECT_NEAR(dbl(poly.margin(f, sc<S>(5), sc<S>(-5))), 10.0 - std::sqrt(50.0), 0.01);
  EXPECT_NEAR(dbl(poly.margin(f, sc<S>(110), sc<S>(110))), 10.0 - std::sqrt(200.0), 0.01);  // past the end
  bool one[5] = {false, false, false, false, true};
  poly.build(f, one, 5, sc<S>(10), strider::units::unit_shift(sc<S>(400)));
  EXPECT_NEAR(dbl(poly.margin(f, S(0), sc<S>(50))), 10.0, 0.01);
  bool none[5] = {};
  poly.build(f, none, 5, sc<S>(10), strider::units::unit_shift(sc<S>(400)));
  EXPECT_EQ(dbl(poly.margin(f, S(0), S(0))), strider::kNoSupportMarginMm);
}

TYPED_TEST(StabilityTest, MatchesDoubleReference) {
  using S = TypeParam;
  const double tol = strider::ScalarTraits<S>::kIsFixed ? 0.02 : 1e-3;  // [mm]
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-350, 350), pad(0, 20);
  std::uniform_int_distribution<int> count(1, 6), bit(0, 1);
  double worst = 0.0;
  for (int n = 0; n < STRIDER_RANDOM_CASES; ++n) {
    const int legs = count(rng);
    Vec3<S> f[6];
    bool c[6];
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < legs; ++i) {
      f[i] = Vec3<S>(sc<S>(pos(rng)), sc<S>(pos(rng)), S(0));
      c[i] = bit(rng) == 1;
      if (c[i]) pts.emplace_back(dbl(f[i].x), dbl(f[i].y));
    }
    if (pts.empty()) continue;
    const double r = pad(rng);
    SupportPolygon<S> poly;
    poly.build(f, c, uint8_t(legs), sc<S>(r), strider::units::unit_shift(sc<S>(800)));
    const Eigen::Vector2d p(pos(rng) * 0.5, pos(rng) * 0.5);
    const Eigen::Vector2d pq(dbl(sc<S>(p.x())), dbl(sc<S>(p.y())));
    const double want = r + ref_signed_distance(pts, pq);
    const double got = dbl(poly.margin(f, sc<S>(p.x()), sc<S>(p.y())));
    worst = std::max(worst, std::fabs(got - want));
    ASSERT_NEAR(got, want, tol) << "case " << n << " feet " << pts.size();
  }
  std::printf("[ measured ] margin error %.2e mm (bound %.0e)\n", worst, tol);
}

TYPED_TEST(StabilityTest, ConstrainReachesTheMargin) {
  using S = TypeParam;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-20, 20), pos(-150, 150);
  double worst = 1e9;
  for (int n = 0; n < STRIDER_RANDOM_CASES; ++n) {
    // A quadruped stance with one or two feet lifted, as the walk and crawl do.
    Vec3<S> f[4] = {Vec3<S>(sc<S>(100 + jitter(rng)), sc<S>(80 + jitter(rng)), S(0)),
                    Vec3<S>(sc<S>(-100 + jitter(rng)), sc<S>(80 + jitter(rng)), S(0)),
                    Vec3<S>(sc<S>(-100 + jitter(rng)), sc<S>(-80 + jitter(rng)), S(0)),
                    Vec3<S>(sc<S>(100 + jitter(rng)), sc<S>(-80 + jitter(rng)), S(0))};
    const int lifted = n % 6;
    bool c[4] = {true, true, true, true};
    if (lifted < 4) c[lifted] = false;
    else { c[lifted - 4] = false; c[lifted - 2] = false; }  // a diagonal pair
    const double r = lifted < 4 ? 5.0 : 10.0, want = 4.0;
    SupportPolygon<S> poly;
    poly.build(f, c, 4, sc<S>(r), strider::units::unit_shift(sc<S>(400)));
    S x = sc<S>(pos(rng)), y = sc<S>(pos(rng));
    poly.constrain(f, x, y, sc<S>(want), false);
    const double m = dbl(poly.margin(f, x, y));
    worst = std::min(worst, m);
    ASSERT_GT(m, want - 0.01) << "case " << n;
  }
  std::printf("[ measured ] constrain: least margin %.3f mm (asked 4)\n", worst);
}

TYPED_TEST(StabilityTest, ConstrainAlongXOnly) {
  using S = TypeParam;
  // mammal8's stance (planar legs: the body shifts along x only).
  Vec3<S> f[4] = {Vec3<S>(sc<S>(60), sc<S>(45), S(0)), Vec3<S>(sc<S>(-60), sc<S>(45), S(0)),
                  Vec3<S>(sc<S>(-75), sc<S>(-45), S(0)), Vec3<S>(sc<S>(75), sc<S>(-45), S(0))};
  bool c[4] = {true, true, false, true};
  SupportPolygon<S> poly;
  poly.build(f, c, 4, sc<S>(5), strider::units::unit_shift(sc<S>(400)));
  S x = S(0), y = S(0);
  poly.constrain(f, x, y, sc<S>(8), true);
  EXPECT_EQ(dbl(y), 0.0);
  EXPECT_GT(dbl(x), 0.0);  // forward, away from the lifted rear foot
  EXPECT_NEAR(dbl(poly.margin(f, x, y)), 8.0, 0.05);
}

}  // namespace
}  // namespace gaittest
