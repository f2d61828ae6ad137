//! mul_u16: the exact 16 x 16 -> 32-bit unsigned product, on the AVR four
//! MUL instructions where avr-gcc 5.4 often calls a 32 x 32-bit library
//! multiply. Shared by Fixed's product and its elementary functions.
#ifndef STRIDER_MATH_MUL16_H
#define STRIDER_MATH_MUL16_H

#include <stdint.h>

#include "flash_table.h"

namespace strider {
namespace detail {

//! a * b, exact.
STRIDER_ALWAYS_INLINE uint32_t mul_u16(uint16_t a, uint16_t b) {
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
  uint32_t r;
  // Schoolbook 16x16 from four 8x8 MULs; MUL writes r1:r0, and r1 is gcc's
  // zero register, cleared again before use (CLR leaves the carry alone).
  __asm__(
      "mul  %A1, %A2\n\t"
      "movw %A0, r0\n\t"
      "mul  %B1, %B2\n\t"
      "movw %C0, r0\n\t"
      "mul  %B1, %A2\n\t"
      "add  %B0, r0\n\t"
      "adc  %C0, r1\n\t"
      "clr  __zero_reg__\n\t"
      "adc  %D0, __zero_reg__\n\t"
      "mul  %A1, %B2\n\t"
      "add  %B0, r0\n\t"
      "adc  %C0, r1\n\t"
      "clr  __zero_reg__\n\t"
      "adc  %D0, __zero_reg__"
      : "=&r"(r)
      : "r"(a), "r"(b));
  return r;
#else
  return uint32_t(a) * uint32_t(b);
#endif
}

}  // namespace detail
}  // namespace strider

#endif  // STRIDER_MATH_MUL16_H
