//! The gait's phase clock: a fraction of a cycle in unsigned integers, so
//! that wrapping around at the end of a cycle is free and exact, the same on
//! the host and the AVR, and the same for float and Fixed.
//!
//! The clock keeps 32 bits (2^32 = one cycle); legs and tables use the top
//! 16 bits (Phase16, 2^16 = one cycle, a resolution of 1.5e-5 cycle). A leg's
//! own phase is a plain uint16_t subtraction: psi = phase - offset (mod 2^16).
#ifndef STRIDER_GAIT_PHASE_H
#define STRIDER_GAIT_PHASE_H

#include <stdint.h>

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
  //! The current phase [2^-32 cycle].
  uint32_t raw() const { return phase_; }
  //! The current phase as Phase16.
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

  uint32_t phase_ = 0;
  uint32_t previous_ = 0;
};

//! A leg's own phase: psi = phase - offset (mod one cycle).
constexpr Phase16 leg_phase(Phase16 phase, Phase16 offset) { return Phase16(phase - offset); }

}  // namespace strider

#endif  // STRIDER_GAIT_PHASE_H
