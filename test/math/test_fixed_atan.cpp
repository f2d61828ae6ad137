// Fixed atan2, asin and acos against long double of the exact Q16.16
// inputs: dense sweeps, exhaustive [-1, 1], edge tables, symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "math/fixed_math.h"
#include "math_test_util.h"

using strider::Fixed;
using strider_test::kPiL;
using strider_test::MaxError;
using strider_test::raw_to_ld;
using strider_test::Xorshift;

namespace {

// Required: atan2 3e-5, asin/acos 6e-5 [rad]. The design gives 0.5 LSB final
// rounding + 0.13 LSB table + 0.08 LSB chord + the ratio (< 0.01 LSB); the
// tests hold it to that, so a regression inside the requirement still fails.
constexpr double kAtan2AbsError = 0.75 * strider_test::kLsb;
constexpr double kAsinAcosAbsError = 0.75 * strider_test::kLsb;
static_assert(kAtan2AbsError <= 3e-5 && kAsinAcosAbsError <= 6e-5, "design bounds within the requirement");
// round(pi 2^16), round(pi/2 2^16), round(pi/4 2^16), round(3 pi/4 2^16).
constexpr int32_t kPiRaw = 205887, kHalfPiRaw = 102944, kQuarterPiRaw = 51472, kThreeQuarterPiRaw = 154416;

double atan2_error(int32_t y, int32_t x) {
  const long double exact = std::atan2(static_cast<long double>(y), static_cast<long double>(x));
  const long double got = raw_to_ld(strider::atan2(Fixed::from_raw(y), Fixed::from_raw(x)).raw());
  // atan2 is discontinuous at pi / -pi: compare on the circle there.
  return static_cast<double>(strider_test::angle_diff(got, exact));
}

// Calls f(y, x) for the points on circles of radius 1.37 * 2^-14 to 2^14 at
// angle steps of pi / 2048 (~0.0015 rad), rounded to Q16.16 raw.
template <typename F>
void for_each_circle_point(F&& f) {
  for (int e = -14; e <= 14; ++e) {
    const long double r = std::ldexp(1.0L, e) * 1.37L;
    for (int k = -2048; k <= 2048; ++k) {
      const long double th = k * kPiL / 2048;
      const int32_t x = static_cast<int32_t>(std::lround(r * std::cos(th) * 65536.0L));
      const int32_t y = static_cast<int32_t>(std::lround(r * std::sin(th) * 65536.0L));
      f(y, x);
    }
  }
}

TEST(FixedAtanTables, AtanTableMatchesItsFormula) {
  for (uint16_t i = 0; i <= 256; ++i) {
    const double t = i / 256.0;
    EXPECT_LE(std::fabs(strider::flash_u16(strider::detail::FixedTables<>::kAtan, i) - (t - std::atan(t)) * 262144.0), 0.5)
        << i;
  }
  EXPECT_EQ(strider::flash_u16(strider::detail::FixedTables<>::kAtan, 257),
            strider::flash_u16(strider::detail::FixedTables<>::kAtan, 256));
}

TEST(FixedAtan2, EdgeTable) {
  auto at = [](int32_t y, int32_t x) { return strider::atan2(Fixed::from_raw(y), Fixed::from_raw(x)).raw(); };
  const int32_t one = 65536;
  EXPECT_EQ(at(0, 0), 0);
  EXPECT_EQ(at(0, one), 0);
  EXPECT_EQ(at(one, 0), kHalfPiRaw);
  EXPECT_EQ(at(-one, 0), -kHalfPiRaw);
  EXPECT_EQ(at(0, -one), kPiRaw);
  EXPECT_EQ(at(one, one), kQuarterPiRaw);
  EXPECT_EQ(at(-one, -one), -kThreeQuarterPiRaw);
  EXPECT_EQ(at(Fixed::kMaxRaw, Fixed::kMaxRaw), kQuarterPiRaw);
  EXPECT_EQ(at(Fixed::kMinRaw, Fixed::kMinRaw), -kThreeQuarterPiRaw);
  EXPECT_EQ(at(one, -one), kThreeQuarterPiRaw);
  EXPECT_EQ(at(Fixed::kMinRaw, 0), -kHalfPiRaw);
  EXPECT_EQ(at(0, Fixed::kMinRaw), kPiRaw);
  EXPECT_EQ(at(1, Fixed::kMaxRaw), 0);         // tiny over huge
  EXPECT_EQ(at(Fixed::kMaxRaw, 1), kHalfPiRaw);
  EXPECT_EQ(at(1, 1), kQuarterPiRaw);           // tiny over tiny
  EXPECT_EQ(at(-1, 1), -kQuarterPiRaw);
  EXPECT_NEAR(at(1, -Fixed::kMaxRaw) / 65536.0, 3.14159265358979, strider_test::kLsb);
  EXPECT_NEAR(strider::atan2(Fixed(1), Fixed(2)).to_double(), std::atan2(1.0, 2.0), kAtan2AbsError);
  EXPECT_NEAR(strider::atan2(Fixed(-300), Fixed(-400)).to_double(), std::atan2(-300.0, -400.0), kAtan2AbsError);
}

// The circle points against the exact angle of each rounded point.
TEST(FixedAtan2, CircleSweep) {
  MaxError err("Fixed atan2, circle sweep");
  for_each_circle_point([&](int32_t y, int32_t x) { err.add(atan2_error(y, x), y, x); });
  err.expect_below(kAtan2AbsError);
}

TEST(FixedAtan2, RandomPairsAndSmallGrid) {
  MaxError err("Fixed atan2, random pairs and every pair in [-256, 256]^2 raw");
  Xorshift rng(555);
  for (int i = 0; i < STRIDER_RANDOM_CASES * 1000; ++i) {
    const int32_t y = rng.raw_any(), x = rng.raw_any();
    err.add(atan2_error(y, x), y, x);
  }
  for (int32_t y = -256; y <= 256; ++y)
    for (int32_t x = -256; x <= 256; ++x) err.add(atan2_error(y, x), y, x);
  err.expect_below(kAtan2AbsError);
}

TEST(FixedAtan2, Symmetries) {
  Xorshift rng(8);
  for (int i = 0; i < STRIDER_RANDOM_CASES * 100; ++i) {
    const int32_t y = rng.raw_any(), x = rng.raw_any();  // never min(): -y exists
    const Fixed fy = Fixed::from_raw(y), fx = Fixed::from_raw(x);
    const int32_t a = strider::atan2(fy, fx).raw();
    if (y != 0) {
      ASSERT_EQ(strider::atan2(-fy, fx).raw(), -a) << y << " " << x;  // odd in y, bit-exact
    }
    ASSERT_LE(std::abs(a), kPiRaw);
    // Mirror in x and swap of the axes: within 1 LSB (the constants round).
    if (y > 0 && x > 0) {
      ASSERT_LE(std::abs(strider::atan2(fy, -fx).raw() - (kPiRaw - a)), 1) << y << " " << x;
      ASSERT_LE(std::abs(strider::atan2(fx, fy).raw() - (kHalfPiRaw - a)), 1) << y << " " << x;
    }
  }
}

// The leg solvers' atan2 (detail::atan2_lean_raw; on the AVR an assembly
// kernel that test_avr_exact holds bit-identical to this C path): the
// documented bound of 6e-5 rad for pairs of every magnitude and sign, plus
// the circle sweep near the diagonal, where its ratio nears 1.
TEST(FixedAtan2Lean, RandomPairsCirclesAndEdges) {
  constexpr double kLeanBound = 6e-5;  // docs/fixed-point.md, "Leg IK fast path"
  auto lean_error = [](int32_t y, int32_t x) {
    const long double exact = std::atan2(static_cast<long double>(y), static_cast<long double>(x));
    return static_cast<double>(strider_test::angle_diff(raw_to_ld(strider::detail::atan2_lean_raw(y, x)), exact));
  };
  MaxError err("Fixed lean atan2 (leg solvers), random pairs, circles, edges");
  Xorshift rng(4242);
  for (int i = 0; i < STRIDER_RANDOM_CASES * 1000; ++i) {
    const int32_t y = rng.raw_any(), x = rng.raw_any();
    err.add(lean_error(y, x), y, x);
  }
  for_each_circle_point([&](int32_t y, int32_t x) { err.add(lean_error(y, x), y, x); });
  const int32_t edges[] = {0, 1, -1, 0x7FFFFF, 0x1000000, -0x1000000, Fixed::kMaxRaw, Fixed::kMinRaw, 12345678};
  for (int32_t y : edges)
    for (int32_t x : edges) err.add(lean_error(y, x), y, x);
  err.expect_below(kLeanBound);
  EXPECT_EQ(strider::detail::atan2_lean_raw(0, 0), 0);
  EXPECT_EQ(strider::detail::atan2_lean_raw(0, -5), kPiRaw);
  EXPECT_NEAR(strider::detail::atan2_lean_raw(7, 0), kHalfPiRaw, 1);  // pi/2 truncated in the fold
  EXPECT_EQ(strider::detail::atan2_lean_raw(-7, 0), -strider::detail::atan2_lean_raw(7, 0));
}

TEST(FixedAsinAcos, EdgeTable) {
  EXPECT_EQ(strider::asin(Fixed(0)).raw(), 0);
  EXPECT_EQ(strider::acos(Fixed(0)).raw(), kHalfPiRaw);
  EXPECT_EQ(strider::asin(Fixed(1)).raw(), kHalfPiRaw);
  EXPECT_EQ(strider::asin(Fixed(-1)).raw(), -kHalfPiRaw);
  EXPECT_EQ(strider::acos(Fixed(1)).raw(), 0);
  EXPECT_EQ(strider::acos(Fixed(-1)).raw(), kPiRaw);
  EXPECT_EQ(strider::asin(Fixed(0.5)).raw(), static_cast<int32_t>(std::lround(std::asin(0.5) * 65536)));
  EXPECT_EQ(strider::acos(Fixed(0.5)).raw(), static_cast<int32_t>(std::lround(std::acos(0.5) * 65536)));
  // Clamped inputs (seed 001's math_error_handler case).
  EXPECT_EQ(strider::asin(Fixed(2)).raw(), kHalfPiRaw);
  EXPECT_EQ(strider::asin(Fixed::min()).raw(), -kHalfPiRaw);
  EXPECT_EQ(strider::acos(Fixed::max()).raw(), 0);
  EXPECT_EQ(strider::acos(Fixed(-5)).raw(), kPiRaw);
  EXPECT_EQ(strider::acos(Fixed::from_raw(65537)).raw(), 0);
  // One step inside +-1, where 1 - x^2 has no bits left in Q16.16.
  const double below_one = 65535.0 / 65536.0;
  EXPECT_NEAR(strider::acos(Fixed::from_raw(65535)).to_double(), std::acos(below_one), kAsinAcosAbsError);
  EXPECT_NEAR(strider::asin(Fixed::from_raw(-65535)).to_double(), -std::asin(below_one), kAsinAcosAbsError);
  EXPECT_NEAR(strider::asin(Fixed::from_raw(1)).to_double(), 1.0 / 65536, 1e-9);
}

// Every representable input in [-1, 1].
TEST(FixedAsinAcos, EveryInputInUnitInterval) {
  MaxError es("Fixed asin, every raw in [-1, 1]"), ec("Fixed acos, every raw in [-1, 1]");
  for (int32_t raw = -65536; raw <= 65536; ++raw) {
    const long double x = raw_to_ld(raw);
    const int32_t s = strider::asin(Fixed::from_raw(raw)).raw();
    const int32_t c = strider::acos(Fixed::from_raw(raw)).raw();
    es.add(static_cast<double>(raw_to_ld(s) - std::asin(x)), static_cast<double>(x));
    ec.add(static_cast<double>(raw_to_ld(c) - std::acos(x)), static_cast<double>(x));
    // Symmetries: asin odd (bit-exact), acos(-x) = pi - acos(x) and
    // asin + acos = pi/2 within 1 LSB.
    ASSERT_EQ(strider::asin(Fixed::from_raw(-raw)).raw(), -s) << raw;
    ASSERT_LE(std::abs(strider::acos(Fixed::from_raw(-raw)).raw() - (kPiRaw - c)), 1) << raw;
    ASSERT_LE(std::abs(s + c - kHalfPiRaw), 1) << raw;
  }
  es.expect_below(kAsinAcosAbsError);
  ec.expect_below(kAsinAcosAbsError);
}

}  // namespace
