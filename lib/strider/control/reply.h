//! ReplyWriter: builds one reply line (`ok ...` / `err <code> <reason>`) in a
//! caller's buffer without printf, always NUL-terminated, truncated when full.
#ifndef STRIDER_CONTROL_REPLY_H
#define STRIDER_CONTROL_REPLY_H

#include <stdint.h>

#include "../math/fixed.h"
#include "../math/flash_table.h"
#include "command.h"

namespace strider {

//! Text in program memory on the AVR (STRIDER_PROGMEM), in RAM elsewhere.
struct FlashText {
  const char* p;
};

inline char flash_char(const char* p) { return char(flash_u8(p)); }

constexpr char kUnknownName[] STRIDER_PROGMEM = "?";

//! Entry `index` of `count` NUL-separated names in flash; "?" past the end.
inline FlashText flash_name(const char* names, uint8_t count, uint8_t index) {
  if (index >= count) return FlashText{kUnknownName};
  const char* p = names;
  for (; index > 0; --index) {
    while (flash_u8(p) != 0) ++p;
    ++p;
  }
  return FlashText{p};
}

//! Suggested buffer: the longest reply (status, ~260 bytes walking with
//! every field, up to ~300 with every number at its widest) + NUL.
constexpr uint16_t kMaxReplyBytes = 304;

class ReplyWriter {
 public:
  //! buf must hold capacity >= 1 bytes.
  ReplyWriter(char* buf, uint16_t capacity) : buf_(buf), cap_(capacity), len_(0) { buf_[0] = 0; }

  ReplyWriter& text(const char* s) {
    while (*s) put(*s++);
    return *this;
  }
  ReplyWriter& text(FlashText s) {
    for (const char* p = s.p;; ++p) {
      const char c = flash_char(p);
      if (c == 0) break;
      put(c);
    }
    return *this;
  }
  ReplyWriter& ch(char c) { put(c); return *this; }

  ReplyWriter& integer(int32_t v) {
    uint32_t u = v < 0 ? uint32_t(0) - uint32_t(v) : uint32_t(v);
    if (v < 0) put('-');
    char digits[10];
    uint8_t n = 0;
    do {
      digits[n++] = char('0' + u % 10u);
      u /= 10u;
    } while (u != 0);
    while (n > 0) put(digits[--n]);
    return *this;
  }

  //! Value given in tenths, printed with one decimal (-125 -> "-12.5").
  ReplyWriter& tenths(int32_t v) {
    const uint32_t u = v < 0 ? uint32_t(0) - uint32_t(v) : uint32_t(v);
    if (v < 0) put('-');
    integer(int32_t(u / 10u));
    put('.');
    put(char('0' + u % 10u));
    return *this;
  }

  //! Value given in hundredths, printed with two decimals (1505 -> "15.05").
  ReplyWriter& hundredths(int32_t v) {
    const uint32_t u = v < 0 ? uint32_t(0) - uint32_t(v) : uint32_t(v);
    if (v < 0) put('-');
    integer(int32_t(u / 100u));
    put('.');
    put(char('0' + u / 10u % 10u));
    put(char('0' + u % 10u));
    return *this;
  }

  //! `key=value` preceded by a space: the fields of ok and status lines.
  ReplyWriter& field(const char* key, int32_t v) { return ch(' ').text(key).ch('=').integer(v); }
  ReplyWriter& field_tenths(const char* key, int32_t v) { return ch(' ').text(key).ch('=').tenths(v); }
  ReplyWriter& field_text(const char* key, const char* v) { return ch(' ').text(key).ch('=').text(v); }
  ReplyWriter& field(FlashText key, int32_t v) { return ch(' ').text(key).ch('=').integer(v); }
  ReplyWriter& field_tenths(FlashText key, int32_t v) { return ch(' ').text(key).ch('=').tenths(v); }
  ReplyWriter& field_text(FlashText key, const char* v) { return ch(' ').text(key).ch('=').text(v); }
  ReplyWriter& field_text(FlashText key, FlashText v) { return ch(' ').text(key).ch('=').text(v); }

  //! Text in flash with up to three numbers: a byte kFormatInteger writes
  //! the next of a, b, c as integer(), kFormatTenths as tenths().
  STRIDER_NOINLINE ReplyWriter& format(FlashText fmt, int32_t a, int32_t b = 0, int32_t c = 0) {
    if (cap_ <= 1) {  // no room at all (a reply nobody sends): no digits computed
      truncated_ = true;
      return *this;
    }
    const int32_t v[3] = {a, b, c};
    uint8_t k = 0;
    for (const char* p = fmt.p;; ++p) {
      const char ch = flash_char(p);
      if (ch == 0) break;
      if (ch == kFormatInteger || ch == kFormatTenths) {
        const int32_t x = k < 3 ? v[k++] : 0;
        if (ch == kFormatInteger) integer(x); else tenths(x);
      } else {
        put(ch);
      }
    }
    return *this;
  }
  static constexpr char kFormatInteger = '\1';  //!< format(): the next number, as integer()
  static constexpr char kFormatTenths = '\2';   //!< format(): the next number, as tenths()

  const char* c_str() const { return buf_; }
  uint16_t length() const { return len_; }
  bool truncated() const { return truncated_; }

 private:
  void put(char c) {
    if (len_ + 1u >= cap_) { truncated_ = true; return; }
    buf_[len_++] = c;
    buf_[len_] = 0;
  }

  char* buf_;
  uint16_t cap_;
  uint16_t len_;
  bool truncated_ = false;
};

//! A reply buffer behind its writer (the writer first: short addressing on the AVR).
struct ReplyLine {
  ReplyLine() : w(buf, sizeof buf) {}
  ReplyWriter w;
  char buf[kMaxReplyBytes];
};

//! `err <code> <reason>` for any numeric code (parser: 1-19, controller: 20+).
inline void write_error(ReplyWriter& w, uint8_t code, const char* reason) {
  w.text("err ").integer(code).ch(' ').text(reason);
}

inline void write_error(ReplyWriter& w, uint8_t code, FlashText reason) {
  w.text("err ").integer(code).ch(' ').text(reason);
}

//! The parser's error reasons in flash, in ParseError order.
constexpr char kParseErrorNames[] STRIDER_PROGMEM =
    "none\0unknown command\0bad argument\0missing argument\0too many arguments\0out of range\0"
    "line too long\0bad byte\0incomplete line\0bad checksum\0bytes lost\0checksum required";
constexpr uint8_t kParseErrorCount = 12;

inline void write_parse_error(ReplyWriter& w, ParseError e) {
  write_error(w, uint8_t(e), flash_name(kParseErrorNames, kParseErrorCount, uint8_t(e)));
}

//! A value -> tenths, rounded half away from zero (|v| < 200,000).
inline int32_t to_tenths(float v) { return v >= 0.0f ? int32_t(v * 10.0f + 0.5f) : -int32_t(-v * 10.0f + 0.5f); }
inline int32_t to_tenths(Fixed v) {
  const int32_t t = v.raw() * 10;  // |v| < 3276.7: no overflow
  return t >= 0 ? (t + 32768) >> 16 : -((-t + 32768) >> 16);
}

}  // namespace strider

#endif  // STRIDER_CONTROL_REPLY_H
