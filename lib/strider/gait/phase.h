//! The gait's phase clock: a fraction of a cycle in unsigned integers (the
//! wrap at the end of a cycle free and exact, the same on the host and the
//! AVR, for float and Fixed): 32 bits in the clock, the top 16 (Phase16) in
//! legs and tables; a leg's own phase is phase - offset (mod 2^16).
#ifndef STRIDER_GAIT_PHASE_H
#define STRIDER_GAIT_PHASE_H

#include <stdint.h>

#include "../math/flash_table.h"
#include "../math/float_bits.h"
#include "../math/scalar.h"

namespace strider {

//! A fraction of a gait cycle: 2^16 = one cycle.
using Phase16 = uint16_t;

//! One cycle in Phase16 units, as a 32-bit number.
constexpr uint32_t kPhaseOne = 65536u;

//! A phase fraction in [0, 1) [cycle] as Phase16, rounded; 1.0 wraps to 0.
constexpr Phase16 phase16(double fraction) {
  return Phase16(uint32_t(fraction * 65536.0 + 0.5) & 0xFFFFu);
}

//! A length of phase in (0, 1] [cycle] as a 32-bit count of Phase16 units
//! (1.0 = 65536, which a Phase16 cannot hold).
constexpr uint32_t phase_span(double fraction) {
  return fraction <= 0.0 ? 0u : fraction >= 1.0 ? kPhaseOne : uint32_t(fraction * 65536.0 + 0.5);
}

//! A gait table's fractions (float duty and offsets) in the engine's units
//! from the float's bits: integers only (no float library on the AVR), the
//! same results as phase16(), phase_span() and Fixed(double) (test/gait).
namespace table_fraction {

//! f in [0, 1] (finite, >= 0) as m 2^-sh: m < 2^24, sh >= 23.
inline uint32_t mantissa(float f, uint8_t* sh) {
  const uint32_t u = detail::magnitude_bits(f);
  const uint8_t e = uint8_t(u >> 23);
  *sh = e == 0 ? uint8_t(149) : uint8_t(150 - e);  // a subnormal: m 2^-149
  return e == 0 ? u : ((u & 0x7FFFFFu) | 0x800000u);
}

//! m >> n and whether that dropped bits: whole bytes first (the AVR
//! shifts by a variable count one bit per loop).
inline uint32_t shift_down(uint32_t m, uint8_t n, bool* inexact) {
  bool lost = false;
  if (n > 31) {
    *inexact = m != 0;
    return 0;
  }
  for (; n >= 8; n = uint8_t(n - 8)) {
    lost |= uint8_t(m) != 0;
    m >>= 8;
  }
  for (; n != 0; --n) {
    lost |= (m & 1u) != 0;
    m >>= 1;
  }
  *inexact = lost;
  return m;
}

//! floor(f 2^17) and whether that dropped bits (f in [0, 1]).
inline uint32_t times_2_17(float f, bool* inexact) {
  uint8_t sh;
  const uint32_t m = mantissa(f, &sh);
  return shift_down(m, uint8_t(sh - 17), inexact);  // sh - 17 >= 6
}

//! round(f 2^16), halves up, for f in [0, 1]: phase16() before its wrap
//! and Fixed's raw value of f.
inline uint32_t q16(float f) {
  bool inexact;
  return (times_2_17(f, &inexact) + 1u) >> 1;
}

//! phase_span(1 - duty) for duty in [0, 1]: round((1 - duty) 2^16).
inline uint32_t swing_span(float duty) {
  bool inexact;
  const uint32_t c = times_2_17(duty, &inexact) + (inexact ? 1u : 0u);  // ceil(duty 2^17)
  return c >= (uint32_t(1) << 17) ? 0u : ((uint32_t(1) << 17) - c + 1u) >> 1;
}

//! round(2^(17 + n) / den) / 2 rounded up, i.e. round(2^(16 + n) / den),
//! saturated at Fixed's largest raw value (den 0 too).
inline Fixed round_power_over(uint8_t n, uint32_t den) {
  if (den == 0) return Fixed::max();
  // 2^i / den for the largest 2^i <= den (no quotient bits before it),
  // then one bit more per step.
  uint32_t top = den, r = 1;
  uint8_t i = 0;
  if (top >> 16) {
    top >>= 16;
    r <<= 16;
    i = 16;
  }
  if (top >> 8) {
    top >>= 8;
    r <<= 8;
    i = uint8_t(i + 8);
  }
  for (; top > 1u; top >>= 1, r <<= 1) ++i;
  uint32_t q = r == den ? 1u : 0u;
  if (q != 0) r = 0;
  for (uint16_t bits = uint16_t(uint16_t(n) + 17u - i); bits != 0; --bits) {
    if (q >= 0x80000000u) return Fixed::max();
    q <<= 1;
    r <<= 1;  // r < den < 2^31
    if (r >= den) {
      r -= den;
      q |= 1u;
    }
  }
  // q = floor(2^17 v): round(2^16 v) = (q + 1) / 2.
  return q >= 0xFFFFFFFEu ? Fixed::max() : Fixed::from_raw(int32_t((q + 1u) >> 1));
}

//! Fixed(1 / f) (rest false; f in (0, 1], 0 saturates) or Fixed(1 / (1 - f))
//! (rest true; f in [0, 1), 1 saturates), rounded as Fixed(double). 1 - f =
//! (2^sh - m) 2^-sh is exact for f >= 2^-8 (sh <= 31); below, f is first
//! rounded up to a multiple of 2^-31 (within one unit of Fixed, where
//! 1 / (1 - f) < 1.004).
STRIDER_NOINLINE inline Fixed inverse_of(float f, bool rest) {
  uint8_t sh;
  uint32_t m = mantissa(f, &sh);
  if (!rest) return round_power_over(sh, m);
  if (sh > 31) {
    bool inexact;
    m = shift_down(m, uint8_t(sh - 31), &inexact) + (inexact ? 1u : 0u);
    sh = 31;
  }
  const uint32_t one = uint32_t(1) << sh;
  return m >= one ? Fixed::max() : round_power_over(sh, one - m);
}
inline Fixed inverse(float f) { return inverse_of(f, false); }
inline Fixed inverse_of_rest(float duty) { return inverse_of(duty, true); }

}  // namespace table_fraction

//! A phase count as a scalar fraction of a cycle [cycle].
inline float phase_to_scalar(uint32_t p, float) { return float(p) * (1.0f / 65536.0f); }
inline Fixed phase_to_scalar(uint32_t p, Fixed) {
  return Fixed::from_raw(p >= 0x7FFFFFFFu ? Fixed::kMaxRaw : int32_t(p));  // Q0.16 is Fixed's raw
}
template <typename S>
S phase_to(uint32_t p) { return phase_to_scalar(p, S()); }

//! A cycle count per tick (dt * frequency, [cycle], in [0, 1)) in Q0.32
//! clock units; saturates just below one cycle, negatives give 0.
inline uint32_t cycles_to_q32(float cycles) {
  if (!(cycles > 0.0f)) return 0u;
  if (cycles >= 0.99999f) return 0xFFFF0000u;
  return uint32_t(cycles * 4294967296.0f);
}
inline uint32_t cycles_to_q32(Fixed cycles) {
  const int32_t raw = cycles.raw();
  if (raw <= 0) return 0u;
  if (raw >= 0xFFFF) return 0xFFFF0000u;
  return uint32_t(raw) << 16;
}

//! The phase clock of a gait: advance(dt * f) once per tick.
class PhaseClock {
 public:
  PhaseClock() : phase_(0), previous_(0) {}
  Phase16 now() const { return Phase16(phase_ >> 16); }
  //! The phase before the last advance().
  Phase16 before() const { return Phase16(previous_ >> 16); }

  //! Sets the phase (also the previous one: no crossing is reported).
  void reset(Phase16 p) { phase_ = previous_ = uint32_t(p) << 16; }

  //! Moves on by `cycles` = dt [s] * frequency [Hz], in [0, 1) [cycle].
  //! Returns true when the cycle wrapped past phase 0.
  template <typename S>
  bool advance(S cycles) {
    return advance_q32(cycles_to_q32(cycles));
  }
  //! Moves on by dt [s] at hz [Hz]. For Fixed the product of the two raw
  //! values is the step in 2^-32 cycle exactly (no rounding to 2^-16).
  bool advance(float dt, float hz) { return advance_q32(cycles_to_q32(dt * hz)); }
  bool advance(Fixed dt, Fixed hz) {
    if (dt.raw() <= 0 || hz.raw() <= 0) return advance_q32(0);
    const uint32_t a = uint32_t(dt.raw()), b = uint32_t(hz.raw());
    // A tick below 62 ms at below 16 Hz cannot reach the cap ((2^12 - 1)
    // (2^20 - 1) < 0xFFFF0000): no 32-bit division (~600 cycles on the AVR).
    if (a < 4096u && b < 1048576u) return advance_q32(a * b);
    return advance_q32(a > 0xFFFF0000u / b ? 0xFFFF0000u : a * b);
  }

  //! True when the last advance() passed `mark` (before < mark <= now, on the
  //! circle): a leg whose lift-off phase is `mark` lifts in this tick.
  bool crossed(Phase16 mark) const {
    const Phase16 was = Phase16(before() - mark);
    const Phase16 is = Phase16(now() - mark);
    return before() != now() && is < was;
  }

 private:
  bool advance_q32(uint32_t step) {
    previous_ = phase_;
    phase_ += step;
    return phase_ < previous_;
  }

  uint32_t phase_;
  uint32_t previous_;
};

}  // namespace strider

#endif  // STRIDER_GAIT_PHASE_H
