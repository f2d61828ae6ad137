// A whole robot on the host as a user meets it: RobotApp<float> with a
// recording servo output, an in-memory EEPROM, a manual clock, the lines it
// sent, and every servo write kept in order (to compare two robots).
#ifndef STRIDER_TEST_CONTROL_APP_RIG_H
#define STRIDER_TEST_CONTROL_APP_RIG_H

#include <stdint.h>

#include <string>
#include <vector>

#include "control/robot_app.h"
#include "fake_store.h"
#include "recording_servo.h"

namespace strider_test {

struct SentLines {
  std::vector<std::string> sent;
  void send_line(uint8_t, const char* line) { sent.push_back(line); }
};

struct AppRig {
  using App = strider::RobotApp<float, RecordingServo, FakeStore>;
  RecordingServo out;
  FakeStore store;
  SentLines lines;
  App app;
  uint32_t now_us = 1000;
  std::vector<uint16_t> frames;                    // channel, ticks of every write; 0xF000 + channel: relaxed
  const strider::ImuSample<float>* imu = nullptr;  // fed before every tick when set
  uint16_t battery_code = 0;                       // fed before every tick when non-zero
  bool began = false;                              // RobotApp::begin() took the model

  explicit AppRig(const strider::RobotModel& m) : app(m, out, store) { began = app.begin(now_us, lines); }

  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; t += 20) {
      now_us += strider::kTickPeriodUs;
      if (imu != nullptr) app.imu(imu, lines);
      if (battery_code != 0) app.battery(battery_code, lines);
      app.tick(now_us, lines);
      for (const auto& w : out.writes) {
        frames.push_back(w.channel);
        frames.push_back(w.ticks);
      }
      for (uint8_t ch : out.relaxed) frames.push_back(uint16_t(0xF000u + ch));
      out.writes.clear();
      out.relaxed.clear();
    }
  }
  void bytes(const std::string& s) {
    for (unsigned char b : s) app.on_byte(1, b, now_us, lines);
  }
  //! The reply to `line` (notices skipped), "(no reply)" if none, after
  //! running settle_ms.
  std::string reply(const std::string& line, uint32_t settle_ms = 0) {
    const size_t before = lines.sent.size();
    bytes(line + "\r\n");
    run_ms(settle_ms);
    for (size_t i = before; i < lines.sent.size(); ++i)
      if (lines.sent[i].rfind("info", 0) != 0) return lines.sent[i];
    return "(no reply)";
  }
};

}  // namespace strider_test

#endif  // STRIDER_TEST_CONTROL_APP_RIG_H
