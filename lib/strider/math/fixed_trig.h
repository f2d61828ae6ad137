//! sin and cos for Fixed (Q16.16 radians), and the exact angle reduction that
//! they share with wrap_pi / wrap_two_pi: Cody-Waite reduction in Q8.24 and a
//! 404-node sin table (docs/fixed-point.md, "sin and cos"). sin(-x) = -sin(x)
//! and cos(-x) = cos(x) bit for bit.
#ifndef STRIDER_MATH_FIXED_TRIG_H
#define STRIDER_MATH_FIXED_TRIG_H

#include <stdint.h>

#include "fixed.h"
#include "fixed_ops.h"

namespace strider {
namespace detail {

// Angles in Q8.24 [2^-24 rad], rounded to nearest.
constexpr int32_t kPiQ24 = 52707179;       //!< pi 2^24
constexpr int32_t kHalfPiQ24 = 26353589;   //!< pi/2 2^24
constexpr int32_t kTwoPiQ24 = 105414357;   //!< 2 pi 2^24 (integer part)
constexpr uint16_t kTwoPiQ24Lo = 4363;     //!< (2 pi 2^24 - kTwoPiQ24) 2^16
constexpr uint16_t kInvTwoPiQ16 = 10430;   //!< 2^16 / (2 pi), truncated
constexpr int32_t kPiRaw = 205887;         //!< pi in Q16.16
constexpr int32_t kTwoPiRaw = 411775;      //!< 2 pi in Q16.16

//! |a| 2^24 - n 2 pi 2^24 modulo 2^32 for |a| = ua / 2^16 >= 8 rad, with
//! n = round(|a| / 2 pi) within +-1: the true value is within +-3 pi.
inline uint32_t reduce_large_angle_q24(uint32_t ua) {
  // n from the high half of |a| alone (|a| < 2^15 rad, so n < 2^13).
  const uint16_t n = hi16(mul_u16(hi16(ua), kInvTwoPiQ16) + uint32_t(0x8000));
  // n 2 pi 2^24 = n kTwoPiQ24 (low 32 bits, from two 16x16 products)
  // + n kTwoPiQ24Lo / 2^16 (rounded).
  const uint16_t n_hi = uint16_t(mul_u16(n, uint16_t(kTwoPiQ24 >> 16)));
  const uint32_t n_two_pi = mul_u16(n, uint16_t(kTwoPiQ24)) + (uint32_t(n_hi) << 16);
  return (ua << 8) - n_two_pi - hi16(mul_u16(n, kTwoPiQ24Lo) + uint32_t(0x8000));
}

//! raw / 2^16 [rad] reduced modulo 2 pi into [-pi, pi], in Q8.24.
//! Error below 1 unit of 2^-24 rad (6e-8 rad) for every input. Odd in raw.
//! Inlined: below 8 rad it is a shift and one conditional 2 pi.
STRIDER_ALWAYS_INLINE int32_t reduce_angle_q24(int32_t raw) {
  const uint32_t ua = abs_u32(raw);
  int32_t s = to_signed(ua < 0x80000UL ? ua << 8 : reduce_large_angle_q24(ua));
  if (s > kPiQ24) {
    s -= kTwoPiQ24;
  } else if (s < -kPiQ24) {
    s += kTwoPiQ24;
  }
  return raw < 0 ? -s : s;
}

//! Rounds a Q8.24 angle to Q16.16, half away from zero (odd).
STRIDER_ALWAYS_INLINE int32_t q24_to_raw(int32_t a) {
  const int32_t m = int32_t((abs_u32(a) + 128U) >> 8);
  return a < 0 ? -m : m;
}

//! wrap_pi for Fixed: the result r has -pi < r <= pi in Fixed comparisons
//! (pi = pi<Fixed>()) and is within 1 LSB of the exact wrapped angle.
inline Fixed wrap_pi(Fixed a) {
  const int32_t q = reduce_angle_q24(a.raw());
  int32_t r = q24_to_raw(q);
  // -kPiRaw is outside the interval: an angle that rounds to it goes to the
  // nearer of -kPiRaw + 1 and kPiRaw around the circle (the midpoint is
  // -52707050.5 in Q8.24), which keeps the error within 0.92 LSB.
  if (r <= -kPiRaw) r = q <= int32_t(-52707051) ? kPiRaw : -kPiRaw + 1;
  return Fixed::from_raw(r);
}

//! wrap_two_pi for Fixed: 0 <= r < two_pi<Fixed>(), within 1 LSB.
inline Fixed wrap_two_pi(Fixed a) {
  const int32_t r = q24_to_raw(reduce_angle_q24(a.raw()));
  return Fixed::from_raw(r < 0 ? r + kTwoPiRaw : r);
}

//! sin (cosine false) or cos (true) of raw / 2^16 [rad] as a raw value, the
//! one out-of-line body of both: sin(raw) = +-sin|s| for raw reduced to s,
//! and cos(raw) = sin(pi/2 - |s|).
STRIDER_NOINLINE inline int32_t sin_cos_raw(int32_t raw, bool cosine) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  const uint32_t ua = abs_u32(raw);
  // Flags: bit 7 the sign of raw, bit 0 cosine.
  const uint8_t flags = uint8_t(uint8_t(uint8_t(uint32_t(raw) >> 24) & 0x80U) | (cosine ? 1U : 0U));
  uint32_t s = ua < 0x80000UL ? ua << 8 : reduce_large_angle_q24(ua);
  int32_t r;
  uint16_t d;
  uint8_t k;
  // The C below in assembly, bit for bit (test_avr_exact: fixed_sin, fixed_cos).
  __asm__(
      // s > pi: s -= 2 pi; s < -pi: s += 2 pi (signed).
      "ldi %[k], lo8(%[pi1])\n\t" "cp %A[s], %[k]\n\t" "ldi %[k], hi8(%[pi1])\n\t" "cpc %B[s], %[k]\n\t"
      "ldi %[k], hlo8(%[pi1])\n\t" "cpc %C[s], %[k]\n\t" "ldi %[k], hhi8(%[pi1])\n\t" "cpc %D[s], %[k]\n\t"
      "brlt 1f\n\t"
      "subi %A[s], lo8(%[tp])\n\t" "sbci %B[s], hi8(%[tp])\n\t" "sbci %C[s], hlo8(%[tp])\n\t" "sbci %D[s], hhi8(%[tp])\n\t"
      "rjmp 2f\n\t"
      "1:\n\t"
      "ldi %[k], lo8(-(%[pi]))\n\t" "cp %A[s], %[k]\n\t" "ldi %[k], hi8(-(%[pi]))\n\t" "cpc %B[s], %[k]\n\t"
      "ldi %[k], hlo8(-(%[pi]))\n\t" "cpc %C[s], %[k]\n\t" "ldi %[k], hhi8(-(%[pi]))\n\t" "cpc %D[s], %[k]\n\t"
      "brge 2f\n\t"
      "subi %A[s], lo8(-(%[tp]))\n\t" "sbci %B[s], hi8(-(%[tp]))\n\t"
      "sbci %C[s], hlo8(-(%[tp]))\n\t" "sbci %D[s], hhi8(-(%[tp]))\n\t"
      "2:\n\t"
      // T = the sine's sign (raw's xor s's); m = |s| in s.
      "mov %[k], %D[s]\n\t" "eor %[k], %[f]\n\t" "bst %[k], 7\n\t"
      "sbrs %D[s], 7\n\t" "rjmp 3f\n\t"
      "com %D[s]\n\t" "com %C[s]\n\t" "com %B[s]\n\t" "neg %A[s]\n\t"
      "sbci %B[s], 0xFF\n\t" "sbci %C[s], 0xFF\n\t" "sbci %D[s], 0xFF\n\t"
      "3:\n\t"
      "sbrs %[f], 0\n\t" "rjmp 4f\n\t"
      // cos: c = pi/2 - m = ~m + (pi/2 + 1); T = c < 0; m = |c|.
      STRIDER_ASM_RSUB32("s", "%[half]")
      "bst %D[s], 7\n\t"
      "sbrs %D[s], 7\n\t" "rjmp 5f\n\t"
      "com %D[s]\n\t" "com %C[s]\n\t" "com %B[s]\n\t" "neg %A[s]\n\t"
      "sbci %B[s], 0xFF\n\t" "sbci %C[s], 0xFF\n\t" "sbci %D[s], 0xFF\n\t"
      "rjmp 5f\n\t"
      // sin: m > pi/2: m = pi - m = ~m + (pi + 1).
      "4:\n\t"
      "ldi %[k], lo8(%[half] + 1)\n\t" "cp %A[s], %[k]\n\t" "ldi %[k], hi8(%[half] + 1)\n\t" "cpc %B[s], %[k]\n\t"
      "ldi %[k], hlo8(%[half] + 1)\n\t" "cpc %C[s], %[k]\n\t" "ldi %[k], hhi8(%[half] + 1)\n\t" "cpc %D[s], %[k]\n\t"
      "brlo 5f\n\t"
      STRIDER_ASM_RSUB32("s", "%[pi]")
      "5:\n\t"
      // sin m: t0, t1 = kSin[i], [i + 1] for i = m >> 16,
      // f = m & 0xFFFF; v = t0 2^8 + ((t1 - t0) f >> 8) in k:r (bytes 0..2:
      // k, B, C of r), then v += v >> 16 and (v + 128) >> 8 into r.
      "movw r30, %C[s]\n\t" "lsl r30\n\t" "rol r31\n\t"
      "subi r30, lo8(-(%[table]))\n\t" "sbci r31, hi8(-(%[table]))\n\t"
      "lpm %B[r], Z+\n\t" "lpm %C[r], Z+\n\t" "lpm %A[d], Z+\n\t" "lpm %B[d], Z\n\t"
      "sub %A[d], %B[r]\n\t" "sbc %B[d], %C[r]\n\t"
      // (t1 - t0) f: P1 in k, P3:P2 in %D[s]:%C[s].
      "mul %B[d], %B[s]\n\t" "movw %C[s], r0\n\t"
      "mul %A[d], %A[s]\n\t" "mov %[k], r1\n\t"
      "mul %A[d], %B[s]\n\t" "add %[k], r0\n\t" "adc %C[s], r1\n\t" "clr __zero_reg__\n\t" "adc %D[s], __zero_reg__\n\t"
      "mul %B[d], %A[s]\n\t" "add %[k], r0\n\t" "adc %C[s], r1\n\t" "clr __zero_reg__\n\t" "adc %D[s], __zero_reg__\n\t"
      "add %B[r], %C[s]\n\t" "adc %C[r], %D[s]\n\t"
      "add %[k], %C[r]\n\t" "adc %B[r], __zero_reg__\n\t" "adc %C[r], __zero_reg__\n\t"
      "clr %D[r]\n\t"
      "lsl %[k]\n\t" "adc %B[r], __zero_reg__\n\t" "adc %C[r], __zero_reg__\n\t" "adc %D[r], __zero_reg__\n\t"
      "mov %A[r], %B[r]\n\t" "mov %B[r], %C[r]\n\t" "mov %C[r], %D[r]\n\t" "clr %D[r]\n\t"
      // The sign: -r = ~r + 1.
      "brtc 6f\n\t"
      STRIDER_ASM_NEG32("r")
      "6:"
      : [r] "=&r"(r), [d] "=&r"(d), [k] "=&d"(k), [s] "+d"(s)
      : [f] "r"(flags), [pi] "i"(kPiQ24), [pi1] "i"(kPiQ24 + 1), [tp] "i"(kTwoPiQ24), [half] "i"(kHalfPiQ24),
        [table] "i"(FixedTables<>::kSin)
      : "r30", "r31");
  return r;
#else
  const int32_t s = reduce_angle_q24(raw);
  bool negative = s < 0;
  uint32_t m = abs_u32(s);
  if (cosine) {
    const int32_t c = kHalfPiQ24 - int32_t(m);
    negative = c < 0;
    m = abs_u32(c);
  } else if (m > uint32_t(kHalfPiQ24)) {
    m = uint32_t(kPiQ24) - m;
  }
  // sin m from the table of 65535 sin, interpolated; v += v >> 16 rescales
  // it to 65536 sin.
  const uint16_t i = uint16_t(m >> 16);
  const uint16_t t0 = flash_u16(FixedTables<>::kSin, i);
  const uint16_t t1 = flash_u16(FixedTables<>::kSin, uint16_t(i + 1U));
  uint32_t v = (uint32_t(t0) << 8) + (mul_u16(uint16_t(t1 - t0), uint16_t(m)) >> 8);
  v += v >> 16;
  const int32_t r = int32_t((v + 128U) >> 8);
  return negative ? -r : r;
#endif
}

}  // namespace detail

//! sin(a) [a in rad], any a; abs error < 1.1 LSB = 1.7e-5 (measured 1.59e-5).
inline Fixed sin(Fixed a) { return Fixed::from_raw(detail::sin_cos_raw(a.raw(), false)); }

//! cos(a) [a in rad] = sin(pi/2 - |a|); abs error < 1.1 LSB = 1.7e-5.
inline Fixed cos(Fixed a) { return Fixed::from_raw(detail::sin_cos_raw(a.raw(), true)); }

}  // namespace strider

#endif  // STRIDER_MATH_FIXED_TRIG_H
