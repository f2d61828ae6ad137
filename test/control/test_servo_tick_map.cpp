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

#include "control/channel_map.h"
#include "control/servo_frame.h"
#include "control/servo_tick_map.h"
#include "fakes/recording_servo.h"
#include "math/fixed.h"
#include "math/scalar.h"
#include "robots/all_robots.h"

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

// The Fixed map's slope and offset in integers (no float library on the
// AVR) against the double computation it replaced: the same ticks over
// dense sweeps of every built-in model's joints, trims and PWM settings,
// or at most one tick apart (counted and printed; never past the limits,
// which MatchesMapJointOverSweeps and the bounds below check).
struct DoubleScale {
  bool ok;
  double travel, tpr, base;
};
DoubleScale double_scale(const strider::ServoChannel<Fixed>& ch, Fixed trim, const Pca9685Timing& timing,
                         double* base_rad) {
  const double ticks_per_us = 262144.0 / double(timing.period_x64());
  const Fixed lo = strider::min_of(ch.min_rad, ch.max_rad), hi = strider::max_of(ch.min_rad, ch.max_rad);
  const Fixed zero = ch.direction < 0 ? -ch.zero_rad : ch.zero_rad;
  *base_rad = (ch.centre_rad - zero + trim - lo).to_double();
  const double lo_us = double(std::min(ch.min_pulse_us, ch.max_pulse_us));
  const double hi_us = double(std::max(ch.min_pulse_us, ch.max_pulse_us));
  const double upr = ch.us_per_rad.to_double();
  const double at_lo = double(ch.min_pulse_us) + lo.to_double() * upr;
  const double at_hi = double(ch.min_pulse_us) + hi.to_double() * upr;
  DoubleScale r{false, (hi - lo).to_double(), upr * ticks_per_us, at_lo * ticks_per_us};
  r.ok = !(at_lo < lo_us || at_hi > hi_us || !(upr >= 0.0)) && r.travel < 4.0 && r.tpr > 0.5 && r.tpr < 8192.0 &&
         r.base + r.tpr * r.travel < 4096.0;
  return r;
}
// The old Fixed folding: k, shift and base_q16 from the doubles.
strider::ServoTickScale<Fixed> old_scale(const DoubleScale& d) {
  strider::ServoTickScale<Fixed> sc;
  uint8_t shift = 2;
  while (d.tpr * double(uint32_t(1) << (shift + 1)) < 65535.5 && shift < 17) ++shift;
  sc.shift = shift;
  sc.k = uint16_t(d.tpr * double(uint32_t(1) << shift) + 0.5);
  sc.base_q16 = uint32_t(d.base * 65536.0 + 0.5);
  return sc;
}

TEST(ServoTickMapFixed, IntegerScaleMatchesTheDoubleOne) {
  long joints = 0, samples = 0, off_by_one = 0, scale_diffs = 0;
  const int16_t trims[] = {0, 1, -7, 45, -120, 300, -450};
  for (const strider::RobotModel* m : strider::kAllRobots) {
    const uint8_t n = m->joint_count();
    for (uint32_t osc : {20000000u, 23000000u, 25000000u, 26500000u, 27000000u, 30000000u}) {
      for (uint16_t pwm : {uint16_t(24), uint16_t(50), uint16_t(60), uint16_t(100), uint16_t(200), uint16_t(330)}) {
        Pca9685Timing timing;
        ASSERT_NE(timing.configure(osc, pwm), strider::PwmTimingStatus::kBadOscillator);
        for (int16_t trim_d : trims) {
          for (uint8_t k = 0; k < n; ++k) {
            const strider::ServoChannel<Fixed> ch =
                strider::make_joint_channel<Fixed>(*m, uint8_t(k / m->dof()), uint8_t(k % m->dof()));
            const Fixed trim = strider::trim_from_decideg<Fixed>(trim_d);
            double base_rad;
            const DoubleScale d = double_scale(ch, trim, timing, &base_rad);
            ServoTickMap<Fixed, 1> map;
            const ServoTickStatus st = map.configure_joint(0, ch, trim, timing);
            ASSERT_EQ(st == ServoTickStatus::kOk, d.ok) << m->name << " joint " << int(k);
            if (!d.ok) continue;
            ++joints;
            const strider::ServoTickJoint<Fixed> j = map.joint(0);
            const strider::ServoTickScale<Fixed> want = old_scale(d);
            ASSERT_EQ(j.scale.shift, want.shift);
            ASSERT_LE(std::abs(int(j.scale.k) - int(want.k)), 1);
            ASSERT_LE(std::labs(long(j.scale.base_q16) - long(want.base_q16)), 1L);
            if (j.scale.k != want.k || j.scale.base_q16 != want.base_q16) ++scale_diffs;
            for (int q = -3200; q <= 3200; ++q) {
              const Fixed d_rad = Fixed::from_raw(int32_t(q) * 64);  // -3.1 .. 3.1 rad, every 2^-10 rad
              const strider::ServoCommand got = map.map(0, d_rad);
              // The old ticks: the same clamped d with the old scale.
              int32_t dd = j.direction < 0 ? (j.base_rad - d_rad).raw() : (j.base_rad + d_rad).raw();
              if (dd < 0) dd = 0;
              if (dd > j.travel_rad.raw()) dd = j.travel_rad.raw();
              uint16_t t = strider::servo_ticks_detail::ticks_of(Fixed::from_raw(dd), want.k, want.shift,
                                                                 want.base_q16);
              t = t < j.lo_ticks ? j.lo_ticks : t > j.hi_ticks ? j.hi_ticks : t;
              ++samples;
              ASSERT_GE(got.ticks, j.lo_ticks);
              ASSERT_LE(got.ticks, j.hi_ticks);
              const int diff = std::abs(int(got.ticks) - int(t));
              ASSERT_LE(diff, 1) << m->name << " joint " << int(k) << " q " << q;
              if (diff != 0) ++off_by_one;
            }
          }
        }
      }
    }
  }
  std::printf("integer scale: %ld joints, %ld with k or base 1 unit apart, %ld of %ld ticks one apart\n", joints,
              scale_diffs, off_by_one, samples);
  EXPECT_GT(joints, 1000);
  EXPECT_LE(off_by_one * 10000, samples);  // rare: at most 1e-4 of the samples
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
