// libFuzzer target: operator input of any kind through the whole robot, the
// RobotApp the firmware runs (two link ports with their parsers, controller
// with deadman and avoidance, walker, servo stage), with host fakes for the
// servo boards, the EEPROM and the sonar, and a manual clock.
//
// Input: byte 0 picks the model (its low 6 bits modulo the built-in models),
// the scalar (bit 7: Fixed, else float) and the clock's start (bit 6: 2 s
// before the microsecond count wraps); then every byte goes to the current
// port as if received, except these directives:
//   0xF0-0xF7  2^(b - 0xF0) control ticks of 20 ms (20 ms .. 2.56 s)
//   0xF8       switch port (0 USB, 1 Bluetooth)
//   0xF9 d     the sonar from now on: an echo at d * 12 mm (0: no echo at all;
//              before any 0xF9: nothing within 3 m)
//   0xFA       the loop stalls: 300 ms pass without a tick
//   0xFB       the last tick took 25 ms (an overrun)
//   0xFC s     one command of random_operator_command() (random_commands.h),
//              its random stream seeded with s
// then 1 s of ticks. At most kMaxTicks ticks per input. With
// STRIDER_FUZZ_TRACE set in the environment, every line the robot sent is
// printed (to read what an input does when run on its own).
//
// Invariants, checked as it runs (abort() when one breaks):
//   - every line the robot sends starts with `ok`, `err` or `info`, and has
//     no line end or control byte in it;
//   - every port gets exactly one `ok`/`err` per line or error that a
//     second CommandParser, fed the same bytes and idle timeouts, reports
//     (every line answered, none twice; RC bytes and blank lines get none);
//   - every servo write is within its channel's joint limits, in ticks of
//     the stage's current PWM timing;
//   - the walker's joint angles and feet stay finite.
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <string>
#include <vector>

#include "control/robot_app.h"
#include "fakes/fake_store.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "math/prng.h"
#include "random_commands.h"
#include "robots/all_robots.h"

namespace {

constexpr uint32_t kMaxTicks = 3000;  // 60 s of robot time per input at most

struct Lines {
  std::vector<std::pair<uint8_t, std::string>> sent;
  void send_line(uint8_t port, const char* line) { sent.emplace_back(port, line); }
};

bool finite_scalar(float v) { return v == v && v < 1e30f && v > -1e30f; }
bool finite_scalar(strider::Fixed) { return true; }

void check(bool ok) {
  if (!ok) abort();
}

template <typename S>
class Run {
 public:
  Run(const strider::RobotModel& m, uint32_t start_us) : model_(m), now_us_(start_us), app_(m, out_, store_) {
    check(app_.begin(now_us_, lines_));
    check_lines();
  }

  void feed(const uint8_t* data, size_t size) {
    for (size_t i = 0; i < size; ++i) {
      const uint8_t b = data[i];
      if (b >= 0xF0 && b <= 0xF7) {
        ticks(1u << (b - 0xF0));
      } else if (b == 0xF8) {
        port_ ^= 1u;
      } else if (b == 0xF9 && i + 1 < size) {
        echo_mm_ = uint16_t(data[++i]) * 12u;
      } else if (b == 0xFA) {
        now_us_ += 300000u;
      } else if (b == 0xFB) {
        app_.record_tick_time(25000);
      } else if (b == 0xFC && i + 1 < size) {
        strider::Prng rng(0xF022u + data[++i]);
        const std::string text = strider_test::random_operator_command([&] { return rng.next_u32(); });
        for (char c : text) byte(uint8_t(c));
      } else {
        byte(b);
      }
    }
    ticks(50);
    if (getenv("STRIDER_FUZZ_TRACE") != nullptr) {
      for (const auto& l : lines_.sent) printf("%d< %s\n", int(l.first), l.second.c_str());
      printf("%u ticks, %u servo writes\n", unsigned(ticks_run_), unsigned(writes_));
    }
  }

 private:
  void byte(uint8_t b) {
    last_byte_ms_[port_] = now_us_ / 1000u;
    strider::Command c;
    count(port_, shadow_[port_].feed(b, &c), c);
    app_.on_byte(port_, b, now_us_, lines_);
    check_lines();
  }

  // What the app's parser reported, from the shadow parser: a reply is due
  // for every error and every command of a line.
  void count(uint8_t port, strider::ParseResult r, const strider::Command& c) {
    if (r == strider::ParseResult::kError ||
        (r == strider::ParseResult::kCommand && c.source == strider::CommandSource::kLine))
      ++expected_[port];
  }

  void ticks(uint32_t n) {
    for (; n != 0 && ticks_run_ < kMaxTicks; --n, ++ticks_run_) {
      now_us_ += strider::kTickPeriodUs;
      if (app_.sonar().ping_due(now_us_)) {
        const strider::EchoSample s{echo_mm_ == 0 ? strider::EchoKind::kNoEdge : strider::EchoKind::kEcho,
                                    uint16_t(echo_mm_ * 2000u / 343u), now_us_};
        app_.sonar().add(s, now_us_);
      }
      // The app's idle rule (RobotApp::tick_controller) on the shadow parsers.
      for (uint8_t p = 0; p < strider::kLinkPorts; ++p) {
        if (strider::elapsed(now_us_ / 1000u, last_byte_ms_[p]) < strider::kLineIdleMs) continue;
        strider::Command c;
        count(p, shadow_[p].idle_timeout(&c), c);
      }
      app_.tick(now_us_, lines_);
      check_writes();
      check_lines();
      check_finite();
    }
  }

  void check_lines() {
    for (; checked_lines_ < lines_.sent.size(); ++checked_lines_) {
      const auto& l = lines_.sent[checked_lines_];
      const std::string& t = l.second;
      const bool info = t.compare(0, 5, "info ") == 0;
      check(info || t.compare(0, 3, "ok ") == 0 || t == "ok" || t.compare(0, 4, "err ") == 0);
      check(t.size() < strider::kMaxReplyBytes);
      for (char c : t) check(c >= 0x20 && c < 0x7F);
      if (!info) {
        check(l.first < strider::kLinkPorts);  // a reply goes to the port it answers
        ++replies_[l.first];
      }
    }
    for (uint8_t p = 0; p < strider::kLinkPorts; ++p) check(replies_[p] == expected_[p]);
  }

  void check_writes() {
    const auto& stage = app_.servos();
    for (const auto& w : out_.writes) {
      bool found = false;
      for (uint8_t k = 0; k < stage.joint_count(); ++k) {
        const auto c = stage.channel(k);
        if (c.channel != w.channel) continue;
        found = true;
        const uint16_t lo = stage.timing().pulse_ticks(strider::servo_pulse_us(c, c.min_rad));
        const uint16_t hi = stage.timing().pulse_ticks(strider::servo_pulse_us(c, c.max_rad));
        check(w.ticks >= lo && w.ticks <= hi);
      }
      check(found);
    }
    writes_ += uint32_t(out_.writes.size());
    out_.writes.clear();
    out_.relaxed.clear();
  }

  void check_finite() {
    const auto& walker = app_.motion().walker();
    for (uint8_t i = 0; i < model_.leg_count; ++i) {
      for (uint8_t j = 0; j < model_.dof(); ++j) check(finite_scalar(walker.leg(i).q[j]));
      const auto& f = walker.engine().foot(i);
      check(finite_scalar(f.x) && finite_scalar(f.y) && finite_scalar(f.z));
    }
  }

  const strider::RobotModel& model_;
  strider_test::RecordingServo out_;
  strider_test::FakeStore store_;
  Lines lines_;
  uint32_t now_us_;
  strider::RobotApp<S, strider_test::RecordingServo, strider_test::FakeStore> app_;
  strider::CommandParser shadow_[strider::kLinkPorts];
  uint32_t last_byte_ms_[strider::kLinkPorts] = {0, 0};
  uint32_t expected_[strider::kLinkPorts] = {0, 0};
  uint32_t replies_[strider::kLinkPorts] = {0, 0};
  size_t checked_lines_ = 0;
  uint32_t ticks_run_ = 0;
  uint32_t writes_ = 0;
  uint16_t echo_mm_ = 3060;  // nothing within the sensor's 3 m
  uint8_t port_ = 1;
};

template <typename S>
void run(const strider::RobotModel& m, uint32_t start_us, const uint8_t* data, size_t size) {
  Run<S>* r = new Run<S>(m, start_us);  // the app is large: not on the fuzzer's stack
  r->feed(data, size);
  delete r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const strider::RobotModel& m = *strider::kAllRobots[(data[0] & 0x3Fu) % strider::kRobotCount];
  const uint32_t start_us = (data[0] & 0x40u) ? 0xFFFFFFFFu - 2000000u : 1000u;
  if (data[0] & 0x80u) {
    run<strider::Fixed>(m, start_us, data + 1, size - 1);
  } else {
    run<float>(m, start_us, data + 1, size - 1);
  }
  return 0;
}
