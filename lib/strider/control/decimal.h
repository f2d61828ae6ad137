//! Decimal number parsing for the text protocol without strtod/atof: an
//! optional sign, digits, an optional '.' and digits, scaled to a fixed
//! number of decimals and rounded half away from zero ("12.35" at 1 decimal
//! -> 124). Overflow-checked in 32 bits; no heap, no float.
#ifndef STRIDER_CONTROL_DECIMAL_H
#define STRIDER_CONTROL_DECIMAL_H

#include <stdint.h>

namespace strider {

enum class DecimalStatus : uint8_t { kOk = 0, kSyntax = 1, kOverflow = 2 };

//! Parses text[0..len) as a decimal scaled by 10^decimals (decimals <= 3).
//! *out is written only on kOk.
inline DecimalStatus parse_decimal(const char* text, uint8_t len, uint8_t decimals, int32_t* out) {
  uint8_t i = 0;
  bool negative = false;
  if (i < len && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  const int32_t kLimit = 2000000000;  // a little under 2^31: the check below never overflows
  int32_t value = 0;
  uint8_t int_digits = 0, frac_digits = 0;
  bool round_up = false;
  bool overflow = false;
  while (i < len && text[i] >= '0' && text[i] <= '9') {
    const int32_t d = text[i++] - '0';
    if (value > (kLimit - d) / 10) overflow = true; else value = value * 10 + d;
    ++int_digits;
  }
  if (i < len && text[i] == '.') {
    ++i;
    while (i < len && text[i] >= '0' && text[i] <= '9') {
      const int32_t d = text[i++] - '0';
      if (frac_digits < decimals) {
        if (value > (kLimit - d) / 10) overflow = true; else value = value * 10 + d;
      } else if (frac_digits == decimals) {
        round_up = d >= 5;
      }
      ++frac_digits;
    }
  }
  if (i != len || (int_digits == 0 && frac_digits == 0)) return DecimalStatus::kSyntax;
  for (uint8_t k = frac_digits; k < decimals; ++k) {
    if (value > kLimit / 10) overflow = true; else value *= 10;
  }
  if (round_up) {
    if (value >= kLimit) overflow = true; else ++value;
  }
  if (overflow) return DecimalStatus::kOverflow;
  *out = negative ? -value : value;
  return DecimalStatus::kOk;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_DECIMAL_H
