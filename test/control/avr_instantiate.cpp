// Instantiates the whole control layer for float and Fixed so that avr-g++
// (gnu++14, ATmega2560) compiles every template, not just the declarations.
#include <stdint.h>

#include "control/avoidance.h"
#include "control/calibration.h"
#include "control/command_parser.h"
#include "control/controller.h"
#include "control/deadman.h"
#include "control/reply.h"
#include "control/servo_frame.h"
#include "control/servo_map.h"
#include "control/settings_store.h"
#include "control/sonar_filter.h"
#include "math/fixed.h"

namespace {

strider::ArrayByteStore<512> g_store;
strider::CommandParser g_parser;
strider::SonarFilter g_sonar;
strider::Avoidance g_avoid;
strider::Deadman g_deadman;
strider::Pca9685Timing g_timing;
volatile uint16_t g_sink;

struct NullServos {
  void write_ticks(uint8_t channel, uint16_t ticks) { g_sink = uint16_t(channel + ticks); }
  void set_prescale(uint8_t p) { g_sink = p; }
  void relax(uint8_t) {}
};

template <typename S>
uint8_t frame(const strider::Settings& s) {
  static const strider::ServoChannel<S> ch[2] = {strider::make_servo_channel<S>(0, 1, 0.0),
                                                 strider::make_servo_channel<S>(1, -1, 0.0)};
  S q[2] = {S(int(g_sink & 3u)), S(1)};
  NullServos out;
  strider::configure_servo_pwm(out, g_timing, s);
  return uint8_t(strider::write_servo_frame(out, ch, q, 2, s, g_timing));
}

constexpr char kNullGaits[] STRIDER_PROGMEM = "trot";

struct NullSink {
  void set_velocity(const strider::Twist& v) { g_sink = uint16_t(v.vx); }
  void stand() {}
  void relax() {}
  bool set_gait(const char* name) { return name[0] == 't'; }
  void choose_pad_gait(const strider::Twist& v) { g_sink = uint16_t(v.wz); }
  strider::RcLimits pad_limits() const { return {}; }
  bool set_body_pose(int32_t, int32_t, int32_t) { return true; }
  bool set_body_height(int32_t h) { return h < 1000; }
  bool set_level(bool on) { return on; }
  strider::LevelCalStart start_level_cal() { return strider::LevelCalStart::kNoImu; }
  void apply_settings(const strider::Settings& s) { g_sink = uint16_t(s.pwm_hz); }
  void write_status(strider::ReplyWriter& w) { w.text(" sink=null"); }
  void write_gait_names(strider::ReplyWriter& w) const { w.text(strider::FlashText{kNullGaits}); }
  const char* gait_name() const { return "trot"; }
  bool tune(strider::TuneParam, int32_t v) { return v > 0; }
  strider::TuneRange tune_range(strider::TuneParam) const { return strider::TuneRange{1, 2}; }
  void write_tuning(strider::ReplyWriter& w) const { w.text(" tuning=null"); }
  bool save_tuning() { return true; }
  const strider::MotionReach& reach() const { return reach_; }
  strider::MotionReach reach_{40, 90, {-10, -10, -20}, {10, 10, 20}};
};

template <typename S>
uint16_t map_one(uint8_t b) {
  const strider::ServoChannel<S> ch = strider::make_servo_channel<S>(b, 1, 0.0);
  return strider::map_joint(ch, S(int(b)), strider::trim_from_decideg<S>(int16_t(b)), g_timing).ticks;
}

}  // namespace

int main() {
  strider::Settings s;
  strider::SettingsRecord record;
  strider::load_settings(g_store, &s);
  strider::load_settings(g_store, &s, &record);
  strider::save_settings(g_store, s);
  strider::save_settings(g_store, s, &record);
  strider::Calibration cal(s);
  cal.start(s);
  cal.set_trim(1, 20);
  cal.save(g_store, s, &record);
  g_timing.configure(s.pca_osc_hz, s.pwm_hz);
  char buf[strider::kMaxReplyBytes];
  for (uint8_t b = 0; b < 200; ++b) {
    strider::Command c;
    strider::ReplyWriter w(buf, sizeof buf);
    if (g_parser.feed(b, &c) == strider::ParseResult::kError) strider::write_parse_error(w, c);
    g_sonar.add(strider::EchoSample{strider::EchoKind::kEcho, uint16_t(b * 50u), 0}, b * 1000ul);
    const strider::Twist t = g_avoid.update(strider::Twist{c.arg[0], 0, 0}, g_sonar.reading(b * 1000ul), b,
                                            strider::default_avoid_config());
    g_sink = uint16_t(t.vx + map_one<float>(b) + map_one<strider::Fixed>(b) + w.length() +
                      g_deadman.expired(b, true));
  }
  g_sink = uint16_t(frame<float>(s) + frame<strider::Fixed>(s));
  NullSink sink;
  strider::Controller<NullSink, strider::ArrayByteStore<512> > ctl(sink, g_store, s, strider::SettingsStatus::kOk,
                                                                     record);
  for (uint8_t b = 0; b < 255; ++b) {
    strider::ReplyWriter w(buf, sizeof buf);
    if (ctl.on_byte(b, b, w) || ctl.tick(b, g_sonar.reading(b), w)) g_sink = w.length();
  }
  return 0;
}
