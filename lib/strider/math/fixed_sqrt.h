//! Square root and hypot for Fixed (Q16.16), integer-only and division-free:
//! normalise, table estimate, exact residual, one Newton step with a table
//! reciprocal (docs/fixed-point.md, "sqrt" and "hypot").
#ifndef STRIDER_MATH_FIXED_SQRT_H
#define STRIDER_MATH_FIXED_SQRT_H

#include <stdint.h>

#include "fixed.h"
#include "fixed_ops.h"

namespace strider {
namespace detail {

//! sqrt(m) for m in [2^30, 2^32) by linear interpolation in the 193-node
//! table: within +-1 of floor(sqrt(m)) (test_fixed_sqrt checks both ends of
//! every 256-wide step of m, which bound it). In [2^15, 2^16].
STRIDER_ALWAYS_INLINE uint32_t isqrt_table_estimate(uint32_t m) {
  const uint16_t k = uint16_t((hi16(m) >> 8) - 64U);
  const uint16_t t0 = flash_u16(FixedTables<>::kSqrt, k);
  const uint16_t t1 = flash_u16(FixedTables<>::kSqrt, uint16_t(k + 1U));
  return uint32_t(32768) + t0 + hi16(mul_u16(uint16_t(t1 - t0), uint16_t(m >> 8)));
}

//! sqrt(m 2^22) for m in [2^30, 2^32) within +-1 of its floor, as q 2^11 +
//! frac: q = floor(sqrt(m)) from the table estimate and its exact residual,
//! frac in [0, 2047] from one Newton step.
STRIDER_ALWAYS_INLINE uint32_t isqrt_q22(uint32_t m) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  // The C (#else) in AVR assembly, bit for bit (test_avr_exact: fixed_isqrt
  // and every function built on it).
  uint32_t root;
  uint16_t q, u, w, x;
  uint8_t e;
  __asm__(
      // q = 32768 + t0 + hi16((t1 - t0) (m >> 8)), t0, t1 = kSqrt[k], [k + 1]
      // for k = (m >> 24) - 64; q = 65536 wraps to 0 in 16 bits, as in C.
      "mov r30, %D[m]\n\t"
      "subi r30, 64\n\t"
      STRIDER_ASM_TABLE_PAIR("sqrt_table", "q", "u")
      "sub %A[u], %A[q]\n\t" "sbc %B[u], %B[q]\n\t"
      STRIDER_ASM_MUL16_HI("%A[u]", "%B[u]", "%B[m]", "%C[m]", "%A[w]", "%A[x]", "%B[x]")
      "add %A[q], %A[x]\n\t" "adc %B[q], %B[x]\n\t"
      "subi %B[q], 0x80\n\t"
      // rem = m - q^2 modulo 2^32, in m.
      "mul %A[q], %A[q]\n\t" "movw %[u], r0\n\t"
      "mul %B[q], %B[q]\n\t" "movw %[w], r0\n\t"
      "mul %A[q], %B[q]\n\t" "movw %[x], r0\n\t"
      "clr __zero_reg__\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "adc %B[w], __zero_reg__\n\t"
      "add %B[u], %A[x]\n\t" "adc %A[w], %B[x]\n\t" "adc %B[w], __zero_reg__\n\t"
      "sub %A[m], %A[u]\n\t" "sbc %B[m], %B[u]\n\t" "sbc %C[m], %A[w]\n\t" "sbc %D[m], %B[w]\n\t"
      // rem < 0: --q, rem += 2q + 1; rem > 2q: rem -= 2q + 1, ++q.
      "sbrs %D[m], 7\n\t"
      "rjmp 1f\n\t"
      "subi %A[q], 1\n\t" "sbci %B[q], 0\n\t"
      "movw %[x], %[q]\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "clr %[e]\n\t" "rol %[e]\n\t" "inc %A[x]\n\t"
      "add %A[m], %A[x]\n\t" "adc %B[m], %B[x]\n\t" "adc %C[m], %[e]\n\t" "adc %D[m], __zero_reg__\n\t"
      "rjmp 2f\n\t"
      "1:\n\t"
      "movw %[x], %[q]\n\t"
      "lsl %A[x]\n\t" "rol %B[x]\n\t" "clr %[e]\n\t" "rol %[e]\n\t"
      "cp %A[x], %A[m]\n\t" "cpc %B[x], %B[m]\n\t" "cpc %[e], %C[m]\n\t" "cpc __zero_reg__, %D[m]\n\t"
      "brcc 2f\n\t"
      "inc %A[x]\n\t"
      "sub %A[m], %A[x]\n\t" "sbc %B[m], %B[x]\n\t" "sbc %C[m], %[e]\n\t" "sbc %D[m], __zero_reg__\n\t"
      "subi %A[q], lo8(-1)\n\t" "sbci %B[q], hi8(-1)\n\t"
      "2:\n\t"
      // rq = recip_q30(q, 0) = r0 - hi16((r0 - r1) (q & 0xFF) 2^8).
      "mov r30, %B[q]\n\t"
      "subi r30, 128\n\t"
      STRIDER_ASM_TABLE_PAIR("recip", "u", "w")
      "movw %[x], %[u]\n\t"
      "sub %A[x], %A[w]\n\t" "sbc %B[x], %B[w]\n\t"
      "mul %A[x], %A[q]\n\t" "mov %A[w], r1\n\t"
      "mul %B[x], %A[q]\n\t" "add %A[w], r0\n\t" "mov %B[w], r1\n\t"
      "clr __zero_reg__\n\t" "adc %B[w], __zero_reg__\n\t"
      "sub %A[u], %A[w]\n\t" "sbc %B[u], %B[w]\n\t"
      // frac = min(hi16((rem >> 1) rq) >> 3, 2047).
      "lsr %C[m]\n\t" "ror %B[m]\n\t" "ror %A[m]\n\t"
      STRIDER_ASM_MUL16_HI("%A[m]", "%B[m]", "%A[u]", "%B[u]", "%A[w]", "%A[x]", "%B[x]")
      "lsr %B[x]\n\t" "ror %A[x]\n\t" "lsr %B[x]\n\t" "ror %A[x]\n\t" "lsr %B[x]\n\t" "ror %A[x]\n\t"
      "cpi %B[x], 8\n\t"
      "brlo 3f\n\t"
      "ldi %A[x], 0xFF\n\t" "ldi %B[x], 0x07\n\t"
      "3:\n\t"
      // root = q 2^11 + frac.
      "clr %D[r]\n\t"
      "mov %B[r], %A[q]\n\t" "mov %C[r], %B[q]\n\t"
      "lsl %B[r]\n\t" "rol %C[r]\n\t" "rol %D[r]\n\t"
      "lsl %B[r]\n\t" "rol %C[r]\n\t" "rol %D[r]\n\t"
      "lsl %B[r]\n\t" "rol %C[r]\n\t" "rol %D[r]\n\t"
      "or %B[r], %B[x]\n\t"
      "mov %A[r], %A[x]"
      : [r] "=&r"(root), [q] "=&d"(q), [u] "=&r"(u), [w] "=&r"(w), [x] "=&d"(x), [e] "=&r"(e), [m] "+r"(m)
      : [sqrt_table] "i"(FixedTables<>::kSqrt), [recip] "i"(FixedTables<>::kRecip)
      : "r30", "r31");
  return root;
#else
  // q = 2^16 squares to 0 modulo 2^32, as uint16_t(q) does: rem stays right.
  uint32_t q = isqrt_table_estimate(m);
  int32_t rem = to_signed(m - mul_u16(uint16_t(q), uint16_t(q)));
  // q is within +-1 of floor(sqrt(m)): one conditional step fixes it.
  if (rem < 0) {
    --q;
    rem += int32_t(2 * q + 1);
  } else if (rem > int32_t(2 * q)) {
    rem -= int32_t(2 * q + 1);
    ++q;
  }
  // Now q = floor(sqrt(m)) < 2^16 and 0 <= rem <= 2q. One Newton step:
  // sqrt(m) - q ~ rem / (2q), in units of 2^-11: rem 2^10 / q.
  const uint16_t q16 = uint16_t(q);
  const uint16_t rq = recip_q30(q16, 0);  // 2^30 / q
  uint16_t frac = uint16_t(hi16(mul_u16(uint16_t(uint32_t(rem) >> 1), rq)) >> 3);
  if (frac > 2047) frac = 2047;
  return mul_u16(q16, 2048) + frac;
#endif
}

//! isqrt_q22() as one shared out-of-line copy, for sqrt(), hypot() and
//! acos(); the leg solvers' hot paths inline their own.
STRIDER_NOINLINE inline uint32_t isqrt_q22_call(uint32_t m) { return isqrt_q22(m); }

//! floor(sqrt(m 2^24)) for m in [2^30, 2^32) from root = isqrt_q22(m),
//! exact: the Newton estimate fixed by the residual, plus the next bit.
inline uint32_t isqrt_q24_floor_from(uint32_t m, uint32_t root) {
  const uint16_t q = uint16_t(root >> 11), frac = uint16_t(uint16_t(root) & 0x7FFU);
  const uint32_t rem = m - mul_u16(q, q);
  // Residual m 2^22 - root^2 = rem 2^22 - q frac 2^12 - frac^2, computed
  // modulo 2^32 (its true value is below 2^28 in magnitude).
  const uint32_t rem22 = uint32_t(uint16_t(uint16_t(rem) << 6)) << 16;
  int32_t res = to_signed(rem22 - (mul_u16(q, uint16_t(frac << 4)) << 8) - mul_u16(frac, frac));
  if (res < 0) {
    --root;
    res += int32_t(2 * root + 1);
  } else if (res > int32_t(2 * root)) {
    res -= int32_t(2 * root + 1);
    ++root;
  }
  // sqrt(m 2^22) in [root, root + 1): the next bit is set when it is at
  // least root + 1/2, i.e. when res >= root + 1/4.
  return 2 * root + (res > int32_t(root) ? 1 : 0);
}

//! floor(sqrt(m 2^24)) for m in [2^30, 2^32), exact.
inline uint32_t isqrt_q24_floor(uint32_t m) { return isqrt_q24_floor_from(m, isqrt_q22_call(m)); }

}  // namespace detail

//! Square root, within 0.625 LSB (measured 0.52; 99.7 % of inputs correctly
//! rounded, the rest 1 LSB off); 0 for v <= 0.
inline Fixed sqrt(Fixed v) {
  if (v.raw() <= 0) return Fixed();
  uint32_t m = uint32_t(v.raw());
  const uint8_t s = detail::normalize_even(m);
  // root ~ sqrt(u 2^(22 + s)); sqrt(u 2^16) = root / 2^(3 + s/2), rounded.
  // The root's +-1 moves the result by at most 1/8 LSB.
  const uint32_t root = detail::isqrt_q22_call(m);
  return Fixed::from_raw(int32_t(detail::shr_round(root, uint8_t(3 + s / 2))));
}

//! sqrt(a^2 + b^2) without overflow of the squares; saturates at max().
//! Within 0.8 LSB while max(|a|, |b|) < 1024 (measured 0.58), relative error
//! below 1.5e-8 above; exact when a or b is 0.
inline Fixed hypot(Fixed a, Fixed b) {
  uint32_t hi = detail::abs_u32(a.raw());
  uint32_t lo = detail::abs_u32(b.raw());
  if (lo > hi) {
    const uint32_t t = hi;
    hi = lo;
    lo = t;
  }
  if (hi >= 0x80000000UL) return Fixed::max();  // |a| = 32768 already overflows
  if (lo == 0) return Fixed::from_raw(int32_t(hi));
  // Scale by 2^s so that hi lies in [2^30, 2^31); then (H^2 + L^2) / 2^32
  // from 16-bit halves (docs/fixed-point.md, "hypot").
  uint8_t s = 0;
  if (hi < 0x8000UL) { hi <<= 16; lo <<= 16; s = 16; }
  if (hi < 0x800000UL) { hi <<= 8; lo <<= 8; s = uint8_t(s + 8); }
  if (hi < 0x8000000UL) { hi <<= 4; lo <<= 4; s = uint8_t(s + 4); }
  if (hi < 0x20000000UL) { hi <<= 2; lo <<= 2; s = uint8_t(s + 2); }
  if (hi < 0x40000000UL) { hi <<= 1; lo <<= 1; s = uint8_t(s + 1); }
  const uint16_t hh = detail::hi16(hi), hl = uint16_t(hi);
  const uint16_t lh = detail::hi16(lo), ll = uint16_t(lo);
  // mid + 2^14 < 2^32 since hh < 2^15; its / 2^15 is built from bytes.
  const uint32_t mid = detail::mul_u16(hh, hl) + detail::mul_u16(lh, ll) + uint32_t(0x4000);
  const uint32_t mid_q15 = (uint32_t(detail::hi16(mid)) << 1) | (uint16_t(mid) >> 15);
  const uint8_t hl8 = uint8_t(hl >> 8), ll8 = uint8_t(ll >> 8);
  const uint16_t low = detail::hi16(detail::mul_u16(hl8, hl8) + detail::mul_u16(ll8, ll8));  // 0 or 1
  uint32_t t = detail::mul_u16(hh, hh) + detail::mul_u16(lh, lh) + mid_q15 + low;
  // t in [2^28, 2^31]: the result is sqrt(t) 2^16 / 2^s.
  const uint8_t e = detail::normalize_even(t);
  const uint8_t k = uint8_t(s + e / 2);
  // One root for both cases: ~ sqrt(t) 2^(11 + e/2).
  const uint32_t root22 = detail::isqrt_q22_call(t);
  uint32_t h;
  if (k >= 7) {
    // result = root22 / 2^(k - 5): the root's +-1 costs at most 1/4 LSB.
    h = detail::shr_round(root22, uint8_t(k - 5));
  } else {
    // Large results: the exact floor of sqrt(t) 2^(12 + e/2) = result 2^(k - 4).
    const uint32_t root = detail::isqrt_q24_floor_from(t, root22);
    h = k >= 5 ? detail::shr_round(root, uint8_t(k - 4))
        : k == 4 ? root
                 : ((2 * root + 1) << (3 - k));  // fewer fraction bits than the result: centre it
  }
  return h >= 0x80000000UL ? Fixed::max() : Fixed::from_raw(int32_t(h));
}

}  // namespace strider

#endif  // STRIDER_MATH_FIXED_SQRT_H
