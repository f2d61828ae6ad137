//! A command line's tokens: split at spaces and tabs, matched against words
//! in flash, read as numbers checked against a range.
#ifndef STRIDER_CONTROL_COMMAND_TOKENS_H
#define STRIDER_CONTROL_COMMAND_TOKENS_H

#include <stdint.h>

#include "../math/flash_table.h"

#include "command.h"
#include "decimal.h"

namespace strider {

constexpr uint8_t kMaxLineTokens = 5;  //!< command word + up to 4 arguments (one more to detect extras)

namespace detail {

struct Token {
  const char* text;
  uint8_t len;
};

//! True when the token is `word`, a NUL-terminated word in flash.
inline bool token_is(const Token& t, const char* word) {
  uint8_t i = 0;
  for (; i < t.len; ++i) {
    if (char(flash_u8(word + i)) != t.text[i]) return false;
  }
  return flash_u8(word + i) == 0;
}

//! Entry of `count` NUL-separated words in flash that token t is, or count.
inline uint8_t word_index(const Token& t, const char* names, uint8_t count) {
  const char* p = names;
  for (uint8_t i = 0; i < count; ++i) {
    if (token_is(t, p)) return i;
    while (flash_u8(p) != 0) ++p;
    ++p;
  }
  return count;
}

//! Splits line into tokens; returns the count, or kMaxLineTokens + 1 when there are more.
inline uint8_t split_tokens(const char* line, uint8_t len, Token* tokens) {
  uint8_t n = 0, i = 0;
  while (i < len) {
    while (i < len && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= len) break;
    const uint8_t start = i;
    while (i < len && line[i] != ' ' && line[i] != '\t') ++i;
    if (n == kMaxLineTokens) return kMaxLineTokens + 1;
    tokens[n].text = line + start;
    tokens[n].len = uint8_t(i - start);
    ++n;
  }
  return n;
}

//! Number token -> scaled integer in [lo, hi], or the error.
inline ParseError number_arg(const Token& t, uint8_t decimals, int32_t lo, int32_t hi, int32_t* out) {
  int32_t v = 0;
  const DecimalStatus s = parse_decimal(t.text, t.len, decimals, &v);
  if (s == DecimalStatus::kSyntax) return ParseError::kBadArgument;
  if (s == DecimalStatus::kOverflow || v < lo || v > hi) return ParseError::kOutOfRange;
  *out = v;
  return ParseError::kNone;
}

//! Exactly `count` tokens from `first` as numbers into cmd->arg[slot..].
inline ParseError number_args(const Token* tokens, uint8_t ntokens, uint8_t first, uint8_t count,
                              uint8_t slot, uint8_t decimals, int32_t lo, int32_t hi, Command* cmd) {
  if (ntokens < first + count) return ParseError::kMissingArgument;
  if (ntokens > first + count) return ParseError::kExtraArgument;
  for (uint8_t k = 0; k < count; ++k) {
    const ParseError e = number_arg(tokens[first + k], decimals, lo, hi, &cmd->arg[slot + k]);
    if (e != ParseError::kNone) return e;
  }
  return ParseError::kNone;
}

//! No tokens from `first` on.
inline ParseError no_args(uint8_t ntokens, uint8_t first) {
  return ntokens > first ? ParseError::kExtraArgument : ParseError::kNone;
}

}  // namespace detail

}  // namespace strider

#endif  // STRIDER_CONTROL_COMMAND_TOKENS_H
