//! Square roots in wide working units (wide_units.h): the root of a sum of
//! squares, and of a product of two, for the leg IK fast paths.
#ifndef STRIDER_KINEMATICS_WIDE_SQRT_H
#define STRIDER_KINEMATICS_WIDE_SQRT_H

#include "wide_units.h"

namespace strider {
namespace leg_ik {
namespace wide {

//! Shift that brings u (!= 0) into [2^31, 2^32): whole bytes, then bits.
STRIDER_ALWAYS_INLINE uint8_t normalize_top(uint32_t& u) {
  const uint8_t k = detail::normalize_even(u);
  if (u >= 0x80000000UL) return k;
  u <<= 1;
  return uint8_t(k + 1);
}

//! round(root 2^e) for e in [-31, 7] (a signed shift of an isqrt result).
STRIDER_ALWAYS_INLINE uint32_t shift_signed(uint32_t root, int8_t e) {
  return e >= 0 ? shl(root, uint8_t(e)) : detail::shr_round(root, uint8_t(-e));
}

//! sqrt(x) for x in Q6.24 (0 < x < 2^30): wide units. kSharedRoot calls the
//! shared root kernel (isqrt_q22_call) instead of inlining it.
template <bool kSharedRoot = false>
STRIDER_ALWAYS_INLINE int32_t sqrt_sq(uint32_t x) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  // normalize_even() and shift_signed() around the root in AVR assembly,
  // with h = s / 2 (test_avr_exact: wide_sqrt_sq).
  uint8_t h;
  __asm__(
      "clr %[h]\n\t"
      "cp %C[x], __zero_reg__\n\t" "cpc %D[x], __zero_reg__\n\t" "brne 1f\n\t"
      "movw %C[x], %A[x]\n\t" "clr %B[x]\n\t" "clr %A[x]\n\t" "ldi %[h], 8\n\t"
      "1:\n\t"
      "tst %D[x]\n\t" "brne 2f\n\t"
      "mov %D[x], %C[x]\n\t" "mov %C[x], %B[x]\n\t" "mov %B[x], %A[x]\n\t" "clr %A[x]\n\t"
      "subi %[h], lo8(-4)\n\t"
      "2:\n\t"
      "mov r30, %D[x]\n\t" "andi r30, 0xF0\n\t" "brne 3f\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "rol %C[x]\n\t" "rol %D[x]\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "rol %C[x]\n\t" "rol %D[x]\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "rol %C[x]\n\t" "rol %D[x]\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "rol %C[x]\n\t" "rol %D[x]\n\t"
      "subi %[h], lo8(-2)\n\t"
      "3:\n\t"
      "mov r30, %D[x]\n\t" "andi r30, 0xC0\n\t" "brne 4f\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "rol %C[x]\n\t" "rol %D[x]\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "rol %C[x]\n\t" "rol %D[x]\n\t"
      "inc %[h]\n\t"
      "4:"
      : [h] "=&d"(h), [x] "+r"(x)
      :
      : "r30");
  uint32_t root = kSharedRoot ? detail::isqrt_q22_call(x) : detail::isqrt_q22(x);
  // root << (5 - h) for h <= 5 (root < 2^27), else shr_round(root, h - 5)
  // (h <= 15 for x >= 1).
  __asm__(
      "ldi r30, 5\n\t" "sub r30, %[h]\n\t" "brmi 6f\n\t" "breq 5f\n\t"
      "7:\n\t"
      "lsl %A[r]\n\t" "rol %B[r]\n\t" "rol %C[r]\n\t" "rol %D[r]\n\t" "dec r30\n\t" "brne 7b\n\t"
      "rjmp 5f\n\t"
      "6:\n\t"
      "neg r30\n\t" "dec r30\n\t"  // n - 1 for n = h - 5 in [1, 10]
      "sbrs r30, 3\n\t" "rjmp 9f\n\t"
      "mov %A[r], %B[r]\n\t" "mov %B[r], %C[r]\n\t" "mov %C[r], %D[r]\n\t" "clr %D[r]\n\t"
      "9:\n\t"
      "andi r30, 7\n\t" "breq 8f\n\t"
      "10:\n\t"
      "lsr %D[r]\n\t" "ror %C[r]\n\t" "ror %B[r]\n\t" "ror %A[r]\n\t" "dec r30\n\t" "brne 10b\n\t"
      "8:\n\t"
      "sec\n\t" "adc %A[r], __zero_reg__\n\t" "adc %B[r], __zero_reg__\n\t"
      "adc %C[r], __zero_reg__\n\t" "adc %D[r], __zero_reg__\n\t"
      "lsr %D[r]\n\t" "ror %C[r]\n\t" "ror %B[r]\n\t" "ror %A[r]\n\t"
      "5:"
      : [r] "+r"(root)
      : [h] "r"(h)
      : "r30");
  return int32_t(root);
#else
  const uint8_t s = detail::normalize_even(x);
  // isqrt_q22 ~ sqrt(x 2^(22 + s)); the wide root is sqrt(x) 2^16.
  return int32_t(shift_signed(detail::isqrt_q22(x), int8_t(5 - s / 2)));
#endif
}

//! sqrt_sq() as one shared out-of-line copy, for the solvers whose every
//! cycle counts less than flash, with the shared root kernel.
STRIDER_NOINLINE inline int32_t sqrt_sq_call(uint32_t x) { return sqrt_sq<true>(x); }

//! sqrt(p q) for p, q > 0 in Q6.24 (a product of up to 60 bits), relative
//! error < 2^-14: both normalised to 16 significant bits, multiplied, and
//! the root from the interpolated table alone. Q6.24.
STRIDER_ALWAYS_INLINE uint32_t sqrt_product(uint32_t p, uint32_t q) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  // The C below in AVR assembly, bit for bit (test_avr_exact:
  // wide_sqrt_product). Only hi16 of the normalised p and q is used, so their
  // bit steps shift the top three bytes; the estimate has at most 17 bits,
  // so the final left shift moves bits within three bytes, then whole bytes.
  uint32_t m;
  uint8_t k;
  __asm__(
      // normalize_top(p), normalize_top(q): k = the sum of their shifts.
      "clr %[k]\n\t"
      "cp %C[p], __zero_reg__\n\t" "cpc %D[p], __zero_reg__\n\t" "brne 1f\n\t"
      "movw %C[p], %A[p]\n\t" "clr %B[p]\n\t" "clr %A[p]\n\t" "ldi %[k], 16\n\t"
      "1:\n\t"
      "tst %D[p]\n\t" "brne 2f\n\t"
      "mov %D[p], %C[p]\n\t" "mov %C[p], %B[p]\n\t" "mov %B[p], %A[p]\n\t" "subi %[k], lo8(-8)\n\t"
      "rjmp 2f\n\t"
      "3:\n\t"
      "lsl %B[p]\n\t" "rol %C[p]\n\t" "rol %D[p]\n\t" "inc %[k]\n\t"
      "2:\n\t"
      "sbrs %D[p], 7\n\t" "rjmp 3b\n\t"
      "cp %C[q], __zero_reg__\n\t" "cpc %D[q], __zero_reg__\n\t" "brne 1f\n\t"
      "movw %C[q], %A[q]\n\t" "clr %B[q]\n\t" "clr %A[q]\n\t" "subi %[k], lo8(-16)\n\t"
      "1:\n\t"
      "tst %D[q]\n\t" "brne 2f\n\t"
      "mov %D[q], %C[q]\n\t" "mov %C[q], %B[q]\n\t" "mov %B[q], %A[q]\n\t" "subi %[k], lo8(-8)\n\t"
      "rjmp 2f\n\t"
      "3:\n\t"
      "lsl %B[q]\n\t" "rol %C[q]\n\t" "rol %D[q]\n\t" "inc %[k]\n\t"
      "2:\n\t"
      "sbrs %D[q], 7\n\t" "rjmp 3b\n\t"
      // m = hi16(p) hi16(q).
      "mul %C[p], %C[q]\n\t" "movw %A[m], r0\n\t"
      "mul %D[p], %D[q]\n\t" "movw %C[m], r0\n\t"
      "mul %D[p], %C[q]\n\t" "add %B[m], r0\n\t" "adc %C[m], r1\n\t"
      "clr __zero_reg__\n\t" "adc %D[m], __zero_reg__\n\t"
      "mul %C[p], %D[q]\n\t" "add %B[m], r0\n\t" "adc %C[m], r1\n\t"
      "clr __zero_reg__\n\t" "adc %D[m], __zero_reg__\n\t"
      // k odd: m >>= 1, --k; then m < 2^30 (bit 30 clear): m <<= 2, k += 2.
      "sbrs %[k], 0\n\t" "rjmp 4f\n\t"
      "lsr %D[m]\n\t" "ror %C[m]\n\t" "ror %B[m]\n\t" "ror %A[m]\n\t" "dec %[k]\n\t"
      "sbrc %D[m], 6\n\t" "rjmp 4f\n\t"
      "lsl %A[m]\n\t" "rol %B[m]\n\t" "rol %C[m]\n\t" "rol %D[m]\n\t"
      "lsl %A[m]\n\t" "rol %B[m]\n\t" "rol %C[m]\n\t" "rol %D[m]\n\t"
      "subi %[k], lo8(-2)\n\t"
      "4:\n\t"
      // isqrt_table_estimate(m) into p's low three bytes: t0, t1 = kSqrt[j],
      // [j + 1] for j = (m >> 24) - 64; 32768 + t0 + hi16((t1 - t0) (m >> 8)).
      "mov r30, %D[m]\n\t" "subi r30, 64\n\t" STRIDER_ASM_TABLE_PAIR("sqrt_table", "p", "q")
      "sub %A[q], %A[p]\n\t" "sbc %B[q], %B[p]\n\t"
      STRIDER_ASM_MUL16_HI("%A[q]", "%B[q]", "%B[m]", "%C[m]", "%C[p]", "%C[q]", "%D[q]")
      "add %A[p], %C[q]\n\t" "adc %B[p], %D[q]\n\t" "clr %C[p]\n\t" "rol %C[p]\n\t"
      "ldi r31, 0x80\n\t" "add %B[p], r31\n\t" "adc %C[p], __zero_reg__\n\t"
      // shift_signed(estimate, e), e = 16 - k / 2 in [-15, 16].
      "lsr %[k]\n\t"
      "ldi r30, 16\n\t" "sub r30, %[k]\n\t"
      "brmi 6f\n\t"
      // e >= 0: e & 7 bits within the three bytes, then whole bytes.
      "mov r31, r30\n\t" "andi r31, 7\n\t" "breq 5f\n\t"
      "7:\n\t"
      "lsl %A[p]\n\t" "rol %B[p]\n\t" "rol %C[p]\n\t" "dec r31\n\t" "brne 7b\n\t"
      "5:\n\t"
      "sbrc r30, 4\n\t" "rjmp 8f\n\t"
      "sbrc r30, 3\n\t" "rjmp 9f\n\t"
      "movw %A[m], %A[p]\n\t" "mov %C[m], %C[p]\n\t" "clr %D[m]\n\t" "rjmp 10f\n\t"
      "9:\n\t"
      "clr %A[m]\n\t" "mov %B[m], %A[p]\n\t" "mov %C[m], %B[p]\n\t" "mov %D[m], %C[p]\n\t" "rjmp 10f\n\t"
      "8:\n\t"
      "clr %A[m]\n\t" "clr %B[m]\n\t" "movw %C[m], %A[p]\n\t" "rjmp 10f\n\t"
      // e < 0: shr_round by n = -e: ((estimate >> (n - 1)) + 1) >> 1.
      "6:\n\t"
      "neg r30\n\t" "dec r30\n\t"
      "sbrs r30, 3\n\t" "rjmp 11f\n\t"
      "mov %A[p], %B[p]\n\t" "mov %B[p], %C[p]\n\t" "clr %C[p]\n\t"
      "11:\n\t"
      "andi r30, 7\n\t" "breq 12f\n\t"
      "13:\n\t"
      "lsr %C[p]\n\t" "ror %B[p]\n\t" "ror %A[p]\n\t" "dec r30\n\t" "brne 13b\n\t"
      "12:\n\t"
      "sec\n\t" "adc %A[p], __zero_reg__\n\t" "adc %B[p], __zero_reg__\n\t" "adc %C[p], __zero_reg__\n\t"
      "lsr %C[p]\n\t" "ror %B[p]\n\t" "ror %A[p]\n\t"
      "movw %A[m], %A[p]\n\t" "mov %C[m], %C[p]\n\t" "clr %D[m]\n\t"
      "10:"
      : [m] "=&r"(m), [k] "=&d"(k), [p] "+r"(p), [q] "+r"(q)
      : [sqrt_table] "i"(detail::FixedTables<>::kSqrt)
      : "r30", "r31");
  return m;
#else
  uint8_t k = uint8_t(normalize_top(p) + normalize_top(q));
  uint32_t m = detail::mul_u16(detail::hi16(p), detail::hi16(q));  // p q = m 2^(32 - k), m >= 2^30
  if (k & 1) {
    m >>= 1;
    --k;
    if (m < 0x40000000UL) { m <<= 2; k = uint8_t(k + 2); }
  }
  // sqrt(m) in [2^15, 2^16]; sqrt(p q) = sqrt(m) 2^(16 - k/2).
  return shift_signed(detail::isqrt_table_estimate(m), int8_t(16 - k / 2));
#endif
}

}  // namespace wide
}  // namespace leg_ik
}  // namespace strider

#endif  // STRIDER_KINEMATICS_WIDE_SQRT_H
