//! Wide working units: the 32-bit integers of Fixed's leg IK fast paths, their
//! conversions from and to Fixed millimetres and their squares. Roots:
//! wide_sqrt.h. Why and how: docs/fixed-point.md, "Leg IK fast path".
#ifndef STRIDER_KINEMATICS_WIDE_UNITS_H
#define STRIDER_KINEMATICS_WIDE_UNITS_H

#include "leg_ik_common.h"

namespace strider {
namespace leg_ik {

//! Lengths in int32 Q3.28 working units (|v| < 8 units); squares in Q6.24,
//! a Fixed square [unit^2] shifted left by 8.
namespace wide {

//! u << k for k in [0, 31]: whole bytes, then single bits.
STRIDER_ALWAYS_INLINE uint32_t shl(uint32_t u, uint8_t k) {
  if (k & 16) u <<= 16;
  if (k & 8) u <<= 8;
  for (k &= 7; k != 0; --k) u <<= 1;
  return u;
}

//! from_mm() for any shift: out of line, the rare case.
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
  // and more): raw 2^k as a whole-byte shift and 8 - k single-bit steps back.
  if (uint8_t(down - 1U) < 7U && m < 0x1000000UL) {
    m <<= 8;
    for (uint8_t r = down; r != 0; --r) m >>= 1;
    out = v_mm.raw() < 0 ? -int32_t(m) : int32_t(m);
    return true;
  }
  return from_mm_general(v_mm, shift, out);
}

//! |v| of from_mm(), for a coordinate that is only squared (the same steps:
//! a shared helper costs the hexapod leg's fast path cycles).
STRIDER_ALWAYS_INLINE bool from_mm_abs(Fixed v_mm, int8_t shift, uint32_t& out) {
  const uint8_t down = uint8_t(shift - 4);
  uint32_t m = Fixed::abs_raw(v_mm.raw());
  if (uint8_t(down - 1U) < 7U && m < 0x1000000UL) {
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
//! modulo 2^32, from one 16x16 product and a 16-bit shift.
STRIDER_ALWAYS_INLINE int32_t from_unit(Fixed v) {
  const uint32_t u = uint32_t(v.raw());
  return detail::to_signed(detail::mul_u16(uint16_t(u), 0x1000U) + (uint32_t(uint16_t(detail::hi16(u) << 12)) << 16));
}

//! A Fixed square or difference of squares [unit^2] below 64 in magnitude
//! in Q6.24: raw 2^8, exact (a product: a negative value shifted left is
//! undefined in C++14).
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

//! The raw difference a - b of two Fixed values below 2^14 in magnitude,
//! without Fixed's saturation test; false when either is larger.
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
// One sq() of operand X added into s (t: scratch) for sq_sum() (a macro: an
// asm template must be one string literal): |X|, then
// hi16(X)^2 and hi16(2 hi16(X) lo16(X)); X is clobbered.
#define STRIDER_WIDE_SQ_ADD(X)                                                                             \
  "sbrs %D[" X "], 7\n\t" "rjmp 1f\n\t"                                                                  \
  STRIDER_ASM_NEG32(X)                                                                                    \
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

//! sq(a) + sq(b) (modulo 2^32); on the AVR in assembly, bit for bit
//! (test_avr_exact: wide_sq_sum).
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

//! from_mm() as one shared out-of-line copy.
STRIDER_NOINLINE inline bool from_mm_call(Fixed v_mm, int8_t shift, int32_t& out) { return from_mm(v_mm, shift, out); }

}  // namespace wide

}  // namespace leg_ik
}  // namespace strider

#endif  // STRIDER_KINEMATICS_WIDE_UNITS_H
