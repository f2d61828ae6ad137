// The constructors for zeroed storage (math/zeroed_storage.h), which the
// firmware uses to build its RobotApp in place in .bss: for every model,
// float and Fixed, the object they build equals, byte for byte, the one the
// default constructor builds in zeroed storage; so do the parts that have
// such a constructor. Both apps then start, take the same commands and
// ticks and give the same lines and servo writes. Built three times: with
// the host's six walker legs, with six on one leg solver (hexapod18's
// firmware layout) and with four on two (dog12's; four-legged models only).
#include <gtest/gtest.h>

#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "control/robot_app.h"
#include "fakes/fake_store.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "robots/all_robots.h"

namespace {

using strider::Fixed;
using strider::kZeroedStorage;

// Static storage for a T, every byte set to kFill before each use through a
// barrier, so that the compiler cannot treat the filling as dead before the
// constructor. kWhich tells the arrays of one type apart.
template <typename T, int kWhich, unsigned char kFill>
struct Filled {
  alignas(T) static unsigned char bytes[sizeof(T)];
  static void* fill() {
    std::memset(bytes, kFill, sizeof bytes);
    asm volatile("" : : "r"(bytes) : "memory");
    return bytes;
  }
};
template <typename T, int kWhich, unsigned char kFill>
alignas(T) unsigned char Filled<T, kWhich, kFill>::bytes[sizeof(T)];

// Zeroed storage the way the firmware has it: a static array (two per type:
// the default constructor's and the tag's).
template <typename T, int kWhich>
struct Zeroed {
  static void* clear() { return Filled<T, kWhich, 0>::fill(); }
};

// Storage that held something else: the default constructor must not rely
// on zeros (objects on the stack or in reused memory take it).
template <typename T>
struct Garbage {
  static void* fill() { return Filled<T, 2, 0xA5>::fill(); }
};

template <typename T>
bool same_bytes(const T* a, const T* b) {
  return std::memcmp(static_cast<const void*>(a), static_cast<const void*>(b), sizeof(T)) == 0;
}

template <typename T>
void expect_same_part(const char* what) {
  T* by_default = new (Zeroed<T, 0>::clear()) T();
  T* by_tag = new (Zeroed<T, 1>::clear()) T(kZeroedStorage);
  EXPECT_TRUE(same_bytes(by_default, by_tag)) << what;
  by_default->~T();
  by_tag->~T();
}

template <typename S>
void expect_same_parts() {
  expect_same_part<strider::GaitConfig<S>>("GaitConfig");
  expect_same_part<strider::VelocityLimits<S>>("VelocityLimits");
  expect_same_part<strider::SupportPolygon<S>>("SupportPolygon");
  expect_same_part<strider::BodyShift<S>>("BodyShift");
  expect_same_part<strider::GaitEngine<S>>("GaitEngine");
  expect_same_part<strider::Walker<S>>("Walker");
  expect_same_part<strider::WalkerMotion<S>>("WalkerMotion");
  expect_same_part<strider::ServoTickMap<S, strider::kMaxServoJoints, 0>>("ServoTickMap");
  expect_same_part<strider::ServoTickMap<S, 18, 3>>("ServoTickMap, 3 slots");
  expect_same_part<strider::ServoStage<S, strider::kMaxServoJoints>>("ServoStage");
}

TEST(ZeroedStorage, PartsEqualTheirDefaultState) {
  expect_same_part<strider::PhaseClock>("PhaseClock");
  expect_same_part<strider::CommandParser>("CommandParser");
  expect_same_part<strider::SonarFilter>("SonarFilter");
  expect_same_part<strider::Avoidance>("Avoidance");
  expect_same_part<strider::Deadman>("Deadman");
  expect_same_parts<float>();
  expect_same_parts<Fixed>();
}

struct Lines {
  std::vector<std::string> sent;
  void send_line(uint8_t port, const char* line) { sent.push_back(std::to_string(port) + " " + line); }
};

template <typename S>
using App = strider::RobotApp<S, strider_test::RecordingServo, strider_test::FakeStore>;

// What an app sends and writes for a fixed script: start-up, stand up,
// commands on both ports, walking and turning, status, relax.
template <typename S>
std::vector<std::string> run_script(App<S>& app, strider_test::RecordingServo& out) {
  Lines lines;
  uint32_t now_us = 1000;
  app.begin(now_us, lines);
  std::vector<std::string> log;
  auto ticks = [&](int n) {
    for (int i = 0; i < n; ++i) {
      now_us += strider::kTickPeriodUs;
      app.tick(now_us, lines);
    }
    for (const auto& w : out.writes) log.push_back("w " + std::to_string(w.channel) + " " + std::to_string(w.ticks));
    for (uint8_t ch : out.relaxed) log.push_back("r " + std::to_string(ch));
    out.writes.clear();
    out.relaxed.clear();
  };
  auto send = [&](uint8_t port, const std::string& text) {
    for (unsigned char b : text) app.on_byte(port, b, now_us, lines);
  };
  ticks(150);
  send(0, "status\r\n");
  send(1, "walk 80 0 0\r\n");
  ticks(60);
  send(0, "walk 40 20 15\r\n");
  ticks(60);
  send(1, "status\r\n");
  send(0, "stop\r\n");
  ticks(60);
  send(0, "relax\r\n");
  ticks(10);
  log.insert(log.end(), lines.sent.begin(), lines.sent.end());
  return log;
}

template <typename S>
void expect_same_app(const strider::RobotModel& model) {
  using A = App<S>;
  strider_test::RecordingServo out_default, out_tag;
  strider_test::FakeStore store_default, store_tag;
  A* by_default = new (Zeroed<A, 0>::clear()) A(model, out_default, store_default);
  A* by_tag = new (Zeroed<A, 1>::clear()) A(kZeroedStorage, model, out_tag, store_tag);
  // The addresses of the fakes and of the app's own parts (the sink's
  // reference to the app, the stage's to the controller's settings) differ:
  // the default's bytes with the tag app's addresses; nothing else may differ.
  std::vector<unsigned char> a(reinterpret_cast<unsigned char*>(by_default),
                               reinterpret_cast<unsigned char*>(by_default) + sizeof(A));
  std::vector<unsigned char> b(reinterpret_cast<unsigned char*>(by_tag), reinterpret_cast<unsigned char*>(by_tag) + sizeof(A));
  const uintptr_t base_a = reinterpret_cast<uintptr_t>(by_default), base_b = reinterpret_cast<uintptr_t>(by_tag);
  for (size_t i = 0; i + sizeof(uintptr_t) <= a.size(); i += alignof(void*)) {
    uintptr_t v;
    std::memcpy(&v, &a[i], sizeof v);
    if (v >= base_a && v < base_a + sizeof(A)) v = v - base_a + base_b;
    else if (v == reinterpret_cast<uintptr_t>(&out_default)) v = reinterpret_cast<uintptr_t>(&out_tag);
    else if (v == reinterpret_cast<uintptr_t>(&store_default)) v = reinterpret_cast<uintptr_t>(&store_tag);
    else continue;
    std::memcpy(&a[i], &v, sizeof v);
  }
  size_t first = 0;
  while (first < a.size() && a[first] == b[first]) ++first;
  EXPECT_EQ(first, a.size()) << model.name << ": the bytes differ from offset " << first << " of " << sizeof(A);
  const std::vector<std::string> tag_log = run_script(*by_tag, out_tag);
  EXPECT_EQ(run_script(*by_default, out_default), tag_log) << model.name;
  by_default->~A();
  by_tag->~A();
  // The default constructor in storage that was not zero: every member it
  // leaves to the zeroed-storage path would show here as other lines or
  // servo writes.
  strider_test::RecordingServo out_garbage;
  strider_test::FakeStore store_garbage;
  A* on_garbage = new (Garbage<A>::fill()) A(model, out_garbage, store_garbage);
  EXPECT_EQ(run_script(*on_garbage, out_garbage), tag_log) << model.name << ", default constructor on non-zero storage";
  on_garbage->~A();
}

TEST(ZeroedStorage, RobotAppEqualsItsDefaultStateForEveryModel) {
  int tested = 0;
  for (uint8_t r = 0; r < strider::kRobotCount; ++r) {
    const strider::RobotModel& model = *strider::kAllRobots[r];
    if (model.leg_count > strider::kWalkerLegs) continue;
    expect_same_app<float>(model);
    expect_same_app<Fixed>(model);
    ++tested;
  }
  EXPECT_GT(tested, 0);
}

}  // namespace
