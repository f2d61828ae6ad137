// The firmware's servo outputs, tick by tick, against a recorded reference:
// each model's firmware ELF on the virtual Mega runs one scripted session
// (stand up, walk, turn, a combined velocity, stop, a second gait, a body
// pose, strafe, stop) for 900 ticks, and every PCA9685 output it writes is
// compared with test/e2e/servo_traces/<model>.txt.
//
// The reference was recorded from the firmware as it was before a change that
// must not change behaviour (a refactor): equal scalars must give the same
// outputs byte for byte. A reference recorded from a float firmware and run
// against a fixed-point one (or the other way round) may differ by one
// PCA9685 count per output, the rounding of the other scalar's IK.
//
// STRIDER_TRACE_RECORD=1 rewrites the references from the firmware under test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "virtual_mega.h"

using strider_vmega::RunStatus;
using strider_vmega::VirtualMega;

namespace {

constexpr int kTicks = 900;
constexpr uint64_t kTickUs = 20000;
constexpr uint64_t kBootTimeoutUs = 8000000;
// Commands go out this long after the tick's reference time: inside the
// period, after the tick's own frame, before the next tick reads the port.
constexpr uint64_t kSendOffsetUs = 8000;
// PCA9685 writes closer than this belong to one frame.
constexpr uint64_t kFrameGapUs = 5000;

std::string firmware_dir() {
  const char* dir = std::getenv("STRIDER_FIRMWARE_DIR");
  return dir && *dir ? std::string(dir) : std::string(STRIDER_FIRMWARE_DIR);
}

bool is_hexapod(const std::string& model) { return model == "hexapod18"; }

// The scalar every firmware computes in (src/firmware_main.h).
constexpr const char* kFirmwareScalar = "fixed";

// The session, one line per tick that sends something. Moving commands are
// repeated every half second (the deadman stops a robot left without one for
// a second).
std::map<int, std::string> script(const std::string& model) {
  std::map<int, std::string> s;
  auto hold = [&](int from, int to, const std::string& line) {
    for (int t = from; t < to; t += 25) s[t] = line;
  };
  hold(200, 350, "walk 60");
  hold(350, 450, "turn 30");
  hold(450, 550, "vel 40 20 10");
  s[550] = "stop";
  s[580] = is_hexapod(model) ? "gait ripple" : "gait trot";
  hold(600, 700, "walk 80");
  s[700] = "stop";
  s[730] = "pose 5 -5 10";
  hold(780, 860, "strafe -40");
  s[860] = "stop";
  return s;
}

struct Trace {
  std::string scalar;
  // tick -> channel -> PCA9685 counts (0 = off), the outputs that changed.
  std::map<int, std::map<int, int>> changes;
};

std::string trace_path(const std::string& model) {
  return std::string(STRIDER_TRACE_DIR) + "/" + model + ".txt";
}

bool read_trace(const std::string& path, Trace* t) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      const size_t at = line.find("scalar=");
      if (at != std::string::npos) t->scalar = line.substr(at + 7);
      continue;
    }
    std::istringstream words(line);
    int tick;
    words >> tick;
    std::string pair;
    while (words >> pair) {
      const size_t colon = pair.find(':');
      t->changes[tick][std::stoi(pair.substr(0, colon))] = std::stoi(pair.substr(colon + 1));
    }
  }
  return true;
}

void write_trace(const std::string& path, const std::string& model, const Trace& t) {
  std::ofstream out(path);
  out << "# Servo outputs of the " << model << " firmware over " << kTicks
      << " ticks of test_servo_trace.cpp's session: scalar=" << t.scalar << "\n";
  out << "# tick, then channel:counts for each output written in that tick (counts = OFF - ON, 0 = off)\n";
  for (const auto& tick : t.changes) {
    out << tick.first;
    for (const auto& ch : tick.second) out << ' ' << ch.first << ':' << ch.second;
    out << '\n';
  }
}

// Runs the model's firmware through the session; the outputs by tick.
bool record(const std::string& model, Trace* t, std::string* error) {
  VirtualMega mega;
  strider_vmega::Options o;
  o.elf_path = firmware_dir() + "/strider_firmware_" + model + ".elf";
  o.sonar_range_mm = 2000;  // open space: avoidance does not slow the walk
  if (!mega.load(o, error)) return false;
  // Tick 0 is the tick of the first output written after the start-up.
  const uint64_t boot_end = mega.now_us() + kBootTimeoutUs;
  while (mega.pulse_log().empty()) {
    if (mega.now_us() >= boot_end || mega.run_for_us(1000) != RunStatus::kOk) {
      *error = "no servo output within the start-up time";
      return false;
    }
  }
  const uint64_t t0 = mega.pulse_log().front().time_us;
  const auto lines = script(model);
  for (int tick = 0; tick < kTicks; ++tick) {
    const auto it = lines.find(tick);
    if (it != lines.end()) {
      if (mega.run_until_us(t0 + tick * kTickUs + kSendOffsetUs) != RunStatus::kOk) return false;
      mega.send(0, it->second + "\n");
    }
  }
  if (mega.run_until_us(t0 + kTicks * kTickUs) != RunStatus::kOk) {
    *error = "the firmware stopped";
    return false;
  }
  // Writes grouped into frames; a frame's tick is the period it starts in.
  const double tick_us = mega.board(0).tick_us();
  uint64_t frame_start = 0, last = 0;
  for (const auto& c : mega.pulse_log()) {
    if (c.time_us - last > kFrameGapUs || frame_start == 0) frame_start = c.time_us;
    last = c.time_us;
    const int tick = int((frame_start - t0 + kTickUs / 4) / kTickUs);
    if (tick >= kTicks) break;
    t->changes[tick][c.channel] = int(std::lround(c.width_us / tick_us));
  }
  t->scalar = kFirmwareScalar;
  return true;
}

class ServoTrace : public ::testing::TestWithParam<const char*> {};

TEST_P(ServoTrace, OutputsMatchTheRecordedReference) {
  const std::string model = GetParam();
  Trace now;
  std::string error;
  ASSERT_TRUE(record(model, &now, &error)) << error;
  ASSERT_GT(now.changes.size(), size_t(400)) << "the session moved the robot";
  const char* rec = std::getenv("STRIDER_TRACE_RECORD");
  if (rec && std::string(rec) == "1") {
    write_trace(trace_path(model), model, now);
    GTEST_SKIP() << "recorded " << trace_path(model);
  }
  Trace ref;
  ASSERT_TRUE(read_trace(trace_path(model), &ref)) << "no reference " << trace_path(model);
  const int tolerance = ref.scalar == now.scalar ? 0 : 1;
  // Outputs compared tick by tick as levels (a write of an unchanged value
  // is no change), channel by channel.
  std::map<int, int> ref_level, now_level;
  int worst = 0, compared = 0, first_bad_tick = -1;
  for (int tick = 0; tick < kTicks; ++tick) {
    auto apply = [&](const Trace& t, std::map<int, int>& level) {
      const auto it = t.changes.find(tick);
      if (it != t.changes.end())
        for (const auto& ch : it->second) level[ch.first] = ch.second;
    };
    apply(ref, ref_level);
    apply(now, now_level);
    for (const auto& ch : ref_level) {
      const auto n = now_level.find(ch.first);
      const int diff = n == now_level.end() ? 4096 : std::abs(n->second - ch.second);
      if (diff > tolerance && first_bad_tick < 0) first_bad_tick = tick;
      worst = std::max(worst, diff);
      ++compared;
    }
    if (now_level.size() != ref_level.size() && first_bad_tick < 0) first_bad_tick = tick;
  }
  EXPECT_LE(worst, tolerance) << model << ": reference scalar=" << ref.scalar << ", firmware scalar=" << now.scalar
                              << ", first difference at tick " << first_bad_tick;
  EXPECT_EQ(first_bad_tick, -1);
  std::printf("%s: %d output samples, largest difference %d counts (reference %s, firmware %s)\n", model.c_str(),
              compared, worst, ref.scalar.c_str(), now.scalar.c_str());
}

INSTANTIATE_TEST_SUITE_P(Models, ServoTrace,
                         ::testing::Values("sprawl8", "mammal8", "dog12", "hexapod18", "spider12"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return std::string(i.param); });

}  // namespace
