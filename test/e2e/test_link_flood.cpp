// End-to-end: the command link under load, on the real firmware ELFs on the
// virtual Mega, with vbench's link floods (docs/reliability.md, "The command
// link under load"):
// - RC bytes back to back at 115200 baud, on USB and on Bluetooth: no reset,
//   the control tick keeps its period;
// - 1,000 random lines a second at 115200: no command runs that was not
//   sent whole, lines that lost bytes are answered `err 10`;
// - checked lines (`$...*hhhh`, CRC-16) and the deliberate `deadman off`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "control/crc.h"
#include "virtual_mega.h"

using strider_vmega::RunStatus;
using strider_vmega::VirtualMega;

namespace {

constexpr uint64_t kBootTimeoutUs = 8000000;

std::string elf_path(const std::string& model) {
  const char* dir = std::getenv("STRIDER_FIRMWARE_DIR");
  return (dir && *dir ? std::string(dir) : std::string(STRIDER_FIRMWARE_DIR)) + "/strider_firmware_" + model + ".elf";
}

// `text*hhhh`: a checked reply; `$text*hhhh`: a checked line (docs/protocol.md).
std::string reply_checked(const std::string& text) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "*%04x", strider::crc16_ccitt(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
  return text + buf;
}
std::string checked(const std::string& text) { return "$" + reply_checked(text); }

std::map<std::string, std::string> fields(const std::string& line) {
  std::map<std::string, std::string> f;
  std::istringstream in(line);
  std::string word;
  while (in >> word) {
    const size_t eq = word.find('=');
    if (eq != std::string::npos) f[word.substr(0, eq)] = word.substr(eq + 1);
  }
  return f;
}

bool starts(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool is_reply(const std::string& l) { return starts(l, "ok") || starts(l, "err"); }

// One firmware on the virtual Mega, lines collected per UART.
class Board {
 public:
  explicit Board(const std::string& model) : model_(model) {}

  bool boot(std::string* error) {
    strider_vmega::Options o;
    o.elf_path = elf_path(model_);
    o.sonar_range_mm = 2000;  // open space ahead
    if (!mega_.load(o, error)) return false;
    return wait_ready(error);
  }
  bool wait_ready(std::string* error) {
    const std::string want = "info strider " + model_ + " ready";
    if (wait_for(1, [&](const std::string& l) { return starts(l, want.c_str()); }, kBootTimeoutUs).empty()) {
      *error = "no `" + want + "`";
      return false;
    }
    return run_for(300000);  // the other port's boot lines
  }

  bool run_for(uint64_t us) {
    const uint64_t end = mega_.now_us() + us;
    while (mega_.now_us() < end) {
      if (mega_.run_for_us(std::min<uint64_t>(2000, end - mega_.now_us())) != RunStatus::kOk) return false;
      collect();
    }
    return true;
  }
  void collect() {
    for (int u = 0; u < 2; ++u) {
      pending_[u] += mega_.take_output(u);
      size_t nl;
      while ((nl = pending_[u].find('\n')) != std::string::npos) {
        std::string l = pending_[u].substr(0, nl);
        if (!l.empty() && l.back() == '\r') l.pop_back();
        lines_[u].push_back(l);
        pending_[u].erase(0, nl + 1);
      }
    }
  }
  template <typename Pred>
  std::string wait_for(int u, Pred pred, uint64_t timeout_us) {
    const uint64_t end = mega_.now_us() + timeout_us;
    for (;;) {
      while (seen_[u] < lines_[u].size()) {
        const std::string& l = lines_[u][seen_[u]++];
        if (pred(l)) return l;
      }
      if (mega_.now_us() >= end || !run_for(2000)) return std::string();
    }
  }
  //! Sends a line, returns its reply (the next ok/err line on that port).
  std::string command(int u, const std::string& line) {
    seen_[u] = lines_[u].size();
    mega_.send(u, line + "\n");
    return wait_for(u, is_reply, 1500000);
  }
  std::map<std::string, std::string> status(int u) { return fields(command(u, "status")); }

  VirtualMega& mega() { return mega_; }
  const std::vector<std::string>& lines(int u) const { return lines_[u]; }
  std::string transcript(int u, size_t from, size_t max_lines = 40) const {
    std::string t;
    for (size_t i = from; i < lines_[u].size() && i < from + max_lines; ++i) t += "  " + lines_[u][i] + "\n";
    return t;
  }

 private:
  std::string model_;
  VirtualMega mega_;
  std::string pending_[2];
  std::vector<std::string> lines_[2];
  size_t seen_[2] = {0, 0};
};

// The servo pulses keep changing while the robot walks: count the 100 ms
// windows of [from_us, to_us) in which no frame changed anything.
int still_windows(VirtualMega& mega, uint64_t from_us, uint64_t to_us) {
  std::vector<int> changes(size_t((to_us - from_us) / 100000), 0);
  for (const auto& c : mega.pulse_log())
    if (c.time_us >= from_us && c.time_us < to_us && size_t((c.time_us - from_us) / 100000) < changes.size())
      ++changes[size_t((c.time_us - from_us) / 100000)];
  return int(std::count(changes.begin(), changes.end(), 0));
}

class LinkFlood : public ::testing::TestWithParam<std::string> {};

// RC bytes back to back at 115200 baud (the issue: a watchdog reset every
// 0.54 s), on USB and then on Bluetooth set to 115200: over 10,000 bytes a
// second, more than the firmware can act on while it walks, so the receive buffer
// overflows. Nothing resets, and the control tick keeps its period: walking
// (deadman 60 s), the legs move in every 100 ms of the flood, and no tick is
// late. Afterwards the link answers again.
TEST_P(LinkFlood, RcBytesBackToBackAt115200) {
  Board b(GetParam());
  std::string error;
  ASSERT_TRUE(b.boot(&error)) << error;
  ASSERT_TRUE(b.run_for(4000000));  // soft start, standing up
  // Bluetooth at 115200 after a save and a reset.
  ASSERT_EQ(b.command(1, "baud 115200"), "ok baud rate=115200 after save and reset");
  ASSERT_EQ(b.command(1, "save"), "ok saved");
  b.mega().reset();
  ASSERT_TRUE(b.wait_ready(&error)) << error;
  ASSERT_TRUE(b.run_for(4000000));
  ASSERT_EQ(b.mega().baud(1), b.mega().baud(0));
  // The deadman at its longest: the walk outlasts each flood's 4 s whatever
  // the robot makes of the bytes.
  ASSERT_EQ(b.command(1, "deadman 60000"), "ok deadman ms=60000");

  for (int u : {0, 1}) {
    SCOPED_TRACE(u == 0 ? "USB" : "Bluetooth");
    ASSERT_EQ(b.command(u, "walk 60"), "ok move vx=60.0 vy=0.0 wz=0.0");
    ASSERT_TRUE(b.run_for(1000000));
    ASSERT_EQ(b.status(u)["overruns"], "0");
    const size_t from = b.lines(u).size();
    strider_vmega::Flood f;
    f.units = {"F"};
    f.per_s = 0;  // back to back
    f.duration_us = 4000000;
    const uint64_t t0 = b.mega().now_us();
    b.mega().clear_pulse_log();
    b.mega().flood(u, f);
    ASSERT_TRUE(b.run_for(4000000));
    const auto sent = b.mega().flood_stats(u);
    // At least the 10,000 bytes a second (simavr's receiver adds each
    // byte's interrupt latency to its 85 us: the virtual wire carries ~91 %).
    EXPECT_GE(sent.bytes, 4u * 10000u) << "not back to back";
    EXPECT_EQ(b.mega().unexpected_resets(), 0) << b.transcript(u, from);
    EXPECT_EQ(still_windows(b.mega(), t0, t0 + 4000000), 0) << "the walk stalled: no tick";
    ASSERT_TRUE(b.run_for(500000));  // the receive buffer drains, the link idles
    auto st = b.status(u);
    EXPECT_EQ(st["mode"], "walking") << b.transcript(u, from);
    EXPECT_EQ(st["overruns"], "0");
    EXPECT_LT(std::atoi(st["tick_max_us"].c_str()), 20000);
    EXPECT_EQ(b.command(u, "stop"), "ok stop");
    ASSERT_TRUE(b.run_for(1000000));
  }
}

// A random command line whose `ok` reply names its values, so that every ok
// tells which line it answers (err replies may answer any).
struct SentLine {
  std::string text;  // without the line end
  std::string ok;    // its ok reply, or its prefix when prefix_only
  bool prefix_only = false;
};

SentLine random_line(std::mt19937& rng) {
  auto num = [&](int lo, int hi) { return lo + int(rng() % uint32_t(hi - lo + 1)); };
  auto d = [](int v) { return std::to_string(v) + ".0"; };
  SentLine s;
  switch (rng() % 9) {
    case 0: {
      const int v = num(-500, 500);
      s.text = "walk " + std::to_string(v);
      s.ok = "ok move vx=" + d(v) + " vy=0.0 wz=0.0";
      break;
    }
    case 1: {
      const int v = num(-500, 500);
      s.text = "strafe " + std::to_string(v);
      s.ok = "ok move vx=0.0 vy=" + d(v) + " wz=0.0";
      break;
    }
    case 2: {
      const int v = num(-360, 360);
      s.text = "turn " + std::to_string(v);
      s.ok = "ok move vx=0.0 vy=0.0 wz=" + d(v);
      break;
    }
    case 3: {
      const int x = num(-500, 500), y = num(-500, 500), z = num(-360, 360);
      s.text = "vel " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z);
      s.ok = "ok move vx=" + d(x) + " vy=" + d(y) + " wz=" + d(z);
      break;
    }
    case 4: {
      const int v = num(0, 100);
      s.text = "speed " + std::to_string(v);
      s.ok = "ok speed pct=" + std::to_string(v);
      break;
    }
    case 5: {
      const int v = num(100, 60000);
      s.text = "deadman " + std::to_string(v);
      s.ok = "ok deadman ms=" + std::to_string(v);
      break;
    }
    case 6: {
      const int r = num(-30, 30), p = num(-30, 30), y = num(-30, 30);
      s.text = "pose " + std::to_string(r) + " " + std::to_string(p) + " " + std::to_string(y);
      s.ok = "ok pose roll=" + d(r) + " pitch=" + d(p) + " yaw=" + d(y);
      break;
    }
    case 7:
      s.text = "stop";
      s.ok = "ok stop";
      break;
    default:
      s.text = "status";
      s.ok = "ok status ";
      s.prefix_only = true;
      break;
  }
  return s;
}

// 1,000 random lines a second at 115200 baud on USB for 3 s: far more than
// the replies can carry back, so the firmware falls behind and its receive
// buffer overflows. Every ok must answer a line that was sent, in the order
// sent (a line glued from two, `deadman ms=0` or `move vx=500` from pieces,
// fails this); the lines that lost bytes are answered err 10.
TEST_P(LinkFlood, RandomLinesThousandPerSecond) {
  Board b(GetParam());
  std::string error;
  ASSERT_TRUE(b.boot(&error)) << error;
  ASSERT_TRUE(b.run_for(4000000));
  std::mt19937 rng(2024u + uint32_t(GetParam().size()));
  std::vector<SentLine> sent;
  strider_vmega::Flood f;
  for (int i = 0; i < 3000; ++i) {
    sent.push_back(random_line(rng));
    f.units.push_back(sent.back().text + "\n");
  }
  f.per_s = 1000;
  f.count = f.units.size();
  const size_t from = b.lines(0).size();
  b.mega().flood(0, f);
  ASSERT_TRUE(b.run_for(3000000));
  for (int k = 0; k < 50 && b.mega().pending_input(0) > 0; ++k) ASSERT_TRUE(b.run_for(100000));
  ASSERT_TRUE(b.run_for(1500000));  // what is left in the buffers, answered
  EXPECT_EQ(b.mega().flood_stats(0).units, sent.size());

  size_t next = 0;  // the sent line after the last one answered ok
  int oks = 0, errs = 0, lost = 0, foreign = 0, unsent = 0;
  std::set<std::string> all_oks;  // what any line sent would be answered
  for (const SentLine& l : sent)
    if (!l.prefix_only) all_oks.insert(l.ok);
  for (size_t i = from; i < b.lines(0).size(); ++i) {
    const std::string& l = b.lines(0)[i];
    if (starts(l, "info")) continue;
    ASSERT_TRUE(is_reply(l)) << "not a reply: " << l;
    if (starts(l, "err")) {
      ++errs;
      lost += starts(l, "err 10 ");
      continue;
    }
    ++oks;
    unsent += !starts(l, "ok status ") && all_oks.count(l) == 0;
    size_t k = next;
    while (k < sent.size() && !(sent[k].prefix_only ? starts(l, sent[k].ok.c_str()) : l == sent[k].ok)) ++k;
    if (k == sent.size()) {
      if (++foreign <= 5) ADD_FAILURE() << "executed a command nobody sent: " << l << "\n" << b.transcript(0, i - 5, 11);
      continue;
    }
    next = k + 1;
  }
  std::printf("%s: 3000 lines sent at 1000 lines/s: %d ok (%d out of order, %d answer no line sent), %d err "
              "(%d err 10 bytes lost)\n",
              GetParam().c_str(), oks, foreign, unsent, errs, lost);
  EXPECT_EQ(foreign, 0);
  EXPECT_GT(oks, 0);
  EXPECT_GT(lost, 0) << "the flood was meant to overflow the receive buffer";
  EXPECT_EQ(b.mega().unexpected_resets(), 0);
  // The link is whole again afterwards.
  EXPECT_EQ(b.command(0, "speed 37"), "ok speed pct=37");
  EXPECT_EQ(b.command(0, "deadman 1000"), "ok deadman ms=1000");
}

INSTANTIATE_TEST_SUITE_P(Models, LinkFlood, ::testing::Values("sprawl8", "hexapod18"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

// Checked lines: `$text*hhhh` with the CRC-16/CCITT-FALSE of text, answered
// with a checked reply; a wrong check is err 9 and changes nothing. Plain
// lines keep working as the phone apps send them.
TEST(LinkChecked, GoodAndBadChecksum) {
  Board b("sprawl8");
  std::string error;
  ASSERT_TRUE(b.boot(&error)) << error;
  ASSERT_TRUE(b.run_for(3000000));
  for (int u : {1, 0}) {
    SCOPED_TRACE(u);
    EXPECT_EQ(b.command(u, checked("speed 40")), reply_checked("ok speed pct=40"));
    EXPECT_EQ(b.command(u, checked("walk 120")), reply_checked("ok move vx=120.0 vy=0.0 wz=0.0"));
    EXPECT_EQ(b.command(u, checked("stop")), reply_checked("ok stop"));
    // A digit changed after the check was made, or the check changed: err 9,
    // nothing applied.
    std::string bad = checked("speed 40");
    bad[7] = '9';
    EXPECT_EQ(b.command(u, bad), reply_checked("err 9 bad checksum: $text*hhhh, hhhh the CRC-16 of text"));
    std::string bad_check = checked("speed 70");
    bad_check.back() = bad_check.back() == '0' ? '1' : '0';
    EXPECT_EQ(b.command(u, bad_check), reply_checked("err 9 bad checksum: $text*hhhh, hhhh the CRC-16 of text"));
    // A checked line that lost its end is no plain line.
    EXPECT_EQ(b.command(u, "$speed 70"), reply_checked("err 9 bad checksum: $text*hhhh, hhhh the CRC-16 of text"));
    EXPECT_EQ(b.status(u)["speed"], "40");
    // Uppercase hex digits are as good; errors of a checked line are checked.
    std::string upper = checked("speed 41");
    for (size_t i = upper.size() - 4; i < upper.size(); ++i) upper[i] = char(std::toupper(upper[i]));
    EXPECT_EQ(b.command(u, upper), reply_checked("ok speed pct=41"));
    EXPECT_EQ(b.command(u, checked("speed 400")), reply_checked("err 5 out of range: speed 0..100"));
    // The long status reply carries its check too.
    const std::string st = b.command(u, checked("status"));
    ASSERT_GT(st.size(), 5u);
    EXPECT_EQ(st, reply_checked(st.substr(0, st.size() - 5)));
    // Plain lines: plain replies.
    EXPECT_EQ(b.command(u, "speed 50"), "ok speed pct=50");
  }
  EXPECT_EQ(b.mega().unexpected_resets(), 0);
}

// The deadman is disarmed only by `deadman off` in a checked line: no
// number and no plain line does it, so neither a glued line nor a typo can.
TEST(LinkChecked, DeadmanOffNeedsTheDeliberateForm) {
  Board b("sprawl8");
  std::string error;
  ASSERT_TRUE(b.boot(&error)) << error;
  ASSERT_TRUE(b.run_for(4000000));
  EXPECT_EQ(b.command(1, "deadman 0"), "err 5 out of range: deadman 1..60000, off only as a checked line");
  EXPECT_EQ(b.command(1, "deadman off"), "err 11 checksum required: $deadman off*cb77, a checked line");
  EXPECT_EQ(b.command(1, checked("deadman 0")),
            reply_checked("err 5 out of range: deadman 1..60000, off only as a checked line"));
  EXPECT_EQ(b.status(1)["deadman_ms"], "1000");
  EXPECT_EQ(b.command(1, checked("deadman off")), reply_checked("ok deadman off"));
  EXPECT_EQ(b.status(1)["deadman_ms"], "0");
  // Walking without keep-alives: no deadman stop.
  ASSERT_EQ(b.command(1, "walk 80"), "ok move vx=80.0 vy=0.0 wz=0.0");
  const size_t from = b.lines(1).size();
  ASSERT_TRUE(b.run_for(3000000));
  for (size_t i = from; i < b.lines(1).size(); ++i) EXPECT_NE(b.lines(1)[i], "info deadman stop");
  EXPECT_EQ(b.status(1)["mode"], "walking");
  // Armed again by any number.
  EXPECT_EQ(b.command(1, "deadman 500"), "ok deadman ms=500");
  EXPECT_FALSE(b.wait_for(1, [](const std::string& l) { return l == "info deadman stop"; }, 1500000).empty());
}

}  // namespace
