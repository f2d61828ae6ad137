//! Integer building blocks shared by the Fixed elementary functions.
//!
//! Everything here is unsigned 16/32-bit arithmetic, whose wrap-around is
//! defined by the language, so the host and the AVR give bit-identical
//! results. Two facts of avr-gcc 5.4 at -Os shape the code:
//! - it computes a 32-bit shift by n (other than 8, 16, 24) with an n-step
//!   loop (~6 cycles per bit), so shifts here are whole bytes plus at most a
//!   few bits, and variable shifts go through shr_var();
//! - it often turns (uint32_t)a * b of 16-bit values into a 32x32 library
//!   call (~100 cycles), so mul_u16() (mul16.h) is four MUL instructions
//!   (~20 cycles).
//! Note that `int` is 16 bits on the AVR: every intermediate above 0xFFFF is
//! a uint32_t.
#ifndef STRIDER_MATH_FIXED_OPS_H
#define STRIDER_MATH_FIXED_OPS_H

#include <stdint.h>

#include "fixed_tables.h"
#include "mul16.h"

namespace strider {
namespace detail {

//! The high 16 bits of x.
STRIDER_ALWAYS_INLINE uint16_t hi16(uint32_t x) { return uint16_t(x >> 16); }

//! The int32_t whose two's complement bits are u (a difference computed
//! modulo 2^32), without implementation-defined conversions.
STRIDER_ALWAYS_INLINE int32_t to_signed(uint32_t u) {
  return u < 0x80000000UL ? int32_t(u) : -int32_t(~u) - 1;
}

//! |v| as uint32_t; v = INT32_MIN gives 2^31.
STRIDER_ALWAYS_INLINE uint32_t abs_u32(int32_t v) { return v < 0 ? uint32_t(0) - uint32_t(v) : uint32_t(v); }

//! x >> n for n in [0, 31]: whole bytes, then at most 7 single-bit steps.
STRIDER_ALWAYS_INLINE uint32_t shr_var(uint32_t x, uint8_t n) {
  if (n & 16) x >>= 16;
  if (n & 8) x >>= 8;
  return x >> (n & 7);
}

//! round(x / 2^n) for n in [1, 31], halves rounded up.
STRIDER_ALWAYS_INLINE uint32_t shr_round(uint32_t x, uint8_t n) { return (shr_var(x, uint8_t(n - 1)) + 1) >> 1; }

//! Shifts u (!= 0) left by the even count s that brings it into
//! [2^30, 2^32) and returns s.
STRIDER_ALWAYS_INLINE uint8_t normalize_even(uint32_t& u) {
  uint8_t s = 0;
  if (u < 0x10000UL) { u <<= 16; s = 16; }
  if (u < 0x1000000UL) { u <<= 8; s = uint8_t(s + 8); }
  if (u < 0x10000000UL) { u <<= 4; s = uint8_t(s + 4); }
  if (u < 0x40000000UL) { u <<= 2; s = uint8_t(s + 2); }
  return s;
}

//! Shifts hi (!= 0) and lo <= hi left together until bit 31 of hi is set.
STRIDER_ALWAYS_INLINE void normalize_pair(uint32_t& hi, uint32_t& lo) {
  if (hi < 0x10000UL) { hi <<= 16; lo <<= 16; }
  if (hi < 0x1000000UL) { hi <<= 8; lo <<= 8; }
  if (hi < 0x10000000UL) { hi <<= 4; lo <<= 4; }
  if (hi < 0x40000000UL) { hi <<= 2; lo <<= 2; }
  if (hi < 0x80000000UL) { hi <<= 1; lo <<= 1; }
}

//! 2^30 / (h / 2^16) = 2^46 / h for h16 = h / 2^16 in [2^15, 2^16) and
//! f8 = the next 8 bits of h: a value in [2^14, 2^15] from a 129-node table
//! with linear interpolation. Relative error below 2^-13; the callers refine
//! the quotients it gives with an exact residual.
STRIDER_ALWAYS_INLINE uint16_t recip_q30(uint16_t h16, uint8_t f8) {
  const uint16_t j = uint16_t((h16 >> 8) - 128U);
  const uint16_t f = uint16_t(uint16_t(uint8_t(h16)) << 8 | f8);
  const uint16_t r0 = flash_u16(FixedTables<>::kRecip, j);
  const uint16_t r1 = flash_u16(FixedTables<>::kRecip, uint16_t(j + 1U));
  return uint16_t(r0 - hi16(mul_u16(uint16_t(r0 - r1), f)));
}

}  // namespace detail
}  // namespace strider

#endif  // STRIDER_MATH_FIXED_OPS_H
