//! Fixed: Strider's fixed-point scalar, signed Q16.16 in an int32_t: range
//! [-32768, 32768), resolution 2^-16. Saturating, rounding arithmetic without
//! 64-bit types (avr-gcc 5.4 miscompiles int64 shifts, docs/benchmarks.md),
//! bit-identical on the host and the AVR (docs/fixed-point.md).
#ifndef STRIDER_MATH_FIXED_H
#define STRIDER_MATH_FIXED_H

#include <stdint.h>

#include "fixed_avr.h"
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

  // The operators saturate (a wrapped coordinate would jump a leg). Constant
  // operands fold through the constexpr raw helpers, run-time ones take the
  // *_fast kernels (the same results, bit for bit).
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

  // Raw helpers, public so the math functions can share them.
  static constexpr int32_t sat_add(int32_t a, int32_t b) {
    return (b > 0 && a > kMaxRaw - b) ? kMaxRaw : (b < 0 && a < kMinRaw - b) ? kMinRaw : a + b;
  }
  //! a - b, saturated (exact: also for b = min()).
  static constexpr int32_t sat_sub(int32_t a, int32_t b) {
    return (b < 0 && a > kMaxRaw + b) ? kMaxRaw : (b > 0 && a < kMinRaw + b) ? kMinRaw : a - b;
  }
  static constexpr int32_t neg_raw(int32_t a) { return a == kMinRaw ? kMaxRaw : -a; }
  static constexpr uint32_t abs_raw(int32_t a) { return a < 0 ? uint32_t(0) - uint32_t(a) : uint32_t(a); }

  //! round((a * b) / 2^16), saturated, from the 16-bit halves of |a|, |b|:
  //! ah*bh*2^16 + ah*bl + al*bh + (al*bl + 2^15) / 2^16.
  static constexpr int32_t mul_raw(int32_t a, int32_t b) {
    return apply_sign(mul_mag(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
  }
  static constexpr uint32_t mul_mag(uint32_t ua, uint32_t ub) {
    return mul_mag_parts(ua >> 16, ua & 0xFFFFu, ub >> 16, ub & 0xFFFFu);
  }

  //! round(a * 2^16 / b) by restoring division on 32-bit words; b == 0
  //! saturates toward the sign of a (never traps, never NaN).
  static constexpr int32_t div_raw(int32_t a, int32_t b) {
    return b == 0 ? (a < 0 ? kMinRaw : kMaxRaw)
                  : apply_sign(div_mag(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
  }

  //! sat_add, sat_sub, mul_raw and div_raw for run time: on the AVR the
  //! kernels of fixed_avr.h (docs/fixed-point.md, "Design for the ATmega2560").
#if defined(__AVR__)
  STRIDER_ALWAYS_INLINE static int32_t sat_add_fast(int32_t a, int32_t b) { return fixed_avr::sat_add(a, b); }
  STRIDER_ALWAYS_INLINE static int32_t sat_sub_fast(int32_t a, int32_t b) { return fixed_avr::sat_sub(a, b); }
  static inline int32_t mul_raw_fast(int32_t a, int32_t b) { return fixed_avr::mul_raw(a, b); }
  static inline int32_t div_raw_fast(int32_t a, int32_t b) {
    return b == 0 ? (a < 0 ? kMinRaw : kMaxRaw)
                  : apply_sign(fixed_avr::div_mag(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
  }
  //! mul_raw with both factors 1 or more in magnitude.
  static int32_t mul_raw_full_avr(int32_t a, int32_t b) {
    return apply_sign(fixed_avr::mul_mag_full(abs_raw(a), abs_raw(b)), (a < 0) != (b < 0));
  }
#else
  STRIDER_ALWAYS_INLINE static int32_t sat_add_fast(int32_t a, int32_t b) { return sat_add(a, b); }
  STRIDER_ALWAYS_INLINE static int32_t sat_sub_fast(int32_t a, int32_t b) { return sat_sub(a, b); }
  static inline int32_t mul_raw_fast(int32_t a, int32_t b) { return mul_raw(a, b); }
  static inline int32_t div_raw_fast(int32_t a, int32_t b) { return div_raw(a, b); }
#endif

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
// The full product under a plain name for fixed_avr::mul_raw()'s jump.
extern "C" __attribute__((used, noinline)) inline int32_t strider_fixed_mul_full_avr(int32_t a, int32_t b) {
  return strider::Fixed::mul_raw_full_avr(a, b);
}
#endif

#endif  // STRIDER_MATH_FIXED_H
