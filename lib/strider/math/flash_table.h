//! Constant tables in flash on the AVR (a `const` table alone is copied into
//! its 8 KB of RAM at start-up), read through flash_u16() and flash_u8(); and
//! the inlining attributes the library shares.
#ifndef STRIDER_MATH_FLASH_TABLE_H
#define STRIDER_MATH_FLASH_TABLE_H

#include <stdint.h>

// avr-libc's PROGMEM and pgm_read_byte/word without its header: gcc's
// progmem attribute (the first 64 KB of flash) and the LPM instruction.
#if defined(__AVR__)
#define STRIDER_PROGMEM __attribute__((__progmem__))
#else
#define STRIDER_PROGMEM
#endif

// Small helpers that avr-gcc at -Os would otherwise call.
#if defined(__GNUC__)
#define STRIDER_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define STRIDER_ALWAYS_INLINE inline
#endif

// Rare, large paths kept out of a hot caller's prologue.
#if defined(__GNUC__)
#define STRIDER_NOINLINE __attribute__((noinline))
#else
#define STRIDER_NOINLINE
#endif

// The same, never cloned, for a function whose inline assembly takes most
// registers: under -flto avr-gcc 5.4 specialises it for a constant argument
// and then finds no registers ("impossible constraints"). clang has no noclone.
#if defined(__GNUC__) && !defined(__clang__)
#define STRIDER_NOINLINE_NOCLONE __attribute__((noinline, noclone))
#elif defined(__GNUC__)
#define STRIDER_NOINLINE_NOCLONE __attribute__((noinline))
#else
#define STRIDER_NOINLINE_NOCLONE
#endif

namespace strider {

//! table[i] of a uint16_t table declared with STRIDER_PROGMEM.
STRIDER_ALWAYS_INLINE uint16_t flash_u16(const uint16_t* table, uint16_t i) {
#if defined(__AVR__)
  uint16_t v;
  const uint16_t* p = table + i;
  asm("lpm %A0, Z+" "\n\t" "lpm %B0, Z" : "=r"(v), "+z"(p));
  return v;
#else
  return table[i];
#endif
}

//! The byte at p, an address declared with STRIDER_PROGMEM.
STRIDER_ALWAYS_INLINE uint8_t flash_u8(const void* p) {
#if defined(__AVR__)
  uint8_t v;
  asm("lpm %0, Z" : "=r"(v) : "z"(p));
  return v;
#else
  return *static_cast<const uint8_t*>(p);
#endif
}

//! Copies n bytes from src, an address declared with STRIDER_PROGMEM, to dst
//! (a struct kept in a flash table; avr-libc's memcpy_P is not header-only).
inline void flash_copy(void* dst, const void* src, uint16_t n) {
  uint8_t* d = static_cast<uint8_t*>(dst);
  const uint8_t* s = static_cast<const uint8_t*>(src);
  for (uint16_t i = 0; i < n; ++i) d[i] = flash_u8(s + i);
}

}  // namespace strider

#endif  // STRIDER_MATH_FLASH_TABLE_H
