//! Wide working units: the 32-bit integer arithmetic of Fixed's leg IK fast
//! paths (two_link.h's solve_wide and the legs' own fast paths): conversions
//! from and to Fixed millimetres, squares, sums of squares and roots.
#ifndef STRIDER_KINEMATICS_WIDE_UNITS_H
#define STRIDER_KINEMATICS_WIDE_UNITS_H

#include "leg_ik_common.h"

namespace strider {
namespace leg_ik {

//! Fixed's integer fast path (docs/fixed-point.md, "Leg IK"). Lengths are
//! "wide" working units: int32 Q3.28 (|v| < 8 units), so a length's top 16
//! bits are Q3.12 and its square needs two 16x16 products; squares are Q6.24,
//! which is a Fixed square in units [unit^2] shifted left by 8 (whole bytes).
namespace wide {

//! u << k for k in [0, 31]: whole bytes, then single bits (avr-gcc loops
//! over every bit of a variable 32-bit shift).
STRIDER_ALWAYS_INLINE uint32_t shl(uint32_t u, uint8_t k) {
  if (k & 16) u <<= 16;
  if (k & 8) u <<= 8;
  for (k &= 7; k != 0; --k) u <<= 1;
  return u;
}

//! from_mm() for any shift: out of line, as only short legs (below 128 mm),
//! very long ones and coordinates of 256 mm or more need it.
inline bool from_mm_general(Fixed v_mm, int8_t shift, int32_t& out) {
  uint32_t m = Fixed::abs_raw(v_mm.raw());
  const int8_t k = int8_t(12 - shift);  // wide = raw 2^(12 - n)
  if (k >= 0) {
    if (k > 15) return false;
    // m 2^k < 2^31; a variable 32-bit shift is a loop.
    if (m >= (uint32_t(0x80000000UL) >> k)) return false;
    m = shl(m, uint8_t(k));
  } else {
    if (k < -24) return false;
    m = detail::shr_round(m, uint8_t(-k));
    if (m >= 0x80000000UL) return false;
  }
  out = v_mm.raw() < 0 ? -int32_t(m) : int32_t(m);
  return true;
}

//! Fixed [mm] to wide units of a leg with unit shift n; false when |v| is
//! 8 units or more (then the caller takes the general path).
STRIDER_ALWAYS_INLINE bool from_mm(Fixed v_mm, int8_t shift, int32_t& out) {
  const uint8_t down = uint8_t(shift - 4);  // 8 - k for wide = raw 2^k, k = 12 - n
  uint32_t m = Fixed::abs_raw(v_mm.raw());
  // The common case, inline: |v| < 256 mm and k in [1, 7] (legs of 128 mm
  // and more). raw 2^k is a whole-byte shift, then 8 - k single-bit steps
  // back (one for a 128-255 mm leg), instead of k steps; it stays below 2^31.
  if (uint8_t(down - 1U) < 7U && m < 0x1000000UL) {
    m <<= 8;
    for (uint8_t r = down; r != 0; --r) m >>= 1;
    out = v_mm.raw() < 0 ? -int32_t(m) : int32_t(m);
    return true;
  }
  return from_mm_general(v_mm, shift, out);
}

//! |v| of from_mm(), for a coordinate that is only squared: no sign to put
//! back and take off again.
STRIDER_ALWAYS_INLINE bool from_mm_abs(Fixed v_mm, int8_t shift, uint32_t& out) {
  const uint8_t down = uint8_t(shift - 4);
  uint32_t m = Fixed::abs_raw(v_mm.raw());
  if (uint8_t(down - 1U) < 7U && m < 0x1000000UL) {  // as in from_mm()
    m <<= 8;
    for (uint8_t r = down; r != 0; --r) m >>= 1;
    out = m;
    return true;
  }
  int32_t w;
  if (!from_mm_general(v_mm, shift, w)) return false;
  out = detail::abs_u32(w);
  return true;
}

//! A Fixed length [unit] below 8 units in wide units (exact): raw 2^12,
//! modulo 2^32, from one 16x16 product and a 16-bit shift (avr-gcc loops
//! 12 times for a 32-bit shift by 12).
STRIDER_ALWAYS_INLINE int32_t from_unit(Fixed v) {
  const uint32_t u = uint32_t(v.raw());
  return detail::to_signed(detail::mul_u16(uint16_t(u), 0x1000U) + (uint32_t(uint16_t(detail::hi16(u) << 12)) << 16));
}

//! A Fixed square or difference of squares [unit^2] below 64 in magnitude
//! (a TwoLink constant of links shorter than 8 units; a1^2 - a2^2 is
//! negative when a1 < a2) in Q6.24: raw 2^8, exact. A product, not
//! raw << 8: shifting a negative value left is undefined in C++14, and
//! |raw| < 2^22 keeps the product inside int32. avr-gcc emits the same
//! byte moves for both.
STRIDER_ALWAYS_INLINE int32_t from_sq(Fixed sq) { return sq.raw() * 256; }

//! A wide length w >= 0 as Fixed [mm] for a leg with unit shift n:
//! round(w 2^(n - 12)) raw; false when it does not fit.
inline bool to_mm(uint32_t w, int8_t shift, Fixed& out) {
  const int8_t k = int8_t(12 - shift);
  if (k > 0) {
    if (k > 31) return false;
    w = detail::shr_round(w, uint8_t(k));
  } else if (k < 0) {
    if (k < -15 || w >= (uint32_t(0x80000000UL) >> -k)) return false;
    w = shl(w, uint8_t(-k));
  }
  if (w >= 0x80000000UL) return false;
  out = Fixed::from_raw(int32_t(w));
  return true;
}

//! The raw difference a - b of two Fixed values below 2^14 in magnitude
//! (16384 mm), without the saturation test of Fixed's operator- (an
//! out-of-line call on the AVR); false when either is larger.
STRIDER_ALWAYS_INLINE bool sub_raw(Fixed a, Fixed b, Fixed& out) {
  const uint32_t ua = uint32_t(a.raw()), ub = uint32_t(b.raw());
  // uint32_t casts: unsigned long is 64 bits on some hosts.
  if (uint32_t(ua + 0x40000000UL) >= 0x80000000UL || uint32_t(ub + 0x40000000UL) >= 0x80000000UL) return false;
  out = Fixed::from_raw(detail::to_signed(ua - ub));
  return true;
}

//! u^2 in Q6.24 for a wide magnitude u < 2^31, within 2 LSB below (the low
//! half's square is dropped).
STRIDER_ALWAYS_INLINE uint32_t sq_abs(uint32_t u) {
  const uint16_t uh = detail::hi16(u);  // < 2^15
  return detail::mul_u16(uh, uh) + detail::hi16(detail::mul_u16(uint16_t(uh << 1), uint16_t(u)));
}

//! w^2 in Q6.24 for a wide w: sq_abs(|w|).
STRIDER_ALWAYS_INLINE uint32_t sq(int32_t w) { return sq_abs(detail::abs_u32(w)); }

#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
// One sq() of operand X added into s (t: scratch) for sq_sum(): |X|, then
// hi16(X)^2 and hi16(2 hi16(X) lo16(X)); X is clobbered.
#define STRIDER_WIDE_SQ_ADD(X)                                                                             \
  "sbrs %D[" X "], 7\n\t" "rjmp 1f\n\t"                                                                  \
  "com %A[" X "]\n\t" "com %B[" X "]\n\t" "com %C[" X "]\n\t" "com %D[" X "]\n\t" "sec\n\t"            \
  "adc %A[" X "], __zero_reg__\n\t" "adc %B[" X "], __zero_reg__\n\t"                                     \
  "adc %C[" X "], __zero_reg__\n\t" "adc %D[" X "], __zero_reg__\n\t"                                     \
  "1:\n\t"                                                                                                \
  "mul %C[" X "], %C[" X "]\n\t" "movw %A[t], r0\n\t"                                                    \
  "mul %D[" X "], %D[" X "]\n\t" "movw %C[t], r0\n\t"                                                    \
  "mul %C[" X "], %D[" X "]\n\t" "add %B[t], r0\n\t" "adc %C[t], r1\n\t"                               \
  "clr __zero_reg__\n\t" "adc %D[t], __zero_reg__\n\t"                                                    \
  "mul %C[" X "], %D[" X "]\n\t" "add %B[t], r0\n\t" "adc %C[t], r1\n\t"                               \
  "clr __zero_reg__\n\t" "adc %D[t], __zero_reg__\n\t"                                                    \
  "add %A[s], %A[t]\n\t" "adc %B[s], %B[t]\n\t" "adc %C[s], %C[t]\n\t" "adc %D[s], %D[t]\n\t"          \
  "lsl %C[" X "]\n\t" "rol %D[" X "]\n\t"                                                                 \
  "mul %C[" X "], %A[" X "]\n\t" "mov %B[t], r1\n\t"                                                     \
  "mul %D[" X "], %B[" X "]\n\t" "movw %C[t], r0\n\t"                                                    \
  "mul %C[" X "], %B[" X "]\n\t" "add %B[t], r0\n\t" "adc %C[t], r1\n\t"                               \
  "clr __zero_reg__\n\t" "adc %D[t], __zero_reg__\n\t"                                                    \
  "mul %D[" X "], %A[" X "]\n\t" "add %B[t], r0\n\t" "adc %C[t], r1\n\t"                               \
  "clr __zero_reg__\n\t" "adc %D[t], __zero_reg__\n\t"                                                    \
  "add %A[s], %C[t]\n\t" "adc %B[s], %D[t]\n\t" "adc %C[s], __zero_reg__\n\t" "adc %D[s], __zero_reg__\n\t"
#endif

//! sq(a) + sq(b) (modulo 2^32). On the AVR in assembly, the same bits: gcc
//! spills the two squares' temporaries around the solvers' live values.
//! test_avr_exact (wide_sq_sum) checks it against the C.
STRIDER_ALWAYS_INLINE uint32_t sq_sum(int32_t a, int32_t b) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  uint32_t s, t;
  __asm__("clr %A[s]\n\t" "clr %B[s]\n\t" "movw %C[s], %A[s]\n\t"
          STRIDER_WIDE_SQ_ADD("a") STRIDER_WIDE_SQ_ADD("b")
          : [s] "=&r"(s), [t] "=&r"(t), [a] "+r"(a), [b] "+r"(b));
  return s;
#else
  return sq(a) + sq(b);
#endif
}
#undef STRIDER_WIDE_SQ_ADD

//! Shift that brings u (!= 0) into [2^31, 2^32): whole bytes, then bits.
STRIDER_ALWAYS_INLINE uint8_t normalize_top(uint32_t& u) {
  uint8_t k = 0;
  if (u < 0x10000UL) { u <<= 16; k = 16; }
  if (u < 0x1000000UL) { u <<= 8; k = uint8_t(k + 8); }
  while (u < 0x80000000UL) { u <<= 1; ++k; }
  return k;
}

//! round(root 2^e) for e in [-31, 7] (a signed shift of an isqrt result).
STRIDER_ALWAYS_INLINE uint32_t shift_signed(uint32_t root, int8_t e) {
  return e >= 0 ? shl(root, uint8_t(e)) : detail::shr_round(root, uint8_t(-e));
}

//! sqrt(x) for x in Q6.24 (0 < x < 2^30): wide units. Inline: one call
//! site per solver, where a call costs more in register saves.
//! kSharedRoot calls the shared root kernel (isqrt_q22_call) instead of
//! inlining it.
template <bool kSharedRoot = false>
STRIDER_ALWAYS_INLINE int32_t sqrt_sq(uint32_t x) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  // normalize_even() and shift_signed() around the root in AVR assembly
  // (gcc loops over the bits of each shift; ~80 -> ~50 cycles), with
  // h = s / 2. test_avr_exact (wide_sqrt_sq) checks it against the C.
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

//! from_mm() as one shared out-of-line copy (the sprawl leg converts five
//! values per solve).
STRIDER_NOINLINE inline bool from_mm_call(Fixed v_mm, int8_t shift, int32_t& out) { return from_mm(v_mm, shift, out); }

//! sqrt(p q) for p, q > 0 in Q6.24 (a product of up to 60 bits), relative
//! error < 2^-14: both are normalised to 16 significant bits, multiplied,
//! and the root comes from the interpolated table alone. Q6.24.
//! Inline for the same reason as sqrt_sq().
STRIDER_ALWAYS_INLINE uint32_t sqrt_product(uint32_t p, uint32_t q) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  // The C below in AVR assembly, step for step (~240 -> ~150 cycles): gcc
  // loops over every bit of its shifts. Only hi16 of the normalised p and q
  // is used, so their bit steps shift the top three bytes. The estimate has
  // at most 17 bits, so the final left shift moves its bits within three
  // bytes first and then whole bytes (the same bits modulo 2^32).
  // test_avr_exact (wide_sqrt_product) checks it against the C bit for bit.
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
      "mov r30, %D[m]\n\t" "subi r30, 64\n\t" "clr r31\n\t" "lsl r30\n\t" "rol r31\n\t"
      "subi r30, lo8(-(%[sqrt_table]))\n\t" "sbci r31, hi8(-(%[sqrt_table]))\n\t"
      "lpm %A[p], Z+\n\t" "lpm %B[p], Z+\n\t"
      "lpm %A[q], Z+\n\t" "lpm %B[q], Z\n\t"
      "sub %A[q], %A[p]\n\t" "sbc %B[q], %B[p]\n\t"
      "mul %A[q], %B[m]\n\t" "mov %C[p], r1\n\t"
      "mul %B[q], %C[m]\n\t" "movw %C[q], r0\n\t"
      "mul %B[q], %B[m]\n\t" "add %C[p], r0\n\t" "adc %C[q], r1\n\t"
      "clr __zero_reg__\n\t" "adc %D[q], __zero_reg__\n\t"
      "mul %A[q], %C[m]\n\t" "add %C[p], r0\n\t" "adc %C[q], r1\n\t"
      "clr __zero_reg__\n\t" "adc %D[q], __zero_reg__\n\t"
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

#endif  // STRIDER_KINEMATICS_WIDE_UNITS_H
