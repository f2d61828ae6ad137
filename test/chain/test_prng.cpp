// Prng (xorshift32): known values, determinism, uniform draws for float,
// double and Fixed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "math/prng.h"

namespace {

using strider::Fixed;
using strider::Prng;

// Marsaglia (2003), section 3: xor32 from y = 2463534242 yields 723471715.
TEST(Prng, MarsagliaFirstValue) {
  Prng rng(2463534242u);
  EXPECT_EQ(rng.next_u32(), 723471715u);
}

// An independent step written from the paper's three lines.
uint32_t xorshift_reference(uint32_t y) {
  y ^= (y << 13);
  y = y ^ (y >> 17);
  return y ^ (y << 5);
}

TEST(Prng, StreamMatchesReferenceAndRepeats) {
  Prng a(12345u), b(12345u);
  uint32_t y = 12345u;
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    y = xorshift_reference(y);
    const uint32_t va = a.next_u32();
    ASSERT_EQ(va, y) << i;
    ASSERT_EQ(b.next_u32(), va);
    ASSERT_NE(va, 0u);
  }
}

TEST(Prng, ZeroSeedIsReplaced) {
  Prng z(0u), d;
  EXPECT_EQ(z.state(), Prng::kDefaultSeed);
  EXPECT_EQ(z.next_u32(), d.next_u32());
  z.seed(0u);
  EXPECT_EQ(z.state(), Prng::kDefaultSeed);
}

template <typename S>
double as_double(S v) { return double(v); }
template <>
double as_double<Fixed>(Fixed v) { return v.to_double(); }

template <typename S>
class PrngTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, double, Fixed>;
TYPED_TEST_SUITE(PrngTyped, Scalars);

// Range [0, 1), mean 1/2, and a chi-square over 16 bins well below the
// 0.1 % critical value (37.7 for 15 degrees of freedom).
TYPED_TEST(PrngTyped, UniformIsInRangeAndFlat) {
  using S = TypeParam;
  Prng rng(777u);
  const int n = 16 * STRIDER_RANDOM_CASES;
  std::vector<int> bins(16, 0);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = as_double(rng.uniform<S>());
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    ++bins[size_t(u * 16.0)];
  }
  EXPECT_NEAR(sum / n, 0.5, 5.0 / std::sqrt(12.0 * n));
  const double expect = n / 16.0;
  double chi2 = 0.0;
  for (int c : bins) chi2 += (c - expect) * (c - expect) / expect;
  EXPECT_LT(chi2, 37.7);
}

TYPED_TEST(PrngTyped, UniformBetweenBounds) {
  using S = TypeParam;
  Prng rng(4u);
  const S lo = S(-2.5), hi = S(7.0);
  double mn = 1e9, mx = -1e9;
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    const double v = as_double(rng.uniform(lo, hi));
    ASSERT_GE(v, -2.5);
    ASSERT_LT(v, 7.0);
    mn = std::min(mn, v);
    mx = std::max(mx, v);
  }
  EXPECT_LT(mn, -2.0);
  EXPECT_GT(mx, 6.5);
}

// Float and Fixed draws come from the same top bits of one stream, so they
// agree to Fixed's resolution: what the host computes in float, the AVR
// reproduces in Fixed.
TEST(Prng, FloatAndFixedDrawsAgree) {
  Prng a(99u), b(99u);
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    const double f = a.uniform<float>();
    const double x = b.uniform<Fixed>().to_double();
    ASSERT_GE(f, x);
    ASSERT_LT(f - x, 1.0 / 65536.0);
  }
}

TEST(Prng, DifferentSeedsGiveDifferentStreams) {
  Prng a(1u), b(2u);
  int same = 0;
  for (int i = 0; i < 100; ++i) same += a.next_u32() == b.next_u32();
  EXPECT_EQ(same, 0);
}

}  // namespace
