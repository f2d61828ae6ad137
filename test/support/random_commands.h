// Seeded random operator input for robustness tests (host RobotApp and the
// firmware on the virtual Mega): any text command with numbers in and far
// out of range, gait names (one unknown), RC buttons, stop and relax, and
// lines of random bytes. `next` gives 32 random bits per call.
#ifndef STRIDER_TEST_SUPPORT_RANDOM_COMMANDS_H
#define STRIDER_TEST_SUPPORT_RANDOM_COMMANDS_H

#include <cstdint>
#include <string>

namespace strider_test {

template <typename Next>
std::string random_operator_command(Next&& next) {
  auto num = [&](int lo, int hi) { return std::to_string(lo + int(next() % uint32_t(hi - lo + 1))); };
  static const char* const kGaits[] = {"walk", "trot", "pace", "crawl", "tripod", "ripple", "wave", "gallop"};
  static const char* const kKeys[] = {"F", "B", "L", "R", "G", "I", "H", "J", "S", "0", "5", "9", "q", "W", "w"};
  switch (next() % 14) {
    case 0: return "walk " + num(-600, 600) + "\n";
    case 1: return "strafe " + num(-600, 600) + "\n";
    case 2: return "turn " + num(-400, 400) + "\n";
    case 3: return "vel " + num(-400, 400) + " " + num(-400, 400) + " " + num(-300, 300) + "\n";
    case 4: return "pose " + num(-40, 40) + " " + num(-40, 40) + " " + num(-40, 40) + "\n";
    case 5: return "height " + num(0, 450) + "\n";
    case 6: return std::string("gait ") + kGaits[next() % 8] + "\n";
    case 7: return "speed " + num(-10, 110) + "\n";
    case 8: return kKeys[next() % 15];
    case 9: return next() % 4 == 0 ? "relax\n" : "stop\n";
    case 10: return next() % 2 ? "avoid off\n" : "avoid on\n";
    case 11: return "pose 0 0 0\n";
    case 12: {
      std::string junk;
      for (int i = 0; i < 12; ++i) junk.push_back(char(next() & 0xFF));
      return junk + "\n";
    }
    default: return "status\n";
  }
}

}  // namespace strider_test

#endif  // STRIDER_TEST_SUPPORT_RANDOM_COMMANDS_H
