//! parse_command_line: one complete text line (without its line ending) ->
//! Command, or the ParseError that explains why not. Words are lowercase,
//! separated by spaces or tabs; numbers are checked against each command's
//! range here, so the controller only sees values it can apply.
#ifndef STRIDER_CONTROL_COMMAND_LINE_H
#define STRIDER_CONTROL_COMMAND_LINE_H

#include <stdint.h>

#include "../gait/gait_tuning.h"
#include "../math/flash_table.h"

#include "command.h"
#include "command_tokens.h"
#include "decimal.h"
#include "settings.h"

namespace strider {

constexpr int32_t kMaxLinearDecimm_s = 5000;  //!< |walk|, |strafe| <= 500.0 mm/s
constexpr int32_t kMaxTurnDecideg_s = 3600;   //!< |turn| <= 360.0 deg/s
constexpr int32_t kMaxPoseDecideg = 300;      //!< |roll|, |pitch|, |yaw| <= 30.0 deg

namespace detail {

//! The command words, in flash on the AVR.
namespace words {
constexpr char kAbort[] STRIDER_PROGMEM = "abort";
constexpr char kAvoid[] STRIDER_PROGMEM = "avoid";
constexpr char kBaud[] STRIDER_PROGMEM = "baud";
constexpr char kCal[] STRIDER_PROGMEM = "cal";
constexpr char kDeadman[] STRIDER_PROGMEM = "deadman";
constexpr char kGait[] STRIDER_PROGMEM = "gait";
constexpr char kGet[] STRIDER_PROGMEM = "get";
constexpr char kHeight[] STRIDER_PROGMEM = "height";
constexpr char kHelp[] STRIDER_PROGMEM = "help";
constexpr char kLevel[] STRIDER_PROGMEM = "level";
constexpr char kOff[] STRIDER_PROGMEM = "off";
constexpr char kOn[] STRIDER_PROGMEM = "on";
constexpr char kOsc[] STRIDER_PROGMEM = "osc";
constexpr char kPose[] STRIDER_PROGMEM = "pose";
constexpr char kPwm[] STRIDER_PROGMEM = "pwm";
constexpr char kRelax[] STRIDER_PROGMEM = "relax";
constexpr char kSave[] STRIDER_PROGMEM = "save";
constexpr char kSet[] STRIDER_PROGMEM = "set";
constexpr char kShow[] STRIDER_PROGMEM = "show";
constexpr char kSpeed[] STRIDER_PROGMEM = "speed";
constexpr char kStart[] STRIDER_PROGMEM = "start";
constexpr char kStatus[] STRIDER_PROGMEM = "status";
constexpr char kStop[] STRIDER_PROGMEM = "stop";
constexpr char kStrafe[] STRIDER_PROGMEM = "strafe";
constexpr char kTrim[] STRIDER_PROGMEM = "trim";
constexpr char kTurn[] STRIDER_PROGMEM = "turn";
constexpr char kVel[] STRIDER_PROGMEM = "vel";
constexpr char kVelocity[] STRIDER_PROGMEM = "velocity";
constexpr char kWalk[] STRIDER_PROGMEM = "walk";
}  // namespace words

inline ParseError parse_cal(const Token* t, uint8_t n, Command* cmd) {
  cmd->usage = Usage::kCal;
  if (n < 2) return ParseError::kMissingArgument;
  const Token& sub = t[1];
  CommandKind none_taken = CommandKind::kNone;  // a word that takes no arguments
  if (token_is(sub, words::kStart)) none_taken = CommandKind::kCalStart;
  if (token_is(sub, words::kSave)) none_taken = CommandKind::kCalSave;
  if (token_is(sub, words::kAbort)) none_taken = CommandKind::kCalAbort;
  if (token_is(sub, words::kShow)) none_taken = CommandKind::kCalShow;
  if (token_is(sub, words::kLevel)) none_taken = CommandKind::kCalLevel;
  if (none_taken != CommandKind::kNone) {
    cmd->kind = none_taken;
    cmd->usage = Usage::kNoArguments;
    return no_args(n, 2);
  }
  if (token_is(sub, words::kOsc)) {
    cmd->kind = CommandKind::kCalOsc;
    cmd->usage = Usage::kCalOsc;
    return number_args(t, n, 2, 1, 0, 0, int32_t(kPca9685MinOscHz), int32_t(kPca9685MaxOscHz), cmd);
  }
  if (token_is(sub, words::kPwm)) {
    cmd->kind = CommandKind::kCalPwm;
    cmd->usage = Usage::kCalPwm;
    return number_args(t, n, 2, 1, 0, 0, 40, 400, cmd);
  }
  if (token_is(sub, words::kTrim)) {
    cmd->kind = CommandKind::kCalTrim;
    cmd->usage = Usage::kCalTrim;
    if (n < 4) return ParseError::kMissingArgument;
    if (n > 4) return ParseError::kExtraArgument;
    const ParseError e = number_arg(t[2], 0, 0, kMaxServoJoints - 1, &cmd->arg[0]);
    if (e != ParseError::kNone) return e;
    return number_arg(t[3], 1, -kMaxTrimDecideg, kMaxTrimDecideg, &cmd->arg[1]);
  }
  return ParseError::kBadArgument;
}

//! `level on` / `level off`.
inline ParseError parse_level(const Token* t, uint8_t n, Command* cmd) {
  cmd->kind = CommandKind::kLevel;
  cmd->usage = Usage::kLevel;
  if (n < 2) return ParseError::kMissingArgument;
  const bool on = token_is(t[1], words::kOn);
  if (!on && !token_is(t[1], words::kOff)) return ParseError::kBadArgument;
  cmd->arg[0] = on ? 1 : 0;
  return no_args(n, 2);
}

inline ParseError parse_avoid(const Token* t, uint8_t n, Command* cmd) {
  cmd->usage = Usage::kAvoid;
  if (n < 2) return ParseError::kMissingArgument;
  if (token_is(t[1], words::kOn) || token_is(t[1], words::kOff)) {
    cmd->kind = CommandKind::kAvoidEnable;
    cmd->arg[0] = token_is(t[1], words::kOn) ? 1 : 0;
    return no_args(n, 2);
  }
  cmd->kind = CommandKind::kAvoidLimits;
  int32_t probe = 0;
  if (parse_decimal(t[1].text, t[1].len, 0, &probe) == DecimalStatus::kSyntax) return ParseError::kBadArgument;
  const ParseError e = number_args(t, n, 1, 2, 0, 0, 20, 3000, cmd);
  if (e != ParseError::kNone) return e;
  return cmd->arg[1] < cmd->arg[0] ? ParseError::kOutOfRange : ParseError::kNone;
}

inline ParseError parse_gait(const Token* t, uint8_t n, Command* cmd) {
  cmd->kind = CommandKind::kGait;
  cmd->usage = Usage::kGait;
  if (n < 2) return ParseError::kMissingArgument;
  if (n > 2) return ParseError::kExtraArgument;
  if (t[1].len >= kCommandWordBytes) return ParseError::kBadArgument;
  for (uint8_t i = 0; i < t[1].len; ++i) {
    const char c = t[1].text[i];
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return ParseError::kBadArgument;
    cmd->word[i] = c;
  }
  cmd->word[t[1].len] = 0;
  return ParseError::kNone;
}

//! `set PARAM VALUE`: arg[0] the TuneParam, arg[1] the value in hundredths
//! (a swing shape: its SwingShape). The range is the walker's: the
//! controller checks it (err 25 with the range).
inline ParseError parse_set(const Token* t, uint8_t n, Command* cmd) {
  cmd->kind = CommandKind::kSet;
  cmd->usage = Usage::kSet;
  if (n < 3) return ParseError::kMissingArgument;
  if (n > 3) return ParseError::kExtraArgument;
  const uint8_t p = word_index(t[1], kTuneParamNames, kTuneParamCount);
  if (p == kTuneParamCount) return ParseError::kBadArgument;
  cmd->arg[0] = p;
  if (p == uint8_t(TuneParam::kSwing)) {
    const uint8_t shape = word_index(t[2], kSwingShapeNames, kSwingShapeCount);
    if (shape == kSwingShapeCount) return ParseError::kBadArgument;
    cmd->arg[1] = shape;
    return ParseError::kNone;
  }
  return number_arg(t[2], 2, 0, 65535, &cmd->arg[1]);
}

//! The commands of one word and `count` numbers into arg[slot..], all with
//! `decimals` decimals and in [lo, hi]: a table in flash, one loop.
struct WordCommand {
  const char* word;  // words::, in flash
  CommandKind kind;
  Usage usage;       // what an error reply names (error_hints.h)
  uint8_t count;
  uint8_t slot;
  uint8_t decimals;
  int32_t lo;
  int32_t hi;
};
constexpr WordCommand kWordCommands[] STRIDER_PROGMEM = {
    {words::kWalk, CommandKind::kMove, Usage::kWalk, 1, 0, 1, -kMaxLinearDecimm_s, kMaxLinearDecimm_s},
    {words::kStrafe, CommandKind::kMove, Usage::kStrafe, 1, 1, 1, -kMaxLinearDecimm_s, kMaxLinearDecimm_s},
    {words::kTurn, CommandKind::kMove, Usage::kTurn, 1, 2, 1, -kMaxTurnDecideg_s, kMaxTurnDecideg_s},
    {words::kVel, CommandKind::kMove, Usage::kVel, 3, 0, 1, -kMaxLinearDecimm_s, kMaxLinearDecimm_s},
    {words::kVelocity, CommandKind::kMove, Usage::kVel, 3, 0, 1, -kMaxLinearDecimm_s, kMaxLinearDecimm_s},
    {words::kStop, CommandKind::kStop, Usage::kNoArguments, 0, 0, 0, 0, 0},
    {words::kRelax, CommandKind::kRelax, Usage::kNoArguments, 0, 0, 0, 0, 0},
    {words::kSpeed, CommandKind::kSpeed, Usage::kSpeed, 1, 0, 0, 0, 100},
    {words::kPose, CommandKind::kPose, Usage::kPose, 3, 0, 1, -kMaxPoseDecideg, kMaxPoseDecideg},
    {words::kHeight, CommandKind::kHeight, Usage::kHeight, 1, 0, 1, 100, 4000},
    {words::kDeadman, CommandKind::kDeadman, Usage::kDeadman, 1, 0, 0, 1, 60000},  // off: parse_command_line()
    {words::kBaud, CommandKind::kBaud, Usage::kBaud, 1, 0, 0, 0, 2000000},
    {words::kSave, CommandKind::kSave, Usage::kNoArguments, 0, 0, 0, 0, 0},
    {words::kStatus, CommandKind::kStatus, Usage::kNoArguments, 0, 0, 0, 0, 0},
    {words::kHelp, CommandKind::kHelp, Usage::kNoArguments, 0, 0, 0, 0, 0},
    {words::kGet, CommandKind::kGet, Usage::kNoArguments, 0, 0, 0, 0, 0},
};
constexpr uint8_t kWordCommandCount = uint8_t(sizeof kWordCommands / sizeof kWordCommands[0]);

//! The command of n (1..kMaxLineTokens) tokens of the line (len bytes).
inline ParseError parse_tokens(const Token* t, uint8_t n, const char* line, uint8_t len, Command* cmd) {
  const Token& w = t[0];
  if (token_is(w, words::kGait)) return parse_gait(t, n, cmd);
  if (token_is(w, words::kAvoid)) return parse_avoid(t, n, cmd);
  if (token_is(w, words::kCal)) return parse_cal(t, n, cmd);
  if (token_is(w, words::kSet)) return parse_set(t, n, cmd);
  if (token_is(w, words::kLevel)) return parse_level(t, n, cmd);
  if (token_is(w, words::kDeadman) && n >= 2 && token_is(t[1], words::kOff)) {
    cmd->kind = CommandKind::kDeadman;  // arg[0] = 0: off, from a checked line only (needs_checked_line())
    cmd->usage = Usage::kDeadman;
    return no_args(n, 2);
  }
  for (uint8_t i = 0; i < kWordCommandCount; ++i) {
    WordCommand wc;
    flash_copy(&wc, &kWordCommands[i], sizeof wc);
    if (!token_is(w, wc.word)) continue;
    cmd->kind = wc.kind;
    cmd->usage = wc.usage;
    if (wc.count == 0) return no_args(n, 1);
    const ParseError e = number_args(t, n, 1, wc.count, wc.slot, wc.decimals, wc.lo, wc.hi, cmd);
    if (e != ParseError::kNone) return e;
    // vel: the turn rate has a range of its own (walk and strafe: arg[2] is 0).
    if (wc.kind == CommandKind::kMove && (cmd->arg[2] < -kMaxTurnDecideg_s || cmd->arg[2] > kMaxTurnDecideg_s)) {
      return ParseError::kOutOfRange;
    }
    if (wc.kind == CommandKind::kBaud && !valid_baud(uint32_t(cmd->arg[0]))) return ParseError::kOutOfRange;
    return ParseError::kNone;
  }
  if (len == 1) {  // a light button's lowercase byte typed on its own line
    const char c = line[0];
    if (c == 'w' || c == 'u' || c == 'v' || c == 'x') { cmd->kind = CommandKind::kLight; cmd->arg[0] = c; return ParseError::kNone; }
  }
  return ParseError::kUnknownCommand;
}

}  // namespace detail

//! True for a command that disarms a failsafe (the deadman off): it runs
//! only from a checked line, which no glued line nor typo produces.
inline bool needs_checked_line(const Command& c) { return c.kind == CommandKind::kDeadman && c.arg[0] == 0; }

//! Parses one line (printable ASCII, no line ending) into *cmd; an error
//! leaves cmd->usage naming the valid values. A blank line is err 1.
inline ParseError parse_command_line(const char* line, uint8_t len, Command* cmd) {
  using namespace detail;
  *cmd = make_command(CommandKind::kNone, CommandSource::kLine);
  Token t[kMaxLineTokens];
  const uint8_t n_split = split_tokens(line, len, t);
  if (n_split == 0) {
    cmd->usage = Usage::kEmptyLine;
    return ParseError::kUnknownCommand;
  }
  const uint8_t n = n_split > kMaxLineTokens ? kMaxLineTokens : n_split;
  const ParseError e = parse_tokens(t, n, line, len, cmd);
  if (n_split > kMaxLineTokens && e != ParseError::kUnknownCommand) return ParseError::kExtraArgument;
  return e;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_COMMAND_LINE_H
