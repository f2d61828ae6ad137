//! Integer building blocks shared by the Fixed elementary functions: unsigned
//! 16/32-bit arithmetic only, shifts in whole bytes plus a few bits (avr-gcc
//! 5.4 loops over every bit of a 32-bit shift; docs/fixed-point.md, "Design
//! for the ATmega2560"). `int` is 16 bits on the AVR.
#ifndef STRIDER_MATH_FIXED_OPS_H
#define STRIDER_MATH_FIXED_OPS_H

#include <stdint.h>

#include "fixed_tables.h"
#include "mul16.h"

#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
// Steps shared by the assembly kernels (macros: an asm template is one string
// literal). STRIDER_ASM_TABLE_PAIR: a = table[i], b = table[i + 1] for the
// index i in r30, with Z left past them. STRIDER_ASM_MUL16_HI: rb:ra:w =
// (x1:x0) (y1:y0) / 2^8, the low byte of the product dropped (byte operands).
// STRIDER_ASM_NEG32: x = -x; STRIDER_ASM_RSUB32: x = c - x as ~x + (c + 1).
#define STRIDER_ASM_TABLE_PAIR(table, a, b)                                                             \
  "clr r31\n\t" "lsl r30\n\t" "rol r31\n\t"                                                             \
  "subi r30, lo8(-(%[" table "]))\n\t" "sbci r31, hi8(-(%[" table "]))\n\t"                             \
  "lpm %A[" a "], Z+\n\t" "lpm %B[" a "], Z+\n\t" "lpm %A[" b "], Z+\n\t" "lpm %B[" b "], Z\n\t"
#define STRIDER_ASM_MUL16_HI(x0, x1, y0, y1, w, ra, rb)                                                 \
  "mul " x0 ", " y0 "\n\t" "mov " w ", r1\n\t" "mul " x1 ", " y1 "\n\t" "movw " ra ", r0\n\t"           \
  "mul " x1 ", " y0 "\n\t" "add " w ", r0\n\t" "adc " ra ", r1\n\t"                                     \
  "clr __zero_reg__\n\t" "adc " rb ", __zero_reg__\n\t"                                                 \
  "mul " x0 ", " y1 "\n\t" "add " w ", r0\n\t" "adc " ra ", r1\n\t"                                     \
  "clr __zero_reg__\n\t" "adc " rb ", __zero_reg__\n\t"
#define STRIDER_ASM_NEG32(x)                                                                                 \
  "com %A[" x "]\n\t" "com %B[" x "]\n\t" "com %C[" x "]\n\t" "com %D[" x "]\n\t" "sec\n\t"               \
  "adc %A[" x "], __zero_reg__\n\t" "adc %B[" x "], __zero_reg__\n\t" "adc %C[" x "], __zero_reg__\n\t"     \
  "adc %D[" x "], __zero_reg__\n\t"
#define STRIDER_ASM_RSUB32(x, c)                                                                             \
  "com %A[" x "]\n\t" "com %B[" x "]\n\t" "com %C[" x "]\n\t" "com %D[" x "]\n\t"                          \
  "subi %A[" x "], lo8(-(" c " + 1))\n\t" "sbci %B[" x "], hi8(-(" c " + 1))\n\t"                           \
  "sbci %C[" x "], hlo8(-(" c " + 1))\n\t" "sbci %D[" x "], hhi8(-(" c " + 1))\n\t"
#endif

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
