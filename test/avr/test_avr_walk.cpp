// The walker on the ATmega2560 against the host: the benchmark firmware
// walks every model in its default gait (tools/bench/gait_scenario.h, quick
// mode) and prints the joints and odometry it ends with; the host replays
// the same walk. Fixed must agree bit for bit (avr-gcc 5.4 has miscompiled
// this code before), float within rounding (avr-libc's float math is not
// glibc's).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "avr_sim.h"
#include "bench_protocol.h"
#include "gait_scenario.h"

namespace {

using strider::Fixed;

const strider_sim::RunResult& avr_run() {
  static const strider_sim::RunResult result = [] {
    strider_sim::RunOptions opt;
    opt.elf_path = STRIDER_BENCH_ELF;
    opt.mode = STRIDER_BENCH_MODE_QUICK | STRIDER_BENCH_MODE_NO_EXACT;
    opt.max_cycles = 2000000000ull;
    return strider_sim::run_firmware(opt);
  }();
  return result;
}

//! The firmware's "walk NAME h h ..." record for NAME, empty if none.
std::vector<int32_t> avr_record(const std::string& name) {
  for (const std::string& line : avr_run().info) {
    std::istringstream in(line);
    std::string tag, n;
    in >> tag >> n;
    if (tag != "walk" || n != name) continue;
    std::vector<int32_t> v;
    std::string h;
    while (in >> h) v.push_back(int32_t(std::strtoul(h.c_str(), nullptr, 16)));
    return v;
  }
  return {};
}

template <typename S>
std::vector<int32_t> host_record(const strider::RobotModel& m) {
  std::unique_ptr<strider::Walker<S>> w(new strider::Walker<S>());
  if (!strider_bench::scenario_configure(*w, m)) return {};
  strider_bench::scenario_restart(*w, m, strider_bench::scenario_speed(*w));
  const uint16_t ticks = uint16_t(strider_bench::kGaitTicks / 8);  // quick mode
  for (uint16_t k = 0; k < ticks; ++k) w->tick(strider::scalar<S>(0.02));
  int32_t v[strider_bench::kWalkRecordMax];
  const uint8_t n = strider_bench::walk_record(*w, v);
  return std::vector<int32_t>(v, v + n);
}

TEST(AvrWalk, RunCompletes) { ASSERT_TRUE(avr_run().ok) << avr_run().error; }

TEST(AvrWalk, FixedBitExact) {
  ASSERT_TRUE(avr_run().ok) << avr_run().error;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    const std::vector<int32_t> avr = avr_record(std::string(m->name) + "_fixed");
    const std::vector<int32_t> host = host_record<Fixed>(*m);
    ASSERT_FALSE(host.empty());
    EXPECT_EQ(avr, host);
  }
}

TEST(AvrWalk, FloatWithinRounding) {
  ASSERT_TRUE(avr_run().ok) << avr_run().error;
  // 1e-3 rad of a joint, 0.1 mm of odometry after the walk.
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    const std::vector<int32_t> avr = avr_record(std::string(m->name) + "_float");
    const std::vector<int32_t> host = host_record<float>(*m);
    ASSERT_EQ(avr.size(), host.size());
    for (size_t i = 0; i < host.size(); ++i) {
      const bool odometry = i + 2 >= host.size();
      EXPECT_NEAR(avr[i], host[i], odometry ? 6554 : 66) << "value " << i;
    }
  }
}

}  // namespace
