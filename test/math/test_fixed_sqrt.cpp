// Fixed sqrt and hypot: the table and Newton stages against exact integer
// roots, dense sweeps against long double, edge tables, symmetry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "math/fixed_math.h"
#include "math_test_util.h"

using strider::Fixed;
using strider_test::MaxError;
using strider_test::Xorshift;

namespace {

// Named bounds. sqrt: the Newton root is within 1 unit of 2^-11 of sqrt(m)
// and the result drops at least 3 of those bits, so 0.5 + 1/8 LSB.
constexpr double kSqrtErrorLsb = 0.625;
constexpr double kSqrtMaxNotRoundedShare = 0.01;  // results 1 LSB from correct rounding
// hypot: within 1 LSB while max(|a|, |b|) < 1024 (design: 0.5 rounding +
// 0.25 Newton root + the dropped low products), relative 2^-26 above.
constexpr double kHypotErrorLsb = 0.8;
constexpr double kHypotRelError = 1.5e-8;
constexpr double kHypotSmallLimit = 1024.0 * 65536.0;  // [raw]

uint64_t isqrt_u64(uint64_t n) {
  uint64_t r = static_cast<uint64_t>(std::sqrt(static_cast<long double>(n)));
  while (r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return r;
}

// round(sqrt(raw 2^16)) exactly, in raw units.
int32_t sqrt_correctly_rounded(int32_t raw) {
  const uint64_t n = static_cast<uint64_t>(raw) << 16;
  const uint64_t f = isqrt_u64(n);
  return static_cast<int32_t>(n - f * f > f ? f + 1 : f);
}

double sqrt_error_lsb(int32_t raw) {
  const long double exact = std::sqrt(static_cast<long double>(raw) * 65536.0L);
  return static_cast<double>(static_cast<long double>(strider::sqrt(Fixed::from_raw(raw)).raw()) - exact);
}

TEST(FixedSqrtTables, SqrtTableMatchesItsFormula) {
  for (uint16_t k = 0; k < 193; ++k) {
    const uint64_t n = static_cast<uint64_t>(64 + k) << 24;
    const uint64_t r = isqrt_u64(n);
    const uint64_t rounded = n - r * r > r ? r + 1 : r;
    EXPECT_EQ(strider::flash_u16(strider::detail::FixedTables<>::kSqrt, k), rounded - 32768) << k;
  }
}

TEST(FixedSqrtTables, RecipTableMatchesItsFormula) {
  for (uint16_t j = 0; j < 129; ++j) {
    const double exact = 4194304.0 / (128 + j);
    EXPECT_LE(std::fabs(strider::flash_u16(strider::detail::FixedTables<>::kRecip, j) - exact), 0.5) << j;
  }
}

// The interpolated reciprocal over every 16-bit head and a spread of tails.
TEST(FixedSqrtTables, InterpolatedReciprocalWithinTwoToMinus13) {
  MaxError err("recip_q30 relative error", false);
  for (uint32_t h16 = 0x8000; h16 <= 0xFFFF; ++h16) {
    for (uint32_t f8 : {0u, 1u, 77u, 128u, 200u, 255u}) {
      const double h = static_cast<double>((h16 << 16) | (f8 << 8));
      const double exact = std::ldexp(1.0, 46) / h;
      const double got = strider::detail::recip_q30(static_cast<uint16_t>(h16), static_cast<uint8_t>(f8));
      err.add((got - exact) / exact, static_cast<double>(h16), static_cast<double>(f8));
    }
  }
  err.expect_below(std::ldexp(1.0, -13));
}

// The interpolated estimate is constant over each 256-wide step of m while
// floor(sqrt(m)) is monotone, so the two ends of every step bound the error:
// this covers all 3 * 2^30 normalised radicands.
TEST(FixedSqrtCore, TableEstimateWithinOneOfFloorForEveryRadicand) {
  int worst_low = 0, worst_high = 0;
  uint64_t floor_root = 1u << 15;  // floor(sqrt(m)), advanced as m grows
  for (uint32_t step = 1u << 22; step < (1u << 24); ++step) {
    for (uint32_t low : {0u, 255u}) {
      const uint32_t m = (step << 8) | low;
      while ((floor_root + 1) * (floor_root + 1) <= m) ++floor_root;
      const int64_t q = strider::detail::isqrt_table_estimate(m);
      const int64_t diff = q - static_cast<int64_t>(floor_root);
      worst_low = std::min<int>(worst_low, static_cast<int>(diff));
      worst_high = std::max<int>(worst_high, static_cast<int>(diff));
    }
  }
  std::cout << "[measured] sqrt table estimate - floor(sqrt(m)) in [" << worst_low << ", " << worst_high << "]\n";
  EXPECT_GE(worst_low, -1);
  EXPECT_LE(worst_high, 1);
}

// The Newton root is within 1 of floor(sqrt(m 2^22)); the exact variant is
// floor(sqrt(m 2^24)).
TEST(FixedSqrtCore, NewtonRootWithinOneAndExactRootIsTheFloor) {
  Xorshift rng(2024);
  int worst = 0;
  auto check = [&](uint32_t m) {
    const uint64_t floor22 = isqrt_u64(static_cast<uint64_t>(m) << 22);
    const uint64_t floor24 = isqrt_u64(static_cast<uint64_t>(m) << 24);
    ASSERT_EQ(strider::detail::isqrt_q24_floor(m), floor24) << m;
    const int diff = static_cast<int>(static_cast<int64_t>(strider::detail::isqrt_q22(m)) - static_cast<int64_t>(floor22));
    worst = std::max(worst, std::abs(diff));
  };
  for (int i = 0; i < STRIDER_RANDOM_CASES * 500; ++i) check(rng.next() | 0x40000000u);
  // Radicands next to perfect squares of the root, where the floor is
  // hardest to get right.
  for (int i = 0; i < STRIDER_RANDOM_CASES * 50; ++i) {
    const uint64_t r = (1u << 27) + rng.next() % ((1u << 28) - (1u << 27));
    for (uint64_t sq : {r * r, r * r + r}) {  // on a root and half-way to the next one
      for (int64_t d : {-1, 0, 1}) {
        const uint64_t m = (sq >> 24) + static_cast<uint64_t>(d);
        if (m >= (1u << 30) && m <= 0xFFFFFFFFu) check(static_cast<uint32_t>(m));
      }
    }
  }
  check(0x40000000u);
  check(0xFFFFFFFFu);
  std::cout << "[measured] Newton root - floor within +-" << worst << "\n";
  EXPECT_LE(worst, 1);
}

TEST(FixedSqrt, EdgeTable) {
  EXPECT_EQ(strider::sqrt(Fixed(0)).raw(), 0);
  EXPECT_EQ(strider::sqrt(Fixed(-1)).raw(), 0);
  EXPECT_EQ(strider::sqrt(Fixed::min()).raw(), 0);
  EXPECT_EQ(strider::sqrt(Fixed::from_raw(-1)).raw(), 0);
  EXPECT_EQ(strider::sqrt(Fixed(1)).raw(), 65536);
  EXPECT_EQ(strider::sqrt(Fixed(4)).raw(), 2 * 65536);
  EXPECT_EQ(strider::sqrt(Fixed(0.25)).raw(), 32768);
  EXPECT_EQ(strider::sqrt(Fixed(10000)).raw(), 100 * 65536);
  EXPECT_EQ(strider::sqrt(Fixed(16384)).raw(), 128 * 65536);
  EXPECT_EQ(strider::sqrt(Fixed::from_raw(1)).raw(), 256);  // sqrt(2^-16) = 2^-8
  EXPECT_EQ(strider::sqrt(Fixed::from_raw(2)).raw(), 362);  // 362.04
  EXPECT_NEAR(strider::sqrt(Fixed::max()).to_double(), std::sqrt(Fixed::max().to_double()), strider_test::kLsb);
  EXPECT_NEAR(strider::sqrt(Fixed(2)).to_double(), std::sqrt(2.0), strider_test::kLsb);
}

TEST(FixedSqrt, DenseSweepWithinBound) {
  MaxError err("Fixed sqrt");
  long long not_rounded = 0;
  auto check = [&](int32_t raw) {
    err.add(sqrt_error_lsb(raw) * strider_test::kLsb, raw);
    if (strider::sqrt(Fixed::from_raw(raw)).raw() != sqrt_correctly_rounded(raw)) ++not_rounded;
  };
  for (int32_t raw = 0; raw < (1 << 20); ++raw) check(raw);                  // every value below 16
  for (int64_t raw = 1 << 20; raw <= 0x7FFFFFFF; raw += 211) check(static_cast<int32_t>(raw));
  for (int32_t d = 0; d < 4096; ++d) check(0x7FFFFFFF - d);                  // the top
  for (int32_t k = 1; k < 46341; k += 7) {                                  // perfect squares and neighbours
    const int64_t sq = static_cast<int64_t>(k) * k;
    for (int64_t d = -1; d <= 1; ++d)
      if (sq + d > 0 && sq + d <= 0x7FFFFFFF) check(static_cast<int32_t>(sq + d));
  }
  err.expect_below(kSqrtErrorLsb * strider_test::kLsb);
  const double share = static_cast<double>(not_rounded) / static_cast<double>(err.samples);
  std::cout << "[measured] Fixed sqrt not correctly rounded: " << not_rounded << " of " << err.samples << " ("
            << share * 100 << " %), each within 1 LSB\n";
  EXPECT_LE(share, kSqrtMaxNotRoundedShare);
}

long double hypot_exact_raw(int32_t a, int32_t b) {
  return std::sqrt(static_cast<long double>(a) * a + static_cast<long double>(b) * b);
}

TEST(FixedHypot, EdgeTable) {
  EXPECT_EQ(strider::hypot(Fixed(0), Fixed(0)).raw(), 0);
  EXPECT_EQ(strider::hypot(Fixed(3), Fixed(4)).raw(), 5 * 65536);
  EXPECT_EQ(strider::hypot(Fixed(-3), Fixed(-4)).raw(), 5 * 65536);
  EXPECT_EQ(strider::hypot(Fixed::from_raw(3), Fixed::from_raw(4)).raw(), 5);
  EXPECT_EQ(strider::hypot(Fixed(300), Fixed(400)).raw(), 500 * 65536);  // squares overflow Q16.16
  EXPECT_EQ(strider::hypot(Fixed(7), Fixed(0)).raw(), 7 * 65536);
  EXPECT_EQ(strider::hypot(Fixed(0), Fixed(-7)).raw(), 7 * 65536);
  // The overflow case the library exists for: 600^2 is far beyond 32767.
  EXPECT_NEAR(strider::hypot(Fixed(600), Fixed(600)).to_double(), 600.0 * std::sqrt(2.0), strider_test::kLsb);
  EXPECT_NEAR(strider::hypot(Fixed(20000), Fixed(20000)).to_double(), 20000.0 * std::sqrt(2.0), 1e-3);
  // Saturation instead of wrap-around.
  EXPECT_EQ(strider::hypot(Fixed(30000), Fixed(30000)).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(strider::hypot(Fixed::max(), Fixed::max()).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(strider::hypot(Fixed::min(), Fixed(0)).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(strider::hypot(Fixed::min(), Fixed::min()).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(strider::hypot(Fixed::max(), Fixed(0)).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(strider::hypot(Fixed::from_raw(1), Fixed(0)).raw(), 1);
}

TEST(FixedHypot, OneAxisIsExactAndSymmetric) {
  Xorshift rng(99);
  for (int i = 0; i < STRIDER_RANDOM_CASES * 20; ++i) {
    const int32_t a = rng.raw_any();
    const int32_t b = rng.raw_any();
    const Fixed fa = Fixed::from_raw(a), fb = Fixed::from_raw(b);  // raw_any() never gives min()
    ASSERT_EQ(strider::hypot(fa, Fixed()).raw(), std::abs(a)) << a;
    const int32_t h = strider::hypot(fa, fb).raw();
    ASSERT_EQ(strider::hypot(fb, fa).raw(), h);
    ASSERT_EQ(strider::hypot(-fa, fb).raw(), h);
    ASSERT_EQ(strider::hypot(fa, -fb).raw(), h);
  }
}

TEST(FixedHypot, DenseSweepWithinBound) {
  MaxError small("Fixed hypot, max(|a|,|b|) < 1024");
  MaxError large("Fixed hypot, max(|a|,|b|) >= 1024 [relative]", false);
  Xorshift rng(4242);
  auto check = [&](int32_t a, int32_t b) {
    const long double exact = hypot_exact_raw(a, b);
    const int32_t got = strider::hypot(Fixed::from_raw(a), Fixed::from_raw(b)).raw();
    if (exact >= 2147483647.0L) {
      ASSERT_EQ(got, Fixed::kMaxRaw) << a << ", " << b;
      return;
    }
    const double e = static_cast<double>(got - exact);
    const double m = std::max(std::fabs(static_cast<double>(a)), std::fabs(static_cast<double>(b)));
    if (m < kHypotSmallLimit) {
      small.add(e * strider_test::kLsb, a, b);
    } else {
      large.add(e / static_cast<double>(exact), a, b);
    }
  };
  for (int i = 0; i < STRIDER_RANDOM_CASES * 1000; ++i) check(rng.raw_any(), rng.raw_any());
  // Leg-sized lengths: up to 1000 mm in 1/4 mm steps against a random other leg.
  for (int32_t a = 0; a < 1000 * 65536; a += 16411) check(a, static_cast<int32_t>(rng.next() % (1000u << 16)));
  for (int32_t a = -300; a <= 300; ++a)
    for (int32_t b = -300; b <= 300; ++b) check(a, b);
  small.expect_below(kHypotErrorLsb * strider_test::kLsb);
  large.expect_below(kHypotRelError);
}

}  // namespace
