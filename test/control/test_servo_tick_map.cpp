// ServoTickMap (the servo loop's folded per-joint mapping) against the
// general map_joint() it replaces: same status, ticks within one of its
// ticks and never outside its ticks of the limits, over dense sweeps of
// joint angles, channels, trims, oscillators and PWM frequencies; NaN and
// infinity hold the centre; frames write every channel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "control/servo_frame.h"
#include "control/servo_tick_map.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "math/scalar.h"

using strider::Fixed;
using strider::Pca9685Timing;
using strider::ServoStatus;
using strider::ServoTickMap;
using strider::ServoTickStatus;

namespace {

template <typename S>
class ServoTickMapTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(ServoTickMapTest, Scalars);

// The most the folded path may differ from map_joint() [ticks]: map_joint
// rounds to whole microseconds first (up to 0.5 us = 0.1 tick at 50 Hz,
// 0.4 tick at 200 Hz) and the 16-bit slope adds < 0.07 tick.
constexpr int kMaxTickDiff = 1;

template <typename S>
void sweep(const strider::ServoChannel<S>* ch, uint8_t n, const strider::Settings& settings,
           const Pca9685Timing& timing, int* worst_diff) {
  ServoTickMap<S> map;
  ASSERT_EQ(map.configure(ch, n, settings, timing), ServoTickStatus::kOk);
  ASSERT_EQ(map.count(), n);
  for (uint8_t i = 0; i < n; ++i) {
    const S trim = strider::trim_from_decideg<S>(settings.trim_decideg[i]);
    const uint16_t lo = timing.pulse_ticks(strider::servo_pulse_us(ch[i], strider::min_of(ch[i].min_rad, ch[i].max_rad)));
    const uint16_t hi = timing.pulse_ticks(strider::servo_pulse_us(ch[i], strider::max_of(ch[i].min_rad, ch[i].max_rad)));
    for (int k = -4000; k <= 4000; ++k) {
      const S q = strider::scalar<S>(k * 0.00075);  // -3 .. 3 rad
      const strider::ServoCommand want = strider::map_joint(ch[i], q, trim, timing);
      const strider::ServoCommand got = map.map(i, q);
      ASSERT_EQ(got.channel, want.channel);
      ASSERT_GE(got.ticks, lo) << "joint " << int(i) << " q " << k;
      ASSERT_LE(got.ticks, hi) << "joint " << int(i) << " q " << k;
      const int diff = std::abs(int(got.ticks) - int(want.ticks));
      ASSERT_LE(diff, kMaxTickDiff) << "joint " << int(i) << " q " << k;
      *worst_diff = std::max(*worst_diff, diff);
      if (got.status != want.status) {
        // Only float, and only where the servo angle sits on a limit to
        // rounding (the folded sum rounds differently): then the ticks agree.
        ASSERT_TRUE((std::is_same<S, float>::value)) << "joint " << int(i) << " q " << k;
        ASSERT_EQ(got.ticks, want.ticks);
      }
    }
  }
}

TYPED_TEST(ServoTickMapTest, MatchesMapJointOverSweeps) {
  using S = TypeParam;
  const strider::ServoChannel<S> ch[6] = {
      strider::make_servo_channel<S>(0, 1, 0.0),
      strider::make_servo_channel<S>(1, -1, 0.0),
      strider::make_servo_channel<S>(5, 1, 30.0, 60.0, 60.0),
      strider::make_servo_channel<S>(9, -1, 10.0, 80.0, 70.0),
      strider::make_servo_channel<S>(16, 1, -15.0, 45.0, 75.0),
      strider::make_servo_channel<S>(31, -1, -40.0, 10.0, 90.0)};
  strider::Settings settings = strider::default_settings();
  const int16_t trims[6] = {0, 45, -120, 300, -7, 1};
  int worst = 0;
  for (uint32_t osc : {23000000u, 25000000u, 27000000u}) {
    for (uint16_t pwm : {uint16_t(50), uint16_t(60), uint16_t(100), uint16_t(200)}) {
      for (int t = 0; t < 2; ++t) {
        for (int i = 0; i < 6; ++i) settings.trim_decideg[i] = t == 0 ? 0 : trims[i];
        Pca9685Timing timing;
        ASSERT_NE(timing.configure(osc, pwm), strider::PwmTimingStatus::kBadOscillator);
        sweep(ch, 6, settings, timing, &worst);
      }
    }
  }
  std::printf("worst tick difference from map_joint: %d\n", worst);
}

TEST(ServoTickMapFloat, NotFiniteHoldsTheCentre) {
  const auto ch = strider::make_servo_channel<float>(3, 1, -15.0, 45.0, 75.0);
  const auto narrow = strider::make_servo_channel<float>(4, -1, 0.0, 10.0, 10.0);
  const strider::ServoChannel<float> chs[2] = {ch, narrow};
  Pca9685Timing timing;
  ServoTickMap<float> map;
  ASSERT_EQ(map.configure(chs, 2, strider::default_settings(), timing), ServoTickStatus::kOk);
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity()}) {
    for (uint8_t i = 0; i < 2; ++i) {
      const strider::ServoCommand want = strider::map_joint(chs[i], bad, 0.0f, timing);
      const strider::ServoCommand got = map.map(i, bad);
      EXPECT_EQ(got.status, ServoStatus::kNotFinite);
      EXPECT_EQ(got.ticks, want.ticks);
    }
  }
  // Huge but finite: clamped to a limit, like map_joint().
  const strider::ServoCommand huge = map.map(0, 3e38f);
  EXPECT_EQ(huge.status, strider::map_joint(ch, 3e38f, 0.0f, timing).status);
  EXPECT_EQ(huge.ticks, strider::map_joint(ch, 3e38f, 0.0f, timing).ticks);
}

TYPED_TEST(ServoTickMapTest, FrameWritesEveryChannelLikeTheGeneralFrame) {
  using S = TypeParam;
  Pca9685Timing timing;
  strider::Settings settings = strider::default_settings();
  settings.pca_osc_hz = 26000000;
  ASSERT_EQ(timing.configure(settings.pca_osc_hz, settings.pwm_hz), strider::PwmTimingStatus::kOk);
  const strider::ServoChannel<S> ch[3] = {strider::make_servo_channel<S>(0, 1, 0.0),
                                          strider::make_servo_channel<S>(1, -1, 0.0),
                                          strider::make_servo_channel<S>(17, 1, 0.0, 10.0, 10.0)};
  settings.trim_decideg[4] = 45;
  ServoTickMap<S> map;
  ASSERT_EQ(map.configure(ch, 3, settings, timing, 3), ServoTickStatus::kOk);
  const S q[3] = {S(0), S(0), strider::deg_to_rad<S>(20)};
  strider_test::RecordingServo general, folded;
  const ServoStatus a = strider::write_servo_frame(general, ch, q, 3, settings, timing, 3);
  const ServoStatus b = strider::write_servo_frame(folded, map, q, 3);
  EXPECT_EQ(a, ServoStatus::kLimited);
  EXPECT_EQ(b, a);
  ASSERT_EQ(folded.writes.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(folded.writes[i].channel, general.writes[i].channel);
    EXPECT_LE(std::abs(int(folded.writes[i].ticks) - int(general.writes[i].ticks)), kMaxTickDiff);
  }
  EXPECT_EQ(folded.writes[2].ticks, general.writes[2].ticks);  // the limit: exact
  // Only the joints the map holds are written.
  strider_test::RecordingServo tail;
  strider::write_servo_frame(tail, map, q, 3, 2);
  EXPECT_EQ(tail.writes.size(), 1u);
}

TEST(ServoTickMapFixed, RefusesTravelsItCannotScale) {
  strider::ServoChannel<Fixed> ch = strider::make_servo_channel<Fixed>(0, 1, 0.0);
  ch.min_rad = Fixed(0);
  ch.max_rad = Fixed(4.5);  // beyond Q2.14
  Pca9685Timing timing;
  ServoTickMap<Fixed> map;
  EXPECT_EQ(map.configure(&ch, 1, strider::default_settings(), timing), ServoTickStatus::kUnsupported);
  EXPECT_EQ(map.count(), 0);
}

}  // namespace
