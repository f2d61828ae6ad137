// Helpers shared by the math tests: a max-error tracker that reports where
// the worst case was, and exact references in long double.
#ifndef STRIDER_TEST_MATH_TEST_UTIL_H
#define STRIDER_TEST_MATH_TEST_UTIL_H

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>

#include "math/fixed.h"

namespace strider_test {

constexpr double kLsb = 1.0 / 65536.0;  // one Q16.16 step
constexpr long double kPiL = 3.141592653589793238462643383279502884L;

inline long double raw_to_ld(int32_t raw) { return static_cast<long double>(raw) / 65536.0L; }

// Largest |error| seen, the input that produced it and how many samples.
struct MaxError {
  std::string name;
  bool absolute;  // errors in value units (also printed in Q16.16 LSB) or relative
  double worst = 0.0;
  double at_a = 0.0, at_b = 0.0;
  long long samples = 0;

  explicit MaxError(std::string n, bool absolute_error = true) : name(std::move(n)), absolute(absolute_error) {}

  void add(double err, double a, double b = 0.0) {
    ++samples;
    const double e = std::fabs(err);
    if (e > worst || std::isnan(err)) {
      worst = std::isnan(err) ? INFINITY : e;
      at_a = a;
      at_b = b;
    }
  }
  // Prints the figure (quoted in docs/fixed-point.md) and checks the bound.
  void expect_below(double bound) const {
    std::cout << "[measured] " << name << ": max |error| " << worst;
    if (absolute) std::cout << " (" << worst / kLsb << " LSB)";
    std::cout << " over " << samples << " inputs, worst at (" << at_a << ", " << at_b << ")\n";
    EXPECT_LE(worst, bound) << name << " worst at (" << at_a << ", " << at_b << ")";
    EXPECT_GT(samples, 0);
  }
};

// Exact angle a - 2 pi k in (-pi, pi] for a long double a.
inline long double wrap_pi_exact(long double a) {
  long double r = std::fmod(a, 2 * kPiL);
  if (r > kPiL) r -= 2 * kPiL;
  if (r <= -kPiL) r += 2 * kPiL;
  return r;
}

// Difference of two angles, wrapped to (-pi, pi].
inline long double angle_diff(long double a, long double b) { return wrap_pi_exact(a - b); }

// A small deterministic generator (xorshift32) so every run sees the same inputs.
struct Xorshift {
  uint32_t s;
  explicit Xorshift(uint32_t seed) : s(seed ? seed : 1u) {}
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return s;
  }
  // A raw value of random sign and random magnitude (uniform in log scale).
  int32_t raw_any() {
    const uint32_t bits = next();
    const int shift = static_cast<int>(next() % 31u);
    const int32_t mag = static_cast<int32_t>((bits & 0x7FFFFFFFu) >> shift);
    return (bits & 0x80000000u) ? -mag : mag;
  }
};

}  // namespace strider_test

#endif  // STRIDER_TEST_MATH_TEST_UTIL_H
