//! The AVR kernels of Fixed's run-time arithmetic (fixed.h): saturating add
//! and subtract, products from the hardware MUL and the restoring division,
//! each bit for bit Fixed's portable C (test_avr_exact).
#ifndef STRIDER_MATH_FIXED_AVR_H
#define STRIDER_MATH_FIXED_AVR_H

#include <stdint.h>

#include "mul16.h"

#if defined(__AVR__)
namespace strider {
namespace fixed_avr {

//! Fixed::sat_add and sat_sub: a 32-bit add or subtract, saturated on the
//! overflow flag toward the true result's sign (b's for a sum, the opposite
//! for a difference: skip is sbrs or sbrc).
#define STRIDER_FX_SAT(op, opc, skip)                                                                          \
  asm(op " %A0, %A1"     "\n\t" opc " %B0, %B1"   "\n\t" opc " %C0, %C1"   "\n\t" opc " %D0, %D1" "\n\t"   \
      "brvc 1f"          "\n\t"                                                                               \
      "ldi %A0, 0xFF"    "\n\t" "ldi %B0, 0xFF"    "\n\t" "ldi %C0, 0xFF"    "\n\t" "ldi %D0, 0x7F" "\n\t"  \
      skip " %D1, 7"     "\n\t" "rjmp 1f"          "\n\t"                                                    \
      "ldi %A0, 0x00"    "\n\t" "ldi %B0, 0x00"    "\n\t" "ldi %C0, 0x00"    "\n\t" "ldi %D0, 0x80" "\n"     \
      "1:"                                                                                                    \
      : "+&d"(a)                                                                                              \
      : "r"(b))
STRIDER_ALWAYS_INLINE int32_t sat_add(int32_t a, int32_t b) {
  STRIDER_FX_SAT("add", "adc", "sbrs");
  return a;
}
STRIDER_ALWAYS_INLINE int32_t sat_sub(int32_t a, int32_t b) {
  STRIDER_FX_SAT("sub", "sbc", "sbrc");
  return a;
}
#undef STRIDER_FX_SAT

// div_mag(ua, ub) for ub != 0: saturated when ua >> 15 >= ub; else the
// remainder ua >> 15 and 31 restoring steps over the bits of ua << 17
// (shifted out of q as the quotient bits shift in), then div_frac's
// rounding step. The remainder stays below ub <= 2^31.
__attribute__((noinline)) inline uint32_t div_mag(uint32_t ua, uint32_t ub) {
  uint32_t rem = (ua >> 16) << 1 | uint32_t((uint16_t(ua) >> 15) & 1u);
  if (rem >= ub) return 0xFFFFFFFFu;
  uint32_t q = ua << 17;
  uint8_t count;
  asm("ldi %[n], 31"      "\n"
      "1:"                "\n\t"
      "lsl %A[q]"         "\n\t" "rol %B[q]"     "\n\t" "rol %C[q]"     "\n\t" "rol %D[q]" "\n\t"
      "rol %A[r]"         "\n\t" "rol %B[r]"     "\n\t" "rol %C[r]"     "\n\t" "rol %D[r]" "\n\t"
      "cp %A[r], %A[u]"   "\n\t" "cpc %B[r], %B[u]" "\n\t" "cpc %C[r], %C[u]" "\n\t" "cpc %D[r], %D[u]" "\n\t"
      "brlo 2f"           "\n\t"
      "sub %A[r], %A[u]"  "\n\t" "sbc %B[r], %B[u]" "\n\t" "sbc %C[r], %C[u]" "\n\t" "sbc %D[r], %D[u]" "\n\t"
      "inc %A[q]"         "\n"  // bit 0 is clear after the shift
      "2:"                "\n\t"
      "dec %[n]"          "\n\t"
      "brne 1b"
      : [q] "+r"(q), [r] "+r"(rem), [n] "=&d"(count)
      : [u] "r"(ub));
  return q + ((rem >= ub - rem) ? 1u : 0u);
}

//! mul_raw for the AVR: a factor below 1.0 in magnitude takes a 32 x 16-bit
//! product of 8 MULs, the others the full product
//! (strider_fixed_mul_full_avr()).
// In the call-clobbered registers (a in r22..r25, b in r18..r21, result in
// r22..r25). With |b| < 2^16 raw (a and b swapped if only |a| is): the sign
// into T, the product P5..P0 of |a| and |b| by byte column into
// r27:r26:r21:r20 (bit 7 of P1, in r30, rounds), then apply_sign().
__attribute__((naked, noinline)) inline int32_t mul_raw(int32_t, int32_t) {
  asm volatile(
      // |b| < 2^16: its top half 0, or 0xFFFF above a non-zero low half.
      "cp r20, r1"       "\n\t" "cpc r21, r1"     "\n\t" "breq 6f"          "\n\t"
      "cpi r20, 0xFF"    "\n\t" "brne 5f"         "\n\t" "cpi r21, 0xFF"    "\n\t" "brne 5f" "\n\t"
      "cp r18, r1"       "\n\t" "cpc r19, r1"     "\n\t" "brne 6f"          "\n"
      "5:"               "\n\t"
      // |a| < 2^16: swap a and b.
      "cp r24, r1"       "\n\t" "cpc r25, r1"     "\n\t" "breq 7f"          "\n\t"
      "cpi r24, 0xFF"    "\n\t" "brne 8f"         "\n\t" "cpi r25, 0xFF"    "\n\t" "brne 8f" "\n\t"
      "cp r22, r1"       "\n\t" "cpc r23, r1"     "\n\t" "brne 7f"          "\n"
      "8:"               "\n\t"
      "jmp strider_fixed_mul_full_avr" "\n"
      "7:"               "\n\t"
      "movw r26, r22"    "\n\t" "movw r30, r24"   "\n\t" "movw r22, r18"    "\n\t" "movw r24, r20" "\n\t"
      "movw r18, r26"    "\n\t" "movw r20, r30"   "\n"
      "6:"               "\n\t"
      "mov r26, r25"     "\n\t" "eor r26, r21"    "\n\t" "bst r26, 7"       "\n\t"
      "sbrs r25, 7"      "\n\t" "rjmp 1f"         "\n\t"
      "com r25"          "\n\t" "com r24"         "\n\t" "com r23"          "\n\t" "neg r22" "\n\t"
      "sbci r23, 0xFF"   "\n\t" "sbci r24, 0xFF"  "\n\t" "sbci r25, 0xFF"   "\n"
      "1:"               "\n\t"
      "sbrs r21, 7"      "\n\t" "rjmp 2f"         "\n\t"
      "com r19"          "\n\t" "neg r18"         "\n\t" "sbci r19, 0xFF"   "\n"
      "2:"               "\n\t"
      "clr r31"          "\n\t"
      "mul r22, r18"     "\n\t" "mov r30, r1"     "\n\t"   // a0b0 -> P1:P0
      "mul r23, r19"     "\n\t" "movw r20, r0"    "\n\t"   // a1b1 -> P3:P2
      "mul r25, r19"     "\n\t" "movw r26, r0"    "\n\t"   // a3b1 -> P5:P4
      "mul r23, r18"     "\n\t"                            // a1b0 -> P2:P1
      "add r30, r0"      "\n\t" "adc r20, r1"     "\n\t" "adc r21, r31"     "\n\t"
      "adc r26, r31"     "\n\t" "adc r27, r31"    "\n\t"
      "mul r22, r19"     "\n\t"                            // a0b1 -> P2:P1
      "add r30, r0"      "\n\t" "adc r20, r1"     "\n\t" "adc r21, r31"     "\n\t"
      "adc r26, r31"     "\n\t" "adc r27, r31"    "\n\t"
      "mul r24, r18"     "\n\t"                            // a2b0 -> P3:P2
      "add r20, r0"      "\n\t" "adc r21, r1"     "\n\t" "adc r26, r31"     "\n\t" "adc r27, r31" "\n\t"
      "mul r25, r18"     "\n\t"                            // a3b0 -> P4:P3
      "add r21, r0"      "\n\t" "adc r26, r1"     "\n\t" "adc r27, r31"     "\n\t"
      "mul r24, r19"     "\n\t"                            // a2b1 -> P4:P3
      "add r21, r0"      "\n\t" "adc r26, r1"     "\n\t" "adc r27, r31"     "\n\t"
      "lsl r30"          "\n\t"                            // + 2^15: carry = bit 15
      "adc r20, r31"     "\n\t" "adc r21, r31"    "\n\t" "adc r26, r31"     "\n\t" "adc r27, r31" "\n\t"
      "clr r1"           "\n\t"
      "movw r22, r20"    "\n\t" "movw r24, r26"   "\n\t"
      "brts 3f"          "\n\t"
      "sbrs r25, 7"      "\n\t" "ret"             "\n\t"   // positive, below 2^31
      "ldi r22, 0xFF"    "\n\t" "ldi r23, 0xFF"   "\n\t" "ldi r24, 0xFF"    "\n\t" "ldi r25, 0x7F" "\n\t"
      "ret"              "\n"
      "3:"               "\n\t"
      "sbrc r25, 7"      "\n\t" "rjmp 4f"         "\n\t"
      "com r25"          "\n\t" "com r24"         "\n\t" "com r23"          "\n\t" "neg r22" "\n\t"
      "sbci r23, 0xFF"   "\n\t" "sbci r24, 0xFF"  "\n\t" "sbci r25, 0xFF"   "\n\t"
      "ret"              "\n"
      "4:"               "\n\t"
      "ldi r22, 0x00"    "\n\t" "ldi r23, 0x00"   "\n\t" "ldi r24, 0x00"    "\n\t" "ldi r25, 0x80" "\n\t"
      "ret");
}

// round(P / 2^16) of the 64-bit product P of two magnitudes (16 MULs by
// byte column), saturated like mul_mag.
STRIDER_ALWAYS_INLINE uint32_t mul_mag_full(uint32_t a, uint32_t b) {
  uint32_t lo, hi;  // P3..P0, P7..P4
  uint8_t zero;
  asm("clr %[z]"                         "\n\t"
      "mul %A[a], %A[b]"                 "\n\t"  // a0b0 -> P1:P0
      "movw %A[lo], r0"                  "\n\t"
      "mul %B[a], %B[b]"                 "\n\t"  // a1b1 -> P3:P2
      "movw %C[lo], r0"                  "\n\t"
      "mul %C[a], %C[b]"                 "\n\t"  // a2b2 -> P5:P4
      "movw %A[hi], r0"                  "\n\t"
      "mul %D[a], %D[b]"                 "\n\t"  // a3b3 -> P7:P6
      "movw %C[hi], r0"                  "\n\t"
// Macros, not constexpr functions: an asm template must be one string literal.
#define STRIDER_FX_COL1(x, y)                                                         \
      "mul " x ", " y "\n\t add %B[lo], r0\n\t adc %C[lo], r1\n\t adc %D[lo], %[z]\n\t" \
      "adc %A[hi], %[z]\n\t adc %B[hi], %[z]\n\t adc %C[hi], %[z]\n\t adc %D[hi], %[z]\n\t"
#define STRIDER_FX_COL2(x, y)                                                         \
      "mul " x ", " y "\n\t add %C[lo], r0\n\t adc %D[lo], r1\n\t adc %A[hi], %[z]\n\t"  \
      "adc %B[hi], %[z]\n\t adc %C[hi], %[z]\n\t adc %D[hi], %[z]\n\t"
#define STRIDER_FX_COL3(x, y)                                                         \
      "mul " x ", " y "\n\t add %D[lo], r0\n\t adc %A[hi], r1\n\t adc %B[hi], %[z]\n\t"  \
      "adc %C[hi], %[z]\n\t adc %D[hi], %[z]\n\t"
#define STRIDER_FX_COL4(x, y)                                                         \
      "mul " x ", " y "\n\t add %A[hi], r0\n\t adc %B[hi], r1\n\t adc %C[hi], %[z]\n\t"  \
      "adc %D[hi], %[z]\n\t"
#define STRIDER_FX_COL5(x, y) \
      "mul " x ", " y "\n\t add %B[hi], r0\n\t adc %C[hi], r1\n\t adc %D[hi], %[z]\n\t"
      STRIDER_FX_COL1("%A[a]", "%B[b]") STRIDER_FX_COL1("%B[a]", "%A[b]")
      STRIDER_FX_COL2("%A[a]", "%C[b]") STRIDER_FX_COL2("%C[a]", "%A[b]")
      STRIDER_FX_COL3("%A[a]", "%D[b]") STRIDER_FX_COL3("%D[a]", "%A[b]")
      STRIDER_FX_COL3("%B[a]", "%C[b]") STRIDER_FX_COL3("%C[a]", "%B[b]")
      STRIDER_FX_COL4("%B[a]", "%D[b]") STRIDER_FX_COL4("%D[a]", "%B[b]")
      STRIDER_FX_COL5("%C[a]", "%D[b]") STRIDER_FX_COL5("%D[a]", "%C[b]")
#undef STRIDER_FX_COL1
#undef STRIDER_FX_COL2
#undef STRIDER_FX_COL3
#undef STRIDER_FX_COL4
#undef STRIDER_FX_COL5
      "clr __zero_reg__"
      : [lo] "=&r"(lo), [hi] "=&r"(hi), [z] "=&r"(zero)
      : [a] "r"(a), [b] "r"(b)
      : "r0");
  if ((hi >> 16) != 0) return 0xFFFFFFFFu;
  const uint32_t mid = (hi << 16) | (lo >> 16);
  return (lo & 0x8000u) ? (mid > 0xFFFFFFFEu ? 0xFFFFFFFFu : mid + 1u) : mid;  // + 1, saturated
}

}  // namespace fixed_avr
}  // namespace strider
#endif

#endif  // STRIDER_MATH_FIXED_AVR_H
