// Every `err` reply the robot can give, on every model: `err <code>
// <reason>: <what is valid>` with something after the colon, the code and
// reason as docs/protocol.md's error table lists them, and nothing changed.
// "Nothing changed" is measured against a twin: two RobotApps with the same
// history, walking; one gets the erroneous input, the other none; both then
// run 2 s and must write the same servo frames, and answer `status`, `get`,
// `cal show` and `help` alike.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "fakes/app_rig.h"
#include "math/prng.h"
#include "random_commands.h"
#include "robots/all_robots.h"

namespace {

struct Robot : strider_test::AppRig {
  explicit Robot(const strider::RobotModel& m) : AppRig(m) { EXPECT_TRUE(began); }
  //! What a user can ask about the robot's state, without changing it.
  std::string state() {
    return reply("status") + "\n" + reply("get") + "\n" + reply("cal show") + "\n" + reply("help");
  }
};

// `err <code> <reason>: <hint>`, split; false if the reply is not of that form.
struct ErrReply {
  int code = 0;
  std::string reason, hint;
};
bool parse_err(const std::string& reply, ErrReply* e) {
  if (reply.rfind("err ", 0) != 0) return false;
  size_t end = 0;
  e->code = std::stoi(reply.substr(4), &end);
  const size_t reason_at = 4 + end + 1;
  const size_t colon = reply.find(": ", reason_at);
  if (colon == std::string::npos || reason_at >= reply.size()) return false;
  e->reason = reply.substr(reason_at, colon - reason_at);
  e->hint = reply.substr(colon + 2);
  return !e->reason.empty() && e->hint.find_first_not_of(' ') != std::string::npos;
}

// The row of docs/protocol.md's error table for `code`, "" if none.
std::string doc_row(int code) {
  std::ifstream in(STRIDER_PROTOCOL_DOC);
  EXPECT_TRUE(in.good()) << STRIDER_PROTOCOL_DOC;
  const std::string head = "| " + std::to_string(code) + " | ";
  for (std::string l; std::getline(in, l);)
    if (l.rfind(head, 0) == 0) return l;
  return "";
}

// The reason named in the doc's row: `reason` in the second column.
bool doc_names(int code, const std::string& reason) {
  const std::string row = doc_row(code);
  const size_t col = row.find(" | ");
  return col != std::string::npos && row.substr(col, row.find(" | ", col + 3) - col).find("`" + reason + "`") != std::string::npos;
}

struct Case {
  const char* name;
  int code;
  std::function<void(Robot&)> setup;  // done to both twins, before the bad input
  std::function<void(Robot&)> bad;    // done to one twin only
};

std::string help_part(const std::string& help, const std::string& key) {
  const size_t at = help.find("; " + key + " ");
  if (at == std::string::npos) return "";
  const size_t from = at + key.size() + 3;
  return help.substr(from, help.find(';', from) - from);
}

// A fall: gravity 80 deg from the chip's z axis (set on both twins).
const strider::ImuSample<float> kTipped{strider::Vec3<float>(0.0f, 9.81f * std::sin(1.4f), 9.81f * std::cos(1.4f)),
                                        strider::Vec3<float>(0.0f, 0.0f, 0.0f), 25.0f};

const strider::ImuSample<float> kLevelPart{strider::Vec3<float>(0.0f, 0.0f, 9.81f), strider::Vec3<float>(0.0f, 0.0f, 0.0f),
                                           25.0f};
// Standing on an 8 deg slope: past the 5 deg `cal level` takes.
const strider::ImuSample<float> kSloped{strider::Vec3<float>(0.0f, 9.81f * std::sin(0.14f), 9.81f * std::cos(0.14f)),
                                        strider::Vec3<float>(0.0f, 0.0f, 0.0f), 25.0f};

std::vector<Case> cases(const strider::RobotModel& m, const std::string& help) {
  auto line = [](std::string s) { return [s](Robot& r) { r.reply(s); }; };
  auto nothing = [](Robot&) {};
  std::vector<Case> out = {
      {"unknown word", 1, nothing, line("dance")},
      {"blanks", 1, nothing, line("   ")},
      {"tab and blank", 1, nothing, line("\t ")},
      {"not a number", 2, nothing, line("walk fast")},
      {"no such word", 2, nothing, line("avoid maybe")},
      {"no such cal step", 2, nothing, line("cal dance")},
      {"too few", 3, nothing, line("vel 100 0")},
      {"too few for avoid", 3, nothing, line("avoid 300")},
      {"too many", 4, nothing, line("stop now")},
      {"too many numbers", 4, nothing, line("speed 10 20")},
      {"walk too fast", 5, nothing, line("walk 600")},
      {"speed", 5, nothing, line("speed 101")},
      {"deadman 0", 5, nothing, line("deadman 0")},
      {"slow before stop", 5, nothing, line("avoid 300 100")},
      {"height far out", 5, nothing, line("height 900")},
      {"no such rate", 5, nothing, line("baud 1234")},
      {"trim joint", 5, line("cal start"), line("cal trim 18 0")},
      {"line too long", 6, nothing, line("walk 10" + std::string(70, ' '))},
      {"control byte", 7, nothing, line("walk \x01 10")},
      {"incomplete line", 8, nothing, [](Robot& r) { r.bytes("walk 30"); }},  // answered at the idle timeout
      {"bad checksum", 9, nothing, line("$speed 40*0154")},
      {"bytes lost", 10, nothing, [](Robot& r) { r.bytes("wal"); r.app.on_bytes_lost(1, r.now_us, r.lines); r.bytes("k 30\r\n"); }},
      {"plain deadman off", 11, nothing, line("deadman off")},
      {"cal step outside", 20, nothing, line("cal trim 1 2")},
      {"cal save outside", 20, nothing, line("cal save")},
      {"walking while calibrating", 21, line("cal start"), line("walk 100")},
      {"store failed", 22, nothing, [](Robot& r) { r.store.fail_at_write = r.store.writes; r.reply("save"); }},
      {"no such gait", 23, nothing, line("gait gallop")},
      {"the other legs' gait", 23, nothing, line(m.leg_count == 6 ? "gait trot" : "gait ripple")},
      {"step height", 25, nothing, line("set step_height 0.5")},
      {"duty", 25, nothing, line("set duty 0.2")},
      {"servo fault", 31,
       [](Robot& r) {
         strider::ServoBoardReport rep;
         rep.faulted = strider::board_bit(0);
         rep.errors = 1;
         r.app.servo_boards(rep, r.now_us, r.lines);
         r.run_ms(500);
       },
       line("walk 80")},
      {"battery critical", 32,
       [](Robot& r) {
         r.battery_code = 573;  // 8.4 V through 20k/10k: a full 2S pack
         r.run_ms(1000);
         r.battery_code = 430;  // 6.3 V: 3.15 V a cell
         r.run_ms(4000);
       },
       line("walk 80")},
      {"fallen", 33,
       [](Robot& r) {
         r.app.set_imu_present(true);
         r.imu = &kTipped;
         r.run_ms(2000);
       },
       line("walk 80")},
      {"cal level walking", 35,
       [](Robot& r) {
         r.app.set_imu_present(true);
         r.imu = &kLevelPart;
         r.run_ms(1000);
       },
       line("cal level")},
      {"cal level on a slope", 36,
       [](Robot& r) {
         r.app.set_imu_present(true);
         r.imu = &kSloped;
         r.reply("stop");
         r.run_ms(5000);  // mammal8's walk takes over 3 s to finish its stop
       },
       line("cal level")},  // the reply a second later, within the 2 s the twins run
  };
  // err 24: past what the legs reach, within the parser's range.
  const std::string heights = help_part(help, "height");
  const int height_max = std::stoi(heights.substr(heights.find("..") + 2));
  const int height_min = std::stoi(heights);
  if (height_max < 400) out.push_back({"height past the reach", 24, nothing, line("height " + std::to_string(height_max + 1))});
  if (height_min > 10) out.push_back({"height under the reach", 24, nothing, line("height " + std::to_string(height_min - 1))});
  out.push_back({"pose past the reach", 24, nothing, line("pose 30 30 30")});
  return out;
}

TEST(ErrorReplies, NameWhatIsValidAndChangeNothing) {
  int checked = 0;
  std::set<int> codes;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    std::string help;
    {
      Robot probe(*m);
      probe.run_ms(100);
      help = probe.reply("help");
    }
    const std::string gaits = help_part(help, "gaits");
    ASSERT_FALSE(gaits.empty()) << help;
    for (const Case& c : cases(*m, help)) {
      SCOPED_TRACE(std::string(m->name) + ": " + c.name);
      Robot a(*m), b(*m);
      for (Robot* r : {&a, &b}) {
        r->run_ms(3000);  // standing
        r->reply("$deadman off*cb77");
        r->reply("walk 60");
        r->run_ms(1000);
        c.setup(*r);
      }
      const size_t before = a.lines.sent.size();
      c.bad(a);
      // Nothing changed: the same frames over the next 2 s, the same answers.
      a.frames.clear();
      b.frames.clear();
      a.run_ms(2000);
      b.run_ms(2000);
      EXPECT_EQ(a.frames, b.frames);
      std::vector<std::string> replies;
      for (size_t i = before; i < a.lines.sent.size(); ++i)
        if (a.lines.sent[i].rfind("info", 0) != 0) replies.push_back(a.lines.sent[i]);
      ASSERT_EQ(replies.size(), 1u) << (replies.empty() ? "(none)" : replies.back());
      ErrReply e;
      ASSERT_TRUE(parse_err(replies[0], &e)) << replies[0];
      EXPECT_EQ(e.code, c.code) << replies[0];
      EXPECT_TRUE(doc_names(e.code, e.reason)) << replies[0] << "\nrow: " << doc_row(e.code);
      if (e.code == 23) {
        EXPECT_EQ(e.hint, gaits) << replies[0];
      }
      if (e.code == 24 && e.reason == "height refused") {
        EXPECT_EQ(e.hint, help_part(help, "height") + " with the body level");
      }
      codes.insert(e.code);
      EXPECT_EQ(a.state(), b.state());
      ++checked;
    }
  }
  std::printf("%d erroneous inputs on %d models, codes", checked, int(sizeof(strider::kAllRobots) / sizeof(strider::kAllRobots[0])));
  for (int c : codes) std::printf(" %d", c);
  std::printf("\n");
  // Every code a RobotApp can answer (30 is the firmware's, at power-up).
  EXPECT_EQ(codes, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 20, 21, 22, 23, 24, 25, 31, 32, 33, 35, 36}));
}

// Seeded random operator input on every model: every err reply has its
// form and a row in the doc, whatever the line.
TEST(ErrorReplies, RandomInputGetsHints) {
  int errors = 0;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    Robot r(*m);
    r.run_ms(3000);
    strider::Prng rng(0xE1100000u + uint32_t(m->kind));
    for (int k = 0; k < 400; ++k) {
      r.bytes(strider_test::random_operator_command([&] { return rng.next_u32(); }));
      r.run_ms(40);
    }
    for (const std::string& l : r.lines.sent) {
      if (l.rfind("err", 0) != 0) continue;
      ++errors;
      ErrReply e;
      EXPECT_TRUE(parse_err(l, &e)) << m->name << ": " << l;
      EXPECT_TRUE(doc_names(e.code, e.reason)) << m->name << ": " << l;
    }
  }
  std::printf("%d err replies checked\n", errors);
  EXPECT_GT(errors, 100);
}

}  // namespace
