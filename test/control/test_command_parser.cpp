// Command protocol: table-driven text lines, every RC byte, line endings,
// overlong and binary input, and seeded random byte streams.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "control/command_parser.h"
#include "control/decimal.h"
#include "control/error_hints.h"
#include "control/line_check.h"
#include "control/reply.h"
#include "fakes/parser_driver.h"

using strider::Command;
using strider::CommandKind;
using strider::CommandParser;
using strider::ParseError;
using strider::ParseResult;
using strider_test::feed_all;

namespace {

struct LineCase {
  const char* line;
  CommandKind kind;
  int32_t a0, a1, a2;
  const char* word;
};

// Every command with its argument scaling (tenths for mm, mm/s, deg, deg/s).
const LineCase kGoodLines[] = {
    {"walk 100", CommandKind::kMove, 1000, 0, 0, ""},
    {"walk -12.5", CommandKind::kMove, -125, 0, 0, ""},
    {"walk +0.05", CommandKind::kMove, 1, 0, 0, ""},
    {"walk 500", CommandKind::kMove, 5000, 0, 0, ""},
    {"strafe 80", CommandKind::kMove, 0, 800, 0, ""},
    {"strafe -80", CommandKind::kMove, 0, -800, 0, ""},
    {"turn 60", CommandKind::kMove, 0, 0, 600, ""},
    {"turn -60", CommandKind::kMove, 0, 0, -600, ""},
    {"turn .5", CommandKind::kMove, 0, 0, 5, ""},
    {"vel 100 -20 15", CommandKind::kMove, 1000, -200, 150, ""},
    {"velocity 400 0 -360", CommandKind::kMove, 4000, 0, -3600, ""},
    {"stop", CommandKind::kStop, 0, 0, 0, ""},
    {"relax", CommandKind::kRelax, 0, 0, 0, ""},
    {"speed 0", CommandKind::kSpeed, 0, 0, 0, ""},
    {"speed 100", CommandKind::kSpeed, 100, 0, 0, ""},
    {"gait trot", CommandKind::kGait, 0, 0, 0, "trot"},
    {"gait tripod", CommandKind::kGait, 0, 0, 0, "tripod"},
    {"pose 5 -3.5 0", CommandKind::kPose, 50, -35, 0, ""},
    {"height 80", CommandKind::kHeight, 800, 0, 0, ""},
    {"avoid on", CommandKind::kAvoidEnable, 1, 0, 0, ""},
    {"level on", CommandKind::kLevel, 1, 0, 0, ""},
    {"level off", CommandKind::kLevel, 0, 0, 0, ""},
    {"avoid off", CommandKind::kAvoidEnable, 0, 0, 0, ""},
    {"avoid 200 400", CommandKind::kAvoidLimits, 200, 400, 0, ""},
    {"avoid 150 150", CommandKind::kAvoidLimits, 150, 150, 0, ""},
    {"deadman 1500", CommandKind::kDeadman, 1500, 0, 0, ""},
    {"deadman 1", CommandKind::kDeadman, 1, 0, 0, ""},
    {"deadman 60000", CommandKind::kDeadman, 60000, 0, 0, ""},
    {"baud 115200", CommandKind::kBaud, 115200, 0, 0, ""},
    {"cal start", CommandKind::kCalStart, 0, 0, 0, ""},
    {"cal trim 3 -2.5", CommandKind::kCalTrim, 3, -25, 0, ""},
    {"cal trim 17 30", CommandKind::kCalTrim, 17, 300, 0, ""},
    {"cal osc 26075000", CommandKind::kCalOsc, 26075000, 0, 0, ""},
    {"cal pwm 330", CommandKind::kCalPwm, 330, 0, 0, ""},
    {"cal show", CommandKind::kCalShow, 0, 0, 0, ""},
    {"cal save", CommandKind::kCalSave, 0, 0, 0, ""},
    {"cal abort", CommandKind::kCalAbort, 0, 0, 0, ""},
    {"save", CommandKind::kSave, 0, 0, 0, ""},
    {"status", CommandKind::kStatus, 0, 0, 0, ""},
    {"help", CommandKind::kHelp, 0, 0, 0, ""},
    {"  walk\t 10  ", CommandKind::kMove, 100, 0, 0, ""},
    {"w", CommandKind::kLight, 'w', 0, 0, ""},
    {"v", CommandKind::kLight, 'v', 0, 0, ""},
};

struct BadCase {
  const char* line;
  ParseError error;
};

const BadCase kBadLines[] = {
    {"jump", ParseError::kUnknownCommand},
    {"walkx 10", ParseError::kUnknownCommand},
    {"wal 10", ParseError::kUnknownCommand},
    {"walk", ParseError::kMissingArgument},
    {"walk 10 20", ParseError::kExtraArgument},
    {"walk ten", ParseError::kBadArgument},
    {"walk 1e3", ParseError::kBadArgument},
    {"walk 1.2.3", ParseError::kBadArgument},
    {"walk -", ParseError::kBadArgument},
    {"walk .", ParseError::kBadArgument},
    {"walk 500.1", ParseError::kOutOfRange},
    {"walk -99999999999", ParseError::kOutOfRange},
    {"turn 361", ParseError::kOutOfRange},
    {"vel 1 2", ParseError::kMissingArgument},
    {"vel 1 2 3 4", ParseError::kExtraArgument},
    {"vel 501 0 0", ParseError::kOutOfRange},
    {"vel 0 0 400", ParseError::kOutOfRange},
    {"stop now", ParseError::kExtraArgument},
    {"speed 101", ParseError::kOutOfRange},
    {"speed -1", ParseError::kOutOfRange},
    {"speed 5.5x", ParseError::kBadArgument},
    {"gait", ParseError::kMissingArgument},
    {"gait Trot", ParseError::kBadArgument},
    {"gait verylongname", ParseError::kBadArgument},
    {"gait trot walk", ParseError::kExtraArgument},
    {"pose 31 0 0", ParseError::kOutOfRange},
    {"pose 1 2", ParseError::kMissingArgument},
    {"height 5", ParseError::kOutOfRange},
    {"avoid", ParseError::kMissingArgument},
    {"level", ParseError::kMissingArgument},
    {"level 1", ParseError::kBadArgument},
    {"level onn", ParseError::kBadArgument},
    {"level on off", ParseError::kExtraArgument},
    {"avoid maybe", ParseError::kBadArgument},
    {"avoid on off", ParseError::kExtraArgument},
    {"avoid 400 200", ParseError::kOutOfRange},
    {"avoid 10 200", ParseError::kOutOfRange},
    {"deadman 60001", ParseError::kOutOfRange},
    {"deadman 0", ParseError::kOutOfRange},           // no number turns it off
    {"deadman off", ParseError::kChecksumRequired},  // only a checked line does
    {"deadman off 5", ParseError::kExtraArgument},
    {"deadman on", ParseError::kBadArgument},
    {"walk 100*1A9", ParseError::kBadArgument},       // no check: a plain line, `*` in a number
    {"walk 100*1A94x", ParseError::kBadArgument},
    {"baud 12345", ParseError::kOutOfRange},
    {"cal", ParseError::kMissingArgument},
    {"cal dance", ParseError::kBadArgument},
    {"cal trim 18 0", ParseError::kOutOfRange},
    {"cal trim 1 30.1", ParseError::kOutOfRange},
    {"cal trim 1", ParseError::kMissingArgument},
    {"cal trim 1 2 3", ParseError::kExtraArgument},
    {"cal osc 19999999", ParseError::kOutOfRange},
    {"cal pwm 39", ParseError::kOutOfRange},
    {"cal start now", ParseError::kExtraArgument},
    {"a b c d e f", ParseError::kUnknownCommand},  // an unknown word is err 1 however long the line
    {"walk 1 2 3 4 5", ParseError::kExtraArgument},
    {"cal trim 1 2 3 4", ParseError::kExtraArgument},
    {" ", ParseError::kUnknownCommand},            // a line of blanks: err 1 empty line
    {"\t \t", ParseError::kUnknownCommand},
    {"status!", ParseError::kUnknownCommand},
};

std::vector<strider_test::ParseEvent> one_line(const std::string& s) {
  CommandParser p;
  return feed_all(p, s);
}

TEST(CommandParser, EveryCommandParses) {
  for (const LineCase& c : kGoodLines) {
    const auto ev = one_line(std::string(c.line) + "\n");
    ASSERT_EQ(ev.size(), 1u) << c.line;
    EXPECT_EQ(ev[0].result, ParseResult::kCommand) << c.line;
    const Command& cmd = ev[0].command;
    EXPECT_EQ(cmd.kind, c.kind) << c.line;
    EXPECT_EQ(cmd.source, strider::CommandSource::kLine) << c.line;
    EXPECT_EQ(cmd.arg[0], c.a0) << c.line;
    EXPECT_EQ(cmd.arg[1], c.a1) << c.line;
    EXPECT_EQ(cmd.arg[2], c.a2) << c.line;
    EXPECT_STREQ(cmd.word, c.word) << c.line;
  }
}

TEST(CommandParser, EveryErrorIsReportedOnce) {
  for (const BadCase& c : kBadLines) {
    const auto ev = one_line(std::string(c.line) + "\r\n");
    ASSERT_EQ(ev.size(), 1u) << c.line;
    EXPECT_EQ(ev[0].result, ParseResult::kError) << c.line;
    EXPECT_EQ(int(ev[0].command.error), int(c.error)) << c.line;
  }
}

// The reply to a bad line names what is valid (docs/protocol.md, error codes).
std::string error_reply(const std::string& line) {
  const auto ev = one_line(line + "\n");
  if (ev.size() != 1u || ev[0].result != ParseResult::kError) return "no error";
  char buf[strider::kMaxReplyBytes];
  strider::ReplyWriter w(buf, sizeof buf);
  struct Gaits {
    void write_gait_names(strider::ReplyWriter& to) const { to.text("walk trot pace crawl"); }
  } gaits;
  strider::write_parse_error(w, ev[0].command, &gaits);
  return w.c_str();
}

TEST(CommandParser, ErrorRepliesNameTheValidValues) {
  const std::string all = "walk strafe turn vel stop relax speed gait pose height level set get avoid deadman baud cal save status help";
  const struct {
    std::string line;
    const char* reply;
  } cases[] = {
      {"dance", "err 1 unknown command: "},
      {"   ", "err 1 empty line: "},
      {"walk", "err 3 missing argument: walk -500..500"},
      {"walk fast", "err 2 bad argument: walk -500..500"},
      {"walk 501", "err 5 out of range: walk -500..500"},
      {"strafe 1 2", "err 4 too many arguments: strafe -500..500"},
      {"turn 361", "err 5 out of range: turn -360..360"},
      {"vel 1 2 400", "err 5 out of range: vel -500..500 -500..500 -360..360"},
      {"velocity 1 2", "err 3 missing argument: vel -500..500 -500..500 -360..360"},
      {"speed 101", "err 5 out of range: speed 0..100"},
      {"pose 0 31 0", "err 5 out of range: pose -30..30 -30..30 -30..30"},
      {"height 9", "err 5 out of range: height 10..400"},
      {"deadman 0", "err 5 out of range: deadman 1..60000, off only as a checked line"},
      {"deadman off 1", "err 4 too many arguments: deadman 1..60000, off only as a checked line"},
      {"deadman off", "err 11 checksum required: $deadman off*cb77, a checked line"},
      {"baud 300", "err 5 out of range: baud 9600 19200 38400 57600 115200"},
      {"stop now", "err 4 too many arguments: none after the command word"},
      {"cal show 1", "err 4 too many arguments: none after the command word"},
      {"gait", "err 3 missing argument: gait walk trot pace crawl"},
      {"gait Trot", "err 2 bad argument: gait walk trot pace crawl"},
      {"avoid", "err 3 missing argument: avoid on, avoid off, avoid STOP SLOW with 20 <= STOP <= SLOW <= 3000"},
      {"level up", "err 2 bad argument: level on, level off"},
      {"avoid 300 200", "err 5 out of range: avoid on, avoid off, avoid STOP SLOW with 20 <= STOP <= SLOW <= 3000"},
      {"cal", "err 3 missing argument: cal start trim osc pwm show save abort level"},
      {"cal dance", "err 2 bad argument: cal start trim osc pwm show save abort level"},
      {"cal trim 18 0", "err 5 out of range: cal trim 0..17 -30..30"},
      {"cal osc 1", "err 5 out of range: cal osc 20000000..30000000"},
      {"cal pwm 401", "err 5 out of range: cal pwm 40..400"},
      {"walk 1 2 3 4 5", "err 4 too many arguments: walk -500..500"},
      {"$walk 1*0000", "err 9 bad checksum: $text*hhhh, hhhh the CRC-16 of text"},
      {std::string(64, 'a'), "err 6 line too long: at most 63 bytes"},
  };
  for (const auto& c : cases) {
    std::string want = c.reply;
    if (want.back() == ' ') want += all;
    EXPECT_EQ(error_reply(c.line), want) << c.line;
    // A reply that ended in `*hhhh` would read as a checked reply to a client.
    const size_t star = want.rfind('*');
    EXPECT_FALSE(star != std::string::npos && star + 5 == want.size()) << want;
  }
  // Without the model's gaits the reply keeps the placeholder.
  const auto ev = one_line("gait\n");
  ASSERT_EQ(ev.size(), 1u);
  char buf[strider::kMaxReplyBytes];
  strider::ReplyWriter w(buf, sizeof buf);
  strider::write_parse_error(w, ev[0].command);
  EXPECT_STREQ(w.c_str(), "err 3 missing argument: gait NAME");
}

// The ranges the replies name are the parser's: both ends of every `a..b`
// are taken, and one past either end is err 5 (one unit: the commands with
// decimals take a tenth past the end too, checked by EveryErrorIsReportedOnce).
TEST(CommandParser, ErrorHintRangesAreTheParsers) {
  int ranges = 0;
  for (uint8_t u = 1; u < uint8_t(strider::Usage::kEmptyLine); ++u) {
    const std::string hint = strider::flash_name(strider::text::kUsageHints, strider::text::kUsageHintCount, u).p;
    std::istringstream in(hint);
    std::vector<std::string> words;
    for (std::string t; in >> t;) words.push_back(t);
    // The command: the words before the first range; the ranges after them, up to a comma.
    std::vector<std::string> head;
    std::vector<std::pair<long, long>> range;
    for (const std::string& t : words) {
      const size_t dots = t.find("..");
      if (dots != std::string::npos) {
        range.emplace_back(std::stol(t.substr(0, dots)), std::stol(t.substr(dots + 2)));
        if (t.back() == ',') break;
      } else if (range.empty() && t.find_first_of(",<=") == std::string::npos && std::isupper(t[0]) == 0) {
        head.push_back(t);
      } else {
        break;
      }
    }
    if (range.empty()) continue;
    std::string cmd;
    for (const std::string& h : head) cmd += h + " ";
    for (size_t k = 0; k < range.size(); ++k) {
      for (int edge = 0; edge < 4; ++edge) {
        std::string line = cmd;
        for (size_t j = 0; j < range.size(); ++j) {
          long v = 0;  // 0 is in every range but cal osc's and cal pwm's: their low end
          if (range[j].first > 0) v = range[j].first;
          if (j == k) v = edge == 0 ? range[j].first : edge == 1 ? range[j].second
                          : edge == 2 ? range[j].first - 1 : range[j].second + 1;
          line += std::to_string(v) + (j + 1 < range.size() ? " " : "");
        }
        const auto ev = one_line(line + "\n");
        ASSERT_EQ(ev.size(), 1u) << line;
        if (edge < 2) {
          EXPECT_EQ(ev[0].result, ParseResult::kCommand) << hint << ": " << line;
        } else {
          EXPECT_EQ(ev[0].result, ParseResult::kError) << hint << ": " << line;
          EXPECT_EQ(int(ev[0].command.error), int(ParseError::kOutOfRange)) << hint << ": " << line;
        }
      }
      ++ranges;
    }
  }
  EXPECT_EQ(ranges, 16);  // walk strafe turn, vel x3, speed, pose x3, height, deadman, cal trim x2, osc, pwm
}

TEST(CommandParser, LineEndingsCrLfCrlf) {
  for (const char* end : {"\r", "\n", "\r\n"}) {
    CommandParser p;
    const auto ev = feed_all(p, std::string("walk 10") + end + "turn 5" + end + end);
    ASSERT_EQ(ev.size(), 2u) << int(end[0]);
    EXPECT_EQ(ev[0].command.arg[0], 100);
    EXPECT_EQ(ev[1].command.arg[2], 50);
  }
  // No ending at all: nothing happens until one arrives or the idle timeout.
  CommandParser p;
  EXPECT_TRUE(feed_all(p, "walk 10").empty());
  Command c{};
  EXPECT_EQ(p.idle_timeout(&c), ParseResult::kError);
  EXPECT_EQ(c.error, ParseError::kIncomplete);
  EXPECT_EQ(feed_all(p, "stop\n").size(), 1u);
  // LF CR (reversed) yields two line ends: still one command, no blank-line reply.
  CommandParser q;
  EXPECT_EQ(feed_all(q, "stop\n\rstop\n\r").size(), 2u);
}

TEST(CommandParser, EveryRcByte) {
  struct Rc {
    char b;
    CommandKind kind;
    int32_t a0, a1, a2;
  };
  const Rc table[] = {
      {'F', CommandKind::kDrive, 1, 0, 0},   {'B', CommandKind::kDrive, -1, 0, 0},
      {'L', CommandKind::kDrive, 0, 1, 0},   {'R', CommandKind::kDrive, 0, -1, 0},
      {'G', CommandKind::kDrive, 0, 0, 1},   {'I', CommandKind::kDrive, 0, 0, -1},
      {'H', CommandKind::kDrive, -1, 1, 0},  {'J', CommandKind::kDrive, -1, -1, 0},
      {'S', CommandKind::kStop, 0, 0, 0},    {'q', CommandKind::kSpeed, 100, 0, 0},
      {'W', CommandKind::kLight, 'W', 0, 0}, {'U', CommandKind::kLight, 'U', 0, 0},
      {'u', CommandKind::kLight, 'u', 0, 0}, {'V', CommandKind::kLight, 'V', 0, 0},
      {'X', CommandKind::kLight, 'X', 0, 0}, {'x', CommandKind::kLight, 'x', 0, 0},
  };
  for (const Rc& rc : table) {
    const auto ev = one_line(std::string(1, rc.b));
    ASSERT_EQ(ev.size(), 1u) << rc.b;
    EXPECT_EQ(ev[0].command.kind, rc.kind) << rc.b;
    EXPECT_EQ(ev[0].command.source, strider::CommandSource::kBareByte) << rc.b;
    EXPECT_EQ(ev[0].command.arg[0], rc.a0) << rc.b;
    EXPECT_EQ(ev[0].command.arg[1], rc.a1) << rc.b;
    EXPECT_EQ(ev[0].command.arg[2], rc.a2) << rc.b;
  }
  for (int d = 0; d <= 9; ++d) {
    const auto ev = one_line(std::string(1, char('0' + d)));
    ASSERT_EQ(ev.size(), 1u);
    EXPECT_EQ(ev[0].command.kind, CommandKind::kSpeed);
    EXPECT_EQ(ev[0].command.arg[0], d * 10);
  }
}

TEST(CommandParser, SeedSixMotionsFromAppAndText) {
  // Seed 000: front, back, left, right, clockwise, anticlockwise.
  const char* app = "FBLRIG";
  const char* text[] = {"walk 100", "walk -100", "strafe 100", "strafe -100", "turn -60", "turn 60"};
  for (int i = 0; i < 6; ++i) {
    const auto a = one_line(std::string(1, app[i]));
    const auto t = one_line(std::string(text[i]) + "\n");
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(t.size(), 1u);
    for (int k = 0; k < 3; ++k) {
      const int32_t sa = a[0].command.arg[k], st = t[0].command.arg[k];
      EXPECT_EQ((sa > 0) - (sa < 0), (st > 0) - (st < 0)) << text[i];
    }
  }
}

TEST(CommandParser, AppStreamWithoutLineEndings) {
  CommandParser p;
  // Held button repeats, speed slider, lights on/off, release: all bare.
  const auto ev = feed_all(p, "FFF5FFwWvVSq0uUxXLLS");
  std::vector<CommandKind> kinds;
  for (const auto& e : ev) {
    EXPECT_EQ(e.result, ParseResult::kCommand);
    kinds.push_back(e.command.kind);
  }
  // w and v are dropped by the lookahead (lights are ignored anyway); 18 others remain.
  EXPECT_EQ(ev.size(), 18u);
  EXPECT_EQ(ev[3].command.kind, CommandKind::kSpeed);
  EXPECT_EQ(ev[3].command.arg[0], 50);
  EXPECT_EQ(ev.back().command.kind, CommandKind::kStop);
  EXPECT_FALSE(p.collecting());
}

TEST(CommandParser, RcByteOnItsOwnLineIsEchoed) {
  CommandParser p;
  const auto ev = feed_all(p, "F\r\n");
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[0].command.kind, CommandKind::kDrive);
  EXPECT_EQ(ev[1].command.kind, CommandKind::kRcEcho);
  EXPECT_EQ(ev[1].command.arg[0], 'F');
  EXPECT_EQ(ev[1].command.source, strider::CommandSource::kLine);
}

TEST(CommandParser, OverlongLineOneErrorThenResync) {
  CommandParser p;
  const std::string longline = "walk " + std::string(200, '1');
  auto ev = feed_all(p, longline + "\nstop\n");
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[0].command.error, ParseError::kLineTooLong);
  EXPECT_EQ(ev[1].command.kind, CommandKind::kStop);
  // Exactly kMaxLineBytes is still accepted.
  std::string max = "help" + std::string(strider::kMaxLineBytes - 4, ' ');
  ev = feed_all(p, max + "\n");
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].command.kind, CommandKind::kHelp);
  ev = feed_all(p, max + " \n");
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].command.error, ParseError::kLineTooLong);
}

TEST(CommandParser, BinaryInsideLineAndBetweenLines) {
  CommandParser p;
  auto ev = feed_all(p, std::string("walk \x01\xff 10\nstop\n"));
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[0].command.error, ParseError::kBadByte);
  EXPECT_EQ(ev[1].command.kind, CommandKind::kStop);
  // Junk between lines: one error, then skipped until a valid start byte.
  ev = feed_all(p, std::string("\x00\x80\xfe\x7f#!F", 7));
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[0].command.error, ParseError::kBadByte);
  EXPECT_EQ(ev[1].command.kind, CommandKind::kDrive);
}

TEST(CommandParser, LightLookaheadKeepsWords) {
  CommandParser p;
  auto ev = feed_all(p, "wF");
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].command.kind, CommandKind::kDrive);
  ev = feed_all(p, "walk 20\n");
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].command.kind, CommandKind::kMove);
  ev = feed_all(p, "v7");
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].command.arg[0], 70);
  Command c{};
  feed_all(p, "w");
  EXPECT_EQ(p.idle_timeout(&c), ParseResult::kNothing);  // a lone light byte is no error
}

TEST(Decimal, ScalesAndRounds) {
  struct D {
    const char* s;
    uint8_t dec;
    strider::DecimalStatus st;
    int32_t v;
  };
  const D table[] = {{"0", 1, strider::DecimalStatus::kOk, 0},
                     {"12.34", 1, strider::DecimalStatus::kOk, 123},
                     {"12.35", 1, strider::DecimalStatus::kOk, 124},
                     {"-12.35", 1, strider::DecimalStatus::kOk, -124},
                     {"7.", 2, strider::DecimalStatus::kOk, 700},
                     {".25", 0, strider::DecimalStatus::kOk, 0},
                     {".5", 0, strider::DecimalStatus::kOk, 1},
                     {"2000000000", 0, strider::DecimalStatus::kOk, 2000000000},
                     {"2000000001", 0, strider::DecimalStatus::kOverflow, 0},
                     {"300000000", 1, strider::DecimalStatus::kOverflow, 0},
                     {"", 0, strider::DecimalStatus::kSyntax, 0},
                     {"+", 0, strider::DecimalStatus::kSyntax, 0},
                     {"1-", 0, strider::DecimalStatus::kSyntax, 0},
                     {"--1", 0, strider::DecimalStatus::kSyntax, 0}};
  for (const D& d : table) {
    int32_t v = -777;
    const auto st = strider::parse_decimal(d.s, uint8_t(std::string(d.s).size()), d.dec, &v);
    EXPECT_EQ(st, d.st) << d.s;
    EXPECT_EQ(v, st == strider::DecimalStatus::kOk ? d.v : -777) << d.s;
  }
}

// The digit loop's first form (separate integer and fraction loops, the
// overflow check by division): the shorter one must give the same status
// and value for every input.
namespace {
strider::DecimalStatus reference_parse_decimal(const char* text, uint8_t len, uint8_t decimals, int32_t* out) {
  uint8_t i = 0;
  bool negative = false;
  if (i < len && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  const int32_t kLimit = 2000000000;  // a little under 2^31: the check below never overflows
  int32_t value = 0;
  uint8_t int_digits = 0, frac_digits = 0;
  bool round_up = false;
  bool overflow = false;
  while (i < len && text[i] >= '0' && text[i] <= '9') {
    const int32_t d = text[i++] - '0';
    if (value > (kLimit - d) / 10) overflow = true; else value = value * 10 + d;
    ++int_digits;
  }
  if (i < len && text[i] == '.') {
    ++i;
    while (i < len && text[i] >= '0' && text[i] <= '9') {
      const int32_t d = text[i++] - '0';
      if (frac_digits < decimals) {
        if (value > (kLimit - d) / 10) overflow = true; else value = value * 10 + d;
      } else if (frac_digits == decimals) {
        round_up = d >= 5;
      }
      ++frac_digits;
    }
  }
  if (i != len || (int_digits == 0 && frac_digits == 0)) return strider::DecimalStatus::kSyntax;
  for (uint8_t k = frac_digits; k < decimals; ++k) {
    if (value > kLimit / 10) overflow = true; else value *= 10;
  }
  if (round_up) {
    if (value >= kLimit) overflow = true; else ++value;
  }
  if (overflow) return strider::DecimalStatus::kOverflow;
  *out = negative ? -value : value;
  return strider::DecimalStatus::kOk;
}
}  // namespace

TEST(Decimal, SameAsTheTwoLoopForm) {
  std::mt19937 rng(5u);
  const char alphabet[] = "0123456789.+-x 9";
  std::uniform_int_distribution<int> len_of(0, 14), char_of(0, int(sizeof alphabet) - 2), dec_of(0, 3);
  for (int n = 0; n < 200000; ++n) {
    std::string s;
    const int len = len_of(rng);
    for (int k = 0; k < len; ++k) s += alphabet[char_of(rng)];
    if (n % 3 == 0 && !s.empty()) s[0] = char('1' + n % 9);  // more long numbers (overflow)
    const uint8_t dec = uint8_t(dec_of(rng));
    int32_t a = -777, b = -777;
    const auto sa = strider::parse_decimal(s.data(), uint8_t(s.size()), dec, &a);
    const auto sb = reference_parse_decimal(s.data(), uint8_t(s.size()), dec, &b);
    ASSERT_EQ(sa, sb) << '"' << s << "\" " << int(dec);
    ASSERT_EQ(a, b) << '"' << s << "\" " << int(dec);
  }
}

TEST(Reply, FormatsWithoutOverrun) {
  char buf[strider::kMaxReplyBytes];
  strider::ReplyWriter w(buf, sizeof buf);
  w.text("ok move").field_tenths("vx", -125).field("speed", 50).field_text("gait", "trot");
  EXPECT_STREQ(w.c_str(), "ok move vx=-12.5 speed=50 gait=trot");
  char small[8];
  strider::ReplyWriter s(small, sizeof small);
  strider::write_parse_error(s, ParseError::kOutOfRange);
  EXPECT_STREQ(s.c_str(), "err 5 o");
  EXPECT_TRUE(s.truncated());
  char b2[32];
  strider::ReplyWriter m(b2, sizeof b2);
  m.integer(INT32_MIN);
  EXPECT_STREQ(m.c_str(), "-2147483648");
}

// `$text*hhhh` with the CRC-16 of text (line_check.h); a reply's `text*hhhh`.
std::string reply_checked(const std::string& text) {
  std::string out(text.size() + strider::kLineCheckBytes + 1, '\0');
  std::copy(text.begin(), text.end(), out.begin());
  strider::append_line_check(&out[0], uint8_t(text.size()));
  out.resize(text.size() + strider::kLineCheckBytes);
  return out;
}
std::string checked(const std::string& text) { return "$" + reply_checked(text); }

TEST(LineCheck, CrcCheckAndAppend) {
  EXPECT_EQ(strider::line_crc("123456789", 9), 0x29B1);  // CRC-16/CCITT-FALSE's check value
  EXPECT_EQ(reply_checked("123456789"), "123456789*29b1");
  EXPECT_EQ(checked("deadman off"), "$deadman off*cb77");
  EXPECT_EQ(checked(""), "$*ffff");
  uint8_t len = 0;
  for (const char* good : {"$123456789*29b1", "$123456789*29B1", "$*ffff", "$deadman off*CB77"}) {
    EXPECT_TRUE(strider::check_line(good, uint8_t(std::string(good).size()), &len)) << good;
    EXPECT_EQ(len, std::string(good).size() - 6) << good;
  }
  for (const char* bad : {"123456789*29b1", "$123456789*29b2", "$123456789*29b", "$123456789*29bg",
                          "$123456789#29b1", "$12345678*29b1", "$*fff", "$"}) {
    EXPECT_FALSE(strider::check_line(bad, uint8_t(std::string(bad).size()), &len)) << bad;
  }
}

// Every command runs from its checked line too, marked as checked; errors of
// a checked line are checked errors (a checked reply).
TEST(CommandParser, CheckedLinesParseAsPlainOnes) {
  for (const LineCase& c : kGoodLines) {
    if (c.kind == CommandKind::kLight) continue;  // a light button's byte, not a command line
    const auto ev = one_line(checked(c.line) + "\r\n");
    ASSERT_EQ(ev.size(), 1u) << c.line;
    EXPECT_EQ(ev[0].result, ParseResult::kCommand) << c.line;
    EXPECT_EQ(ev[0].command.kind, c.kind) << c.line;
    EXPECT_EQ(ev[0].command.source, strider::CommandSource::kCheckedLine) << c.line;
    EXPECT_EQ(ev[0].command.arg[0], c.a0) << c.line;
    EXPECT_STREQ(ev[0].command.word, c.word) << c.line;
  }
  for (const BadCase& c : kBadLines) {
    if (c.error == ParseError::kChecksumRequired) continue;
    const auto ev = one_line(checked(c.line) + "\n");
    ASSERT_EQ(ev.size(), 1u) << c.line;
    EXPECT_EQ(int(ev[0].command.error), int(c.error)) << c.line;
    EXPECT_EQ(ev[0].command.source, strider::CommandSource::kCheckedLine) << c.line;
  }
  // Uppercase hex digits are as good; a `$` line without its check is not.
  std::string upper = checked("speed 41");
  for (char& ch : upper) ch = char(std::toupper(ch));
  upper = checked("speed 41").substr(0, 9) + upper.substr(9);
  auto ev = one_line(upper + "\n");
  ASSERT_EQ(ev.size(), 1u) << upper;
  EXPECT_EQ(ev[0].command.kind, CommandKind::kSpeed) << upper;
  for (const char* bad : {"$speed 41", "$speed 41*", "$speed 41*abc", "$", "$*"}) {
    ev = one_line(std::string(bad) + "\n");
    ASSERT_EQ(ev.size(), 1u) << bad;
    EXPECT_EQ(ev[0].command.error, ParseError::kBadChecksum) << bad;
    EXPECT_EQ(ev[0].command.source, strider::CommandSource::kCheckedLine) << bad;
  }
}

// A command from a text line. RC buttons act as their byte arrives, between
// lines (a line's first byte changed into `F` is the button F), and a line
// end after one only echoes it (kRcEcho).
bool line_command(const strider_test::ParseEvent& e) {
  return e.result == ParseResult::kCommand && e.command.source != strider::CommandSource::kBareByte &&
         e.command.kind != CommandKind::kRcEcho;
}

// Any one byte changed, anywhere in a checked line (its check included),
// and any two checked lines glued at any point: err 9 (or a parse error),
// never a command (a CRC-16 detects every burst of up to 16 bits).
TEST(CommandParser, CheckedLineCatchesEveryChangedByteAndGlue) {
  const char* texts[] = {"walk 100", "speed 50", "deadman off", "vel -12.5 300 45", "gait tripod", "status"};
  int cases = 0;
  for (const char* t : texts) {
    const std::string line = checked(t);
    for (size_t i = 0; i < line.size(); ++i) {
      for (int delta = 1; delta < 95; ++delta) {
        std::string bad = line;
        bad[i] = char(0x20 + (bad[i] - 0x20 + delta) % 95);  // another printable byte
        if (i + 4 >= line.size() && std::tolower(bad[i]) == std::tolower(line[i])) continue;  // the same hex digit
        const auto ev = one_line(bad + "\n");
        ++cases;
        for (const auto& e : ev) ASSERT_FALSE(line_command(e)) << bad;
      }
    }
    for (const char* u : texts) {
      const std::string other = checked(u);
      for (size_t i = 1; i < line.size(); ++i)
        for (size_t j = 1; j < other.size(); ++j) {
          const std::string glued = line.substr(0, i) + other.substr(j);
          if (glued == line || glued == other) continue;
          const auto ev = one_line(glued + "\n");
          ++cases;
          for (const auto& e : ev) ASSERT_FALSE(line_command(e)) << glued;
        }
    }
  }
  EXPECT_GT(cases, 10000);
  // The deadman off only from its checked line.
  auto ev = one_line(checked("deadman off") + "\n");
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].command.kind, CommandKind::kDeadman);
  EXPECT_EQ(ev[0].command.arg[0], 0);
  EXPECT_TRUE(strider::needs_checked_line(ev[0].command));
  ev = one_line("deadman off\n");
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].command.error, ParseError::kChecksumRequired);
  EXPECT_EQ(ev[0].command.source, strider::CommandSource::kLine);
}

// Feeds `before`, then lost(), then `after`: the events after the gap.
std::vector<strider_test::ParseEvent> across_gap(CommandParser& p, const std::string& before, const std::string& after,
                                                 std::vector<strider_test::ParseEvent>* first = nullptr) {
  auto ev = feed_all(p, before);
  if (first) *first = ev;
  p.lost();
  return feed_all(p, after);
}

// Bytes lost inside a line or between lines: the damaged line is answered
// kBytesLost at its end, once, and nothing after the gap runs before that
// line end: not a glued command, not a line's tail taken for RC bytes.
TEST(CommandParser, LostBytesDropTheDamagedLine) {
  std::vector<strider_test::ParseEvent> first;
  {  // inside a line: "walk 1|00\n" (the gap ate "23\nspeed 1")
    CommandParser p;
    auto ev = across_gap(p, "walk 1", "00\nspeed 5\n");
    ASSERT_EQ(ev.size(), 2u);
    EXPECT_EQ(ev[0].result, ParseResult::kError);
    EXPECT_EQ(ev[0].command.error, ParseError::kBytesLost);
    EXPECT_EQ(ev[1].command.kind, CommandKind::kSpeed);  // the next whole line runs
  }
  {  // between lines: "stop\n|00\n" must not set the RC speed 0 twice
    CommandParser p;
    auto ev = across_gap(p, "stop\n", "00\nF", &first);
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].command.kind, CommandKind::kStop);
    ASSERT_EQ(ev.size(), 2u);
    EXPECT_EQ(ev[0].command.error, ParseError::kBytesLost);
    EXPECT_EQ(ev[1].command.kind, CommandKind::kDrive);  // an RC byte after the line end
  }
  {  // RC bytes after a gap wait for a line end (or the idle timeout)
    CommandParser p;
    auto ev = across_gap(p, "FF", "FFFF");
    EXPECT_TRUE(ev.empty());
    Command c;
    EXPECT_EQ(p.idle_timeout(&c), ParseResult::kError);
    EXPECT_EQ(c.error, ParseError::kBytesLost);
    EXPECT_EQ(feed_all(p, "F").size(), 1u);
  }
  {  // a gap right after CR: the LF that follows ends a line of its own
    CommandParser p;
    auto ev = across_gap(p, "stop\r", "\nstatus\r\n");
    ASSERT_EQ(ev.size(), 2u);
    EXPECT_EQ(ev[0].command.error, ParseError::kBytesLost);
    EXPECT_EQ(ev[1].command.kind, CommandKind::kStatus);
  }
  {  // a line already discarded after an error: no second reply
    CommandParser p;
    auto ev = across_gap(p, std::string(70, 'a'), "bc\nstop\n", &first);
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].command.error, ParseError::kLineTooLong);
    ASSERT_EQ(ev.size(), 1u);
    EXPECT_EQ(ev[0].command.kind, CommandKind::kStop);
  }
  {  // several gaps in one damaged line: one reply
    CommandParser p;
    auto ev = across_gap(p, "walk", " 1");
    p.lost();
    auto more = feed_all(p, "0\n");
    EXPECT_TRUE(ev.empty());
    ASSERT_EQ(more.size(), 1u);
    EXPECT_EQ(more[0].command.error, ParseError::kBytesLost);
  }
}

// Seeded: two valid lines, the first cut at any point, bytes lost, the
// second from any point on: whatever the pieces spell, nothing runs from
// the gap up to the next line end, and the line after that runs.
TEST(CommandParser, NoCommandIsGluedAcrossAGap) {
  const char* lines[] = {"walk 100", "speed 0", "deadman 500", "vel 1 2 3", "turn -45", "stop", "avoid off",
                         "gait trot", "pose 1 2 3", "F", "status"};
  const size_t n = sizeof lines / sizeof lines[0];
  std::mt19937 rng(4242u);
  for (int k = 0; k < STRIDER_RANDOM_CASES; ++k) {
    const std::string a = std::string(lines[rng() % n]) + "\n";
    const std::string b = std::string(lines[rng() % n]) + (rng() % 2 ? "\r\n" : "\n");
    const size_t i = rng() % (a.size() + 1), j = rng() % b.size();
    CommandParser p;
    across_gap(p, a.substr(0, i), "");
    const auto ev = feed_all(p, b.substr(j));
    for (const auto& e : ev) ASSERT_NE(e.result, ParseResult::kCommand) << a.substr(0, i) << "|" << b.substr(j);
    ASSERT_EQ(ev.size(), 1u) << a.substr(0, i) << "|" << b.substr(j);
    EXPECT_EQ(ev[0].command.error, ParseError::kBytesLost);
    const auto next = feed_all(p, "speed 20\n");
    ASSERT_EQ(next.size(), 1u);
    EXPECT_EQ(next[0].command.kind, CommandKind::kSpeed);
  }
}

// Random byte streams (fixed seed): never more than one event per byte, the
// partial line stays bounded, and a newline always brings the parser back.
TEST(CommandParser, RandomStreamsResynchronise) {
  std::mt19937 rng(20240601u);
  std::uniform_int_distribution<int> len_dist(1, 200);
  std::uniform_int_distribution<int> byte_dist(0, 255);
  std::uniform_int_distribution<int> mix(0, 3);
  const char* alphabet = "walk strafe turn vel 0123456789.-+ \t\r\nFBLRSGIHJqwvWV";
  const std::string alpha(alphabet);
  std::uniform_int_distribution<size_t> alpha_dist(0, alpha.size() - 1);
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    CommandParser p;
    const int n = len_dist(rng);
    const bool textish = mix(rng) != 0;
    for (int k = 0; k < n; ++k) {
      const uint8_t b = textish ? uint8_t(alpha[alpha_dist(rng)]) : uint8_t(byte_dist(rng));
      Command c{};
      const ParseResult r = p.feed(b, &c);
      ASSERT_LE(p.line_length(), strider::kMaxLineBytes);
      if (r == ParseResult::kError) {
        ASSERT_NE(c.error, ParseError::kNone);
      }
      if (r == ParseResult::kCommand) {
        ASSERT_NE(c.kind, CommandKind::kNone);
      }
    }
    // Resync: after a line end, a valid line is understood.
    auto ev = feed_all(p, "\nstatus\n");
    ASSERT_FALSE(ev.empty());
    EXPECT_EQ(ev.back().result, ParseResult::kCommand) << "case " << i;
    EXPECT_EQ(ev.back().command.kind, CommandKind::kStatus) << "case " << i;
  }
}

}  // namespace
