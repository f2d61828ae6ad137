//! Prng: Marsaglia's xorshift32 (G. Marsaglia, "Xorshift RNGs", J. Stat.
//! Softw. 8(14), 2003; shifts 13, 17, 5; period 2^32 - 1), bit-identical on
//! the host and the AVR, for particle swarms and IK restarts.
#ifndef STRIDER_MATH_PRNG_H
#define STRIDER_MATH_PRNG_H

#include <stdint.h>

#include "fixed.h"

namespace strider {

class Prng {
 public:
  //! Seed 0 is the one state xorshift cannot leave: it is replaced.
  static constexpr uint32_t kDefaultSeed = 2463534242u;  // Marsaglia's example seed

  constexpr explicit Prng(uint32_t seed = kDefaultSeed) : state_(seed != 0u ? seed : kDefaultSeed) {}

  void seed(uint32_t s) { state_ = s != 0u ? s : kDefaultSeed; }
  uint32_t state() const { return state_; }

  //! The next 32 random bits.
  uint32_t next_u32() {
    uint32_t x = state_;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    state_ = x;
    return x;
  }

  //! Uniform in [0, 1) for S = float, double or Fixed (the top bits are
  //! used: xorshift's low bits are its weakest).
  template <typename S>
  S uniform() { return uniform_impl(static_cast<S*>(nullptr)); }

  //! Uniform in [lo, hi) (hi - lo must be representable in S).
  template <typename S>
  S uniform(S lo, S hi) { return lo + (hi - lo) * uniform<S>(); }

 private:
  // 24 bits: every value is exact in float.
  float uniform_impl(float*) { return float(next_u32() >> 8) * (1.0f / 16777216.0f); }
  // 53 bits from two draws on the host; on the AVR double is a 32-bit float,
  // where the sum may round up to 1, so it is kept below 1.
  double uniform_impl(double*) {
    const uint32_t hi = next_u32() >> 5;  // 27 bits
    const uint32_t lo = next_u32() >> 6;  // 26 bits
    const double r = (double(hi) * 67108864.0 + double(lo)) * (1.0 / 9007199254740992.0);
    return r < 1.0 ? r : 1.0 - 1.0 / 16777216.0;
  }
  // 16 bits: every Q16.16 value in [0, 1).
  Fixed uniform_impl(Fixed*) { return Fixed::from_raw(int32_t(next_u32() >> 16)); }

  uint32_t state_;
};

}  // namespace strider

#endif  // STRIDER_MATH_PRNG_H
