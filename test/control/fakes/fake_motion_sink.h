// A MotionSink that records what the controller asked for.
#ifndef STRIDER_TEST_CONTROL_FAKE_MOTION_SINK_H
#define STRIDER_TEST_CONTROL_FAKE_MOTION_SINK_H

#include <stdint.h>

#include <string>
#include <vector>

#include "control/avoidance.h"
#include "control/motion_reach.h"
#include "control/reply.h"
#include "control/settings.h"
#include "gait/gait_tuning.h"

namespace strider_test {

struct FakeMotionSink {
  strider::Twist velocity{0, 0, 0};
  int stands = 0;
  int relaxes = 0;
  std::string gait = "walk";
  int32_t pose[3] = {0, 0, 0};
  int32_t height = 0;
  strider::Settings applied{};
  int settings_applied = 0;

  void set_velocity(const strider::Twist& v) { velocity = v; }
  void stand() { velocity = strider::Twist{0, 0, 0}; ++stands; }
  void relax() { velocity = strider::Twist{0, 0, 0}; ++relaxes; }
  bool set_gait(const char* name) {
    const std::string n(name);
    if (n != "walk" && n != "trot" && n != "pace" && n != "crawl") return false;
    gait = n;
    return true;
  }
  // RC buttons' speeds, as the controller passed them for a gait choice.
  std::vector<strider::Twist> pad_speeds;
  void choose_pad_gait(const strider::Twist& v) { pad_speeds.push_back(v); }
  strider::RcLimits pad_limits() const { return {}; }
  bool refuse_pose = false;
  bool set_body_pose(int32_t r, int32_t p, int32_t y) {
    if (refuse_pose) return false;
    pose[0] = r;
    pose[1] = p;
    pose[2] = y;
    return true;
  }
  bool set_body_height(int32_t h) {
    if (h > 1500) return false;  // pretend 150 mm is the most this robot reaches
    height = h;
    return true;
  }
  // `level on|off`: refused (false) without an IMU.
  bool has_imu = false;
  bool level = false;
  bool set_level(bool on) {
    if (!has_imu) return false;
    level = on;
    return true;
  }
  // `cal level`: what start_level_cal() answers (kStarted: the reply is level_cal_done()'s).
  strider::LevelCalStart level_cal = strider::LevelCalStart::kNoImu;
  int level_cal_starts = 0;
  strider::LevelCalStart start_level_cal() {
    ++level_cal_starts;
    return level_cal;
  }
  // What it pretends the legs reach: 10..150 mm (set_body_height() above).
  strider::MotionReach reach_mm_deg{10, 150, {-20, -15, -30}, {20, 12, 30}};
  void write_gait_names(strider::ReplyWriter& w) const { w.text("walk trot pace crawl"); }
  // Live gait parameters: it takes step heights of 1.00..20.00 mm and any
  // other value, and records what it took.
  int32_t tuned[strider::kTuneParamCount] = {};
  bool save_tuning_fails = false;
  int tunings_saved = 0;
  const char* gait_name() const { return gait.c_str(); }
  bool tune(strider::TuneParam p, int32_t v) {
    if (!strider::tune_value_allowed(bounds(), p, v)) return false;
    tuned[uint8_t(p)] = v;
    return true;
  }
  strider::TuneRange tune_range(strider::TuneParam p) const { return strider::range_of(bounds(), p); }
  void write_tuning(strider::ReplyWriter& w) const { w.text(" tuning=fake"); }
  bool save_tuning() {
    ++tunings_saved;
    return !save_tuning_fails;
  }
  static strider::TuneBounds bounds() {
    return strider::TuneBounds{{100, 2000}, {500, 10000}, {20, 500}, {50, 95}, 0x1E};
  }
  const strider::MotionReach& reach() const { return reach_mm_deg; }
  void write_status(strider::ReplyWriter& w) { w.text(" sink=fake"); }
  void apply_settings(const strider::Settings& s) {
    applied = s;
    ++settings_applied;
  }
};

}  // namespace strider_test

#endif
