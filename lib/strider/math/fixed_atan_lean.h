//! The leg solvers' atan2 for Fixed raws: atan2() (fixed_atan.h) without
//! the residual step, error < 6e-5 rad for about half the cycles
//! (docs/fixed-point.md, "Leg IK fast path").
#ifndef STRIDER_MATH_FIXED_ATAN_LEAN_H
#define STRIDER_MATH_FIXED_ATAN_LEAN_H

#include <stdint.h>

#include "fixed_ops.h"
#include "fixed_trig.h"

namespace strider {
namespace detail {

//! The octant fold's flags.
constexpr uint8_t kLeanXNeg = 1, kLeanYNeg = 2, kLeanSwapped = 4;

#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
//! atan2_lean_raw()'s C path in AVR assembly, bit for bit (test_avr_exact);
//! only the bytes that reach the result are shifted and multiplied. Returns
//! the octant angle in Q0.16 and the fold flags.
STRIDER_ALWAYS_INLINE uint16_t atan2_lean_avr(uint32_t hi, uint32_t lo, uint8_t& flags) {
  uint16_t a, u, w, t;
  uint8_t f;
  __asm__(
      // Signs and magnitudes: hi = |x|, lo = |y| (-x = ~x + 1; r1 is 0 here).
      "clr %[f]\n\t"
      "sbrs %D[hi], 7\n\t"
      "rjmp 5f\n\t"
      "ori %[f], 1\n\t"
      STRIDER_ASM_NEG32("hi")
      "5:\n\t"
      "sbrs %D[lo], 7\n\t"
      "rjmp 6f\n\t"
      "ori %[f], 2\n\t"
      STRIDER_ASM_NEG32("lo")
      "6:\n\t"
      // Fold: hi >= lo.
      "cp %A[hi], %A[lo]\n\t" "cpc %B[hi], %B[lo]\n\t"
      "cpc %C[hi], %C[lo]\n\t" "cpc %D[hi], %D[lo]\n\t"
      "brsh 7f\n\t"
      "ori %[f], 4\n\t"
      "movw %[u], %A[hi]\n\t" "movw %[w], %C[hi]\n\t"
      "movw %A[hi], %A[lo]\n\t" "movw %C[hi], %C[lo]\n\t"
      "movw %A[lo], %[u]\n\t" "movw %C[lo], %[w]\n\t"
      "7:\n\t"
      // hi = 0 (both 0): the angle is 0.
      "cp %A[hi], __zero_reg__\n\t" "cpc %B[hi], __zero_reg__\n\t"
      "cpc %C[hi], __zero_reg__\n\t" "cpc %D[hi], __zero_reg__\n\t"
      "brne 8f\n\t"
      "clr %A[a]\n\t" "clr %B[a]\n\t"
      "rjmp 9f\n\t"
      "8:\n\t"
      // Whole bytes: hi < 2^16 shifts both by 16, then hi < 2^24 by 8.
      "cp %C[hi], __zero_reg__\n\t" "cpc %D[hi], __zero_reg__\n\t"
      "brne 1f\n\t"
      "movw %C[hi], %A[hi]\n\t" "clr %A[hi]\n\t" "clr %B[hi]\n\t"
      "movw %C[lo], %A[lo]\n\t" "clr %A[lo]\n\t" "clr %B[lo]\n\t"
      "1:\n\t"
      "tst %D[hi]\n\t"
      "brne 2f\n\t"
      "mov %D[hi], %C[hi]\n\t" "mov %C[hi], %B[hi]\n\t" "mov %B[hi], %A[hi]\n\t" "clr %A[hi]\n\t"
      "mov %D[lo], %C[lo]\n\t" "mov %C[lo], %B[lo]\n\t" "mov %B[lo], %A[lo]\n\t" "clr %A[lo]\n\t"
      "rjmp 2f\n\t"
      // Bits: shift until bit 31 of hi is set (at most 7 steps).
      "3:\n\t"
      "lsl %A[hi]\n\t" "rol %B[hi]\n\t" "rol %C[hi]\n\t" "rol %D[hi]\n\t"
      "lsl %B[lo]\n\t" "rol %C[lo]\n\t" "rol %D[lo]\n\t"
      "2:\n\t"
      "sbrs %D[hi], 7\n\t"
      "rjmp 3b\n\t"
      // recip_q30(hh, f8): r0 = T[j], r1 = T[j + 1] for j = (hh >> 8) - 128,
      // f = (hh & 0xFF) << 8 | f8, r = r0 - hi16((r0 - r1) f).
      "mov r30, %D[hi]\n\t"
      "subi r30, 128\n\t"
      STRIDER_ASM_TABLE_PAIR("recip", "u", "w")
      "movw %[t], %[u]\n\t"
      "sub %A[t], %A[w]\n\t" "sbc %B[t], %B[w]\n\t"
      STRIDER_ASM_MUL16_HI("%A[t]", "%B[t]", "%B[hi]", "%C[hi]", "%A[w]", "%A[a]", "%B[a]")
      "sub %A[u], %A[a]\n\t" "sbc %B[u], %B[a]\n\t"
      // p = hi16(lo) r; t = p >> 14 (bits 14..29), 0xFFFF when p >= 2^30.
      STRIDER_ASM_MUL16_HI("%C[lo]", "%D[lo]", "%A[u]", "%B[u]", "%A[w]", "%A[a]", "%B[a]")
      "lsl %A[w]\n\t" "rol %A[a]\n\t" "rol %B[a]\n\t" "brcs 3f\n\t"
      "lsl %A[w]\n\t" "rol %A[a]\n\t" "rol %B[a]\n\t" "brcc 4f\n\t"
      "3:\n\t"
      "clr %A[a]\n\t" "com %A[a]\n\t" "clr %B[a]\n\t" "com %B[a]\n\t"
      "4:\n\t"
      // d0 = A[i], d1 = A[i + 1] for i = t >> 8; D 2^-8 = d0 + (d1 - d0)
      // (t & 0xFF) / 2^8 (the low byte of the product drops out), then
      // a = t - ((D 2^-8 + 2) >> 2) in 16 bits.
      "mov r30, %B[a]\n\t"
      STRIDER_ASM_TABLE_PAIR("atan", "u", "w")
      "sub %A[w], %A[u]\n\t" "sbc %B[w], %B[u]\n\t"
      "mul %A[w], %A[a]\n\t" "mov %A[t], r1\n\t"
      "mul %B[w], %A[a]\n\t" "add %A[t], r0\n\t" "mov %B[t], r1\n\t"
      "clr __zero_reg__\n\t" "adc %B[t], __zero_reg__\n\t"
      "add %A[t], %A[u]\n\t" "adc %B[t], %B[u]\n\t"
      "subi %A[t], lo8(-2)\n\t" "sbci %B[t], hi8(-2)\n\t"
      "lsr %B[t]\n\t" "ror %A[t]\n\t" "lsr %B[t]\n\t" "ror %A[t]\n\t"
      "sub %A[a], %A[t]\n\t" "sbc %B[a], %B[t]\n\t"
      "9:"
      : [a] "=&r"(a), [u] "=&r"(u), [w] "=&r"(w), [t] "=&d"(t), [f] "=&d"(f), [hi] "+r"(hi), [lo] "+r"(lo)
      : [recip] "i"(FixedTables<>::kRecip), [atan] "i"(FixedTables<>::kAtan)
      : "r30", "r31");
  flags = f;
  return a;
}
#endif

//! atan2(y, x) in Q16.16 [rad], (-pi, pi]; 0 for (0, 0); error < 6e-5 rad:
//! the octant fold, lo / hi from 16 bits and the table reciprocal, then
//! atan t = t - D(t) from the atan table.
STRIDER_ALWAYS_INLINE int32_t atan2_lean_raw(int32_t y, int32_t x) {
  uint8_t flags;
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  const uint16_t octant = atan2_lean_avr(uint32_t(x), uint32_t(y), flags);
  // The C's unfolding (below) in assembly too: c - a as ~a + (c + 1).
  int32_t a;
  __asm__(
      "movw %A[a], %[o]\n\t" "clr %C[a]\n\t" "clr %D[a]\n\t"
      "sbrs %[f], 2\n\t" "rjmp 1f\n\t"
      STRIDER_ASM_RSUB32("a", "%[half]")
      "1:\n\t"
      "sbrs %[f], 0\n\t" "rjmp 2f\n\t"
      STRIDER_ASM_RSUB32("a", "%[pi]")
      "2:\n\t"
      "sbrs %[f], 1\n\t" "rjmp 3f\n\t"
      "com %A[a]\n\t" "com %B[a]\n\t" "com %C[a]\n\t" "com %D[a]\n\t"
      "subi %A[a], 0xFF\n\t" "sbci %B[a], 0xFF\n\t" "sbci %C[a], 0xFF\n\t" "sbci %D[a], 0xFF\n\t"
      "3:"
      : [a] "=&d"(a)
      : [o] "r"(octant), [f] "r"(flags), [half] "i"(int32_t(kHalfPiQ24 >> 8)), [pi] "i"(int32_t((kPiQ24 + 128) >> 8)));
  return a;
#else
  flags = uint8_t((x < 0 ? kLeanXNeg : 0) | (y < 0 ? kLeanYNeg : 0));
  uint32_t hi = abs_u32(x), lo = abs_u32(y);
  if (lo > hi) {
    const uint32_t t = hi;
    hi = lo;
    lo = t;
    flags = uint8_t(flags | kLeanSwapped);
  }
  if (hi == 0) return 0;
  normalize_pair(hi, lo);
  const uint16_t r = recip_q30(hi16(hi), uint8_t(uint16_t(hi) >> 8));  // 2^46 / hi
  uint32_t p = mul_u16(hi16(lo), r);  // ~ (lo / hi) 2^30
  if (p > 0x3FFFFFFFUL) p = 0x3FFFFFFFUL;
  const uint16_t t = uint16_t(hi16(p) << 2) | uint16_t(uint16_t(p) >> 14);  // lo / hi in Q0.16
  // atan t = t - D(t), D in units of 2^-18: Q16.16 is t - D / 4.
  const uint16_t d0 = flash_u16(FixedTables<>::kAtan, uint8_t(t >> 8));
  const uint16_t d1 = flash_u16(FixedTables<>::kAtan, uint16_t(uint8_t(t >> 8) + 1U));
  const uint32_t d = (uint32_t(d0) << 8) + mul_u16(uint16_t(d1 - d0), uint8_t(t));  // D 2^26
  int32_t a = int32_t(uint16_t(t - uint16_t(uint16_t((d + 512U) >> 8) >> 2)));
  if (flags & kLeanSwapped) a = int32_t(kHalfPiQ24 >> 8) - a;
  if (flags & kLeanXNeg) a = int32_t((kPiQ24 + 128) >> 8) - a;
  return (flags & kLeanYNeg) ? -a : a;
#endif
}

//! A difference a of two angles in (-pi, pi] [Q16.16 raw], wrapped back
//! into (-pi, pi].
STRIDER_ALWAYS_INLINE int32_t wrap_pi_once_raw(int32_t a) {
  constexpr int32_t pi_raw = int32_t((kPiQ24 + 128) >> 8);
  if (a > pi_raw) {
    a -= 2 * pi_raw;
  } else if (a <= -pi_raw) {
    a += 2 * pi_raw;
  }
  return a;
}

//! atan2_lean_raw() as one shared out-of-line copy, for the solvers whose
//! every cycle counts less than flash.
STRIDER_NOINLINE inline int32_t atan2_lean_call(int32_t y, int32_t x) { return atan2_lean_raw(y, x); }

}  // namespace detail
}  // namespace strider

#endif  // STRIDER_MATH_FIXED_ATAN_LEAN_H
