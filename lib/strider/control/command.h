//! Command: what the protocol parser hands the controller. Parsing and
//! applying are separate: the parser only checks syntax and ranges; the
//! controller decides whether a command is allowed now.
//!
//! Numeric arguments are integers in the unit given per kind; "deci" means
//! tenths (walk 12.5 -> arg[0] = 125 [0.1 mm/s]).
#ifndef STRIDER_CONTROL_COMMAND_H
#define STRIDER_CONTROL_COMMAND_H

#include <stdint.h>

namespace strider {

enum class CommandKind : uint8_t {
  kNone = 0,
  kDrive,        //!< RC button: arg = x, y, turn directions (-1/0/+1), scaled by speed %
  kMove,         //!< walk/strafe/turn/vel: arg = vx [0.1 mm/s], vy [0.1 mm/s], wz [0.1 deg/s]
  kStop,         //!< stop walking and stand
  kRelax,        //!< all servos limp
  kSpeed,        //!< arg[0] = speed [%] 0-100
  kGait,         //!< word = gait name
  kPose,         //!< arg = roll, pitch, yaw [0.1 deg]
  kHeight,       //!< arg[0] = body height [0.1 mm]
  kAvoidEnable,  //!< arg[0] = 1 on, 0 off
  kAvoidLimits,  //!< arg[0] = stop distance [mm], arg[1] = slow-down distance [mm]
  kDeadman,      //!< arg[0] = timeout [ms]; 0 = off (`deadman off`, a checked line only)
  kBaud,         //!< arg[0] = UART rate [baud] (applied after save + reset)
  kCalStart,     //!< enter calibration: servos to neutral, trims editable
  kCalTrim,      //!< arg[0] = joint index, arg[1] = trim [0.1 deg]
  kCalOsc,       //!< arg[0] = PCA9685 oscillator [Hz]
  kCalPwm,       //!< arg[0] = PWM frequency [Hz]
  kCalShow,      //!< report the live trims
  kCalSave,      //!< keep the live calibration and write it to EEPROM
  kCalAbort,     //!< restore the saved calibration
  kSave,         //!< write the current settings to EEPROM
  kStatus,       //!< one status line
  kHelp,         //!< one line listing the commands
  kLight,        //!< RC light button (W w U u V v X x): acknowledged, ignored
  kRcEcho,       //!< an RC byte on its own text line: arg[0] = the byte (already applied)
  kSet,          //!< a live gait parameter: arg[0] = TuneParam, arg[1] = value [unit / 100] (swing: SwingShape)
  kGet,          //!< report the live gait parameters
  kLevel,        //!< arg[0] = 1 on, 0 off: hold the body level from the IMU (level_body.h)
  kCalLevel      //!< measure the accelerometer's offsets standing on level ground, and save them
};

//! Where a command came from: bare RC bytes get no reply (the app shows
//! none and repeats buttons); text lines get exactly one, a checked line
//! (`text*HHHH`, command_parser.h) a checked one.
enum class CommandSource : uint8_t { kBareByte = 0, kLine = 1, kCheckedLine = 2 };

//! Parser error codes: stable numbers, listed in docs/protocol.md.
//! 1-19 are found by the parser, 20+ by the controller.
enum class ParseError : uint8_t {
  kNone = 0,
  kUnknownCommand = 1,  //!< first word is no command
  kBadArgument = 2,     //!< argument is not a number / not an allowed word
  kMissingArgument = 3, //!< fewer arguments than the command needs
  kExtraArgument = 4,   //!< more arguments than the command takes
  kOutOfRange = 5,      //!< number outside the command's range
  kLineTooLong = 6,     //!< line longer than kMaxLineBytes
  kBadByte = 7,         //!< non-printable or non-ASCII byte
  kIncomplete = 8,      //!< partial line abandoned (no byte for the idle timeout)
  kBadChecksum = 9,     //!< a checked line whose CRC does not match its text
  kBytesLost = 10,      //!< the line overlaps bytes the receiver dropped
  kChecksumRequired = 11  //!< the command disarms a failsafe: only in a checked line
};

constexpr uint8_t kCommandWordBytes = 8;  //!< gait name: up to 7 chars + NUL

//! With a parse error: which valid values the `err` reply names
//! (error_hints.h), set by the parser for the command it recognised.
enum class Usage : uint8_t {
  kNone = 0,
  kWalk, kStrafe, kTurn, kVel, kSpeed, kPose, kHeight, kDeadman, kBaud,
  kNoArguments,  //!< stop, relax, save, status, help, cal start/show/save/abort/level
  kGait, kAvoid, kCal, kCalTrim, kCalOsc, kCalPwm, kSet, kLevel,
  kEmptyLine     //!< a line of blanks (err 1 empty line)
};

struct Command {
  CommandKind kind;
  CommandSource source;
  ParseError error;               //!< set when the parser reports an error
  int32_t arg[3];                 //!< meaning per kind (see CommandKind)
  char word[kCommandWordBytes];   //!< NUL-terminated word argument (gait name)
  Usage usage;                    //!< with an error: the valid values to name
};

inline Command make_command(CommandKind kind, CommandSource source) {
  Command c;
  c.kind = kind;
  c.source = source;
  c.error = ParseError::kNone;
  c.arg[0] = c.arg[1] = c.arg[2] = 0;
  for (uint8_t i = 0; i < kCommandWordBytes; ++i) c.word[i] = 0;
  c.usage = Usage::kNone;
  return c;
}

//! The short reason that follows `err <code>` in a reply.
inline const char* error_reason(ParseError e) {
  switch (e) {
    case ParseError::kNone: return "none";
    case ParseError::kUnknownCommand: return "unknown command";
    case ParseError::kBadArgument: return "bad argument";
    case ParseError::kMissingArgument: return "missing argument";
    case ParseError::kExtraArgument: return "too many arguments";
    case ParseError::kOutOfRange: return "out of range";
    case ParseError::kLineTooLong: return "line too long";
    case ParseError::kBadByte: return "bad byte";
    case ParseError::kIncomplete: return "incomplete line";
    case ParseError::kBadChecksum: return "bad checksum";
    case ParseError::kBytesLost: return "bytes lost";
    case ParseError::kChecksumRequired: return "checksum required";
  }
  return "error";
}

}  // namespace strider

#endif  // STRIDER_CONTROL_COMMAND_H
