// The controller with a fake motion sink, in-memory EEPROM and manual clock:
// one reply per line, RC buttons scaled by speed, deadman, avoidance
// sequences, calibration save/abort through the link, EEPROM fallback.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "control/controller.h"
#include "fakes/fake_motion_sink.h"
#include "fakes/fake_store.h"
#include "fakes/manual_clock.h"

using strider::RobotMode;
using strider::SonarReading;
using strider::SonarStatus;
using strider_test::FakeMotionSink;
using strider_test::FakeStore;
using strider_test::ManualClock;

namespace {

struct Rig {
  FakeMotionSink sink;
  FakeStore store;
  ManualClock clock;
  strider::Settings loaded;
  strider::SettingsStatus load_status;
  strider::Controller<FakeMotionSink, FakeStore>* ctl = nullptr;
  SonarReading sonar{SonarStatus::kOk, strider::kSonarFarMm};

  Rig() {
    load_status = strider::load_settings(store, &loaded);
    ctl = new strider::Controller<FakeMotionSink, FakeStore>(sink, store, loaded, load_status);
  }
  ~Rig() { delete ctl; }

  std::vector<std::string> send(const std::string& bytes) {
    std::vector<std::string> replies;
    for (unsigned char b : bytes) {
      char buf[strider::kMaxReplyBytes];
      strider::ReplyWriter w(buf, sizeof buf);
      if (ctl->on_byte(b, clock.now_ms(), w)) replies.push_back(w.c_str());
    }
    return replies;
  }
  std::vector<std::string> run_ms(uint32_t ms) {
    std::vector<std::string> notes;
    for (uint32_t t = 0; t < ms; t += 20) {
      clock.advance_ms(20);
      char buf[strider::kMaxReplyBytes];
      strider::ReplyWriter w(buf, sizeof buf);
      if (ctl->tick(clock.now_ms(), sonar, w)) notes.push_back(w.c_str());
    }
    return notes;
  }
};

TEST(Controller, OneReplyPerLine) {
  Rig r;
  const auto replies = r.send("walk 100\r\nspeed 70\nbogus\r\ngait trot\ngait gallop\nstatus\nhelp\n\n\r\n");
  ASSERT_EQ(replies.size(), 7u);
  EXPECT_EQ(replies[0], "ok move vx=100.0 vy=0.0 wz=0.0");
  EXPECT_EQ(replies[1], "ok speed pct=70");
  EXPECT_EQ(replies[2], "err 1 unknown command: walk strafe turn vel stop relax speed gait pose height level set get avoid deadman baud cal save status help");
  EXPECT_EQ(replies[3], "ok gait trot");
  EXPECT_EQ(replies[4], "err 23 unknown gait: walk trot pace crawl");
  EXPECT_EQ(replies[5].rfind("ok status mode=walking speed=70", 0), 0u) << replies[5];
  EXPECT_NE(replies[5].find("eeprom=empty"), std::string::npos);
  EXPECT_EQ(replies[6].rfind("ok help", 0), 0u);
  EXPECT_EQ(r.sink.velocity.vx, 1000);
}

// Every err names what is valid; a line of blanks is answered too, an empty
// line is not (a terminal's CR LF pairs, docs/protocol.md); `help` lists the
// robot's gaits and heights.
TEST(Controller, ErrorsAndHelpNameTheValidValues) {
  Rig r;
  const std::string all = "walk strafe turn vel stop relax speed gait pose height level set get avoid deadman baud cal save status help";
  auto replies = r.send("  \r\n\n\t\nhelp\nheight 160\ngait Trot\n");
  ASSERT_EQ(replies.size(), 5u);
  EXPECT_EQ(replies[0], "err 1 empty line: " + all);
  EXPECT_EQ(replies[1], "err 1 empty line: " + all);
  EXPECT_EQ(replies[2], "ok help " + all + "; gaits walk trot pace crawl; height 10..150");
  EXPECT_EQ(replies[3], "err 24 height refused: 10..150 with the body level");
  EXPECT_EQ(replies[4], "err 2 bad argument: gait walk trot pace crawl");
  r.sink.refuse_pose = true;
  replies = r.send("pose 20 0 0\n");
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0], "err 24 pose refused: roll -20..20 pitch -15..12 yaw -30..30 one at a time");
  r.ctl->set_servo_fault(true);
  replies = r.send("walk 50\nstop\n");
  ASSERT_EQ(replies.size(), 2u);
  EXPECT_EQ(replies[0], "err 31 servo fault: see pca9685= in status; stop, relax and the rest work");
  EXPECT_EQ(replies[1], "ok stop");
  replies = r.send("cal trim 1 2\n");
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0], "err 20 cal start first: cal start, then cal trim osc pwm save abort");
}

TEST(Controller, RcButtonsScaleWithSpeedAndStaySilent) {
  Rig r;
  EXPECT_TRUE(r.send("7F").empty());
  EXPECT_EQ(r.sink.velocity.vx, 1550 * 70 / 100);
  r.send("qG");
  EXPECT_EQ(r.sink.velocity.wz, 600);  // anticlockwise at 100 %
  r.send("S");
  EXPECT_EQ(r.ctl->mode(), RobotMode::kStanding);
  EXPECT_EQ(r.sink.velocity.vx, 0);
  const auto replies = r.send("I\r\n");
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0], "ok rc I");
  EXPECT_EQ(r.sink.velocity.wz, -600);
}

// An RC button's speed goes to the sink's gait choice (gait/gait_choice.h)
// before the walk; a text `walk` keeps the gait the user chose.
TEST(Controller, RcButtonsOfferTheirSpeedForAGaitChoice) {
  Rig r;
  r.send("walk 100\n");
  EXPECT_TRUE(r.sink.pad_speeds.empty());
  r.send("5F");
  ASSERT_EQ(r.sink.pad_speeds.size(), 1u);
  EXPECT_EQ(r.sink.pad_speeds[0].vx, 1550 * 50 / 100);
  r.send("S");  // the stop keeps the gait
  EXPECT_EQ(r.sink.pad_speeds.size(), 1u);
}

TEST(Controller, DeadmanStopsSilentLink) {
  Rig r;  // defaults: 1000 ms
  r.send("F");
  auto notes = r.run_ms(900);
  EXPECT_EQ(r.ctl->mode(), RobotMode::kWalking);
  r.send("F");  // the app repeats a held button
  notes = r.run_ms(900);
  EXPECT_EQ(r.ctl->mode(), RobotMode::kWalking);
  notes = r.run_ms(200);
  EXPECT_EQ(r.ctl->mode(), RobotMode::kStanding);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "info deadman stop");
  EXPECT_EQ(r.sink.velocity.vx, 0);
  EXPECT_GE(r.sink.stands, 1);
  // No number turns it off, nor the plain `deadman off`: only the checked
  // line (CRC-16 of "deadman off" = cb77) does.
  auto replies = r.send("deadman 0\ndeadman off\nwalk 50\n");
  ASSERT_EQ(replies.size(), 3u);
  EXPECT_EQ(replies[0], "err 5 out of range: deadman 1..60000, off only as a checked line");
  EXPECT_EQ(replies[1], "err 11 checksum required: $deadman off*cb77, a checked line");
  r.run_ms(1100);
  EXPECT_EQ(r.ctl->mode(), RobotMode::kStanding);
  replies = r.send("$deadman off*cb77\nwalk 50\n");
  ASSERT_EQ(replies.size(), 2u);
  EXPECT_EQ(replies[0], "ok deadman off");
  EXPECT_EQ(r.ctl->settings().deadman_ms, 0);
  r.run_ms(10000);
  EXPECT_EQ(r.ctl->mode(), RobotMode::kWalking);
}

// `level on|off` goes to the sink; without an IMU it is refused with its own
// code and changes nothing.
TEST(Controller, LevelNeedsAnImu) {
  Rig r;
  EXPECT_EQ(r.send("level on\n"),
            std::vector<std::string>{"err 34 no imu: level needs an MPU-6050 on the I2C bus (status shows imu=)"});
  EXPECT_FALSE(r.sink.level);
  r.sink.has_imu = true;
  EXPECT_EQ(r.send("level on\n"), std::vector<std::string>{"ok level on"});
  EXPECT_TRUE(r.sink.level);
  EXPECT_EQ(r.send("level off\n"), std::vector<std::string>{"ok level off"});
  EXPECT_FALSE(r.sink.level);
  r.sink.has_imu = false;
  r.send("level on\n");
  EXPECT_FALSE(r.sink.level);
}

TEST(Controller, AvoidanceSequence) {
  Rig r;
  r.send("$deadman off*cb77\nwalk 100\n");
  r.run_ms(100);
  EXPECT_EQ(r.sink.velocity.vx, 1000);
  r.sonar = SonarReading{SonarStatus::kOk, 150};
  auto notes = r.run_ms(100);
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes[0], "info avoid sidestep");
  EXPECT_EQ(r.sink.velocity.vx, 0);
  EXPECT_GT(r.sink.velocity.vy, 0);
  r.sonar = SonarReading{SonarStatus::kOk, strider::kSonarFarMm};
  r.run_ms(1000);
  EXPECT_EQ(r.sink.velocity.vx, 1000);
  EXPECT_EQ(r.sink.velocity.vy, 0);
  r.sonar = SonarReading{SonarStatus::kFailed, strider::kSonarFarMm};
  notes = r.run_ms(40);
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes[0], "info avoid sensor_fault");
  EXPECT_EQ(r.sink.velocity.vx, 0);
  r.send("avoid off\n");
  r.run_ms(40);
  EXPECT_EQ(r.sink.velocity.vx, 1000);
}

TEST(Controller, CalibrationSaveAbortAndReload) {
  Rig r;
  auto replies = r.send("cal trim 0 5\ncal start\nwalk 10\ncal trim 2 -3.5\ncal osc 26100000\ncal abort\n");
  ASSERT_EQ(replies.size(), 6u);
  EXPECT_EQ(replies[0], "err 20 cal start first: cal start, then cal trim osc pwm save abort");
  EXPECT_EQ(replies[2], "err 21 calibrating: cal save or cal abort first");
  EXPECT_EQ(replies[3], "ok cal trim joint=2 deg=-3.5");
  EXPECT_EQ(r.sink.applied.trim_decideg[2], 0);  // abort restored the saved (default) values
  EXPECT_EQ(r.sink.applied.pca_osc_hz, strider::kPca9685NominalOscHz);
  replies = r.send("cal start\ncal trim 2 -3.5\ncal save\n");
  EXPECT_EQ(replies.back(), "ok cal saved");
  strider::Settings back;
  ASSERT_EQ(strider::load_settings(r.store, &back), strider::SettingsStatus::kOk);
  EXPECT_EQ(back.trim_decideg[2], -35);
  // A failing EEPROM is reported and changes nothing stored.
  r.store.fail_at_write = r.store.writes;
  replies = r.send("avoid 250 500\nsave\n");
  EXPECT_EQ(replies.back(), "err 22 store failed: the EEPROM did not read back; nothing saved");
}

// Every reply with numbers in it, byte for byte (docs/protocol.md).
TEST(Controller, NumericRepliesVerbatim) {
  Rig r;
  const auto replies = r.send(
      "strafe -2.5\nturn 12.3\nvel 1 -2 3.5\npose -1.5 2 0.04\nheight 120.5\navoid 150 2999\ndeadman 2500\n"
      "baud 57600\ncal start\ncal trim 17 -0.1\ncal osc 24999999\ncal pwm 333\ncal show\ncal abort\n");
  ASSERT_EQ(replies.size(), 14u);
  EXPECT_EQ(replies[0], "ok move vx=0.0 vy=-2.5 wz=0.0");
  EXPECT_EQ(replies[1], "ok move vx=0.0 vy=0.0 wz=12.3");
  EXPECT_EQ(replies[2], "ok move vx=1.0 vy=-2.0 wz=3.5");
  EXPECT_EQ(replies[3], "ok pose roll=-1.5 pitch=2.0 yaw=0.0");
  EXPECT_EQ(replies[4], "ok height mm=120.5");
  EXPECT_EQ(replies[5], "ok avoid stop_mm=150 slow_mm=2999");
  EXPECT_EQ(replies[6], "ok deadman ms=2500");
  EXPECT_EQ(replies[7], "ok baud rate=57600 after save and reset");
  EXPECT_EQ(replies[8], "ok cal start");
  EXPECT_EQ(replies[9], "ok cal trim joint=17 deg=-0.1");
  EXPECT_EQ(replies[10], "ok cal osc hz=24999999");
  EXPECT_EQ(replies[11], "ok cal pwm hz=333");
  EXPECT_EQ(replies[12], "ok cal osc=24999999 trims=0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,-0.1 level_mg=0,0");
  EXPECT_EQ(replies[13], "ok cal aborted");
}

TEST(Controller, CorruptEepromFallsBackAndSays) {
  FakeStore store;
  strider::Settings s = strider::default_settings();
  s.deadman_ms = 2000;
  ASSERT_EQ(strider::save_settings(store, s), strider::SettingsStatus::kOk);
  store.bytes[10] ^= 0x40;
  strider::Settings loaded;
  const auto st = strider::load_settings(store, &loaded);
  EXPECT_EQ(st, strider::SettingsStatus::kCorrupt);
  FakeMotionSink sink;
  strider::Controller<FakeMotionSink, FakeStore> ctl(sink, store, loaded, st);
  char buf[strider::kMaxReplyBytes];
  std::string reply;
  for (char c : std::string("status\n")) {
    strider::ReplyWriter w(buf, sizeof buf);
    if (ctl.on_byte(uint8_t(c), 0, w)) reply = w.c_str();
  }
  EXPECT_NE(reply.find("eeprom=corrupt"), std::string::npos) << reply;
  EXPECT_NE(reply.find("deadman_ms=1000"), std::string::npos) << reply;
  EXPECT_EQ(sink.applied.deadman_ms, 1000);
}

}  // namespace

namespace {

TEST(Controller, LongestRepliesFit) {
  Rig r;
  auto replies = r.send("cal start\n");
  for (int j = 0; j < strider::kMaxServoJoints; ++j) r.send("cal trim " + std::to_string(j) + " -29.9\n");
  replies = r.send("cal show\nwalk -499.9\nstatus\n");
  ASSERT_EQ(replies.size(), 3u);
  // With offsets of -100 mg each (the widest) ` level_mg=-100,-100` is 6 more.
  EXPECT_EQ(replies[0].size(), 26u + 18u * 6u - 1u + 13u) << replies[0];
  EXPECT_LE(replies[0].size() + 6u, strider::kMaxReplyBytes - 1u);
  r.send("cal abort\nvel -499.9 -499.9 -359.9\n");
  r.sonar = SonarReading{SonarStatus::kOk, 2999};
  r.send("deadman 60000\n");
  r.run_ms(20);
  replies = r.send("status\n");
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_NE(replies[0].find("eeprom=empty"), std::string::npos) << replies[0];
  EXPECT_LT(replies[0].size() + 3, size_t(strider::kMaxReplyBytes));
}

}  // namespace

namespace {

TEST(Controller, JunkAndIdleTimeoutAnsweredOnce) {
  Rig r;
  auto replies = r.send(std::string("\x01\x02\x03walk 10\n"));
  ASSERT_EQ(replies.size(), 2u);
  EXPECT_EQ(replies[0], "err 7 bad byte: printable ASCII only");
  EXPECT_EQ(replies[1], "ok move vx=10.0 vy=0.0 wz=0.0");
  r.send("speed 4");  // no line end
  char buf[strider::kMaxReplyBytes];
  strider::ReplyWriter w(buf, sizeof buf);
  ASSERT_TRUE(r.ctl->on_idle(r.clock.now_ms(), w));
  EXPECT_STREQ(w.c_str(), "err 8 incomplete line: end each line with CR or LF");
  EXPECT_EQ(r.ctl->speed_pct(), 50);  // unchanged
  replies = r.send(std::string(100, 'a') + "\nstop\n");
  ASSERT_EQ(replies.size(), 2u);
  EXPECT_EQ(replies[0], "err 6 line too long: at most 63 bytes");
  EXPECT_EQ(replies[1], "ok stop");
}

}  // namespace

#include <fstream>
#include <sstream>

namespace {

// docs/protocol.md must list every error code and every help word.
TEST(ProtocolDoc, ListsEveryCodeAndCommand) {
  std::ifstream in(STRIDER_PROTOCOL_DOC);
  ASSERT_TRUE(in.good()) << STRIDER_PROTOCOL_DOC;
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  for (int code = 1; code <= 11; ++code) {
    const auto e = static_cast<strider::ParseError>(code);
    const std::string row = "| " + std::to_string(code) + " | `" + strider::error_reason(e) + "`";
    EXPECT_NE(doc.find(row), std::string::npos) << row;
  }
  for (int code : {20, 21, 22, 23, 24, 25, 31, 32, 33, 34, 35, 36}) EXPECT_NE(doc.find("| " + std::to_string(code) + " |"), std::string::npos) << code;
  Rig r;
  const auto help = r.send("help\n");
  ASSERT_EQ(help.size(), 1u);
  // "ok help <words>; gaits <the model's>; height <lo>..<hi>"
  std::istringstream words(help[0].substr(8, help[0].find(';') - 8));
  std::string word;
  int n = 0;
  while (words >> word) {
    ++n;
    EXPECT_NE(doc.find("| `" + word), std::string::npos) << word;
    strider::Command c;
    EXPECT_NE(strider::parse_command_line(word.c_str(), uint8_t(word.size()), &c), strider::ParseError::kUnknownCommand)
        << word;
  }
  EXPECT_GE(n, 15);
}

}  // namespace
