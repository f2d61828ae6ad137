//! CommandParser: the Bluetooth byte stream, one byte at a time, -> Commands.
//! Two protocols share the link (docs/protocol.md, "Telling RC bytes from
//! text"): the RC app's bare bytes, recognised only between lines ('w' and
//! 'v' through a one-byte lookahead), and text lines ending in CR, LF or
//! CRLF, a `$` line checked (line_check.h). An error is reported once and
//! the rest of its line discarded; lost() discards the line the dropped
//! bytes fell into, answered kBytesLost at its end.
#ifndef STRIDER_CONTROL_COMMAND_PARSER_H
#define STRIDER_CONTROL_COMMAND_PARSER_H

#include <stdint.h>

#include "command.h"
#include "command_line.h"
#include "line_check.h"

namespace strider {

constexpr uint8_t kMaxLineBytes = 63;  //!< longest accepted text line, without its ending

enum class ParseResult : uint8_t {
  kNothing = 0,  //!< byte consumed, nothing to do yet
  kCommand = 1,  //!< *out holds a command to apply
  kError = 2     //!< *out->error says what was wrong; reply `err`, change nothing
};

//! RC app byte -> command, or kNone when b is no RC byte.
inline Command rc_command(uint8_t b) {
  Command c = make_command(CommandKind::kNone, CommandSource::kBareByte);
  // (x forward, y left, turn anticlockwise); a switch keeps the table out of RAM.
  int8_t x = 0, y = 0, turn = 0;
  switch (b) {
    case 'F': x = 1; break;
    case 'B': x = -1; break;
    case 'L': y = 1; break;
    case 'R': y = -1; break;
    case 'G': turn = 1; break;
    case 'I': turn = -1; break;
    case 'H': x = -1; y = 1; break;
    case 'J': x = -1; y = -1; break;
    default: break;
  }
  if (x != 0 || y != 0 || turn != 0) {
    c.kind = CommandKind::kDrive;
    c.arg[0] = x;
    c.arg[1] = y;
    c.arg[2] = turn;
    return c;
  }
  if (b == 'S') { c.kind = CommandKind::kStop; return c; }
  if (b >= '0' && b <= '9') { c.kind = CommandKind::kSpeed; c.arg[0] = (b - '0') * 10; return c; }
  if (b == 'q') { c.kind = CommandKind::kSpeed; c.arg[0] = 100; return c; }
  if (b == 'W' || b == 'w' || b == 'U' || b == 'u' || b == 'V' || b == 'v' || b == 'X' || b == 'x') {
    c.kind = CommandKind::kLight;
    c.arg[0] = b;
  }
  return c;
}

class CommandParser {
 public:
  //! Feeds one received byte. On kCommand or kError, *out is filled.
  ParseResult feed(uint8_t b, Command* out) {
    if (b == '\r' || b == '\n') return line_end(b, out);
    after_cr_ = false;
    switch (state_) {
      case State::kCollect: return collect(b, out);
      case State::kDiscard:
      case State::kLost: return ParseResult::kNothing;
      case State::kIdle:
      case State::kSkipJunk: break;
    }
    return start(b, out);
  }

  //! No byte for a while: a partial line is abandoned (kIncomplete), a
  //! lone 'w'/'v' (a light button) dropped silently.
  ParseResult idle_timeout(Command* out) {
    const State was = state_;
    const uint8_t len = len_;
    state_ = State::kIdle;
    len_ = 0;
    last_rc_ = 0;
    if (was == State::kLost) return error(ParseError::kBytesLost, out);
    if (was != State::kCollect || is_light_lookahead(len)) return ParseResult::kNothing;
    bool blank = true;
    for (uint8_t i = 0; i < len; ++i) blank = blank && (line_[i] == ' ' || line_[i] == '\t');
    return blank ? ParseResult::kNothing : error(ParseError::kIncomplete, out);
  }

  //! The receiver dropped bytes before the next one: the line they fell
  //! into (or the next) is discarded, answered kBytesLost at its end.
  void lost() {
    if (state_ != State::kDiscard) state_ = State::kLost;
    len_ = 0;
    last_rc_ = 0;
    after_cr_ = false;  // an LF after the gap may end a line of its own
  }

  bool collecting() const { return state_ == State::kCollect; }  //!< inside a text line
  uint8_t line_length() const { return len_; }                   //!< bytes of the partial line

 private:
  enum class State : uint8_t { kIdle, kCollect, kDiscard, kSkipJunk, kLost };

  static bool is_lower(uint8_t b) { return b >= 'a' && b <= 'z'; }
  static bool is_bare_rc(uint8_t b) {
    return b != 'w' && b != 'v' && rc_command(b).kind != CommandKind::kNone;
  }
  bool is_light_lookahead(uint8_t len) const { return len == 1 && (line_[0] == 'w' || line_[0] == 'v'); }

  ParseResult error(ParseError e, Command* out, CommandSource source = CommandSource::kLine) {
    *out = make_command(CommandKind::kNone, source);
    out->error = e;
    return ParseResult::kError;
  }

  ParseResult start(uint8_t b, Command* out) {
    if (is_bare_rc(b)) {
      state_ = State::kIdle;
      last_rc_ = b;
      *out = rc_command(b);
      return ParseResult::kCommand;
    }
    last_rc_ = 0;
    if (is_lower(b) || b == ' ' || b == '\t' || b == kLineCheckStart) {
      state_ = State::kCollect;
      line_[0] = char(b);
      len_ = 1;
      return ParseResult::kNothing;
    }
    if (state_ == State::kSkipJunk) return ParseResult::kNothing;
    state_ = State::kSkipJunk;
    return error(ParseError::kBadByte, out);
  }

  ParseResult collect(uint8_t b, Command* out) {
    if (is_light_lookahead(len_) && !is_lower(b)) {
      state_ = State::kIdle;  // the pending byte was a light button: ignored
      len_ = 0;
      return start(b, out);
    }
    if (b < 0x20 ? b != '\t' : b >= 0x7F) {
      state_ = State::kDiscard;
      return error(ParseError::kBadByte, out);
    }
    if (len_ >= kMaxLineBytes) {
      state_ = State::kDiscard;
      return error(ParseError::kLineTooLong, out);
    }
    line_[len_++] = char(b);
    return ParseResult::kNothing;
  }

  ParseResult line_end(uint8_t b, Command* out) {
    const bool swallow = b == '\n' && after_cr_;
    after_cr_ = b == '\r';
    if (swallow) return ParseResult::kNothing;  // the LF of a CRLF
    const State was = state_;
    state_ = State::kIdle;
    const uint8_t len = len_;
    len_ = 0;
    if (was == State::kDiscard) return ParseResult::kNothing;  // error already reported
    if (was == State::kLost) return error(ParseError::kBytesLost, out);
    if (was != State::kCollect) {
      if (last_rc_ == 0) return ParseResult::kNothing;  // empty line
      *out = make_command(CommandKind::kRcEcho, CommandSource::kLine);
      out->arg[0] = last_rc_;
      last_rc_ = 0;
      return ParseResult::kCommand;
    }
    return complete_line(len, out);
  }

  // Not inlined: the parse's tokens are off the stack when the command runs.
  STRIDER_NOINLINE ParseResult complete_line(uint8_t len, Command* out) {
    const char* text = line_;
    uint8_t text_len = len;
    const bool checked = line_[0] == kLineCheckStart;
    const CommandSource source = checked ? CommandSource::kCheckedLine : CommandSource::kLine;
    if (checked) {
      if (!check_line(line_, len, &text_len)) return error(ParseError::kBadChecksum, out, source);
      ++text;
    }
    ParseError e = parse_command_line(text, text_len, out);
    if (e == ParseError::kNone && !checked && needs_checked_line(*out)) e = ParseError::kChecksumRequired;
    if (e != ParseError::kNone) {
      const Usage usage = out->usage;  // the valid values the reply names
      error(e, out, source);
      out->usage = usage;
      return ParseResult::kError;
    }
    out->source = source;
    return out->kind == CommandKind::kNone ? ParseResult::kNothing : ParseResult::kCommand;
  }

  char line_[kMaxLineBytes];
  uint8_t len_ = 0;
  uint8_t last_rc_ = 0;  // RC byte just applied: a line end right after it echoes it
  bool after_cr_ = false;
  State state_ = State::kIdle;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_COMMAND_PARSER_H
