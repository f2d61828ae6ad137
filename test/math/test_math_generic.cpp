// The scalar-generic interface, typed over float and Fixed: wrap_pi and
// wrap_two_pi (range, accuracy, totality) and round trips between the
// elementary functions, the way IK code uses them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "math/scalar.h"
#include "math_test_util.h"

using strider::Fixed;
using strider_test::kPiL;
using strider_test::MaxError;

namespace {

template <typename S>
struct Tol;
template <>
struct Tol<float> {
  static constexpr double kWrap = 1e-6;       // [rad] |a| <= 1e4
  static constexpr double kRoundTrip = 2e-6;  // [rad] or relative
  static constexpr double kValue = 1.2e-7;    // sin/cos value error (libm, float rounding)
  static constexpr double kMaxAngle = 1e4;    // [rad] sweep limit
};
template <>
struct Tol<Fixed> {
  static constexpr double kWrap = 1.0 / 65536;  // 1 LSB
  static constexpr double kRoundTrip = 4e-5;    // [rad] atan2/asin/acos + sin/cos
  static constexpr double kValue = 3e-5;        // sin/cos value error
  static constexpr double kMaxAngle = 32767;    // [rad] the whole range
};

template <typename S>
class MathGeneric : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(MathGeneric, Scalars);

template <typename S>
void check_wrap(MaxError& err_pi, MaxError& err_two_pi, S a) {
  const S r = strider::wrap_pi(a);
  ASSERT_TRUE(-strider::pi<S>() < r && r <= strider::pi<S>()) << strider::to_double(a) << " -> " << strider::to_double(r);
  const S t = strider::wrap_two_pi(a);
  ASSERT_TRUE(S(0) <= t && t < strider::two_pi<S>()) << strider::to_double(a) << " -> " << strider::to_double(t);
  const long double exact = strider_test::wrap_pi_exact(static_cast<long double>(strider::to_double(a)));
  err_pi.add(static_cast<double>(strider_test::angle_diff(strider::to_double(r), exact)), strider::to_double(a));
  err_two_pi.add(static_cast<double>(strider_test::angle_diff(strider::to_double(t), exact)), strider::to_double(a));
}

TYPED_TEST(MathGeneric, WrapPiAndTwoPiSweep) {
  using S = TypeParam;
  MaxError ep(std::string(strider::ScalarTraits<S>::name()) + " wrap_pi");
  MaxError et(std::string(strider::ScalarTraits<S>::name()) + " wrap_two_pi");
  const double step = Tol<S>::kMaxAngle / 400000.0;
  for (double a = -Tol<S>::kMaxAngle; a <= Tol<S>::kMaxAngle; a += step) check_wrap(ep, et, strider::scalar<S>(a));
  for (int k = -2000; k <= 2000; ++k) {  // around every multiple of pi
    const double c = static_cast<double>(k * kPiL);
    for (double d : {-1e-4, -1e-6, 0.0, 1e-6, 1e-4}) check_wrap(ep, et, strider::scalar<S>(c + d));
  }
  for (S a : {S(0), strider::pi<S>(), -strider::pi<S>(), strider::two_pi<S>(), -strider::two_pi<S>(),
              strider::half_pi<S>(), strider::scalar<S>(3 * 3.14159265358979), strider::scalar<S>(-3 * 3.14159265358979)})
    check_wrap(ep, et, a);
  ep.expect_below(Tol<S>::kWrap);
  et.expect_below(Tol<S>::kWrap);
}

TEST(MathGenericWrap, FixedEveryRawNearZeroAndWholeRange) {
  MaxError ep("Fixed wrap_pi, dense"), et("Fixed wrap_two_pi, dense");
  for (int32_t raw = -900000; raw <= 900000; ++raw) check_wrap(ep, et, Fixed::from_raw(raw));
  for (int64_t raw = Fixed::kMinRaw; raw <= Fixed::kMaxRaw; raw += 4099) check_wrap(ep, et, Fixed::from_raw(static_cast<int32_t>(raw)));
  check_wrap(ep, et, Fixed::max());
  check_wrap(ep, et, Fixed::min());
  ep.expect_below(Tol<Fixed>::kWrap);
  et.expect_below(Tol<Fixed>::kWrap);
}

TEST(MathGenericWrap, FloatHugeNanAndInfinityGiveFiniteValuesInRange) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(strider::wrap_pi(nan), 0.0f);
  EXPECT_EQ(strider::wrap_pi(inf), 0.0f);
  EXPECT_EQ(strider::wrap_pi(-inf), 0.0f);
  EXPECT_EQ(strider::wrap_two_pi(nan), 0.0f);
  EXPECT_EQ(strider::wrap_two_pi(-inf), 0.0f);
  EXPECT_EQ(strider::wrap_two_pi(-0.0f), 0.0f);
  for (float a : {1e5f, -1e5f, 4.1e5f, 1e7f, -3e7f, 1e20f, -1e30f, 3.4e38f, -3.4e38f, 1e-40f, -1e-40f}) {
    const float r = strider::wrap_pi(a), t = strider::wrap_two_pi(a);
    EXPECT_TRUE(std::isfinite(r) && -strider::pi<float>() < r && r <= strider::pi<float>()) << a << " -> " << r;
    EXPECT_TRUE(std::isfinite(t) && 0.0f <= t && t < strider::two_pi<float>()) << a << " -> " << t;
    // The float value's own remainder (fmod is exact) up to float rounding.
    const long double exact = strider_test::wrap_pi_exact(static_cast<long double>(a));
    EXPECT_NEAR(static_cast<double>(strider_test::angle_diff(r, exact)), 0.0, 1e-6 + std::fabs(a) * 1e-7) << a;
  }
}

// asin(sin t) and acos(cos t) are ill-conditioned where the derivative of
// sin (cos) vanishes: a value error d becomes an angle error of about
// d / |cos t| (/ |sin t|), at most sqrt(2 d) at the turning point, so the
// bound carries that factor; atan2 needs none.
double conditioned(double value_error, double slope) {
  return std::min(value_error / std::fabs(slope), 2 * std::sqrt(2 * value_error));
}

TYPED_TEST(MathGeneric, TrigRoundTrips) {
  using S = TypeParam;
  MaxError e_atan2(std::string(strider::ScalarTraits<S>::name()) + " atan2(sin t, cos t) - t");
  MaxError e_asin(std::string(strider::ScalarTraits<S>::name()) + " (asin(sin t) - t) / conditioned bound", false);
  MaxError e_acos(std::string(strider::ScalarTraits<S>::name()) + " (acos(cos t) - |t|) / conditioned bound", false);
  for (int k = -20000; k <= 20000; ++k) {
    const double th = k * 3.14159265358979 / 20000;
    const S t = strider::scalar<S>(th);
    const double td = strider::to_double(t);
    e_atan2.add(static_cast<double>(strider_test::angle_diff(strider::to_double(strider::atan2(strider::sin(t), strider::cos(t))), td)),
                td);
    if (std::fabs(td) <= 3.14159265358979 / 2) {
      const double bound = Tol<S>::kRoundTrip + conditioned(Tol<S>::kValue, std::cos(td));
      e_asin.add((strider::to_double(strider::asin(strider::sin(t))) - td) / bound, td);
    }
    const double bound = Tol<S>::kRoundTrip + conditioned(Tol<S>::kValue, std::sin(td));
    e_acos.add((strider::to_double(strider::acos(strider::cos(t))) - std::fabs(td)) / bound, td);
  }
  e_atan2.expect_below(Tol<S>::kRoundTrip);
  e_asin.expect_below(1.0);
  e_acos.expect_below(1.0);
}

TYPED_TEST(MathGeneric, SqrtAndHypotRoundTrips) {
  using S = TypeParam;
  for (double v : {0.0, 1e-3, 0.5, 1.0, 2.0, 3.0, 85.0, 125.0, 181.0, 600.0, 1000.0}) {
    const S x = strider::scalar<S>(v);
    if (v * v > 0.01 && v * v < 32767) {  // x * x must neither underflow nor saturate Fixed
      EXPECT_NEAR(strider::to_double(strider::sqrt(x * x)), strider::to_double(x), 1e-6 * v + 2.0 / 65536) << v;
    }
    for (double th : {0.0, 0.3, 1.2, 2.5, -2.0}) {
      const S c = strider::scalar<S>(v * std::cos(th)), s = strider::scalar<S>(v * std::sin(th));
      const double exact = std::hypot(strider::to_double(c), strider::to_double(s));
      EXPECT_NEAR(strider::to_double(strider::hypot(c, s)), exact, 1e-6 * v + 1.0 / 65536) << v << " " << th;
    }
  }
  EXPECT_EQ(strider::sqrt(strider::scalar<S>(-4.0)), S(0));
  EXPECT_EQ(strider::atan2(S(0), S(0)), S(0));
}

}  // namespace
