//! Checked lines (docs/protocol.md, "Checked lines"): `$`, the text, `*` and
//! four hex digits, the CRC-16/CCITT-FALSE (crc.h) of the text; the reply to
//! one is its text followed by `*hhhh`, written in lowercase (read in either).
#ifndef STRIDER_CONTROL_LINE_CHECK_H
#define STRIDER_CONTROL_LINE_CHECK_H

#include <stdint.h>

#include "crc.h"

namespace strider {

constexpr char kLineCheckStart = '$';   //!< first byte of a checked line
constexpr char kLineCheckMark = '*';    //!< before the check digits
constexpr uint8_t kLineCheckBytes = 5;  //!< `*hhhh`

//! The CRC of a line's text.
inline uint16_t line_crc(const char* text, uint16_t len) {
  return crc16_ccitt(reinterpret_cast<const uint8_t*>(text), len);
}

//! A hex digit's value (either case), or -1.
inline int8_t hex_digit_value(char c) {
  if (c >= '0' && c <= '9') return int8_t(c - '0');
  if (c >= 'a' && c <= 'f') return int8_t(c - 'a' + 10);
  if (c >= 'A' && c <= 'F') return int8_t(c - 'A' + 10);
  return -1;
}

//! True when a checked line (from its `$`, no line ending) ends in `*hhhh`
//! with the CRC of its text, then at line + 1, *text_len long.
inline bool check_line(const char* line, uint8_t len, uint8_t* text_len) {
  if (len < 1 + kLineCheckBytes || line[0] != kLineCheckStart || line[len - kLineCheckBytes] != kLineCheckMark)
    return false;
  uint16_t check = 0;
  for (uint8_t i = uint8_t(len - 4); i < len; ++i) {
    const int8_t d = hex_digit_value(line[i]);
    if (d < 0) return false;
    check = uint16_t(uint16_t(check << 4) | uint8_t(d));
  }
  *text_len = uint8_t(len - 1 - kLineCheckBytes);
  return line_crc(line + 1, *text_len) == check;
}

//! Writes `*hhhh` and a NUL after text[0..len) (room for kLineCheckBytes + 1).
inline void append_line_check(char* text, uint16_t len) {
  uint16_t crc = line_crc(text, len);
  char* p = text + len;
  *p = kLineCheckMark;
  for (uint8_t i = 4; i > 0; --i, crc = uint16_t(crc >> 4)) {
    const uint8_t d = uint8_t(crc & 0xF);
    p[i] = char(d < 10 ? '0' + d : 'a' + d - 10);
  }
  p[kLineCheckBytes] = 0;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_LINE_CHECK_H
