//! Fixed: Strider's fixed-point scalar, signed Q16.16 in an int32_t.
//!
//! Range [-32768, 32768) with a resolution of 2^-16 (1.5e-5): millimetres up to
//! +-32 m at 0.015 um and radians at 0.00087 deg. Designed for the ATmega2560:
//! - no 64-bit arithmetic anywhere (avr-gcc 5.4 miscompiles int64 shifts, see
//!   docs/kinematics.md), products are built from four 16x16->32 partial
//!   products, which the AVR does with its 8x8 hardware multiplier;
//! - multiplication rounds to nearest and saturates instead of wrapping;
//! - division is exact long division on 32-bit words: correct but slow, so hot
//!   paths multiply by precomputed reciprocals instead.
//! All operations use unsigned or well-defined signed arithmetic, so host and
//! AVR builds give bit-identical results (tested on the simulated Mega).
#ifndef STRIDER_MATH_FIXED_H
#define STRIDER_MATH_FIXED_H

#include <stdint.h>

#include "mul16.h"

namespace strider {

class Fixed {
 public:
  static constexpr int kFracBits = 16;
  static constexpr int32_t kOneRaw = int32_t(1) << kFracBits;
  static constexpr int32_t kMaxRaw = 0x7FFFFFFF;
  static constexpr int32_t kMinRaw = -0x7FFFFFFF - 1;

  constexpr Fixed() : raw_(0) {}
  //! From an integer; saturates outside the range.
  constexpr explicit Fixed(int v) : raw_(from_long(v)) {}
  constexpr explicit Fixed(long v) : raw_(from_long(v)) {}
  //! From a floating constant, rounded to nearest and saturated. On the AVR
  //! use it with constants only (it is folded at compile time).
  constexpr explicit Fixed(float v) : raw_(from_double(v)) {}
  constexpr explicit Fixed(double v) : raw_(from_double(v)) {}

  static constexpr Fixed from_raw(int32_t raw) { return Fixed(raw, RawTag()); }
  constexpr int32_t raw() const { return raw_; }
  constexpr float to_float() const { return float(raw_) * (1.0f / 65536.0f); }
  constexpr double to_double() const { return double(raw_) / 65536.0; }
  //! Truncates toward zero.
  constexpr int32_t to_int() const {
    return raw_ >= 0 ? (raw_ >> kFracBits) : -int32_t(abs_raw(raw_) >> kFracBits);
  }

  static constexpr Fixed max() { return from_raw(kMaxRaw); }
  static constexpr Fixed min() { return from_raw(kMinRaw); }
  static constexpr Fixed epsilon() { return from_raw(1); }

  // Addition and subtraction saturate: a wrapped coordinate would jump a leg.
  // Constant operands fold through the constexpr path; at run time the AVR
  // adds in registers and tests the overflow flag (an out-of-line call of
  // ~80 cycles in C, 6 inline; the same result, bit for bit).
  friend constexpr Fixed operator+(Fixed a, Fixed b) {
    return from_raw((__builtin_constant_p(a.raw_) && __builtin_constant_p(b.raw_)) ? sat_add(a.raw_, b.raw_)
                                                                                  : sat_add_fast(a.raw_, b.raw_));
  }
  friend constexpr Fixed operator-(Fixed a, Fixed b) {
    return from_raw((__builtin_constant_p(a.raw_) && __builtin_constant_p(b.raw_)) ? sat_sub(a.raw_, b.raw_)
                                                                                  : sat_sub_fast(a.raw_, b.raw_));
  }
  constexpr Fixed operator-() const { return from_raw(neg_raw(raw_)); }
  constexpr Fixed operator+() const { return *this; }
  // Constant operands fold through the constexpr path; run-time products on
  // the AVR take the hand-scheduled multiply (same result, bit for bit).
  friend constexpr Fixed operator*(Fixed a, Fixed b) {
    return from_raw((__builtin_constant_p(a.raw_) && __builtin_constant_p(b.raw_)) ? mul_raw(a.raw_, b.raw_)
                                                                                  : mul_raw_fast(a.raw_, b.raw_));
  }
  friend constexpr Fixed operator/(Fixed a, Fixed b) {
    return from_raw((__builtin_constant_p(a.raw_) && __builtin_constant_p(b.raw_)) ? div_raw(a.raw_, b.raw_)
                                                                                  : div_raw_fast(a.raw_, b.raw_));
  }

  Fixed& operator+=(Fixed o) { return *this = *this + o; }
  Fixed& operator-=(Fixed o) { return *this = *this - o; }
  Fixed& operator*=(Fixed o) { return *this = *this * o; }
  Fixed& operator/=(Fixed o) { return *this = *this / o; }

  friend constexpr bool operator==(Fixed a, Fixed b) { return a.raw_ == b.raw_; }
  friend constexpr bool operator!=(Fixed a, Fixed b) { return a.raw_ != b.raw_; }
  friend constexpr bool operator<(Fixed a, Fixed b) { return a.raw_ < b.raw_; }
  friend constexpr bool operator>(Fixed a, Fixed b) { return a.raw_ > b.raw_; }
  friend constexpr bool operator<=(Fixed a, Fixed b) { return a.raw_ <= b.raw_; }
  friend constexpr bool operator>=(Fixed a, Fixed b) { return a.raw_ >= b.raw_; }

  //! Multiplies by 2^n (n >= 0) or divides by 2^-n, saturating. Cheap on the AVR.
  constexpr Fixed scaled_pow2(int n) const {
    return n >= 0 ? from_raw(shl_sat(raw_, n)) : from_raw(asr_round(raw_, -n));
  }

  // ---- raw helpers, public so the math functions can share them ----------
  static constexpr int32_t sat_add(int32_t a, int32_t b) {
    return (b > 0 && a > kMaxRaw - b) ? kMaxRaw : (b < 0 && a < kMinRaw - b) ? kMinRaw : a + b;
  }
  //! a - b, saturated (exact: also for b = min()).
  static constexpr int32_t sat_sub(int32_t a, int32_t b) {
    return (b < 0 && a > kMaxRaw + b) ? kMaxRaw : (b > 0 && a < kMinRaw + b) ? kMinRaw : a - b;
  }
  static constexpr int32_t neg_raw(int32_t a) { return a == kMinRaw ? kMaxRaw : -a; }
  //! sat_add and sat_sub for run time: on the AVR a 32-bit add or subtract
  //! and a branch on the overflow flag, which saturates toward the true
  //! result's sign (b's for a sum, the opposite of b's for a difference).
  STRIDER_ALWAYS_INLINE static int32_t sat_add_fast(int32_t a, int32_t b) {
#if defined(__AVR__)
    asm("add %A0, %A1"     "\n\t" "adc %B0, %B1"     "\n\t" "adc %C0, %C1"     "\n\t" "adc %D0, %D1" "\n\t"
        "brvc 1f"          "\n\t"
        "ldi %A0, 0xFF"    "\n\t" "ldi %B0, 0xFF"    "\n\t" "ldi %C0, 0xFF"    "\n\t" "ldi %D0, 0x7F" "\n\t"
        "sbrs %D1, 7"      "\n\t" "rjmp 1f"          "\n\t"
        "ldi %A0, 0x00"    "\n\t" "ldi %B0, 0x00"    "\n\t" "ldi %C0, 0x00"    "\n\t" "ldi %D0, 0x80" "\n"
        "1:"
        : "+&d"(a)
        : "r"(b));
    return a;
#else
    return sat_add(a, b);
#endif
  }
  STRIDER_ALWAYS_INLINE static int32_t sat_sub_fast(int32_t a, int32_t b) {
#if defined(__AVR__)
    asm("sub %A0, %A1"     "\n\t" "sbc %B0, %B1"     "\n\t" "sbc %C0, %C1"     "\n\t" "sbc %D0, %D1" "\n\t"
        "brvc 1f"          "\n\t"
        "ldi %A0, 0xFF"    "\n\t" "ldi %B0, 0xFF"    "\n\t" "ldi %C0, 0xFF"    "\n\t" "ldi %D0, 0x7F" "\n\t"
        "sbrc %D1, 7"      "\n\t" "rjmp 1f"          "\n\t"
        "ldi %A0, 0x00"    "\n\t" "ldi %B0, 0x00"    "\n\t" "ldi %C0, 0x00"    "\n\t" "ldi %D0, 0x80" "\n"
        "1:"
        : "+&d"(a)
        : "r"(b));
    return a;
#else
    return sat_sub(a, b);
#endif
  }
  static constexpr uint32_t abs_raw(int32_t a) { return a < 0 ? uint32_t(0) - uint32_t(a) : uint32_t(a); }

  //! round((a * b) / 2^16), saturated, with no 64-bit type: |a| = ah:al and
  //! |b| = bh:bl in 16-bit halves, and
  //! |a*b| / 2^16 = ah*bh*2^16 + ah*bl + al*bh + (al*bl + 2^15) / 2^16.
  static constexpr int32_t mul_raw(int32_t a, int32_t b) {
    return apply_sign(mul_mag(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
  }
  static constexpr uint32_t mul_mag(uint32_t ua, uint32_t ub) {
    return mul_mag_parts(ua >> 16, ua & 0xFFFFu, ub >> 16, ub & 0xFFFFu);
  }
  //! mul_raw for run time: identical results, and on the AVR 16 x 16-bit
  //! hardware products instead of four 32-bit multiply calls (avr-gcc 5.4
  //! does not narrow them: 582 cycles in C).
  static inline int32_t mul_raw_fast(int32_t a, int32_t b) {
#if defined(__AVR__)
    return mul_raw_avr(a, b);
#else
    return mul_raw(a, b);
#endif
  }

#if defined(__AVR__)
  //! mul_raw with both factors 1 or more in magnitude, for the AVR (the
  //! target of strider_fixed_mul_full_avr()).
  static int32_t mul_raw_full_avr(int32_t a, int32_t b) {
    return apply_sign(mul_mag_full_avr(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
  }
#endif

  //! round(a * 2^16 / b) by restoring division on 32-bit words; b == 0
  //! saturates toward the sign of a (never traps, never NaN).
  static constexpr int32_t div_raw(int32_t a, int32_t b) {
    return b == 0 ? (a < 0 ? kMinRaw : kMaxRaw)
                  : apply_sign(div_mag(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
  }
  //! div_raw for run time: identical results; on the AVR one 31-step
  //! restoring loop in registers (~880 cycles) instead of a 32-bit library
  //! division and 17 steps in C (~1,600).
  static inline int32_t div_raw_fast(int32_t a, int32_t b) {
#if defined(__AVR__)
    return b == 0 ? (a < 0 ? kMinRaw : kMaxRaw)
                  : apply_sign(div_mag_avr(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
#else
    return div_raw(a, b);
#endif
  }

 private:
  struct RawTag {};
  constexpr Fixed(int32_t raw, RawTag) : raw_(raw) {}

  static constexpr int32_t from_long(long v) {
    return v >= 32768L ? kMaxRaw : v < -32768L ? kMinRaw : int32_t(v) * kOneRaw;
  }
  static constexpr int32_t from_double(double v) {
    return v >= 32767.99998 ? kMaxRaw
           : v <= -32768.0  ? kMinRaw
           : v >= 0         ? int32_t(v * 65536.0 + 0.5)
                            : -int32_t(-v * 65536.0 + 0.5);
  }
  static constexpr int32_t apply_sign(uint32_t mag, bool negative) {
    return negative ? (mag >= 0x80000000u ? kMinRaw : -int32_t(mag))
                    : (mag >= 0x80000000u ? kMaxRaw : int32_t(mag));
  }
  // Saturates at 2^32-1: apply_sign then clamps to the int32 range.
  static constexpr uint32_t mul_mag_parts(uint32_t ah, uint32_t al, uint32_t bh, uint32_t bl) {
    return (ah * bh >= 0x8000u) ? 0xFFFFFFFFu
                                : add_sat_u(add_sat_u((ah * bh) << 16, ah * bl),
                                            add_sat_u(al * bh, (al * bl + 0x8000u) >> 16));
  }
  static constexpr uint32_t add_sat_u(uint32_t a, uint32_t b) {
    return a > 0xFFFFFFFFu - b ? 0xFFFFFFFFu : a + b;
  }
  // |a| * 2^16 / |b|, rounded. The integer part must fit 16 bits or it
  // saturates; the fraction comes from 16 restoring steps plus one for rounding.
  static constexpr uint32_t div_mag(uint32_t ua, uint32_t ub) {
    return (ua / ub) >= 0x8000u ? 0xFFFFFFFFu : div_frac((ua / ub) << 16, ua % ub, ub, 17);
  }
  // One restoring-division step per call; rem < ub always, so rem*2 may need
  // 33 bits: compare before doubling instead.
  static constexpr uint32_t div_frac(uint32_t q, uint32_t rem, uint32_t ub, int steps) {
    return steps == 0 ? q
           : steps == 1 ? q + ((rem >= ub - rem) ? 1u : 0u)  // rounding bit
                        : div_frac(q | ((rem >= ub - rem) ? (1u << (steps - 2)) : 0u),
                                   (rem >= ub - rem) ? rem - (ub - rem) : rem * 2u, ub, steps - 1);
  }
#if defined(__AVR__)
  // div_mag(ua, ub) for ub != 0: the integer part ua / ub saturates at 2^15
  // (ua >> 15 >= ub). Otherwise the top 17 bits of ua 2^16 leave the
  // remainder ua >> 15 and a zero quotient, and 31 steps of restoring
  // division take the other 31 bits (ua << 17, shifted out of q as the
  // quotient bits shift in). The remainder stays below ub <= 2^31, so its
  // doubling fits 32 bits. Then div_frac's rounding step.
  __attribute__((noinline)) static uint32_t div_mag_avr(uint32_t ua, uint32_t ub) {
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
  //! mul_raw for the AVR: a factor below 1.0 in magnitude (sines,
  //! fractions, reciprocals, every Q0.16 ratio) takes a 32 x 16-bit product
  //! of 8 MULs (~50 cycles), the others the full 16-MUL product.
  // mul_raw(a, b) in the call-clobbered registers (a in r22..r25, b in
  // r18..r21, result in r22..r25), no register saves. Both factors 1 or
  // more in magnitude: a jump to strider_fixed_mul_full_avr(). Else, with
  // |b| < 2^16 raw (a and b swapped if only |a| is): the sign into T,
  // |a| and |b| in place, the product P5..P0 of |a| and |b| (8 MULs) by byte
  // column into r27:r26:r21:r20 (P0 never carries: only a0 b0 reaches it;
  // bit 7 of P1, in r30, rounds), then apply_sign(). Below 2^32 always, so
  // mul_mag_parts' saturation cannot occur.
  __attribute__((naked, noinline)) static int32_t mul_raw_avr(int32_t, int32_t) {
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


  // The 64-bit product P7..P0 of two magnitudes from 16 8x8 MULs, summed by
  // byte column; returns round(P / 2^16) saturated like mul_mag.
  STRIDER_ALWAYS_INLINE static uint32_t mul_mag_full_avr(uint32_t a, uint32_t b) {
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
    return (lo & 0x8000u) ? add_sat_u(mid, 1u) : mid;
  }
#endif
  static constexpr int32_t shl_sat(int32_t v, int n) {
    return n == 0 ? v
           : v > (kMaxRaw >> 1) ? kMaxRaw
           : v < (kMinRaw >> 1) ? kMinRaw
                                : shl_sat(int32_t(uint32_t(v) << 1), n - 1);
  }
  static constexpr int32_t asr_round(int32_t v, int n) {
    return n >= 31 ? 0 : apply_sign((abs_raw(v) + (uint32_t(1) << (n - 1))) >> n, v < 0);
  }

  int32_t raw_;
};

}  // namespace strider

#if defined(__AVR__)
// The full product, under a plain name for the jump in Fixed::mul_raw_avr();
// `used` keeps it although only assembly refers to it.
extern "C" __attribute__((used, noinline)) inline int32_t strider_fixed_mul_full_avr(int32_t a, int32_t b) {
  return strider::Fixed::mul_raw_full_avr(a, b);
}
#endif

#endif  // STRIDER_MATH_FIXED_H
