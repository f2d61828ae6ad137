//! The valid values an `err` reply names after its reason (`err 5 out of
//! range: walk -500..500`), in flash on the AVR. The controller's codes
//! (20+) write their own.
#ifndef STRIDER_CONTROL_ERROR_HINTS_H
#define STRIDER_CONTROL_ERROR_HINTS_H

#include <stdint.h>

#include "command.h"
#include "reply.h"

namespace strider {
namespace text {

//! Every command word, as `help` and `err 1` list them.
constexpr char kCommandList[] STRIDER_PROGMEM =
    "walk strafe turn vel stop relax speed gait pose height level set get avoid deadman baud cal save status help";

//! The valid form of each command, in Usage order; command_line.h's ranges.
constexpr char kUsageHints[] STRIDER_PROGMEM =
    "\0"
    "walk -500..500\0"
    "strafe -500..500\0"
    "turn -360..360\0"
    "vel -500..500 -500..500 -360..360\0"
    "speed 0..100\0"
    "pose -30..30 -30..30 -30..30\0"
    "height 10..400\0"
    "deadman 1..60000, off only as a checked line\0"
    "baud 9600 19200 38400 57600 115200\0"
    "none after the command word\0"
    "gait NAME\0"
    "avoid on, avoid off, avoid STOP SLOW with 20 <= STOP <= SLOW <= 3000\0"
    "cal start trim osc pwm show save abort level\0"
    "cal trim 0..17 -30..30\0"
    "cal osc 20000000..30000000\0"
    "cal pwm 40..400\0"
    "set step_height|step_length|cycle|duty VALUE, set swing rectangle|semicircle|ellipse|cycloid|parabola|bezier\0"
    "level on, level off\0"
    "";
constexpr uint8_t kUsageHintCount = uint8_t(Usage::kEmptyLine);

//! What errors 6-11 (ParseError order from kLineTooLong) ask for.
constexpr char kLinkErrorHints[] STRIDER_PROGMEM =
    "at most 63 bytes\0"
    "printable ASCII only\0"
    "end each line with CR or LF\0"
    "$text*hhhh, hhhh the CRC-16 of text\0"
    "send the line again\0"
    "$deadman off*cb77, a checked line";  // not at the end: a reply ending in *hhhh reads as a checked one
constexpr uint8_t kLinkErrorHintCount = 6;

constexpr char kEmptyLine[] STRIDER_PROGMEM = "empty line";
constexpr char kHintSeparator[] STRIDER_PROGMEM = ": ";
constexpr char kGait_[] STRIDER_PROGMEM = "gait ";

}  // namespace text

//! A sink that names no gaits (write_parse_error() without one).
struct NoGaitNames {
  void write_gait_names(ReplyWriter&) const {}
};

//! `err <code> <reason>: <valid values>` for a parser error of c; gaits:
//! what names the model's gaits for `gait`'s NAME (a MotionSink, motion_modes.h).
template <typename Gaits = NoGaitNames>
void write_parse_error(ReplyWriter& w, const Command& c, const Gaits* gaits = nullptr) {
  const uint8_t code = uint8_t(c.error);
  const bool empty = c.error == ParseError::kUnknownCommand && c.usage == Usage::kEmptyLine;
  write_error(w, code, empty ? FlashText{text::kEmptyLine} : flash_name(kParseErrorNames, kParseErrorCount, code));
  w.text(FlashText{text::kHintSeparator});
  if (c.error == ParseError::kUnknownCommand) {
    w.text(FlashText{text::kCommandList});
  } else if (code >= uint8_t(ParseError::kLineTooLong)) {
    w.text(flash_name(text::kLinkErrorHints, text::kLinkErrorHintCount, uint8_t(code - uint8_t(ParseError::kLineTooLong))));
  } else if (c.usage == Usage::kGait && gaits != nullptr) {
    gaits->write_gait_names(w.text(FlashText{text::kGait_}));
  } else if (c.usage != Usage::kNone) {
    w.text(flash_name(text::kUsageHints, text::kUsageHintCount, uint8_t(c.usage)));
  } else {
    w.text(FlashText{text::kCommandList});  // an error without a command: every command
  }
}

}  // namespace strider

#endif  // STRIDER_CONTROL_ERROR_HINTS_H
