// vbench scripts: one directive per line, `#` starts a comment.
//   at T send TEXT     bytes to UART1 (the HC-05) at T seconds; \n \r \t \\ \xHH escapes
//   at T send0 TEXT    the same to UART0 (USB)
//   at T range MM      HC-SR04 sees an obstacle at MM millimetres
//   at T range none    no echo at all (the echo line stays low)
//   at T reset         external reset (RESET pin)
//   at T flood R S TEXT   a link flood on UART1: TEXT R times a second (or
//                      R = max: back to back) for S seconds
//   at T flood0 R S TEXT  the same on UART0
// Without `at T` a directive applies at once (commands piped into vbench).
#ifndef STRIDER_TOOLS_VBENCH_SCRIPT_H
#define STRIDER_TOOLS_VBENCH_SCRIPT_H

#include <cstdint>
#include <string>
#include <vector>

namespace strider_vmega {

class VirtualMega;

struct ScriptEvent {
  enum class Kind { kSend, kRange, kReset, kFlood };
  bool immediate = false;  // no `at T`
  uint64_t time_us = 0;
  Kind kind = Kind::kSend;
  int uart = 1;
  std::string text;        // kSend: the bytes, escapes resolved
  double range_mm = -1;    // kRange: negative = no echo
  double per_s = 0;        // kFlood: repetitions of text a second, 0 = back to back
  double duration_s = 0;   // kFlood: how long
  int line = 0;            // source line, for messages
};

//! Resolves \n \r \t \\ and \xHH; false and *error on a bad escape.
bool unescape(const std::string& in, std::string* out, std::string* error);

//! Parses one line; false and *error on a syntax error. Blank and comment
//! lines give true with *has_event = false.
bool parse_script_line(const std::string& line, ScriptEvent* event, bool* has_event, std::string* error);

//! Parses a whole script; events keep their order of appearance and are
//! stable-sorted by time.
bool parse_script(const std::string& text, std::vector<ScriptEvent>* events, std::string* error);

//! Applies an event to the Mega now.
void apply_event(const ScriptEvent& event, VirtualMega& mega);

}  // namespace strider_vmega

#endif  // STRIDER_TOOLS_VBENCH_SCRIPT_H
