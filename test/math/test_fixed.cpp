// Fixed (Q16.16) arithmetic against exact double results.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "math/fixed.h"

using strider::Fixed;

namespace {

double exact_mul_raw(int32_t a, int32_t b) {
  const double p = double(a) * double(b) / 65536.0;
  return std::round(p);  // half away from zero, like Fixed
}

TEST(Fixed, ConvertsConstants) {
  EXPECT_EQ(Fixed(1).raw(), 65536);
  EXPECT_EQ(Fixed(-3).raw(), -3 * 65536);
  EXPECT_EQ(Fixed(0.5).raw(), 32768);
  EXPECT_EQ(Fixed(-0.5f).raw(), -32768);
  EXPECT_EQ(Fixed(40000).raw(), Fixed::kMaxRaw);
  EXPECT_EQ(Fixed(-40000.0).raw(), Fixed::kMinRaw);
  EXPECT_EQ(Fixed(-2.75).to_int(), -2);
  EXPECT_EQ(Fixed::min().to_int(), -32768);
  EXPECT_NEAR(Fixed(1.2345).to_double(), 1.2345, 1.0 / 65536);
}

TEST(Fixed, AddSubSaturate) {
  EXPECT_EQ((Fixed(30000) + Fixed(30000)).raw(), Fixed::kMaxRaw);
  EXPECT_EQ((Fixed(-30000) - Fixed(30000)).raw(), Fixed::kMinRaw);
  EXPECT_EQ((-Fixed::min()).raw(), Fixed::kMaxRaw);
  EXPECT_EQ((Fixed(2) - Fixed(3)).raw(), -65536);
}

TEST(Fixed, MultiplyMatchesRoundedExactProduct) {
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int32_t> any(Fixed::kMinRaw, Fixed::kMaxRaw);
  std::uniform_int_distribution<int32_t> small(-(1 << 24), 1 << 24);
  for (int i = 0; i < STRIDER_RANDOM_CASES * 10; ++i) {
    const int32_t a = (i % 2) ? any(rng) : small(rng);
    const int32_t b = small(rng);
    const double e = exact_mul_raw(a, b);
    const int32_t got = Fixed::mul_raw(a, b);
    if (e > Fixed::kMaxRaw) {
      EXPECT_EQ(got, Fixed::kMaxRaw);
    } else if (e < Fixed::kMinRaw) {
      EXPECT_EQ(got, Fixed::kMinRaw);
    } else {
      ASSERT_EQ(got, int32_t(e)) << a << " * " << b;
    }
  }
  EXPECT_EQ((Fixed(3) * Fixed(-0.5)).raw(), -98304);
  EXPECT_EQ((Fixed(200) * Fixed(200)).raw(), Fixed::kMaxRaw);
}

TEST(Fixed, DivideMatchesRoundedExactQuotient) {
  std::mt19937 rng(777);
  std::uniform_int_distribution<int32_t> any(Fixed::kMinRaw + 1, Fixed::kMaxRaw);
  for (int i = 0; i < STRIDER_RANDOM_CASES * 10; ++i) {
    const int32_t a = any(rng) >> (i % 16);
    int32_t b = any(rng) >> (i % 24);
    if (b == 0) b = 1;
    const double e = std::round(double(a) * 65536.0 / double(b));
    const int32_t got = Fixed::div_raw(a, b);
    if (e > Fixed::kMaxRaw) {
      EXPECT_EQ(got, Fixed::kMaxRaw);
    } else if (e < Fixed::kMinRaw) {
      EXPECT_EQ(got, Fixed::kMinRaw);
    } else {
      ASSERT_EQ(got, int32_t(e)) << a << " / " << b;
    }
  }
  EXPECT_EQ((Fixed(1) / Fixed(0)).raw(), Fixed::kMaxRaw);
  EXPECT_EQ((Fixed(-1) / Fixed(0)).raw(), Fixed::kMinRaw);
  EXPECT_EQ((Fixed(1) / Fixed(3)).raw(), 21845);
}

}  // namespace
