// RobotApp, the firmware's whole loop with fakes: boot notices, soft start
// one leg at a time, the standing pose's pulses equal an independent IK +
// servo map, slew-limited outputs within every channel's limits while
// walking, relax and wake-up, two ports that never mix their lines, and
// pose/height refusals that change nothing, seeded random operator input
// within every limit. Every model, float and Fixed.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "control/robot_app.h"
#include "fakes/fake_store.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "math/prng.h"
#include "random_commands.h"
#include "robots/all_robots.h"

namespace {

struct Lines {
  std::vector<std::pair<uint8_t, std::string>> sent;
  void send_line(uint8_t port, const char* line) { sent.emplace_back(port, line); }
  std::vector<std::string> on(uint8_t port) const {
    std::vector<std::string> out;
    for (const auto& l : sent)
      if (l.first == port || l.first == strider::kAllPorts) out.push_back(l.second);
    return out;
  }
};

template <typename S, typename P = strider::HostProfile<S>>
struct Rig {
  using App = strider::RobotApp<S, strider_test::RecordingServo, strider_test::FakeStore, P>;
  const strider::RobotModel& model;
  strider_test::RecordingServo out;
  strider_test::FakeStore store;
  Lines lines;
  App* app = nullptr;
  uint32_t now_us = 1000;
  std::map<uint8_t, uint16_t> ticks;  // last written per channel
  std::map<uint8_t, int> max_jump;    // largest change between writes per channel
  std::map<uint8_t, std::pair<uint16_t, uint16_t>> range;  // lowest, highest written per channel

  //! held: what the boards drive at start-up (a warm start, RobotApp::begin()).
  explicit Rig(const strider::RobotModel& m, const uint16_t* held = nullptr, uint8_t channels = 0) : model(m) {
    app = new App(model, out, store);
    EXPECT_TRUE(app->begin(now_us, lines, held, channels));
  }
  ~Rig() { delete app; }

  void collect() {
    for (uint8_t ch : out.relaxed) ticks.erase(ch);  // a frame relaxes before it writes
    for (const auto& w : out.writes) {
      auto it = ticks.find(w.channel);
      if (it != ticks.end()) {
        const int jump = std::abs(int(w.ticks) - int(it->second));
        max_jump[w.channel] = std::max(max_jump[w.channel], jump);
      }
      ticks[w.channel] = w.ticks;
      auto r = range.emplace(w.channel, std::make_pair(w.ticks, w.ticks)).first;
      r->second.first = std::min(r->second.first, w.ticks);
      r->second.second = std::max(r->second.second, w.ticks);
    }
    out.writes.clear();
    out.relaxed.clear();
  }
  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; t += 20) {
      now_us += strider::kTickPeriodUs;
      app->tick(now_us, lines);
      collect();
    }
  }
  void send(uint8_t port, const std::string& text) {
    for (unsigned char b : text) app->on_byte(port, b, now_us, lines);
  }
};

// The standing pulses from the model alone: the library's IK of each leg's
// standing foot and the channel map, computed here step by step.
template <typename S>
std::map<uint8_t, uint16_t> expected_standing(const strider::RobotModel& m, const strider::Pca9685Timing& timing) {
  std::map<uint8_t, uint16_t> out;
  strider::ServoChannel<S> ch[strider::kMaxServoJoints];
  EXPECT_EQ(strider::make_channel_map<S>(m, ch), m.joint_count());
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    strider::AnyLeg<S> leg;
    EXPECT_TRUE(strider::AnyLeg<S>::from_model(m, i, leg));
    typename strider::AnyLeg<S>::Joints q;
    strider::Vec3<S> reached;
    const auto target = leg.mount().body_to_leg(strider::Vec3<S>::from(m.legs[i].stand_mm));
    EXPECT_NE(leg.ik(target, q, reached), strider::IkStatus::kUnreachable);
    for (uint8_t j = 0; j < m.dof(); ++j) {
      const auto& c = ch[i * m.dof() + j];
      out[c.channel] = strider::map_joint(c, q[j], S(0), timing).ticks;
    }
  }
  return out;
}

template <typename S>
class RobotAppTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(RobotAppTest, Scalars);

TYPED_TEST(RobotAppTest, BootsSoftStartsAndStandsOnTheIkPose) {
  using S = TypeParam;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    Rig<S> r(*m);
    const auto boot = r.lines.on(1);
    ASSERT_EQ(boot.size(), 2u);
    EXPECT_EQ(boot[0].rfind(std::string("info strider ") + m->name + " ready", 0), 0u) << boot[0];
    EXPECT_EQ(boot[1], "info eeprom empty, defaults");
    // First tick: every output off, then the first leg only.
    r.now_us += strider::kTickPeriodUs;
    r.app->tick(r.now_us, r.lines);
    EXPECT_EQ(r.out.relaxed.size(), m->joint_count());
    EXPECT_EQ(r.out.writes.size(), m->dof());
    r.collect();
    // One more leg every soft-start step.
    r.run_ms(strider::kSoftStartStepMs);
    EXPECT_EQ(r.ticks.size(), 2u * m->dof());
    r.run_ms(strider::kSoftStartStepMs * m->leg_count + 3000);
    ASSERT_EQ(r.ticks.size(), m->joint_count());
    EXPECT_EQ(r.app->motion().walker().engine().state(), strider::GaitState::kStanding);
    const auto expected = expected_standing<S>(*m, r.app->servos().timing());
    for (const auto& e : expected) {
      // Fixed: the walker's feet come from the gait engine, the expectation
      // from the model directly: allow one tick (~0.09 deg at 50 Hz).
      EXPECT_NEAR(r.ticks[e.first], e.second, 1) << "channel " << int(e.first);
    }
    EXPECT_GT(r.out.flushes, 0);
  }
}

TYPED_TEST(RobotAppTest, WalksWithinLimitsAndNeverJumps) {
  using S = TypeParam;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    Rig<S> r(*m);
    r.run_ms(strider::kSoftStartStepMs * m->leg_count + 3000);
    r.max_jump.clear();
    r.range.clear();
    r.send(1, "speed 100\nwalk 60\n");
    const auto replies = r.lines.on(1);
    ASSERT_GE(replies.size(), 4u);
    EXPECT_EQ(replies[replies.size() - 1].rfind("ok move", 0), 0u) << replies.back();
    for (int k = 0; k < 40; ++k) {
      r.send(1, "F");  // the RC app repeats a held button: the deadman stays fed
      r.run_ms(100);
    }
    EXPECT_EQ(r.app->controller().mode(), strider::RobotMode::kWalking);
    int moved = 0;
    const auto& stage = r.app->servos();
    for (uint8_t k = 0; k < stage.joint_count(); ++k) {
      const auto& c = stage.channel(k);
      const uint16_t lo = stage.timing().pulse_ticks(strider::servo_pulse_us(c, c.min_rad));
      const uint16_t hi = stage.timing().pulse_ticks(strider::servo_pulse_us(c, c.max_rad));
      EXPECT_GE(r.ticks[c.channel], lo);
      EXPECT_LE(r.ticks[c.channel], hi);
      if (r.range.count(c.channel) == 0) continue;  // not written while walking (a joint at rest)
      EXPECT_GE(r.range[c.channel].first, lo);
      EXPECT_LE(r.range[c.channel].second, hi);
      if (r.range[c.channel].second - r.range[c.channel].first > 5) ++moved;
      // Never more per frame than the servo turns in 20 ms (+1 tick rounding).
      const double us = strider::servo_speed_deg_s(m->servo[k % m->dof()]) * 0.02 * 2000.0 / 180.0;
      EXPECT_LE(r.max_jump[c.channel], int(us * 4096.0 / 20000.0 * 1.02) + 1) << "channel " << int(c.channel);
    }
    EXPECT_GT(moved, m->joint_count() / 2);
  }
}

// Seeded random operator input for 40 s on every model: any command with any
// number (in range and far out of it), gait changes, RC buttons, relax and
// wake-up, and bytes of garbage, a few a second. Every line answered is
// `ok`, `err` or `info`; every servo write stays within its channel's joint
// limits; the joints and feet stay finite (float has NaN to lose: the
// quadrupeds' firmwares compute in float).
bool finite_scalar(float v) { return v == v && v < 1e30f && v > -1e30f; }
bool finite_scalar(strider::Fixed) { return true; }  // every value is finite

TYPED_TEST(RobotAppTest, RandomOperatorInputStaysWithinLimits) {
  using S = TypeParam;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    Rig<S> r(*m);
    r.run_ms(strider::kSoftStartStepMs * m->leg_count + 2000);
    r.send(1, "$deadman off*cb77\n");  // the deadman off: a checked line
    strider::Prng rng(0x5EED0000u + uint32_t(m->leg_count) * 31u + uint32_t(m->kind));
    const auto& stage = r.app->servos();
    int commands = 0, out_of_limits = 0, not_finite = 0, walking = 0, writes = 0;
    for (int tick = 0; tick < 2000; ++tick) {
      if (rng.next_u32() % 8 == 0) {
        r.send(uint8_t(rng.next_u32() % 2), strider_test::random_operator_command([&] { return rng.next_u32(); }));
        ++commands;
      }
      r.now_us += strider::kTickPeriodUs;
      r.app->tick(r.now_us, r.lines);
      for (const auto& w : r.out.writes) {
        for (uint8_t k = 0; k < stage.joint_count(); ++k) {
          const auto& c = stage.channel(k);
          if (c.channel != w.channel) continue;
          const uint16_t lo = stage.timing().pulse_ticks(strider::servo_pulse_us(c, c.min_rad));
          const uint16_t hi = stage.timing().pulse_ticks(strider::servo_pulse_us(c, c.max_rad));
          if (w.ticks < lo || w.ticks > hi) ++out_of_limits;
        }
      }
      writes += int(r.out.writes.size());
      r.collect();
      walking += r.app->controller().mode() == strider::RobotMode::kWalking;
      const auto& walker = r.app->motion().walker();
      for (uint8_t i = 0; i < m->leg_count; ++i) {
        for (uint8_t j = 0; j < m->dof(); ++j) not_finite += !finite_scalar(walker.leg(i).q[j]);
        const auto& f = walker.engine().foot(i);
        not_finite += !finite_scalar(f.x) + !finite_scalar(f.y) + !finite_scalar(f.z);
      }
    }
    std::printf("%s: %d commands, %d of 2000 ticks walking, %d servo writes\n", m->name, commands, walking, writes);
    EXPECT_GT(commands, 200);
    EXPECT_EQ(out_of_limits, 0);
    EXPECT_EQ(not_finite, 0);
    for (const auto& l : r.lines.sent) {
      const std::string& t = l.second;
      EXPECT_TRUE(t.rfind("ok", 0) == 0 || t.rfind("err", 0) == 0 || t.rfind("info", 0) == 0) << t;
    }
    // Still in command afterwards: it stands up and walks when asked.
    r.send(0, "stop\npose 0 0 0\nspeed 100\n");
    r.run_ms(8000);
    r.send(0, "walk 40\n");
    r.run_ms(1000);
    EXPECT_EQ(r.app->controller().mode(), strider::RobotMode::kWalking);
  }
}

TYPED_TEST(RobotAppTest, RelaxThenWakeSoftStartsAgain) {
  using S = TypeParam;
  Rig<S> r(strider::kHexapod18);
  r.run_ms(5000);
  r.send(0, "relax\r\n");
  EXPECT_EQ(r.lines.on(0).back(), "ok relax");
  r.run_ms(20);
  EXPECT_TRUE(r.ticks.empty());  // every channel full-off
  r.run_ms(1000);
  EXPECT_TRUE(r.ticks.empty());  // stays limp
  r.send(0, "stop\r\n");
  r.run_ms(20);
  EXPECT_EQ(r.ticks.size(), 3u);  // one leg back on
  r.run_ms(6000);
  EXPECT_EQ(r.ticks.size(), 18u);
  EXPECT_EQ(r.app->motion().walker().engine().state(), strider::GaitState::kStanding);
}

TYPED_TEST(RobotAppTest, PortsKeepTheirOwnLines) {
  using S = TypeParam;
  Rig<S> r(strider::kSprawl8);
  const std::string a = "status\n", b = "gait trot\n";
  for (size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    if (i < a.size()) r.app->on_byte(0, uint8_t(a[i]), r.now_us, r.lines);
    if (i < b.size()) r.app->on_byte(1, uint8_t(b[i]), r.now_us, r.lines);
  }
  ASSERT_EQ(r.lines.sent.size(), 4u);  // two boot notices, two replies
  EXPECT_EQ(r.lines.sent[2].first, 0);
  EXPECT_EQ(r.lines.sent[2].second.rfind("ok status mode=standing", 0), 0u) << r.lines.sent[2].second;
  EXPECT_NE(r.lines.sent[2].second.find(" gait=crawl"), std::string::npos);
  EXPECT_NE(r.lines.sent[2].second.find(" overruns=0"), std::string::npos);
  EXPECT_EQ(r.lines.sent[3].first, 1);
  EXPECT_EQ(r.lines.sent[3].second, "ok gait trot");
}

// The whole status line, byte for byte (docs/protocol.md), walking after a
// few ticks and with one overrun recorded. sprawl8's crawl makes 0.47 of its
// gait's speed on the ground (speed_correction.h): the command asks 64 mm/s
// of the gait, more than it walks with the sideways and turning parts, so
// walk_* are the body speeds of what the gait can: 0.78 of each part.
TYPED_TEST(RobotAppTest, StatusLineVerbatim) {
  using S = TypeParam;
  Rig<S> r(strider::kSprawl8);
  r.run_ms(3000);
  r.app->record_tick_time(21000);
  const std::string cmd = "$deadman off*cb77\nvel 30 -20 10\n";
  for (char ch : cmd) r.app->on_byte(0, uint8_t(ch), r.now_us, r.lines);
  r.run_ms(1000);
  const size_t from = r.lines.sent.size();
  for (char ch : std::string("status\n")) r.app->on_byte(1, uint8_t(ch), r.now_us, r.lines);
  ASSERT_EQ(r.lines.sent.size(), from + 1);
  EXPECT_EQ(r.lines.sent[from].first, 1);
  // -15.65 mm/s: the last digit is the scalar's rounding.
  const std::string walk_vy = std::is_same<S, float>::value ? "-15.6" : "-15.7";
  EXPECT_EQ(r.lines.sent[from].second,
            "ok status mode=walking speed=50 vx=30.0 vy=-20.0 wz=10.0 avoid=forward sonar=none deadman_ms=0 eeprom=empty "
            "walk_vx=23.5 walk_vy=" + walk_vy + " walk_wz=7.8 gait=crawl state=walking ik=clamped servos=on pca9685=ok i2c_errors=0 "
            "overruns=1 tick_max_us=21000");
}

// The status line with every field at its widest the robot can show at
// once (walking, turning and strafing at the limits, a faulted board on
// each address, every counter at its top, a stack probe) fits the reply
// buffer: nothing is cut off.
TEST(RobotAppStatus, LongestStatusLineFits) {
  Rig<float> r(strider::kHexapod18);
  r.run_ms(5000);
  r.app->set_stack_probe([]() { return uint16_t(1023); });
  r.app->record_tick_time(999999);
  r.app->record_missed_ticks(65535);
  strider::ServoBoardReport rep;
  rep.errors = 65535;
  r.app->servo_boards(rep, r.now_us, r.lines);
  r.send(1, "deadman 60000\nspeed 100\ngait ripple\nvel -499.9 -499.9 -359.9\n");
  r.run_ms(3000);
  const auto status = [&]() {
    const size_t from = r.lines.sent.size();
    r.send(1, "status\n");
    EXPECT_EQ(r.lines.sent.size(), from + 1);
    const std::string line = r.lines.sent.back().second;
    EXPECT_NE(line.find(" stack_peak=1023"), std::string::npos) << line;  // the last field, whole
    EXPECT_LT(line.size() + 1, size_t(strider::kMaxReplyBytes)) << line;
    return line;
  };
  const std::string walking = status();
  EXPECT_NE(walking.find("mode=walking"), std::string::npos) << walking;
  rep.faulted = 3;
  r.app->servo_boards(rep, r.now_us, r.lines);  // stops the walk
  const std::string faulted = status();
  EXPECT_NE(faulted.find(" pca9685=0x40,0x41 i2c_errors=65535 "), std::string::npos) << faulted;
  std::printf("walking: %zu bytes, both boards faulted: %zu bytes (buffer %u)\n", walking.size(), faulted.size(),
              unsigned(strider::kMaxReplyBytes));
}

// A servo board stops answering mid-walk (RobotApp::servo_boards(), from the
// firmware's driver): one notice, the walk stops, walking is refused with
// err 31 and `status` names the board; back in its power-on state, its legs
// get their first pulses again one at a time (a quarter second apart) and
// walking is allowed once they all have.
TYPED_TEST(RobotAppTest, ServoBoardFaultStopsTheWalkUntilTheBoardIsBack) {
  using S = TypeParam;
  const strider::RobotModel& m = strider::kHexapod18;
  Rig<S> r(m);
  r.run_ms(5000);
  r.send(1, "$deadman off*cb77\nwalk 80\n");
  r.run_ms(1000);
  ASSERT_EQ(r.app->controller().mode(), strider::RobotMode::kWalking);
  strider::ServoBoardReport rep;
  rep.faulted = strider::board_bit(1);
  rep.errors = 1;
  size_t from = r.lines.sent.size();
  r.app->servo_boards(rep, r.now_us, r.lines);
  r.app->servo_boards(rep, r.now_us, r.lines);  // the same again: no second notice
  ASSERT_EQ(r.lines.sent.size(), from + 1);
  EXPECT_EQ(r.lines.sent[from].first, strider::kAllPorts);
  EXPECT_EQ(r.lines.sent[from].second, "info fault pca9685 0x41");
  EXPECT_EQ(r.app->controller().mode(), strider::RobotMode::kStanding);
  r.run_ms(2000);
  EXPECT_EQ(r.app->motion().walker().engine().state(), strider::GaitState::kStanding);
  from = r.lines.sent.size();
  r.send(1, "walk 80\nF\nstop\nstatus\n");
  ASSERT_EQ(r.lines.sent.size(), from + 4);
  EXPECT_EQ(r.lines.sent[from].second, "err 31 servo fault: see pca9685= in status; stop, relax and the rest work");
  EXPECT_EQ(r.lines.sent[from + 1].second, "ok rc F");  // the line's echo; the button itself was refused
  EXPECT_EQ(r.lines.sent[from + 2].second, "ok stop");
  EXPECT_NE(r.lines.sent[from + 3].second.find(" servos=on pca9685=0x41 i2c_errors=1 "), std::string::npos)
      << r.lines.sent[from + 3].second;
  EXPECT_EQ(r.app->controller().command().vx, 0);

  // Back in its power-on state: its outputs are off, the others hold theirs.
  std::vector<uint16_t> outputs(32, strider::kPcaFullOff);
  for (const auto& t : r.ticks)
    if (t.first < 16) outputs[t.first] = t.second;
  rep.faulted = 0;
  rep.restored = strider::board_bit(1);
  rep.outputs = outputs.data();
  rep.channels = 32;
  from = r.lines.sent.size();
  r.app->servo_boards(rep, r.now_us, r.lines);
  ASSERT_EQ(r.lines.sent.size(), from + 1);
  EXPECT_EQ(r.lines.sent[from].second, "info pca9685 0x41 restored");
  EXPECT_EQ(r.out.relaxed.size(), 9u);  // the second board's joints: off, as the board is
  r.collect();
  r.max_jump.clear();
  r.run_ms(700);  // legs 0-2 (first board) switched on again from their pulses, legs 3-5 not yet
  for (const auto& t : r.ticks) EXPECT_LT(t.first, 16) << "channel " << int(t.first) << " too early";
  r.send(1, "walk 80\n");
  EXPECT_EQ(r.lines.on(1).back(), "err 31 servo fault: see pca9685= in status; stop, relax and the rest work");
  r.run_ms(1000);
  EXPECT_EQ(r.ticks.size(), m.joint_count());
  const auto expected = expected_standing<S>(m, r.app->servos().timing());
  for (const auto& e : expected) EXPECT_NEAR(r.ticks[e.first], e.second, 1) << "channel " << int(e.first);
  for (const auto& j : r.max_jump) EXPECT_LE(j.second, 2) << "channel " << int(j.first) << " jumped";
  r.send(1, "walk 80\n");
  EXPECT_EQ(r.lines.on(1).back().rfind("ok move", 0), 0u) << r.lines.on(1).back();

  // Lost and back between two reports (a short power cut the driver found
  // and mended at once): both notices, and its legs on again.
  r.collect();
  for (const auto& t : r.ticks) outputs[t.first] = t.first < 16 ? strider::kPcaFullOff : t.second;
  rep.restored = strider::board_bit(0);
  from = r.lines.sent.size();
  r.app->servo_boards(rep, r.now_us, r.lines);
  ASSERT_EQ(r.lines.sent.size(), from + 2);
  EXPECT_EQ(r.lines.sent[from].second, "info fault pca9685 0x40");
  EXPECT_EQ(r.lines.sent[from + 1].second, "info pca9685 0x40 restored");
  EXPECT_EQ(r.app->controller().mode(), strider::RobotMode::kStanding);
  r.run_ms(2000);
  for (const auto& e : expected) EXPECT_NEAR(r.ticks[e.first], e.second, 1) << "channel " << int(e.first);
}

// A warm start: the boards kept the pulses of the run before (an MCU reset
// mid-walk). Every joint whose pulse is within its limits keeps it: no
// relax, the walker starts standing (not sitting: no leg is pulled up),
// and each leg moves from where it is to the standing pose at its soft-start
// turn, slew-limited. A pulse outside its joint's limits is switched off.
TYPED_TEST(RobotAppTest, WarmStartHoldsThePulsesTheBoardsKept) {
  using S = TypeParam;
  for (const strider::RobotModel* m : {&strider::kHexapod18, &strider::kSprawl8}) {
    SCOPED_TRACE(m->name);
    Rig<S> before(*m);
    before.run_ms(5000);
    before.send(1, "$deadman off*cb77\nwalk 80\n");
    before.run_ms(1300);
    ASSERT_EQ(before.app->controller().mode(), strider::RobotMode::kWalking);
    std::vector<uint16_t> outputs(32, strider::kPcaFullOff);
    for (const auto& t : before.ticks) outputs[t.first] = t.second;
    const uint8_t bad = strider::joint_channel(*m, 0, 0);
    outputs[bad] = 4000;  // beyond any joint's limits

    Rig<S> r(*m, outputs.data(), 32);
    const auto boot = r.lines.on(1);
    ASSERT_EQ(boot.size(), 3u);
    EXPECT_EQ(boot[2], "info servos held joints=" + std::to_string(m->joint_count() - 1));
    EXPECT_EQ(r.out.relaxed, std::vector<uint8_t>{bad});
    EXPECT_EQ(r.app->motion().walker().engine().state(), strider::GaitState::kStanding);
    r.out.relaxed.clear();
    for (uint8_t ch = 0; ch < 32; ++ch)
      if (ch != bad && outputs[ch] != strider::kPcaFullOff) r.ticks[ch] = outputs[ch];
    r.run_ms(strider::kSoftStartStepMs * m->leg_count + 3000);
    EXPECT_TRUE(r.out.relaxed.empty());
    EXPECT_EQ(r.app->motion().walker().engine().state(), strider::GaitState::kStanding);
    const auto expected = expected_standing<S>(*m, r.app->servos().timing());
    for (const auto& e : expected) EXPECT_NEAR(r.ticks[e.first], e.second, 1) << "channel " << int(e.first);
    for (uint8_t k = 0; k < m->joint_count(); ++k) {
      const auto c = r.app->servos().channel(k);
      const double us = strider::servo_speed_deg_s(m->servo[k % m->dof()]) * 0.02 * 2000.0 / 180.0;
      EXPECT_LE(r.max_jump[c.channel], int(us * 4096.0 / 20000.0 * 1.02) + 1) << "channel " << int(c.channel);
    }
  }
}

// `text*hhhh` (line_check.h): a checked reply; with `$` before it, a checked line.
std::string with_check(const std::string& text) {
  char buf[strider::kMaxReplyBytes];
  std::snprintf(buf, sizeof buf, "%s", text.c_str());
  strider::append_line_check(buf, uint8_t(text.size()));
  return buf;
}

// A checked line gets a checked reply, a status line and an error too; a
// plain line a plain one. Bytes lost before a line's end: err 10 at that
// end, and nothing from the damaged line runs.
TYPED_TEST(RobotAppTest, CheckedRepliesAndLostBytes) {
  using S = TypeParam;
  Rig<S> r(strider::kSprawl8);
  r.run_ms(3000);
  auto last = [&] { return r.lines.sent.back().second; };
  r.send(0, "$" + with_check("speed 40") + "\r\n");
  EXPECT_EQ(last(), with_check("ok speed pct=40"));
  r.send(0, "$" + with_check("speed 400") + "\r\n");
  EXPECT_EQ(last(), with_check("err 5 out of range: speed 0..100"));
  r.send(0, "$speed 41*0000\r\n");
  EXPECT_EQ(last(), with_check("err 9 bad checksum: $text*hhhh, hhhh the CRC-16 of text"));
  r.send(0, "$" + with_check("status") + "\n");
  const std::string st = last();
  ASSERT_GT(st.size(), 100u);
  EXPECT_EQ(st, with_check(st.substr(0, st.size() - strider::kLineCheckBytes)));
  EXPECT_NE(st.find(" speed=40 "), std::string::npos) << st;
  r.send(0, "speed 45\n");
  EXPECT_EQ(last(), "ok speed pct=45");

  // The gap fell into "speed 7": what is left, "0\n", must not run (and
  // must not set the RC speed 0 either), and is answered err 10.
  const size_t before = r.lines.sent.size();
  r.send(1, "speed 7");
  r.app->on_bytes_lost(1, r.now_us, r.lines);
  r.send(1, "0\n");
  ASSERT_EQ(r.lines.sent.size(), before + 1);
  EXPECT_EQ(last(), "err 10 bytes lost: send the line again");
  EXPECT_EQ(r.lines.sent.back().first, 1);
  EXPECT_EQ(r.app->controller().speed_pct(), 45);
  // Between lines: "00" after a gap is no pair of RC speed bytes.
  r.app->on_bytes_lost(1, r.now_us, r.lines);
  r.send(1, "00\nspeed 60\n");
  EXPECT_EQ(r.lines.sent[r.lines.sent.size() - 2].second, "err 10 bytes lost: send the line again");
  EXPECT_EQ(last(), "ok speed pct=60");
  // The other port is not affected.
  r.app->on_bytes_lost(1, r.now_us, r.lines);
  r.send(0, "speed 61\n");
  EXPECT_EQ(last(), "ok speed pct=61");
  r.send(1, "\n");  // port 1's damaged line ends
  EXPECT_EQ(last(), "err 10 bytes lost: send the line again");
  // Bytes lost at the end of what was sent, then silence: the next line,
  // after the idle time, is whole.
  r.send(1, "speed 6");
  r.now_us += strider::kLineIdleMs * 1000u;
  r.app->on_bytes_lost(1, r.now_us, r.lines);
  EXPECT_EQ(last(), "err 8 incomplete line: end each line with CR or LF");  // "speed 6" lost its end
  r.send(1, "speed 62\n");
  EXPECT_EQ(last(), "ok speed pct=62");
  r.now_us += strider::kLineIdleMs * 1000u;
  const size_t n = r.lines.sent.size();
  r.app->on_bytes_lost(1, r.now_us, r.lines);  // between lines: nothing to answer
  EXPECT_EQ(r.lines.sent.size(), n);
  r.send(1, "speed 63\n");
  EXPECT_EQ(last(), "ok speed pct=63");
}

// `help` names the model's gaits and the heights its legs reach; a refused
// height or pose names what they reach, and those edges are taken.
TYPED_TEST(RobotAppTest, HelpAndRefusalsNameWhatTheModelReaches) {
  using S = TypeParam;
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    Rig<S> r(*m);
    r.run_ms(4000);
    const strider::MotionReach reach = r.app->motion().reach();
    const int stand = int(strider::to_double(r.app->motion().stand_height_mm()) + 0.5);
    EXPECT_LT(reach.height_min_mm, stand);
    EXPECT_GT(reach.height_max_mm, stand);
    auto reply = [&](const std::string& line) {
      r.send(1, line + "\n");
      return r.lines.on(1).back();
    };
    // mammal8's presets (gait_presets.h) follow its gaits.
    const std::string gaits = m->leg_count == 6                      ? "tripod ripple wave"
                              : std::strcmp(m->name, "mammal8") == 0 ? "walk trot pace crawl walk10 trot10 pace10 trot50"
                                                                     : "walk trot pace crawl";
    const std::string heights = std::to_string(reach.height_min_mm) + ".." + std::to_string(reach.height_max_mm);
    const std::string help = reply("help");
    EXPECT_NE(help.find("; gaits " + gaits + "; height " + heights), std::string::npos) << help;
    EXPECT_EQ(reply("gait gallop"), "err 23 unknown gait: " + gaits);
    if (reach.height_max_mm < strider::kReachHeightMaxMm)
      EXPECT_EQ(reply("height " + std::to_string(reach.height_max_mm + 1)),
                "err 24 height refused: " + heights + " with the body level");
    EXPECT_EQ(reply("height " + std::to_string(reach.height_max_mm)).rfind("ok height", 0), 0u);
    EXPECT_EQ(reply("height " + std::to_string(reach.height_min_mm)).rfind("ok height", 0), 0u);
    EXPECT_EQ(reply("height " + std::to_string(stand)).rfind("ok height", 0), 0u);
    const char* axes[3] = {"roll", "pitch", "yaw"};
    std::string poses;
    for (int a = 0; a < 3; ++a) {
      poses += std::string(a ? " " : "") + axes[a] + " " + std::to_string(reach.angle_min_deg[a]) + ".." +
               std::to_string(reach.angle_max_deg[a]);
      for (int deg : {int(reach.angle_min_deg[a]), int(reach.angle_max_deg[a])}) {
        std::string line = "pose";
        for (int k = 0; k < 3; ++k) line += " " + std::to_string(k == a ? deg : 0);
        EXPECT_EQ(reply(line).rfind("ok pose", 0), 0u) << line;
      }
    }
    if (reach.angle_max_deg[0] < strider::kReachAngleMaxDeg)
      EXPECT_EQ(reply("pose " + std::to_string(reach.angle_max_deg[0] + 1) + " 0 0"),
                "err 24 pose refused: " + poses + " one at a time");
    std::printf("%s: height %s (stands at %d), %s\n", m->name, heights.c_str(), stand, poses.c_str());
  }
}

TYPED_TEST(RobotAppTest, RefusedPoseAndGarbageChangeNothing) {
  using S = TypeParam;
  Rig<S> r(strider::kHexapod18);
  r.run_ms(5000);
  r.send(1, "pose 0 0 5\nheight 300\nheight 120\n");
  const auto replies = r.lines.on(1);
  ASSERT_GE(replies.size(), 3u);
  EXPECT_EQ(replies[replies.size() - 3].rfind("ok pose", 0), 0u) << replies[replies.size() - 3];
  EXPECT_EQ(replies[replies.size() - 2].rfind("err 24", 0), 0u) << replies[replies.size() - 2];
  EXPECT_EQ(replies[replies.size() - 1].rfind("ok height", 0), 0u) << replies[replies.size() - 1];
  const S z = r.app->motion().offsets().translation_mm.z;
  EXPECT_NEAR(strider::to_double(z), 10.0, 0.01);  // 120 mm over a 110 mm standing height
  strider::Prng rng(7);
  for (int i = 0; i < 2000; ++i) {
    const uint8_t b = uint8_t(rng.next_u32() & 0xFF);
    if (b == 'F' || b == 'B' || b == 'L' || b == 'R' || b == 'G' || b == 'I' || b == 'H' || b == 'J') continue;
    r.app->on_byte(1, b, r.now_us, r.lines);
  }
  r.send(1, "\nstop\n");
  r.run_ms(2000);
  EXPECT_EQ(r.app->controller().mode(), strider::RobotMode::kStanding);
  EXPECT_EQ(r.app->overruns(), 0);
}

// Calibration rebuilds the servo map from the model (the stage keeps no
// channels of its own), a leg per frame while every output holds its pulse:
// a trim moves its servo by the trim, a new PWM frequency keeps the pulse
// widths, abort goes back to the standing pulses, and no frame jumps.
TYPED_TEST(RobotAppTest, CalibrationRebuildsTheServoMapFromTheModel) {
  using S = TypeParam;
  const strider::RobotModel& m = strider::kHexapod18;
  Rig<S> r(m);
  r.run_ms(5000);
  const auto standing = r.ticks;
  ASSERT_EQ(standing.size(), m.joint_count());
  const auto& stage = r.app->servos();
  const uint8_t k = 4;  // leg 1's femur: mirrored on a right leg, not on a left one
  const strider::ServoChannel<S> ch = strider::make_joint_channel<S>(m, 1, 1);
  EXPECT_EQ(stage.channel(k).channel, ch.channel);
  EXPECT_EQ(stage.channel(k).direction, ch.direction);
  const S q = r.app->motion().walker().leg(1).q[1];
  const auto expect = [&](int16_t trim_decideg) {
    return strider::map_joint(ch, q, strider::trim_from_decideg<S>(trim_decideg), stage.timing()).ticks;
  };
  EXPECT_NEAR(standing.at(ch.channel), expect(0), 1);
  r.max_jump.clear();
  r.send(1, "cal start\ncal trim 4 -5\n");
  EXPECT_EQ(r.lines.on(1).back(), "ok cal trim joint=4 deg=-5.0");
  r.run_ms(20);  // the first frame: apply the settings, fit leg 0; hold
  EXPECT_EQ(r.ticks.at(ch.channel), standing.at(ch.channel));
  r.run_ms(20 * m.leg_count + 200);
  EXPECT_NEAR(r.ticks.at(ch.channel), expect(-50), 1);
  EXPECT_GT(std::abs(int(r.ticks.at(ch.channel)) - int(standing.at(ch.channel))), 8);  // 5 deg: ~11 ticks
  for (const auto& t : standing) {
    if (t.first == ch.channel) continue;
    EXPECT_EQ(r.ticks.at(t.first), t.second) << "channel " << int(t.first);
  }
  // Never more per frame than the servo turns in 20 ms (+1 tick rounding).
  const auto check_slew = [&]() {
    for (const auto& j : r.max_jump) {
      const double us = strider::servo_speed_deg_s(m.servo[j.first % 16 % m.dof()]) * 0.02 * 2000.0 / 180.0;
      EXPECT_LE(j.second, int(us * 262144.0 / double(stage.timing().period_x64()) * 1.02) + 1) << "channel " << int(j.first);
    }
    r.max_jump.clear();
  };
  check_slew();
  // A new period: every pulse keeps its width in the first frame (ticks
  // scaled by the periods' ratio), then the map is rebuilt.
  r.send(1, "cal pwm 100\n");
  r.run_ms(20);
  EXPECT_NEAR(r.ticks.at(ch.channel), expect(-50), 3);  // expect(): the new timing already
  r.max_jump.clear();
  r.run_ms(20 * m.leg_count + 200);
  check_slew();
  EXPECT_NEAR(stage.timing().period_x64(), strider::Pca9685Timing().period_x64() / 2, 2 * 64);  // 10 ms
  EXPECT_NEAR(r.ticks.at(ch.channel), expect(-50), 1);
  r.send(1, "cal abort\n");
  r.run_ms(20);
  r.max_jump.clear();
  r.run_ms(20 * m.leg_count + 400);
  check_slew();
  for (const auto& t : standing) EXPECT_NEAR(r.ticks.at(t.first), t.second, 1) << "channel " << int(t.first);
  EXPECT_EQ(r.app->overruns(), 0);
}

TEST(RobotAppTiming, RecordsOverruns) {
  Rig<float> r(strider::kMammal8);
  r.app->record_tick_time(5000);
  r.app->record_tick_time(25000);
  r.app->record_missed_ticks(3);
  EXPECT_EQ(r.app->overruns(), 4);
  EXPECT_EQ(r.app->tick_max_us(), 25000u);
}

// The boot notice names the record the settings came from (docs/protocol.md):
// its slot and sequence number, the single record of earlier firmware, a
// damaged other slot, or the defaults.
TEST(RobotAppEeprom, BootNoticeNamesTheRecord) {
  Rig<float> r(strider::kSprawl8);
  auto reboot = [&r]() {
    delete r.app;
    r.lines = Lines();
    r.app = new Rig<float>::App(r.model, r.out, r.store);
    EXPECT_TRUE(r.app->begin(r.now_us, r.lines));
    const auto boot = r.lines.on(1);
    return boot.size() == 2 ? boot[1] : std::string("no boot notice");
  };
  r.send(1, "cal start\ncal trim 0 5\ncal save\n");
  EXPECT_EQ(reboot(), "info eeprom ok slot=0 seq=1");
  r.send(1, "speed 80\nsave\n");
  EXPECT_EQ(reboot(), "info eeprom ok slot=1 seq=2");
  r.store.bytes[strider::kSettingsSlotBytes + 30] ^= 0x01;  // slot 1 damaged: slot 0 in force
  EXPECT_EQ(reboot(), "info eeprom ok slot=0 seq=1 other=corrupt");
  r.send(1, "save\n");  // into slot 1 again: the damage is repaired
  EXPECT_EQ(reboot(), "info eeprom ok slot=1 seq=2");
  r.store.bytes[0] ^= 0x01;
  r.store.bytes[strider::kSettingsSlotBytes] ^= 0x01;
  EXPECT_EQ(reboot(), "info eeprom corrupt, defaults");
  // The single record of firmware before the slots (layout version 1).
  r.store.erase();
  uint8_t rec[4 + strider::kSettingsPayloadBytesV2 + 2] = {'S', 'T', 1, strider::kSettingsPayloadBytesV2};
  uint8_t payload[strider::kSettingsPayloadBytes];
  strider::encode_settings(strider::default_settings(), payload);
  std::memcpy(rec + 4, payload, strider::kSettingsPayloadBytesV2);  // its layout: without the offsets
  const uint16_t crc = strider::crc16_ccitt(rec, sizeof rec - 2);
  rec[sizeof rec - 2] = uint8_t(crc);
  rec[sizeof rec - 1] = uint8_t(crc >> 8);
  std::memcpy(r.store.bytes, rec, sizeof rec);
  EXPECT_EQ(reboot(), "info eeprom ok version=1");
}

}  // namespace

namespace {

// The flash copies of the state names are the protocol's (docs/protocol.md)
// and equal the host-side to_string() where there is one.
TEST(FlashNames, EqualToString) {
  const char* const avoid[] = {"pass", "forward", "sidestep", "clearing", "blocked", "sensor_fault"};
  for (uint8_t i = 0; i < 6; ++i) EXPECT_STREQ(strider::to_flash(strider::AvoidState(i)).p, avoid[i]);
  const char* const mode[] = {"standing", "walking", "relaxed", "calibrating"};
  for (uint8_t i = 0; i < 4; ++i) EXPECT_STREQ(strider::to_flash(strider::RobotMode(i)).p, mode[i]);
  const char* const settings[] = {"ok", "empty", "corrupt", "old_version", "invalid", "write_failed", "no_space"};
  for (uint8_t i = 0; i < 7; ++i) EXPECT_STREQ(strider::to_flash(strider::SettingsStatus(i)).p, settings[i]);
  for (uint8_t i = 0; i < 6; ++i)
    EXPECT_STREQ(strider::text::to_flash(strider::GaitState(i)).p, strider::to_string(strider::GaitState(i)));
  for (uint8_t i = 0; i < 4; ++i)
    EXPECT_STREQ(strider::text::to_flash(strider::IkStatus(i)).p, strider::to_string(strider::IkStatus(i)));
  for (uint8_t i = 0; i < strider::kParseErrorCount; ++i)
    EXPECT_STREQ(strider::flash_name(strider::kParseErrorNames, strider::kParseErrorCount, i).p,
                 strider::error_reason(strider::ParseError(i)));
  EXPECT_STREQ(strider::to_flash(strider::AvoidState(6)).p, "?");
}

}  // namespace

namespace {

// Tuned gait parameters replace the defaults before the robot stands; bad
// ones change nothing.
TEST(RobotAppGaitParams, ReplaceTheDefaultsOrChangeNothing) {
  Rig<float> r(strider::kHexapod18);
  strider::GaitParams p = *strider::gait_params_for(strider::kHexapod18);
  p.step_height_mm += 10.0f;
  ASSERT_TRUE(r.app->set_gait_params(p));
  EXPECT_NEAR(double(r.app->motion().walker().engine().config().step_height_mm), double(p.step_height_mm), 1e-4);
  strider::GaitParams bad = p;
  std::strcpy(bad.default_gait, "gallop");  // a name of no gait (fits kGaitNameBytes)
  EXPECT_FALSE(r.app->set_gait_params(bad));
  EXPECT_NEAR(double(r.app->motion().walker().engine().config().step_height_mm), double(p.step_height_mm), 1e-4);
  r.run_ms(strider::kSoftStartStepMs * 6 + 3000);
  EXPECT_EQ(r.app->motion().walker().engine().state(), strider::GaitState::kStanding);
}

}  // namespace
