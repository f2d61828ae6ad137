//! Decimal number parsing without strtod: sign, digits, '.', digits, scaled
//! to a fixed number of decimals, rounded half away from zero ("12.35" at 1
//! decimal -> 124); overflow-checked in 32 bits, no float.
#ifndef STRIDER_CONTROL_DECIMAL_H
#define STRIDER_CONTROL_DECIMAL_H

#include <stdint.h>

#include "../math/flash_table.h"

namespace strider {

enum class DecimalStatus : uint8_t { kOk = 0, kSyntax = 1, kOverflow = 2 };

namespace detail {
constexpr int32_t kDecimalLimit = 2000000000;  // a little under 2^31: value * 10 + 9 never overflows below it

//! *value = *value * 10 + d, or false past kDecimalLimit.
STRIDER_NOINLINE inline bool push_digit(int32_t* value, uint8_t d) {
  if (*value > kDecimalLimit / 10) return false;
  const int32_t v = *value * 10 + d;
  if (v > kDecimalLimit) return false;
  *value = v;
  return true;
}
}  // namespace detail

//! Parses text[0..len) as a decimal scaled by 10^decimals (decimals <= 3).
//! *out is written only on kOk.
inline DecimalStatus parse_decimal(const char* text, uint8_t len, uint8_t decimals, int32_t* out) {
  uint8_t i = 0;
  bool negative = false;
  if (i < len && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  int32_t value = 0;
  uint8_t int_digits = 0, frac_digits = 0;
  bool dot = false;
  bool round_up = false;
  bool overflow = false;
  for (; i < len; ++i) {
    const char ch = text[i];
    if (ch == '.' && !dot) {
      dot = true;
      continue;
    }
    if (ch < '0' || ch > '9') break;
    const uint8_t d = uint8_t(ch - '0');
    if (!dot) {
      ++int_digits;
    } else {
      const uint8_t k = frac_digits++;
      if (k == decimals) round_up = d >= 5;
      if (k >= decimals) continue;
    }
    if (!detail::push_digit(&value, d)) overflow = true;
  }
  if (i != len || (int_digits == 0 && frac_digits == 0)) return DecimalStatus::kSyntax;
  for (uint8_t k = frac_digits; k < decimals; ++k) {
    if (!detail::push_digit(&value, 0)) overflow = true;
  }
  if (round_up) {
    if (value >= detail::kDecimalLimit) overflow = true; else ++value;
  }
  if (overflow) return DecimalStatus::kOverflow;
  *out = negative ? -value : value;
  return DecimalStatus::kOk;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_DECIMAL_H
