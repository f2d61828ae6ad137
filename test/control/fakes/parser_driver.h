// Feeds a byte string through a CommandParser and records every event.
#ifndef STRIDER_TEST_CONTROL_PARSER_DRIVER_H
#define STRIDER_TEST_CONTROL_PARSER_DRIVER_H

#include <string>
#include <vector>

#include "control/command_parser.h"

namespace strider_test {

struct ParseEvent {
  strider::ParseResult result;
  strider::Command command;
};

inline std::vector<ParseEvent> feed_all(strider::CommandParser& parser, const std::string& bytes) {
  std::vector<ParseEvent> events;
  for (unsigned char b : bytes) {
    strider::Command c = strider::make_command(strider::CommandKind::kNone, strider::CommandSource::kLine);
    const strider::ParseResult r = parser.feed(b, &c);
    if (r != strider::ParseResult::kNothing) events.push_back(ParseEvent{r, c});
  }
  return events;
}

}  // namespace strider_test

#endif
