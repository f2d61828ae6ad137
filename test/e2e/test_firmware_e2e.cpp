// End-to-end: the real firmware ELF of each model on the virtual Mega
// (tools/vbench), driven through the Bluetooth UART like a phone would.
// Expected pulses come from the library independently of the firmware: the
// model's standing feet through AnyLeg IK, the channel map and the servo map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "control/channel_map.h"
#include "control/pca9685_timing.h"
#include "control/servo_map.h"
#include "control/settings.h"
#include "kinematics/any_leg.h"
#include "random_commands.h"
#include "robots/all_robots.h"
#include "virtual_mega.h"

using strider_vmega::RunStatus;
using strider_vmega::VirtualMega;

namespace {

constexpr uint64_t kBootTimeoutUs = 8000000;   // start-up incl. the velocity-limit search
constexpr uint64_t kSettleTimeoutUs = 8000000;  // soft start and standing up
constexpr double kTickToleranceUs = 2.5;        // in PCA9685 counts: Fixed-point IK vs float

// The CMake build's ELFs, or another build's (the PlatformIO one) when the
// environment variable STRIDER_FIRMWARE_DIR names their folder.
std::string firmware_dir() {
  const char* dir = std::getenv("STRIDER_FIRMWARE_DIR");
  return dir && *dir ? std::string(dir) : std::string(STRIDER_FIRMWARE_DIR);
}

std::string elf_path(const std::string& model) {
  return firmware_dir() + "/strider_firmware_" + model + ".elf";
}

std::map<std::string, std::string> status_fields(const std::string& line) {
  std::map<std::string, std::string> f;
  std::istringstream in(line);
  std::string word;
  while (in >> word) {
    const size_t eq = word.find('=');
    if (eq != std::string::npos) f[word.substr(0, eq)] = word.substr(eq + 1);
  }
  return f;
}

// Drives one firmware: line collection, waiting, expectations from the library.
class Robot {
 public:
  explicit Robot(const std::string& model) : name_(model), model_(strider::find_robot(model.c_str())) {}

  bool boot(std::string* error) { return load(error) && wait_ready(error); }

  // A fresh virtual Mega with the servo boards at `boards`, not yet run.
  bool load(std::string* error, const std::vector<uint8_t>& boards = {0x40, 0x41}) {
    strider_vmega::Options o;
    o.elf_path = elf_path(name_);
    o.sonar_range_mm = 2000;  // open space ahead: avoidance lets the robot walk
    o.pca_addresses = boards;
    if (!model_) {
      *error = "unknown model";
      return false;
    }
    return mega_.load(o, error);
  }

  bool wait_ready(std::string* error) {
    const std::string want = "info strider " + name_ + " ready";
    if (wait_for_line([&](const std::string& l) { return l.rfind(want, 0) == 0; }, kBootTimeoutUs).empty()) {
      *error = "no `" + want + "` within " + std::to_string(kBootTimeoutUs / 1000000) + " s";
      return false;
    }
    return true;
  }

  // Runs in 2 ms steps; collects UART1 lines into lines_.
  bool run_for(uint64_t us) {
    const uint64_t end = mega_.now_us() + us;
    while (mega_.now_us() < end) {
      const uint64_t step = std::min<uint64_t>(2000, end - mega_.now_us());
      if (mega_.run_for_us(step) != RunStatus::kOk) return false;
      collect();
    }
    return true;
  }

  void collect() {
    pending_ += mega_.take_output(1);
    size_t nl;
    while ((nl = pending_.find('\n')) != std::string::npos) {
      std::string l = pending_.substr(0, nl);
      if (!l.empty() && l.back() == '\r') l.pop_back();
      lines_.push_back(l);
      pending_.erase(0, nl + 1);
    }
  }

  // First new line satisfying pred within timeout_us ("" if none).
  template <typename Pred>
  std::string wait_for_line(Pred pred, uint64_t timeout_us) {
    const uint64_t end = mega_.now_us() + timeout_us;
    for (;;) {
      while (seen_ < lines_.size()) {
        const std::string& l = lines_[seen_++];
        if (pred(l)) return l;
      }
      if (mega_.now_us() >= end || !run_for(2000)) return std::string();
    }
  }

  // Sends a text line; returns its reply (the next ok/err line).
  std::string command(const std::string& line, uint64_t timeout_us = 1500000) {
    seen_ = lines_.size();
    mega_.send(1, line + "\n");
    return wait_for_line([](const std::string& l) { return l.rfind("ok", 0) == 0 || l.rfind("err", 0) == 0; },
                         timeout_us);
  }

  std::map<std::string, std::string> status() {
    seen_ = lines_.size();
    mega_.send(1, "status\n");
    return status_fields(wait_for_line([](const std::string& l) { return l.rfind("ok status", 0) == 0; }, 1500000));
  }

  // Runs until no channel changed for quiet_us (or timeout_us).
  bool settle(uint64_t quiet_us, uint64_t timeout_us) {
    const uint64_t end = mega_.now_us() + timeout_us;
    while (mega_.now_us() < end) {
      const auto& log = mega_.pulse_log();
      const uint64_t last = log.empty() ? 0 : log.back().time_us;
      if (!log.empty() && mega_.now_us() - last >= quiet_us) return true;
      if (!run_for(20000)) return false;
    }
    return false;
  }

  // The library's standing pulses [us] by global channel, with trims [0.1 deg].
  std::map<int, double> expected_standing(const int16_t* trim_decideg = nullptr) const {
    std::map<int, double> out;
    strider::Pca9685Timing timing;
    timing.configure(strider::kPca9685NominalOscHz, 50);
    const double tick_us = mega_.board(0).tick_us();
    for (uint8_t i = 0; i < model_->leg_count; ++i) {
      strider::AnyLeg<float> leg;
      EXPECT_TRUE(strider::AnyLeg<float>::from_model(*model_, i, leg));
      strider::AnyLeg<float>::Joints q;
      strider::Vec3<float> reached;
      const strider::IkStatus s = leg.ik_body(model_->legs[i].stand_mm, q, reached);
      EXPECT_NE(s, strider::IkStatus::kUnreachable) << "leg " << int(i);
      for (uint8_t j = 0; j < model_->dof(); ++j) {
        const auto ch = strider::make_joint_channel<float>(*model_, i, j);
        const int k = i * model_->dof() + j;
        const float trim = trim_decideg ? strider::trim_from_decideg<float>(trim_decideg[k]) : 0.0f;
        const strider::ServoCommand cmd = strider::map_joint(ch, q[j], trim, timing);
        out[ch.channel] = cmd.ticks * tick_us;
      }
    }
    return out;
  }

  // Pulse range [us] of every joint's channel.
  std::map<int, std::pair<double, double>> pulse_limits() const {
    std::map<int, std::pair<double, double>> out;
    for (uint8_t i = 0; i < model_->leg_count; ++i)
      for (uint8_t j = 0; j < model_->dof(); ++j) {
        const auto ch = strider::make_joint_channel<float>(*model_, i, j);
        const double per_rad = double(ch.us_per_rad);
        out[ch.channel] = {ch.min_pulse_us + double(ch.min_rad) * per_rad,
                           ch.min_pulse_us + double(ch.max_rad) * per_rad};
      }
    return out;
  }

  struct Motion {
    double joint_speed_us_s = 0;  // mean |d pulse / dt| summed over all channels [us/s]
    double period_s = 0;          // step period of the busiest channel [s], 0 if unclear
    double walked_mm_s = 0;       // forward body speed from the feet on the ground [mm/s]
  };

  // Body-frame feet [mm] from the outputs: pulses back to joint angles
  // (channel_map.h's joint_from_pulse) and the leg's FK.
  std::vector<strider::Vec3<float>> feet() const {
    std::vector<strider::Vec3<float>> out;
    for (uint8_t i = 0; i < model_->leg_count; ++i) {
      strider::AnyLeg<float> leg;
      strider::AnyLeg<float>::from_model(*model_, i, leg);
      strider::AnyLeg<float>::Joints q;
      for (uint8_t j = 0; j < model_->dof(); ++j) {
        const auto ch = strider::make_joint_channel<float>(*model_, i, j);
        q[j] = float(strider::joint_from_pulse(ch, mega_.pulse_us(ch.channel)));
      }
      out.push_back(leg.fk_body(q));
    }
    return out;
  }

  // Samples every output each 20 ms for duration_us after settle_us of ramp,
  // repeating the key every 200 ms as the app does for a held button.
  Motion measure(uint64_t settle_us, uint64_t duration_us, const std::string& keep_alive) {
    const int n = mega_.board_count() * 16;
    std::vector<std::vector<double>> series(static_cast<size_t>(n));
    uint64_t next_key = mega_.now_us();
    const uint64_t start = mega_.now_us() + settle_us;
    const uint64_t end = start + duration_us;
    // Feet on the ground (within 3 mm of the lowest) move backwards at the
    // body's speed: their displacement between samples, per sample (NaN: no
    // foot down). Summed over whole step periods only: a gait that shifts
    // its body moves the stance feet back and forth within a period, which
    // cancels over whole periods but not over a part of one.
    std::vector<strider::Vec3<float>> prev_feet;
    std::vector<double> travel;
    while (mega_.now_us() < end) {
      if (mega_.now_us() >= next_key) {
        mega_.send(1, keep_alive);
        next_key += 200000;
      }
      if (!run_for(20000)) break;
      if (mega_.now_us() < start) continue;
      for (int c = 0; c < n; ++c) series[size_t(c)].push_back(mega_.pulse_us(c));
      const auto f = feet();
      if (!prev_feet.empty()) {
        float low = 1e9f;
        for (size_t i = 0; i < f.size(); ++i) low = std::min({low, f[i].z, prev_feet[i].z});
        double dx = 0;
        int down = 0;
        for (size_t i = 0; i < f.size(); ++i)
          if (f[i].z < low + 3.0f && prev_feet[i].z < low + 3.0f) {
            dx += double(f[i].x - prev_feet[i].x);
            ++down;
          }
        travel.push_back(down > 0 ? -dx / down : std::nan(""));
      }
      prev_feet = f;
    }
    Motion m;
    int busiest = -1;
    double busiest_path = 0;
    for (int c = 0; c < n; ++c) {
      double path = 0;
      for (size_t i = 1; i < series[size_t(c)].size(); ++i)
        path += std::fabs(series[size_t(c)][i] - series[size_t(c)][i - 1]);
      m.joint_speed_us_s += path / (double(duration_us) * 1e-6);
      if (path > busiest_path) {
        busiest_path = path;
        busiest = c;
      }
    }
    if (busiest >= 0) m.period_s = period_s(series[size_t(busiest)], 0.02);
    size_t used = travel.size();
    if (m.period_s > 0) {
      const double whole = std::floor(double(travel.size()) * 0.02 / m.period_s) * m.period_s;
      used = std::min(used, size_t(std::lround(whole / 0.02)));
    }
    double travel_mm = 0, travel_s = 0;
    for (size_t i = 0; i < used; ++i)
      if (!std::isnan(travel[i])) {
        travel_mm += travel[i];
        travel_s += 0.02;
      }
    m.walked_mm_s = travel_s > 0 ? travel_mm / travel_s : 0.0;
    return m;
  }

  // Fundamental period [s] of a sampled signal: the first autocorrelation
  // peak above half the zero-lag value.
  static double period_s(const std::vector<double>& x, double dt_s) {
    const size_t n = x.size();
    if (n < 10) return 0.0;
    double mean = 0;
    for (double v : x) mean += v;
    mean /= double(n);
    auto ac = [&](size_t lag) {
      double sum = 0;
      for (size_t i = 0; i + lag < n; ++i) sum += (x[i] - mean) * (x[i + lag] - mean);
      return sum / double(n - lag);
    };
    const double a0 = ac(0);
    if (a0 <= 0) return 0.0;
    for (size_t lag = 2; lag + 1 < n / 2; ++lag) {
      const double a = ac(lag);
      if (a > 0.5 * a0 && a >= ac(lag - 1) && a >= ac(lag + 1)) return double(lag) * dt_s;
    }
    return 0.0;
  }

  VirtualMega& mega() { return mega_; }
  const strider::RobotModel& model() const { return *model_; }
  const std::vector<std::string>& lines() const { return lines_; }
  size_t mark() const { return lines_.size(); }
  bool any_line_since(size_t from, const std::string& prefix) const {
    for (size_t i = from; i < lines_.size(); ++i)
      if (lines_[i].rfind(prefix, 0) == 0) return true;
    return false;
  }
  std::string transcript(size_t from = 0) const {
    std::string t;
    for (size_t i = from; i < lines_.size(); ++i) t += "  " + lines_[i] + "\n";
    return t;
  }

 private:
  std::string name_;
  const strider::RobotModel* model_;
  VirtualMega mega_;
  std::string pending_;
  std::vector<std::string> lines_;
  size_t seen_ = 0;
};

void expect_standing(Robot& r, const int16_t* trims, const char* when) {
  const auto expected = r.expected_standing(trims);
  const double tol = kTickToleranceUs * r.mega().board(0).tick_us();
  for (const auto& e : expected)
    EXPECT_NEAR(r.mega().pulse_us(e.first), e.second, tol) << when << ": channel " << e.first;
  // Channels no joint uses stay off.
  for (int c = 0; c < r.mega().board_count() * 16; ++c) {
    if (expected.count(c)) continue;
    EXPECT_EQ(r.mega().pulse_us(c), 0.0) << when << ": unused channel " << c;
  }
}

class FirmwareWalk : public ::testing::TestWithParam<std::string> {};
class FirmwarePersistence : public ::testing::TestWithParam<std::string> {};
class FirmwareFuzz : public ::testing::TestWithParam<std::string> {};
class FirmwareReset : public ::testing::TestWithParam<std::string> {};
class FirmwareSoak : public ::testing::TestWithParam<std::string> {};

// Boot, stand, walk, speed, avoidance, deadman: one boot, several checks.
TEST_P(FirmwareWalk, BootStandWalkAvoidStop) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();

  // After the soft start the outputs hold the standing pose's IK.
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs)) << "outputs never settled";
  EXPECT_TRUE(r.any_line_since(0, "info eeprom")) << r.transcript();  // fresh EEPROM: defaults
  expect_standing(r, nullptr, "after boot");
  const auto& prescale_board = r.mega().board(0);
  EXPECT_EQ(prescale_board.prescale(), strider::pca9685_prescale(strider::kPca9685NominalOscHz, 50));
  EXPECT_FALSE(prescale_board.sleeping());

  // F: the gait moves every leg, within every channel's limits.
  const auto limits = r.pulse_limits();
  r.mega().clear_pulse_log();
  r.mega().send(1, "F");
  r.measure(0, 2000000, "F");
  std::map<int, std::pair<double, double>> seen;
  for (const auto& c : r.mega().pulse_log()) {
    auto it = seen.find(c.channel);
    if (it == seen.end()) seen[c.channel] = {c.width_us, c.width_us};
    else it->second = {std::min(it->second.first, c.width_us), std::max(it->second.second, c.width_us)};
  }
  std::vector<int> legs_moved(r.model().leg_count, 0);
  for (const auto& l : limits) {
    auto it = seen.find(l.first);
    if (it == seen.end()) continue;  // e.g. an abduction joint walking straight
    EXPECT_GE(it->second.first, l.second.first - 1.0) << "channel " << l.first;
    EXPECT_LE(it->second.second, l.second.second + 1.0) << "channel " << l.first;
    EXPECT_GT(it->second.first, 0.0) << "channel " << l.first << " went limp";
    for (uint8_t i = 0; i < r.model().leg_count; ++i)
      for (uint8_t j = 0; j < r.model().dof(); ++j)
        if (strider::joint_channel(r.model(), i, j) == l.first && it->second.second - it->second.first > 20.0)
          legs_moved[i] = 1;
  }
  for (uint8_t i = 0; i < r.model().leg_count; ++i) EXPECT_TRUE(legs_moved[i]) << "leg " << int(i) << " did not step";

  // Speed keys: 1 (10 %) against q (100 %). The joints move faster (a
  // higher step rate, a longer stride or both) and the walked speed rises.
  // (10 %: some gaits top out below 30 % of the app's 155 mm/s.)
  r.mega().send(1, "1");
  // 6 s windows: three of mammal8's 2 s walk cycles (the period needs two
  // in the window, and the speed is taken over whole periods).
  const Robot::Motion slow = r.measure(1000000, 6000000, "F");
  const double vx_slow = std::atof(r.status()["vx"].c_str());
  r.mega().send(1, "q");
  const Robot::Motion fast = r.measure(1000000, 6000000, "F");
  auto st = r.status();
  const double vx_fast = std::atof(st["vx"].c_str());
  std::printf("%s: 10 %%: vx %.1f mm/s, walked %.1f mm/s, step period %.2f s, joints %.0f us/s; "
              "100 %%: vx %.1f, walked %.1f, %.2f s, %.0f us/s\n",
              GetParam().c_str(), vx_slow, slow.walked_mm_s, slow.period_s, slow.joint_speed_us_s, vx_fast,
              fast.walked_mm_s, fast.period_s, fast.joint_speed_us_s);
  // The walked speed (feet on the ground, through FK of the pulses) follows
  // the keys: 10 % is at most 15.5 mm/s (with room for the estimate), 100 %
  // is faster. The status reports the command; the gait engine walks what
  // the robot can (mammal8 tops out near 17 mm/s).
  EXPECT_GT(vx_fast, vx_slow);
  EXPECT_LT(slow.walked_mm_s, 1.5 * 15.5);
  EXPECT_GT(fast.walked_mm_s, slow.walked_mm_s);
  EXPECT_EQ(st["speed"], "100");
  EXPECT_EQ(st["mode"], "walking");

  // An obstacle at 15 cm while walking forward: avoidance takes over.
  size_t from = r.mark();
  r.mega().set_range_mm(150);
  r.measure(0, 1500000, "F");
  bool avoided = false;
  for (size_t i = from; i < r.lines().size(); ++i)
    if (r.lines()[i].rfind("info avoid", 0) == 0 && r.lines()[i] != "info avoid forward") avoided = true;
  EXPECT_TRUE(avoided) << r.transcript(from);
  st = r.status();
  EXPECT_NE(st["avoid"], "forward");
  EXPECT_NE(st["avoid"], "pass");
  r.mega().set_range_mm(2000);

  // Silence while walking: the deadman stops the robot.
  from = r.mark();
  ASSERT_EQ(r.command("walk 100").rfind("ok move", 0), 0u);
  EXPECT_FALSE(r.wait_for_line([](const std::string& l) { return l == "info deadman stop"; }, 2500000).empty())
      << r.transcript(from);
  ASSERT_TRUE(r.settle(500000, 5000000));
  expect_standing(r, nullptr, "after the deadman stop");
  EXPECT_EQ(r.mega().unexpected_resets(), 0) << r.transcript();
  // HC-SR04 datasheet: at least 60 ms between pings (1 ms of slack for the
  // firmware's loop granularity against the simulated clock).
  EXPECT_GE(r.mega().sonar_min_trigger_interval_us(), 59000u);
  EXPECT_EQ(r.mega().sonar_short_triggers(), 0);
  // TRIG high for at least the HC-SR04's 10 us, whatever the compiler made
  // of the delay (PlatformIO's -flto once made 8.9 us of it).
  EXPECT_GE(r.mega().sonar_min_trigger_width_us(), 10.0);
  EXPECT_GT(r.mega().sonar_triggers(), 0);
  // Every servo frame at the bus limit: at most 0.1 ms per channel on a
  // 400 kHz bus (18 channels in 1.8 ms, 8 in 0.8 ms; the boot's set-up
  // transfers are frames of their own).
  int max_bytes = 0;
  double max_bus_us = 0;
  for (const auto& f : r.mega().i2c_frames(5000)) {
    max_bytes = std::max(max_bytes, f.bytes);
    max_bus_us = std::max(max_bus_us, f.bus_time_us());
  }
  EXPECT_LE(max_bus_us, 100.0 * r.model().joint_count()) << max_bytes << " bytes";
  // The firmware's own stack figure (its paint, searched from the heap's
  // top) agrees with the deepest stack pointer the simulator saw (the
  // status command's own frames come after its figure is taken).
  const int fw_stack = std::atoi(r.status()["stack_peak"].c_str());
  EXPECT_NEAR(fw_stack, int(r.mega().stack_peak_bytes()), 64) << "status stack_peak " << fw_stack;
  ::testing::Test::RecordProperty("i2c_max_bytes_per_frame", max_bytes);
  ::testing::Test::RecordProperty("i2c_max_us_per_frame_400khz", int(max_bus_us + 0.5));
  ::testing::Test::RecordProperty("stack_peak_bytes", int(r.mega().stack_peak_bytes()));
  std::printf("%s: i2c max %d bytes/frame = %.0f us at 400 kHz; stack peak %u bytes, static %u bytes\n",
              GetParam().c_str(), max_bytes, max_bus_us, r.mega().stack_peak_bytes(), r.mega().static_ram_bytes());
  EXPECT_EQ(r.mega().stack_overflow_us(), 0u) << "stack peak " << r.mega().stack_peak_bytes() << " bytes, static "
                                              << r.mega().static_ram_bytes() << " bytes";
}

// Garbage on the link, calibration kept over a reset, corrupt EEPROM.
TEST_P(FirmwarePersistence, GarbageCalibrationEeprom) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  auto before = r.status();

  // Random bytes that are neither RC buttons nor line starts: errors only.
  std::mt19937 rng(1234);
  std::string junk;
  while (junk.size() < 300) {
    const uint8_t b = uint8_t(rng());
    // Not CR/LF, and not tab: a tab starts a text line (docs/protocol.md).
    if (b >= 0x80 || (b < 0x20 && b != '\n' && b != '\r' && b != '\t')) junk.push_back(char(b));
  }
  size_t from = r.mark();
  r.mega().send(1, junk);
  for (int i = 0; i < 100 && r.mega().pending_input(1) > 0; ++i) r.run_for(20000);
  r.run_for(300000);
  EXPECT_TRUE(r.any_line_since(from, "err ")) << r.transcript(from);
  EXPECT_FALSE(r.any_line_since(from, "ok")) << r.transcript(from);
  auto after = r.status();
  for (const char* key : {"mode", "speed", "vx", "vy", "wz", "avoid", "deadman_ms", "gait", "eeprom"})
    EXPECT_EQ(after[key], before[key]) << key;
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
  expect_standing(r, nullptr, "after garbage");

  // Calibration saved to EEPROM survives a reset.
  ASSERT_EQ(r.command("cal start").rfind("ok", 0), 0u);
  ASSERT_EQ(r.command("cal trim 0 5").rfind("ok", 0), 0u);
  ASSERT_EQ(r.command("cal save"), "ok cal saved");
  from = r.mark();
  r.mega().reset();
  ASSERT_TRUE(r.wait_ready(&error)) << error;
  // The boot names the record: the first save of a fresh EEPROM, slot 0.
  EXPECT_EQ(r.wait_for_line([](const std::string& l) { return l.rfind("info eeprom", 0) == 0; }, 1000000),
            "info eeprom ok slot=0 seq=1")
      << r.transcript(from);
  EXPECT_EQ(r.command("cal show").rfind("ok cal osc=25000000 trims=5.0,", 0), 0u);
  EXPECT_EQ(r.status()["eeprom"], "ok");
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs));
  int16_t trims[strider::kMaxServoJoints] = {50};
  expect_standing(r, trims, "with trim 0 = 5 deg");

  // A corrupt record: defaults and a notice.
  std::vector<uint8_t> image = r.mega().eeprom();
  image[6] ^= 0x5A;
  r.mega().set_eeprom(image);
  from = r.mark();
  r.mega().reset();
  ASSERT_TRUE(r.wait_ready(&error)) << error;
  r.run_for(200000);
  bool notice = false;
  for (size_t i = from; i < r.lines().size(); ++i)
    if (r.lines()[i].rfind("info eeprom", 0) == 0 && r.lines()[i].find("corrupt") != std::string::npos) notice = true;
  EXPECT_TRUE(notice) << r.transcript(from);
  EXPECT_EQ(r.command("cal show").rfind("ok cal osc=25000000 trims=0.0,", 0), 0u);
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
}

// Seeded random operator input for 15 s: any command with any number, gait
// changes, RC buttons, relax and wake-up, bytes of garbage, over Bluetooth,
// about six a second. The firmware answers every line with ok, err or info,
// never resets, never drives a joint past its limits (by more than the
// half microsecond of a pulse's rounding; 0 = an output off),
// and walks when asked afterwards.
TEST_P(FirmwareFuzz, RandomOperatorInput) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  ASSERT_EQ(r.command("$deadman off*cb77").rfind("ok deadman off", 0), 0u);  // a checked line (protocol.md)
  const auto limits = r.pulse_limits();
  r.mega().clear_pulse_log();
  const size_t from = r.mark();
  std::mt19937 rng(777u + uint32_t(GetParam().size()));
  int sent = 0;
  for (int k = 0; k < 90; ++k) {  // 90 x 160 ms = 14.4 s
    r.mega().send(1, strider_test::random_operator_command([&] { return uint32_t(rng()); }));
    ++sent;
    ASSERT_TRUE(r.run_for(160000));
  }
  r.run_for(500000);
  // The bounds as the firmware sends them (servo_map.h's limit_ticks()): the
  // limit's pulse in whole microseconds, then the tick toward the inside of
  // the range, so at most half a microsecond beyond the exact limit.
  const double slack_us = 0.5 + 0.01;
  int outside = 0;
  for (const auto& c : r.mega().pulse_log()) {
    auto it = limits.find(c.channel);
    if (it == limits.end() || c.width_us == 0.0) continue;
    if (c.width_us < it->second.first - slack_us || c.width_us > it->second.second + slack_us) {
      if (++outside <= 5)
        ADD_FAILURE() << "channel " << c.channel << " at " << c.time_us << " us: " << c.width_us << " us outside "
                      << it->second.first << ".." << it->second.second;
    }
  }
  EXPECT_EQ(outside, 0);
  int answered = 0;
  for (size_t i = from; i < r.lines().size(); ++i) {
    const std::string& l = r.lines()[i];
    EXPECT_TRUE(l.rfind("ok", 0) == 0 || l.rfind("err", 0) == 0 || l.rfind("info", 0) == 0) << l;
    answered += l.rfind("ok", 0) == 0 || l.rfind("err", 0) == 0;
  }
  EXPECT_GT(answered, sent / 2);
  EXPECT_EQ(r.mega().unexpected_resets(), 0) << r.transcript(from);
  EXPECT_EQ(r.mega().stack_overflow_us(), 0u);
  // Still in command: it stands and walks when asked.
  ASSERT_EQ(r.command("stop").rfind("ok", 0), 0u);
  ASSERT_EQ(r.command("pose 0 0 0").rfind("ok", 0), 0u);
  ASSERT_EQ(r.command("speed 100").rfind("ok", 0), 0u);
  r.run_for(8000000);
  ASSERT_EQ(r.command("walk 40").rfind("ok move", 0), 0u);
  r.run_for(1000000);
  EXPECT_EQ(r.status()["mode"], "walking") << r.transcript(from);
}

// The RESET button (or a watchdog reset) in the middle of a walk: the boards
// keep their power and their last frame through the MCU's reset. From the
// reset until the robot stands again, every output either stops or sends a
// pulse a servo can take at the 50 Hz the boards were set to: never the
// 1 kHz, 66-81 us pulses that a software reset plus a default frequency give.
TEST_P(FirmwareReset, MidWalkResetSendsOnlyServoPulses) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  for (int k = 0; k < 6; ++k) {  // held, as a phone app repeats it (the deadman)
    ASSERT_EQ(r.command("walk 60").rfind("ok move", 0), 0u);
    r.run_for(250000);
  }
  ASSERT_EQ(r.status()["mode"], "walking");
  const auto limits = r.pulse_limits();
  r.mega().clear_pulse_log();
  const size_t from = r.mark();
  r.mega().reset();
  ASSERT_TRUE(r.wait_ready(&error)) << error << r.transcript(from);
  // Sampled every 0.5 ms while it starts and stands: the frequency too.
  const uint64_t end = r.mega().now_us() + kSettleTimeoutUs;
  int foreign_rate = 0;
  while (r.mega().now_us() < end) {
    ASSERT_EQ(r.mega().run_for_us(500), RunStatus::kOk);
    for (int b = 0; b < r.mega().board_count(); ++b) {
      const auto& board = r.mega().board(b);
      bool active = false;
      for (int ch = 0; ch < 16; ++ch) active = active || board.pulse_us(ch) > 0.0;
      if (active && std::fabs(board.pwm_hz() - 50.0) > 3.0 && ++foreign_rate <= 3)
        ADD_FAILURE() << "board " << b << " pulsing at " << board.pwm_hz() << " Hz at " << r.mega().now_us() << " us";
    }
  }
  r.collect();
  EXPECT_EQ(foreign_rate, 0);
  int foreign_pulses = 0;
  for (const auto& c : r.mega().pulse_log()) {
    if (c.width_us == 0.0) continue;
    auto it = limits.find(c.channel);
    const bool ok = it != limits.end() && c.width_us >= it->second.first - 1.0 && c.width_us <= it->second.second + 1.0;
    if (!ok && ++foreign_pulses <= 5)
      ADD_FAILURE() << "channel " << c.channel << " at " << c.time_us << " us: " << c.width_us << " us";
  }
  EXPECT_EQ(foreign_pulses, 0);
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  expect_standing(r, nullptr, "standing after the reset");
  EXPECT_EQ(r.mega().unexpected_resets(), 0) << r.transcript(from);
}

// --- Faults: servo boards, the bus, resets (docs/reliability.md) -------------

// A predicate for wait_for_line(): exactly this line.
std::function<bool(const std::string&)> is_line(const std::string& want) {
  return [want](const std::string& l) { return l == want; };
}

// Walks forward at 60 mm/s for 1.5 s, the command repeated as a phone app
// repeats a held button (the deadman); true when the robot walks.
bool walk(Robot& r) {
  for (int k = 0; k < 6; ++k) {
    if (r.command("walk 60").rfind("ok move", 0) != 0) return false;
    r.run_for(250000);
  }
  return r.status()["mode"] == "walking";
}

// Waits until every leg is switched on again (`servos=on`: the soft start
// over, which takes a quarter second per leg) and the outputs are still.
bool stand_settled(Robot& r) {
  const uint64_t end = r.mega().now_us() + kSettleTimeoutUs;
  while (r.status()["servos"] != "on")
    if (r.mega().now_us() > end || !r.run_for(250000)) return false;
  return r.settle(300000, kSettleTimeoutUs);
}

// Runs for `us` in 0.5 ms steps, sampling every joint's output; returns how
// many samples found a joint without a pulse (the first one in *first).
int samples_with_a_joint_off(Robot& r, uint64_t us, std::string* first) {
  const auto limits = r.pulse_limits();
  const uint64_t end = r.mega().now_us() + us;
  int off = 0;
  while (r.mega().now_us() < end) {
    if (r.mega().run_for_us(500) != RunStatus::kOk) return -1;
    for (const auto& l : limits)
      if (r.mega().pulse_us(l.first) == 0.0) {
        if (off++ == 0) *first = "channel " + std::to_string(l.first) + " at " + std::to_string(r.mega().now_us()) + " us";
        break;
      }
  }
  r.collect();
  return off;
}

// Pulse changes since the log was cleared outside the joints' limits (0 = off is not counted).
int pulses_outside_limits(Robot& r) {
  const auto limits = r.pulse_limits();
  int outside = 0;
  for (const auto& c : r.mega().pulse_log()) {
    auto it = limits.find(c.channel);
    if (c.width_us == 0.0 || it == limits.end()) continue;
    if ((c.width_us < it->second.first - 1.0 || c.width_us > it->second.second + 1.0) && ++outside <= 3)
      ADD_FAILURE() << "channel " << c.channel << " at " << c.time_us << " us: " << c.width_us << " us";
  }
  return outside;
}

// The addresses `status` lists for every board the model uses: 0x40[,0x41].
std::string all_boards(const strider::RobotModel& m) {
  return strider::pca_board_count(m) == 2 ? "0x40,0x41" : "0x40";
}

class FirmwareBoards : public ::testing::TestWithParam<std::string> {};

// No servo board answers at power-up: the firmware starts anyway, names each
// missing board, reports them in `status` and refuses to walk.
TEST_P(FirmwareBoards, NoBoardAtBoot) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.load(&error, {})) << error;
  ASSERT_TRUE(r.wait_ready(&error)) << error << r.transcript();
  EXPECT_FALSE(r.wait_for_line(is_line("info fault pca9685 0x40"), 500000).empty()) << r.transcript();
  r.run_for(1000000);
  auto st = r.status();
  EXPECT_EQ(st["pca9685"], all_boards(r.model()));
  EXPECT_GE(std::atoi(st["i2c_errors"].c_str()), 1);
  EXPECT_EQ(r.command("walk 50"), "err 31 servo fault: see pca9685= in status; stop, relax and the rest work");
  EXPECT_EQ(r.command("F"), "ok rc F");  // an RC button: refused without a reply of its own
  st = r.status();
  EXPECT_EQ(st["mode"], "standing");
  EXPECT_EQ(st["vx"], "0.0");
  EXPECT_EQ(r.mega().unexpected_resets(), 0) << r.transcript();
}

// The bus held low from power-up (a slave holding SDA): Wire's time-out ends
// every transfer, so the firmware starts, reports the bus and the boards,
// and answers; once the bus is free it takes the boards and stands up.
TEST_P(FirmwareBoards, StuckBusAtBootRecovers) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.load(&error)) << error;
  r.mega().set_bus_stuck(true);
  const std::string ready = "info strider " + GetParam() + " ready";
  EXPECT_FALSE(r.wait_for_line([&](const std::string& l) { return l.rfind(ready, 0) == 0; }, 1000000).empty())
      << "no `" << ready << "` within 1 s of a stuck bus\n" << r.transcript();
  EXPECT_FALSE(r.wait_for_line(is_line("info fault i2c timeout"), 1000000).empty()) << r.transcript();
  r.run_for(1000000);
  auto st = r.status();
  EXPECT_EQ(st["pca9685"], all_boards(r.model())) << r.transcript();
  EXPECT_EQ(r.command("walk 50"), "err 31 servo fault: see pca9685= in status; stop, relax and the rest work");
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
  const uint64_t freed = r.mega().now_us();
  r.mega().set_bus_stuck(false);
  EXPECT_FALSE(r.wait_for_line(is_line("info pca9685 0x40 restored"), 300000).empty()) << r.transcript();
  std::printf("%s: boards restored %.0f ms after the bus was freed\n", GetParam().c_str(),
              double(r.mega().now_us() - freed) / 1000.0);
  ASSERT_TRUE(stand_settled(r));
  expect_standing(r, nullptr, "after the stuck bus");
  EXPECT_EQ(r.mega().board(0).prescale(), strider::pca9685_prescale(strider::kPca9685NominalOscHz, 50));
  st = r.status();
  EXPECT_EQ(st["pca9685"], "ok");
  EXPECT_GE(std::atoi(st["i2c_errors"].c_str()), 1);

  // The bus stuck again mid-walk: the walk stops, nothing resets, and the
  // boards, which kept running, go on from the pulses they hold.
  ASSERT_TRUE(walk(r)) << r.transcript();
  r.mega().clear_pulse_log();
  size_t from = r.mark();
  r.mega().set_bus_stuck(true);
  EXPECT_FALSE(r.wait_for_line(is_line("info fault i2c timeout"), 300000).empty()) << r.transcript(from);
  r.run_for(1500000);
  EXPECT_EQ(r.status()["mode"], "standing");
  r.mega().set_bus_stuck(false);
  EXPECT_FALSE(r.wait_for_line(is_line("info pca9685 0x40 restored"), 300000).empty()) << r.transcript(from);
  ASSERT_TRUE(stand_settled(r));
  expect_standing(r, nullptr, "after the bus came back");
  for (const auto& c : r.mega().pulse_log()) EXPECT_GT(c.width_us, 0.0) << "channel " << c.channel << " went off";
  EXPECT_EQ(pulses_outside_limits(r), 0);
  EXPECT_EQ(r.mega().unexpected_resets(), 0) << r.transcript(from);
}

// The MCU hangs during start-up, before the servo boards are set up: the
// watchdog runs from the first line of setup(), so the board resets, says
// so, and starts.
TEST_P(FirmwareBoards, HangDuringStartUpEndsInAWatchdogReset) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.load(&error)) << error;
  // In setup(): the serial ports are set up, the servo boards not yet.
  while (r.mega().baud(0) == 0 && r.mega().now_us() < 100000) ASSERT_EQ(r.mega().run_for_us(20), RunStatus::kOk);
  ASSERT_TRUE(r.mega().i2c_log().empty());
  r.mega().hang();
  ASSERT_TRUE(r.wait_ready(&error)) << error << r.transcript();
  EXPECT_EQ(r.mega().unexpected_resets(), 1);
  EXPECT_LT(r.mega().now_us(), 1000000u);
  EXPECT_TRUE(r.any_line_since(0, "info reset watchdog")) << r.transcript();
  ASSERT_TRUE(stand_settled(r));
  expect_standing(r, nullptr, "after the watchdog reset");
}

// hexapod18 drives two boards, 0x40 and 0x41; the second one missing.
TEST(FirmwareBoardsHexapod, SecondBoardMissing) {
  Robot r("hexapod18");
  std::string error;
  ASSERT_TRUE(r.load(&error, {0x40})) << error;
  ASSERT_TRUE(r.wait_ready(&error)) << error << r.transcript();
  EXPECT_FALSE(r.wait_for_line(is_line("info fault pca9685 0x41"), 500000).empty()) << r.transcript();
  ASSERT_TRUE(stand_settled(r));
  EXPECT_FALSE(r.any_line_since(0, "info fault pca9685 0x40")) << r.transcript();
  auto st = r.status();
  EXPECT_EQ(st["pca9685"], "0x41");
  EXPECT_GE(std::atoi(st["i2c_errors"].c_str()), 1);
  EXPECT_EQ(r.command("walk 60"), "err 31 servo fault: see pca9685= in status; stop, relax and the rest work");
  // The first board's legs stand.
  const auto expected = r.expected_standing();
  const double tol = kTickToleranceUs * r.mega().board(0).tick_us();
  for (const auto& e : expected) {
    if (e.first < 16) EXPECT_NEAR(r.mega().pulse_us(e.first), e.second, tol) << "channel " << e.first;
  }
}

// Board 0x41 loses its supply mid-walk (its servos go limp) and gets it
// back in its power-on state: the fault is reported within a frame or two,
// the walk stops and stays refused, the board is set up again (prescale,
// awake), its legs are switched on again and the robot stands and walks.
TEST(FirmwareBoardsHexapod, BoardLosesPowerMidWalkAndComesBack) {
  Robot r("hexapod18");
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  ASSERT_TRUE(walk(r)) << r.transcript();
  size_t from = r.mark();
  const uint64_t cut = r.mega().now_us();
  r.mega().set_board_power(1, false);
  ASSERT_FALSE(r.wait_for_line(is_line("info fault pca9685 0x41"), 200000).empty()) << r.transcript(from);
  const double detect_ms = double(r.mega().now_us() - cut) / 1000.0;
  r.run_for(1500000);  // the gait finishes its step and stands
  auto st = r.status();
  EXPECT_EQ(st["mode"], "standing") << r.transcript(from);
  EXPECT_EQ(st["state"], "standing");
  EXPECT_EQ(st["pca9685"], "0x41");
  const int errors = std::atoi(st["i2c_errors"].c_str());
  EXPECT_GE(errors, 1);
  EXPECT_EQ(r.command("walk 60"), "err 31 servo fault: see pca9685= in status; stop, relax and the rest work");
  // Stopped: the first board's legs hold still.
  r.mega().clear_pulse_log();
  r.run_for(500000);
  for (const auto& c : r.mega().pulse_log()) EXPECT_GE(c.channel, 16) << "channel " << c.channel << " still moves";

  from = r.mark();
  const uint64_t back = r.mega().now_us();
  r.mega().set_board_power(1, true);  // power-on state: asleep, every output off
  ASSERT_FALSE(r.wait_for_line(is_line("info pca9685 0x41 restored"), 300000).empty()) << r.transcript(from);
  const double restore_ms = double(r.mega().now_us() - back) / 1000.0;
  EXPECT_FALSE(r.mega().board(1).sleeping());
  EXPECT_EQ(r.mega().board(1).prescale(), strider::pca9685_prescale(strider::kPca9685NominalOscHz, 50));
  r.mega().clear_pulse_log();
  ASSERT_TRUE(stand_settled(r));
  expect_standing(r, nullptr, "after the board came back");
  EXPECT_EQ(pulses_outside_limits(r), 0);
  double driven_ms = 0;
  for (const auto& c : r.mega().pulse_log())
    if (c.channel >= 16 && c.width_us > 0) driven_ms = std::max(driven_ms, double(c.time_us - back) / 1000.0);
  st = r.status();
  EXPECT_EQ(st["pca9685"], "ok");
  EXPECT_EQ(std::atoi(st["i2c_errors"].c_str()), errors);  // probes of the missing board are not errors
  EXPECT_EQ(st["servos"], "on");
  ASSERT_TRUE(walk(r)) << r.transcript(from);
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
  std::printf("hexapod18: board 0x41 off: reported after %.0f ms; on: restored after %.0f ms, its legs on "
              "within %.0f ms\n", detect_ms, restore_ms, driven_ms);
}

// Board 0x41's supply drops for 30 ms while the robot stands: no frame goes
// to it (nothing moves), and it answers again at once, but asleep with its
// outputs off. The firmware's periodic check of MODE1 finds it, sets it up
// again and switches its legs on.
TEST(FirmwareBoardsHexapod, PowerGlitchWhileStandingIsFound) {
  Robot r("hexapod18");
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(stand_settled(r));
  const size_t from = r.mark();
  const uint64_t cut = r.mega().now_us();
  r.mega().set_board_power(1, false);
  r.run_for(30000);
  r.mega().set_board_power(1, true);
  EXPECT_EQ(r.mega().pulse_us(16), 0.0);  // limp
  ASSERT_FALSE(r.wait_for_line(is_line("info fault pca9685 0x41"), 500000).empty()) << r.transcript(from);
  ASSERT_FALSE(r.wait_for_line(is_line("info pca9685 0x41 restored"), 300000).empty()) << r.transcript(from);
  std::printf("hexapod18: a 30 ms power cut of board 0x41 while standing found and the board set up again "
              "after %.0f ms\n", double(r.mega().now_us() - cut) / 1000.0);
  ASSERT_TRUE(stand_settled(r));
  expect_standing(r, nullptr, "after the power glitch");
  EXPECT_EQ(r.status()["pca9685"], "ok");
}

// Board 0x41's bus wires come loose mid-walk and back: it keeps its supply
// and its registers, so its servos hold their pulses throughout; the
// firmware reads them back and moves its legs on from there.
TEST(FirmwareBoardsHexapod, BoardWiresComeLooseAndBack) {
  Robot r("hexapod18");
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  ASSERT_TRUE(walk(r)) << r.transcript();
  r.mega().clear_pulse_log();
  const size_t from = r.mark();
  r.mega().set_board_attached(1, false);
  ASSERT_FALSE(r.wait_for_line(is_line("info fault pca9685 0x41"), 200000).empty()) << r.transcript(from);
  r.run_for(1500000);
  EXPECT_EQ(r.status()["mode"], "standing");
  r.mega().set_board_attached(1, true);
  ASSERT_FALSE(r.wait_for_line(is_line("info pca9685 0x41 restored"), 300000).empty()) << r.transcript(from);
  ASSERT_TRUE(stand_settled(r));
  expect_standing(r, nullptr, "after the wires came back");
  for (const auto& c : r.mega().pulse_log()) EXPECT_GT(c.width_us, 0.0) << "channel " << c.channel << " went off";
  EXPECT_EQ(pulses_outside_limits(r), 0);
  EXPECT_EQ(r.status()["pca9685"], "ok");
}

// A RESET mid-walk, then a hang that the watchdog ends: the boards kept
// running, so the firmware keeps their pulses (no joint ever goes off, the
// robot does not drop), says why it restarted, and stands up from the pose
// they hold.
TEST_P(FirmwareReset, WarmResetKeepsTheJointsOn) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  ASSERT_TRUE(walk(r)) << r.transcript();
  const std::string held = "info servos held joints=" + std::to_string(r.model().joint_count());
  r.mega().clear_pulse_log();
  size_t from = r.mark();
  r.mega().reset();
  std::string first;
  EXPECT_EQ(samples_with_a_joint_off(r, 1000000, &first), 0) << "after the reset, first: " << first;
  EXPECT_TRUE(r.any_line_since(from, "info reset external")) << r.transcript(from);
  EXPECT_TRUE(r.any_line_since(from, held)) << r.transcript(from);
  ASSERT_TRUE(stand_settled(r));
  EXPECT_EQ(samples_with_a_joint_off(r, 1000, &first), 0);
  expect_standing(r, nullptr, "standing after the reset");
  EXPECT_EQ(pulses_outside_limits(r), 0);

  ASSERT_TRUE(walk(r)) << r.transcript(from);
  r.mega().clear_pulse_log();
  from = r.mark();
  r.mega().hang();
  EXPECT_EQ(samples_with_a_joint_off(r, 1500000, &first), 0) << "after the hang, first: " << first;
  EXPECT_EQ(r.mega().unexpected_resets(), 1);
  EXPECT_TRUE(r.any_line_since(from, "info reset watchdog")) << r.transcript(from);
  EXPECT_TRUE(r.any_line_since(from, held)) << r.transcript(from);
  ASSERT_TRUE(stand_settled(r));
  expect_standing(r, nullptr, "standing after the watchdog reset");
  EXPECT_EQ(pulses_outside_limits(r), 0);
}

// A soak: seeded random operator input (commands, RC keys, garbage), a line
// every 0.5 s on average with the keys held, for STRIDER_SOAK_SECONDS of
// simulated time (default 20 s in the test command; `tools/dev soak
// --minutes 30` for the long run). Checked as it runs, in 60 s chunks: no
// reset, no overrun, no pulse past a joint's limits or not finite, the stack
// not growing after the first chunk, every line answered.
TEST_P(FirmwareSoak, RandomOperatorSoak) {
  const char* env = std::getenv("STRIDER_SOAK_SECONDS");
  const double seconds = env != nullptr ? std::atof(env) : 20.0;
  ASSERT_GT(seconds, 0.0);
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(300000, kSettleTimeoutUs));
  const auto limits = r.pulse_limits();
  std::mt19937 rng(4242u + uint32_t(GetParam().size()));
  const uint64_t start_us = r.mega().now_us();
  const uint64_t end_us = start_us + uint64_t(seconds * 1e6);
  const uint64_t chunk_us = 60000000;
  uint32_t stack_after_first_chunk = 0;
  int outside = 0, sent = 0;
  while (r.mega().now_us() < end_us) {
    const uint64_t chunk_end = std::min(end_us, r.mega().now_us() + chunk_us);
    while (r.mega().now_us() < chunk_end) {
      r.mega().send(1, strider_test::random_operator_command([&] { return uint32_t(rng()); }));
      ++sent;
      ASSERT_TRUE(r.run_for(200000 + rng() % 600000)) << "simulation stopped at " << r.mega().now_us() << " us";
    }
    for (const auto& c : r.mega().pulse_log()) {
      if (c.width_us == 0.0) continue;
      auto it = limits.find(c.channel);
      const bool ok = std::isfinite(c.width_us) && it != limits.end() && c.width_us >= it->second.first - 0.51 &&
                      c.width_us <= it->second.second + 0.51;
      if (!ok && ++outside <= 5)
        ADD_FAILURE() << "channel " << c.channel << " at " << c.time_us << " us: " << c.width_us << " us";
    }
    r.mega().clear_pulse_log();
    r.mega().clear_i2c_log();
    ASSERT_EQ(r.mega().unexpected_resets(), 0) << "at " << r.mega().now_us() << " us";
    ASSERT_EQ(r.mega().stack_overflow_us(), 0u);
    if (stack_after_first_chunk == 0) stack_after_first_chunk = r.mega().stack_peak_bytes();
  }
  EXPECT_EQ(outside, 0);
  auto st = r.status();
  EXPECT_EQ(st["overruns"], "0") << "tick_max_us " << st["tick_max_us"];
  // Stable: a few bytes of interrupt nesting at most beyond the first chunk's depth.
  EXPECT_LE(r.mega().stack_peak_bytes(), stack_after_first_chunk + 32u);
  EXPECT_LE(r.mega().stack_peak_bytes(), 1024u);
  int answered = 0;
  for (const auto& l : r.lines()) {
    answered += l.rfind("ok", 0) == 0 || l.rfind("err", 0) == 0;
    std::string token;  // no NaN or infinity reaches a reply
    for (char ch : l + " ") {
      if (ch == ' ' || ch == '=' || ch == ',') {
        EXPECT_TRUE(token != "nan" && token != "-nan" && token != "inf" && token != "-inf") << l;
        token.clear();
      } else {
        token.push_back(ch);
      }
    }
  }
  EXPECT_GT(answered, sent / 2);
  std::printf("%s: soak %.0f s simulated, %d inputs, stack peak %u bytes, tick_max_us %s\n", GetParam().c_str(),
              double(r.mega().now_us() - start_us) * 1e-6, sent, r.mega().stack_peak_bytes(),
              st["tick_max_us"].c_str());
}

std::string param_name(const ::testing::TestParamInfo<std::string>& p) { return p.param; }

INSTANTIATE_TEST_SUITE_P(Models, FirmwareWalk,
                         ::testing::Values("sprawl8", "mammal8", "dog12", "hexapod18", "spider12"), param_name);
// Every model's firmware: the link and EEPROM code is shared, but each build
// has its own scalar (float or fixed point), layout and trims.
INSTANTIATE_TEST_SUITE_P(Models, FirmwareFuzz,
                         ::testing::Values("sprawl8", "mammal8", "dog12", "hexapod18", "spider12"), param_name);
INSTANTIATE_TEST_SUITE_P(Models, FirmwarePersistence,
                         ::testing::Values("sprawl8", "mammal8", "dog12", "hexapod18", "spider12"), param_name);
INSTANTIATE_TEST_SUITE_P(Models, FirmwareSoak,
                         ::testing::Values("sprawl8", "mammal8", "dog12", "hexapod18", "spider12"), param_name);
INSTANTIATE_TEST_SUITE_P(Models, FirmwareReset,
                         ::testing::Values("sprawl8", "mammal8", "dog12", "hexapod18", "spider12"), param_name);
// One board and float (sprawl8), two boards and fixed point (hexapod18).
INSTANTIATE_TEST_SUITE_P(Models, FirmwareBoards, ::testing::Values("sprawl8", "hexapod18"), param_name);

// A draining battery on A0 (vbench's ADC, the 3:1 divider of the board
// file): reported in status, a low notice while it still walks, a critical
// one that stops the walk and sits the robot down with walking refused
// (err 32), and back up once the pack is charged.
class FirmwareBattery : public ::testing::TestWithParam<std::string> {};
TEST_P(FirmwareBattery, DrainingPackWarnsThenSitsThenRecovers) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs)) << "outputs never settled";
  auto pack = [&](double volts) { r.mega().set_adc_volts(0, volts / 3.0); };
  auto wait_notice = [&](const std::string& head, uint64_t timeout_us) {
    return r.wait_for_line([&](const std::string& l) { return l.rfind(head, 0) == 0; }, timeout_us);
  };
  EXPECT_EQ(r.status().count("battery_mv"), 0u) << "no battery wired: no field";
  pack(7.6);
  EXPECT_FALSE(wait_notice("info battery ok", 4000000).empty()) << r.transcript();  // after the 2 s hold
  const auto st = r.status();
  ASSERT_EQ(st.count("battery_mv"), 1u) << r.transcript();
  EXPECT_NEAR(std::stoi(st.at("battery_mv")), 7600, 30);
  EXPECT_EQ(r.command("walk 40").rfind("ok", 0), 0u);
  pack(6.9);  // 3.45 V a cell
  EXPECT_FALSE(wait_notice("info battery low", 4000000).empty()) << r.transcript();
  EXPECT_EQ(r.command("walk 40").rfind("ok", 0), 0u) << "a low pack still walks";
  pack(6.4);  // 3.2 V a cell
  EXPECT_FALSE(wait_notice("info battery critical", 4000000).empty()) << r.transcript();
  r.run_for(4000000);
  EXPECT_EQ(r.status()["state"], "sitting");
  EXPECT_EQ(r.command("walk 40").rfind("err 32", 0), 0u) << r.transcript();
  pack(8.2);
  EXPECT_FALSE(wait_notice("info battery ok", 6000000).empty()) << r.transcript();
  r.run_for(4000000);
  EXPECT_EQ(r.status()["state"], "standing");
  EXPECT_EQ(r.command("walk 40").rfind("ok", 0), 0u);
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
}
INSTANTIATE_TEST_SUITE_P(Models, FirmwareBattery, ::testing::Values("sprawl8", "hexapod18"), param_name);

// An MPU-6050 on the bus (vbench's, fed a tilt): found at start-up, roll and
// pitch in status, a tip-over past 50 deg is a fall (limp, walking refused
// with err 33), set upright it clears and walks again. Without the part the
// status says imu=none.
class FirmwareImu : public ::testing::TestWithParam<std::string> {};
TEST_P(FirmwareImu, TiltIsReportedAndATipOverIsAFall) {
  {
    Robot none(GetParam());
    std::string error;
    ASSERT_TRUE(none.boot(&error)) << error;
    EXPECT_EQ(none.status()["imu"], "none") << none.transcript();
  }
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.load(&error)) << error;
  r.mega().set_imu_present(true);
  auto tilt = [&](double roll_deg) {  // gravity's reaction in the chip's axes, rolled about x
    const double a = roll_deg * M_PI / 180.0, g = 9.80665;
    r.mega().set_imu_accel_m_s2(0.0, g * std::sin(a), g * std::cos(a));
    r.mega().set_imu_gyro_rad_s(0.0, 0.0, 0.0);
  };
  tilt(10.0);
  ASSERT_TRUE(r.wait_ready(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs)) << "outputs never settled";
  r.run_for(3000000);  // the filter settles on the accelerometer
  auto st = r.status();
  EXPECT_EQ(st["imu"], "ok") << r.transcript();
  ASSERT_EQ(st.count("roll"), 1u) << r.transcript();
  EXPECT_NEAR(std::stod(st["roll"]), 10.0, 0.5);
  EXPECT_NEAR(std::stod(st["pitch"]), 0.0, 0.5);
  EXPECT_EQ(r.command("walk 40").rfind("ok", 0), 0u);
  tilt(80.0);  // tipped over
  EXPECT_FALSE(r.wait_for_line([](const std::string& l) { return l == "info fall"; }, 6000000).empty())
      << r.transcript();
  EXPECT_EQ(r.status()["imu"], "fallen");
  EXPECT_EQ(r.command("walk 40").rfind("err 33", 0), 0u) << r.transcript();
  EXPECT_EQ(r.status()["mode"], "relaxed");
  tilt(2.0);  // set upright
  EXPECT_FALSE(r.wait_for_line([](const std::string& l) { return l == "info fall cleared"; }, 8000000).empty())
      << r.transcript();
  EXPECT_EQ(r.command("walk 40").rfind("ok", 0), 0u) << r.transcript();
  r.run_for(2000000);
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
  EXPECT_LE(r.mega().stack_peak_bytes(), 1024u) << "with the IMU read every tick";
  std::printf("%s with the IMU: stack peak %u bytes\n", GetParam().c_str(), unsigned(r.mega().stack_peak_bytes()));
}
INSTANTIATE_TEST_SUITE_P(Models, FirmwareImu, ::testing::Values("sprawl8", "hexapod18"), param_name);

// `level on|off` on the virtual Mega: refused (err 34) without the part; with
// it, status says imu=level, and a tilt the pose cannot take away (vbench's
// part reads a fixed 12 deg roll whatever the legs do) drives the pose to
// what the legs reach, walking and standing, within the stack's 1 KB.
// Walking, the part reads a turn of 3 deg/s that no trim takes away: the
// heading hold (control/yaw_hold.h) trims the gait's turn every 0.2 s up to
// its limit, each trim planning the gait again, in the same ticks as the
// level's reach checks: the longest tick stays within 10 ms.
class FirmwareLevel : public ::testing::TestWithParam<std::string> {};
TEST_P(FirmwareLevel, LevelOnNeedsThePartAndStaysWithinTheStack) {
  {
    Robot none(GetParam());
    std::string error;
    ASSERT_TRUE(none.boot(&error)) << error;
    EXPECT_EQ(none.command("level on").rfind("err 34 no imu", 0), 0u) << none.transcript();
    EXPECT_EQ(none.status()["imu"], "none");
  }
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.load(&error)) << error;
  r.mega().set_imu_present(true);
  const double a = 12.0 * M_PI / 180.0, g = 9.80665;
  r.mega().set_imu_accel_m_s2(0.0, g * std::sin(a), g * std::cos(a));
  r.mega().set_imu_gyro_rad_s(0.0, 0.0, 0.0);
  ASSERT_TRUE(r.wait_ready(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs)) << "outputs never settled";
  EXPECT_EQ(r.command("level on"), "ok level on") << r.transcript();
  r.run_for(3000000);
  EXPECT_EQ(r.status()["imu"], "level") << r.transcript();
  ASSERT_EQ(r.command("$deadman off*cb77").rfind("ok deadman off", 0), 0u);  // walking 6 s on one command
  EXPECT_EQ(r.command("walk 40").rfind("ok", 0), 0u) << r.transcript();
  r.mega().set_imu_gyro_rad_s(0.0, 0.0, 3.0 * M_PI / 180.0);
  r.run_for(6000000);
  const std::string walking = r.command("status");
  EXPECT_NE(walking.find(" wz=0.0 "), std::string::npos) << walking;       // the command's
  EXPECT_NE(walking.find(" walk_wz=-"), std::string::npos) << walking;     // trimmed against the turn
  EXPECT_EQ(r.command("stop"), "ok stop");
  r.mega().set_imu_gyro_rad_s(0.0, 0.0, 0.0);
  EXPECT_EQ(r.command("level off"), "ok level off");
  r.run_for(2000000);
  auto st = r.status();
  EXPECT_EQ(st["imu"], "ok") << r.transcript();
  EXPECT_EQ(st["overruns"], "0");
  EXPECT_LE(std::stol(st["tick_max_us"]), 10000) << "level and heading hold in the same ticks";
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
  EXPECT_LE(r.mega().stack_peak_bytes(), 1024u) << "with the level's reach checks";
  std::printf("%s with level on: stack peak %u bytes, tick_max_us %s\n", GetParam().c_str(),
              unsigned(r.mega().stack_peak_bytes()), st["tick_max_us"].c_str());
}
INSTANTIATE_TEST_SUITE_P(Models, FirmwareLevel, ::testing::Values("sprawl8", "hexapod18"), param_name);

// `cal level` on the virtual Mega: vbench's part lying level but reading
// 49.9 / -26.4 mg off on x / y (the simulator's seed-1 draw) and 5 deg/s off
// on every gyro axis. Uncalibrated, status reads the offsets' tilt; `cal
// level` answers a second later with the offsets and saves them; roll and
// pitch then read ~0, after a reset too (from the EEPROM; the gyro's offset
// is then 0, as a warm start learns one only slowly). Refused on a
// 8 deg tilt (err 36) and walking (err 35), nothing saved; a corrupt record
// gives the defaults (no offsets) and says so.
class FirmwareLevelCal : public ::testing::TestWithParam<std::string> {};
TEST_P(FirmwareLevelCal, CalLevelRemovesTheAccelerometerOffset) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.load(&error)) << error;
  r.mega().set_imu_present(true);
  const double g = 9.80665;
  double w = 5.0 * M_PI / 180.0;
  auto lie = [&](double roll_deg) {  // rolled about x, with the part's offsets
    const double a = roll_deg * M_PI / 180.0;
    r.mega().set_imu_accel_m_s2(0.0499 * g, g * std::sin(a) - 0.0264 * g, g * std::cos(a));
    r.mega().set_imu_gyro_rad_s(w, w, w);
  };
  lie(0.0);
  ASSERT_TRUE(r.wait_ready(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs)) << "outputs never settled";
  r.run_for(4000000);
  auto st = r.status();
  ASSERT_EQ(st.count("roll"), 1u) << r.transcript();
  EXPECT_NEAR(std::stod(st["pitch"]), -2.86, 0.3) << "uncalibrated: +x reads as nose up";
  EXPECT_NEAR(std::stod(st["roll"]), -1.51, 0.3);
  const double before_roll = std::stod(st["roll"]), before_pitch = std::stod(st["pitch"]);
  // Refusals: walking, then a tilted robot. Nothing saved.
  EXPECT_EQ(r.command("walk 40").rfind("ok", 0), 0u);
  EXPECT_EQ(r.command("cal level").rfind("err 35 not standing still", 0), 0u) << r.transcript();
  EXPECT_EQ(r.command("stop"), "ok stop");
  r.run_for(2000000);
  lie(8.0);
  r.run_for(6000000);
  EXPECT_EQ(r.command("cal level", 3000000), "err 36 not level: stand on level ground (within 5 deg)") << r.transcript();
  EXPECT_EQ(r.mega().eeprom()[0], 0xFF) << "nothing saved";
  lie(0.0);
  r.run_for(6000000);
  const uint64_t t0 = r.mega().now_us();
  EXPECT_EQ(r.command("cal level", 3000000), "ok cal level x_mg=50 y_mg=-26 saved") << r.transcript();
  const double took_s = double(r.mega().now_us() - t0) * 1e-6;
  EXPECT_NEAR(took_s, 1.0, 0.1);
  r.run_for(1000000);
  st = r.status();
  EXPECT_NEAR(std::stod(st["roll"]), 0.0, 0.15) << r.transcript();
  EXPECT_NEAR(std::stod(st["pitch"]), 0.0, 0.15);
  const std::string show = r.command("cal show");
  EXPECT_EQ(show.substr(show.find(" level_mg=")), " level_mg=50,-26");
  std::printf("%s cal level: roll/pitch %.1f/%.1f deg before, %s/%s after (%.2f s)\n", GetParam().c_str(),
              before_roll, before_pitch, st["roll"].c_str(), st["pitch"].c_str(), took_s);
  // After a reset, from the EEPROM. (A warm start: the robot stands at
  // once and the filter learns a gyro offset with its slow gains, which
  // is not what this test is about: a part without one from here on.)
  w = 0.0;
  lie(0.0);
  size_t from = r.mark();
  r.mega().reset();
  ASSERT_TRUE(r.wait_ready(&error)) << error;
  EXPECT_EQ(r.wait_for_line([](const std::string& l) { return l.rfind("info eeprom", 0) == 0; }, 1000000),
            "info eeprom ok slot=0 seq=1")
      << r.transcript(from);
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs));
  r.run_for(4000000);
  st = r.status();
  EXPECT_NEAR(std::stod(st["roll"]), 0.0, 0.15) << r.transcript();
  EXPECT_NEAR(std::stod(st["pitch"]), 0.0, 0.15);
  // A corrupt record: the defaults, no offsets, and eeprom= says so.
  std::vector<uint8_t> image = r.mega().eeprom();
  image[60] ^= 0x01;  // the x offset's byte
  r.mega().set_eeprom(image);
  from = r.mark();
  r.mega().reset();
  ASSERT_TRUE(r.wait_ready(&error)) << error;
  EXPECT_EQ(r.wait_for_line([](const std::string& l) { return l.rfind("info eeprom", 0) == 0; }, 1000000),
            "info eeprom corrupt, defaults")
      << r.transcript(from);
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs));
  r.run_for(4000000);
  st = r.status();
  EXPECT_EQ(st["eeprom"], "corrupt");
  EXPECT_NEAR(std::stod(st["pitch"]), -2.86, 0.3);
  const std::string show2 = r.command("cal show");
  EXPECT_EQ(show2.substr(show2.find(" level_mg=")), " level_mg=0,0");
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
  EXPECT_LE(r.mega().stack_peak_bytes(), 1024u) << "with the measurement and its late reply";
  std::printf("%s with cal level: stack peak %u bytes\n", GetParam().c_str(), unsigned(r.mega().stack_peak_bytes()));
}
INSTANTIATE_TEST_SUITE_P(Models, FirmwareLevelCal, ::testing::Values("hexapod18"), param_name);

}  // namespace

// Live gait parameters on the firmware (the phone's lines): `get` shows the
// model's own, `set` changes them while the robot walks (no overrun, every
// joint within its limits), refused values name their range, `save` keeps
// them over a reset, and the status says where they came from.
class FirmwareTuning : public ::testing::TestWithParam<std::string> {};
TEST_P(FirmwareTuning, SetWalkSaveReset) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs)) << "outputs never settled";
  const std::string own = r.command("get");
  ASSERT_EQ(own.rfind("ok get gait=", 0), 0u) << own;
  EXPECT_EQ(r.status().count("tune"), 0u);
  const bool hexapod = GetParam() == "hexapod18";
  const std::string swing = hexapod ? "parabola" : "cycloid";
  EXPECT_EQ(r.command("deadman 60000"), "ok deadman ms=60000");
  EXPECT_EQ(r.command("set step_height 12.50"), "ok set step_height 12.50");
  EXPECT_EQ(r.command("set cycle 1.10"), "ok set cycle 1.10");
  EXPECT_EQ(r.command("set swing " + swing), "ok set swing " + swing);
  EXPECT_EQ(r.command("set step_height 99"), std::string("err 25 step_height out of range: 1.00..") +
                                                  (hexapod ? "30.00" : "20.00"));
  EXPECT_EQ(r.command("set duty 0.99").rfind("err 25 duty out of range: ", 0), 0u);
  EXPECT_EQ(r.command("walk 30").rfind("ok move", 0), 0u);
  const auto limits = r.pulse_limits();
  r.mega().clear_pulse_log();
  r.run_for(2000000);
  EXPECT_EQ(r.command("set step_length 30"), "ok set step_length 30.00");
  r.run_for(2000000);
  size_t pulses = 0;
  for (const auto& c : r.mega().pulse_log()) {
    const auto lim = limits.find(c.channel);
    if (lim == limits.end() || c.width_us == 0) continue;
    ++pulses;
    EXPECT_GE(c.width_us, lim->second.first - 1.0) << "channel " << c.channel;
    EXPECT_LE(c.width_us, lim->second.second + 1.0) << "channel " << c.channel;
  }
  EXPECT_GT(pulses, 100u);
  auto st = r.status();
  EXPECT_EQ(st["state"], "walking");
  EXPECT_EQ(st["tune"], "changed");
  EXPECT_EQ(st["overruns"], "0") << "tick_max_us=" << st["tick_max_us"];
  EXPECT_EQ(r.command("stop"), "ok stop");
  r.run_for(3000000);
  EXPECT_EQ(r.command("save"), "ok saved");
  const std::string tuned = r.command("get");
  EXPECT_NE(tuned.find(" step_height=12.50 step_length=30.00 cycle=1.10 "), std::string::npos) << tuned;
  EXPECT_NE(tuned.find(" swing=" + swing + " "), std::string::npos) << tuned;
  r.mega().reset();
  ASSERT_TRUE(r.wait_ready(&error)) << error;
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs));
  EXPECT_EQ(r.command("get"), tuned);
  EXPECT_EQ(r.status()["tune"], "saved");
  EXPECT_EQ(r.mega().unexpected_resets(), 0);
  std::printf("%s: %s\n", GetParam().c_str(), tuned.c_str());
}
INSTANTIATE_TEST_SUITE_P(Models, FirmwareTuning, ::testing::Values("sprawl8", "hexapod18"), param_name);

// The replies a user meets first, from the firmware itself (its texts are in
// flash): `help` names the model's gaits and heights; every erroneous line
// is answered `err <code> <reason>: <what is valid>`, an unknown gait with
// the gaits `help` lists, a line of blanks too; and on sprawl8 the examples
// of docs/protocol.md's error section come back exactly as written there.
static std::vector<std::pair<std::string, std::string>> protocol_doc_examples() {
  std::ifstream in(STRIDER_PROTOCOL_DOC);
  std::vector<std::pair<std::string, std::string>> out;
  bool armed = false, block = false;
  for (std::string l; std::getline(in, l);) {
    if (l.find("Examples, sprawl8:") != std::string::npos) armed = true;
    if (armed && l.rfind("```", 0) == 0) {
      if (block) break;
      block = true;
      continue;
    }
    const size_t arrow = l.find("->");
    if (!block || arrow == std::string::npos) continue;
    auto trim = [](std::string s) {
      s.erase(0, s.find_first_not_of(' '));
      s.erase(s.find_last_not_of(' ') + 1);
      return s;
    };
    out.emplace_back(trim(l.substr(0, arrow)), trim(l.substr(arrow + 2)));
  }
  return out;
}

class FirmwareReplies : public ::testing::TestWithParam<std::string> {};
TEST_P(FirmwareReplies, ErrorsNameWhatIsValid) {
  Robot r(GetParam());
  std::string error;
  ASSERT_TRUE(r.boot(&error)) << error << "\n" << r.transcript();
  ASSERT_TRUE(r.settle(500000, kSettleTimeoutUs)) << "outputs never settled";
  const std::string help = r.command("help");
  const size_t g = help.find("; gaits "), h = help.find("; height ");
  ASSERT_NE(g, std::string::npos) << help;
  ASSERT_NE(h, std::string::npos) << help;
  const std::string gaits = help.substr(g + 8, h - g - 8);
  EXPECT_EQ(r.command("gait gallop"), "err 23 unknown gait: " + gaits);
  EXPECT_EQ(r.command("height 9000"), "err 5 out of range: height 10..400");
  const std::string other_gait = gaits.find("tripod") != std::string::npos ? "gait trot" : "gait ripple";
  for (const std::string& line : {std::string("dance"), std::string("  \t "), other_gait, std::string("vel 100 0"),
                                 std::string("stop now"), std::string("avoid maybe"), std::string("cal trim 1 2"),
                                 std::string("deadman off"), std::string("set step_height 0.5"),
                                 std::string("pose 30 30 30"), std::string("baud 1234")}) {
    const std::string reply = r.command(line);
    const size_t colon = reply.find(": ");
    EXPECT_EQ(reply.rfind("err ", 0), 0u) << line << " -> " << reply;
    ASSERT_NE(colon, std::string::npos) << line << " -> " << reply;
    EXPECT_GT(reply.size(), colon + 3) << line << " -> " << reply;
  }
  EXPECT_EQ(r.command("  ").rfind("err 1 empty line: walk strafe", 0), 0u);
  EXPECT_EQ(r.status()["mode"], "standing");  // none of it moved the robot
  if (GetParam() != "sprawl8") return;
  const auto examples = protocol_doc_examples();
  EXPECT_GE(examples.size(), 5u);
  for (const auto& e : examples) EXPECT_EQ(r.command(e.first), e.second) << e.first;
}
INSTANTIATE_TEST_SUITE_P(Models, FirmwareReplies,
                         ::testing::Values("sprawl8", "mammal8", "dog12", "hexapod18", "spider12"), param_name);
