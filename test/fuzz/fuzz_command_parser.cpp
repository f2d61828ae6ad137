// libFuzzer target: arbitrary bytes through the command parser, replies
// formatted for every event, idle timeouts interleaved. Checks the parser's
// invariants (bounded line, an error code on every error) and that a line end
// always resynchronises.
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "control/command_parser.h"
#include "control/error_hints.h"
#include "control/reply.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  strider::CommandParser parser;
  char buf[strider::kMaxReplyBytes];
  for (size_t i = 0; i < size; ++i) {
    strider::Command cmd;
    strider::ParseResult r = data[i] == 0x1B ? parser.idle_timeout(&cmd) : parser.feed(data[i], &cmd);
    if (parser.line_length() > strider::kMaxLineBytes) abort();
    strider::ReplyWriter w(buf, sizeof buf);
    if (r == strider::ParseResult::kError) {
      if (cmd.error == strider::ParseError::kNone) abort();
      strider::write_parse_error(w, cmd);
    } else if (r == strider::ParseResult::kCommand) {
      if (cmd.kind == strider::CommandKind::kNone) abort();
      w.text("ok").field("a0", cmd.arg[0]).field_tenths("a1", cmd.arg[1]).field_text("w", cmd.word);
    }
  }
  strider::Command cmd;
  parser.feed('\n', &cmd);
  const char* probe = "status\n";
  strider::ParseResult last = strider::ParseResult::kNothing;
  for (const char* p = probe; *p; ++p) last = parser.feed(uint8_t(*p), &cmd);
  if (last != strider::ParseResult::kCommand || cmd.kind != strider::CommandKind::kStatus) abort();
  return 0;
}
