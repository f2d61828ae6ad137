//! Checked lines (docs/protocol.md, "Checked lines"), NMEA-like: `$`, the
//! text, `*` and four hex digits, the CRC-16/CCITT-FALSE (crc.h) of the text
//! between `$` and `*`; the reply to one is its text followed by `*hhhh`.
//! A program that needs to know that a line arrived as sent, and that a
//! reply is the one to it, sends checked lines; phone apps keep plain ones.
//!
//! The `$` marks a line as checked from its first byte, so a checked line
//! that lost its end (or was glued to the tail of another) is refused rather
//! than read as a plain one; a CRC-16 catches every change of up to 16
//! consecutive bits and all but one in 65,536 others. The robot writes the
//! digits in lowercase (and reads either case): a line's tail that lost its
//! head can then not begin with the RC buttons `B` or `F`.
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
  uint16_t crc = kCrc16Init;
  for (uint16_t i = 0; i < len; ++i) crc = crc16_ccitt_update(crc, uint8_t(text[i]));
  return crc;
}

//! A hex digit's value (either case), or -1.
inline int8_t hex_digit_value(char c) {
  if (c >= '0' && c <= '9') return int8_t(c - '0');
  if (c >= 'a' && c <= 'f') return int8_t(c - 'a' + 10);
  if (c >= 'A' && c <= 'F') return int8_t(c - 'A' + 10);
  return -1;
}

//! A checked line (len bytes from its `$`, no line ending) -> true when it
//! ends in `*hhhh` and hhhh is the CRC of its text, which is then at
//! line + 1 and *text_len long.
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

//! Writes `*hhhh` (lowercase) and a NUL after text[0..len): a reply to a
//! checked line. text must have room for kLineCheckBytes + 1 more bytes.
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
