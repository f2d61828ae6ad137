// PCA9685 timing against the datasheet formula for 23-27 MHz oscillators, and
// the joint -> servo map (zero, direction, trim, limits) over float and Fixed,
// including the property that no input (NaN, inf, huge) leaves the limits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "control/pca9685_timing.h"
#include "control/servo_map.h"
#include "math/fixed.h"
#include "math/scalar.h"

using strider::Fixed;
using strider::Pca9685Timing;
using strider::ServoStatus;

namespace {

// Rounding to the nearest tick is the only error: at most half a tick, plus
// the cached period's rounding (1/128 us over a >= 2.4 ms period: < 0.02 tick).
constexpr double kMaxTickError = 0.5 + 0.02;

TEST(Pca9685Timing, PrescaleKnownAnswers) {
  EXPECT_EQ(strider::pca9685_prescale(25000000, 50), 121);    // round(122.07) - 1
  EXPECT_EQ(strider::pca9685_prescale(25000000, 200), 30);    // datasheet example: 0x1E
  EXPECT_EQ(strider::pca9685_prescale(25000000, 1526), 3);    // datasheet max frequency
  EXPECT_EQ(strider::pca9685_prescale(25000000, 24), 253);    // datasheet min frequency
  strider::PwmTimingStatus st;
  EXPECT_EQ(strider::pca9685_prescale(25000000, 10, &st), 255);
  EXPECT_EQ(st, strider::PwmTimingStatus::kClamped);
  EXPECT_EQ(strider::pca9685_prescale(25000000, 2000, &st), 3);
  EXPECT_EQ(st, strider::PwmTimingStatus::kClamped);
  Pca9685Timing t;
  EXPECT_EQ(t.configure(19000000, 50), strider::PwmTimingStatus::kBadOscillator);
  EXPECT_EQ(t.prescale(), 121);  // previous configuration kept
}

TEST(Pca9685Timing, MatchesDatasheetFormula23To27MHz) {
  const uint16_t freqs[] = {40, 50, 60, 100, 200, 330, 400};
  const uint16_t widths[] = {0, 500, 1000, 1500, 1501, 2000, 2500, 3000};
  double worst = 0;
  Pca9685Timing t;
  for (uint32_t osc = 23000000; osc <= 27000000; osc += 997) {
    for (uint16_t f : freqs) {
      ASSERT_EQ(t.configure(osc, f), strider::PwmTimingStatus::kOk);
      const double p = std::round(double(osc) / (4096.0 * f)) - 1.0;
      ASSERT_EQ(t.prescale(), int(p)) << osc << " " << f;
      const double period_us = (p + 1.0) * 4096.0 * 1e6 / osc;
      ASSERT_NEAR(t.period_x64() / 64.0, period_us, 1.0 / 128 + 1e-9);
      for (uint16_t w : widths) {
        const double exact = std::min(4095.0, w * 4096.0 / period_us);
        const double err = std::fabs(t.pulse_ticks(w) - exact);
        worst = std::max(worst, err);
        ASSERT_LE(err, kMaxTickError) << osc << " Hz " << f << " Hz " << w << " us";
      }
    }
  }
  RecordProperty("worst_tick_error", std::to_string(worst));
  std::printf("pca9685: worst tick error %.5f (bound %.4f)\n", worst, kMaxTickError);
  // The oscillator matters: on a 27 MHz board, timing built for the nominal
  // 25 MHz makes 1500 us come out 7 % short; the calibrated one is right.
  Pca9685Timing nominal, calibrated;
  nominal.configure(25000000, 50);
  calibrated.configure(27000000, 50);
  const auto actual_us = [](const Pca9685Timing& timing, uint16_t ticks) {
    return ticks * (timing.prescale() + 1.0) / 27e6 * 1e6;
  };
  EXPECT_LT(actual_us(nominal, nominal.pulse_ticks(1500)), 1400.0);
  EXPECT_NEAR(actual_us(calibrated, calibrated.pulse_ticks(1500)), 1500.0, 2.5);  // half a tick
}

TEST(Pca9685Timing, TicksSaturateAt4095) {
  Pca9685Timing t;
  t.configure(25000000, 400);  // period 2.5 ms
  EXPECT_EQ(t.pulse_ticks(65535), 4095);
  EXPECT_EQ(t.pulse_ticks(0), 0);
}

template <typename S>
class ServoMapTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(ServoMapTest, Scalars);

// Pulse error of the map against the exact pulse (rounding + scalar precision).
constexpr double kMaxPulseErrorUs = 0.5 + 0.05;

TYPED_TEST(ServoMapTest, KnownAnswers) {
  using S = TypeParam;
  Pca9685Timing timing;
  const auto ch = strider::make_servo_channel<S>(7, 1, 0.0, 60.0, 60.0);
  const S zero_trim(0);
  auto cmd = strider::map_joint(ch, zero_trim, zero_trim, timing);
  EXPECT_EQ(cmd.channel, 7);
  EXPECT_EQ(cmd.pulse_us, 1500);
  EXPECT_EQ(cmd.status, ServoStatus::kOk);
  EXPECT_EQ(cmd.ticks, timing.pulse_ticks(1500));
  // +45 deg joint -> +500 us; mirrored direction -> -500 us.
  cmd = strider::map_joint(ch, strider::deg_to_rad<S>(45), zero_trim, timing);
  EXPECT_EQ(cmd.pulse_us, 2000);
  const auto mirrored = strider::make_servo_channel<S>(0, -1, 0.0, 60.0, 60.0);
  cmd = strider::map_joint(mirrored, strider::deg_to_rad<S>(45), zero_trim, timing);
  EXPECT_EQ(cmd.pulse_us, 1000);
  // Zero offset: the joint's zero at 30 deg sits at the servo centre.
  const auto offset = strider::make_servo_channel<S>(0, 1, 30.0, 60.0, 60.0);
  cmd = strider::map_joint(offset, strider::deg_to_rad<S>(30), zero_trim, timing);
  EXPECT_EQ(cmd.pulse_us, 1500);
  // Trim +2.5 deg -> +27.8 us.
  cmd = strider::map_joint(ch, zero_trim, strider::trim_from_decideg<S>(25), timing);
  EXPECT_NEAR(cmd.pulse_us, 1500 + 2000.0 * 2.5 / 180.0, kMaxPulseErrorUs);
  // Limits: 70 deg asked, 60 allowed.
  cmd = strider::map_joint(ch, strider::deg_to_rad<S>(70), zero_trim, timing);
  EXPECT_EQ(cmd.status, ServoStatus::kLimited);
  EXPECT_NEAR(cmd.pulse_us, 1500 + 2000.0 * 60.0 / 180.0, kMaxPulseErrorUs);
  cmd = strider::map_joint(ch, strider::deg_to_rad<S>(-170), zero_trim, timing);
  EXPECT_EQ(cmd.status, ServoStatus::kLimited);
  EXPECT_NEAR(cmd.pulse_us, 1500 - 2000.0 * 60.0 / 180.0, kMaxPulseErrorUs);
}

TYPED_TEST(ServoMapTest, DenseSweepMatchesDouble) {
  using S = TypeParam;
  Pca9685Timing timing;
  const auto ch = strider::make_servo_channel<S>(0, -1, 10.0, 80.0, 70.0);
  double worst = 0;
  for (double deg = -120; deg <= 120; deg += 0.05) {
    const auto cmd = strider::map_joint(ch, strider::scalar<S>(deg * strider::kDegToRad), S(0), timing);
    double servo = 90.0 - (deg - 10.0);
    servo = std::min(160.0, std::max(10.0, servo));
    const double exact = 500.0 + servo / 180.0 * 2000.0;
    worst = std::max(worst, std::fabs(cmd.pulse_us - exact));
    ASSERT_LE(std::fabs(cmd.pulse_us - exact), kMaxPulseErrorUs) << deg;
  }
  std::printf("servo map (%s): worst pulse error %.3f us\n", strider::ScalarTraits<S>::name(), worst);
}

// Property: whatever the joint angle and trim, the pulse stays within the
// pulses of the channel's limits.
template <typename S>
S random_scalar(std::mt19937& rng);
template <>
float random_scalar<float>(std::mt19937& rng) {
  std::uniform_int_distribution<int> pick(0, 9);
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(), 3.0e38f, -3.0e38f, 1e-40f};
  const int k = pick(rng);
  if (k < 6 && pick(rng) < 3) return specials[k];
  std::uniform_real_distribution<float> d(-20.0f, 20.0f);
  return d(rng);
}
template <>
Fixed random_scalar<Fixed>(std::mt19937& rng) {
  std::uniform_int_distribution<int32_t> d(INT32_MIN, INT32_MAX);
  return Fixed::from_raw(d(rng));
}

TYPED_TEST(ServoMapTest, NeverOutOfLimits) {
  using S = TypeParam;
  std::mt19937 rng(99u);
  Pca9685Timing timing;
  const auto ch = strider::make_servo_channel<S>(3, 1, -15.0, 45.0, 75.0);
  const uint16_t lo = strider::servo_pulse_us(ch, ch.min_rad);
  const uint16_t hi = strider::servo_pulse_us(ch, ch.max_rad);
  for (int i = 0; i < STRIDER_RANDOM_CASES * 5; ++i) {
    const S joint = random_scalar<S>(rng);
    const S trim = (i % 3 == 0) ? random_scalar<S>(rng) : S(0);
    const auto cmd = strider::map_joint(ch, joint, trim, timing);
    ASSERT_GE(cmd.pulse_us, lo);
    ASSERT_LE(cmd.pulse_us, hi);
    ASSERT_LE(cmd.ticks, timing.pulse_ticks(hi));
    ASSERT_GE(cmd.ticks, timing.pulse_ticks(lo));
  }
}

TEST(ServoMapFloat, NanHoldsCentre) {
  Pca9685Timing timing;
  const auto ch = strider::make_servo_channel<float>(3, 1, -15.0, 45.0, 75.0);
  auto cmd = strider::map_joint(ch, std::nanf(""), 0.0f, timing);
  EXPECT_EQ(cmd.status, ServoStatus::kNotFinite);
  EXPECT_EQ(cmd.pulse_us, 1500);
  cmd = strider::map_joint(ch, 0.1f, std::numeric_limits<float>::infinity(), timing);
  EXPECT_EQ(cmd.status, ServoStatus::kNotFinite);
  EXPECT_EQ(cmd.pulse_us, 1500);
}

}  // namespace

#include "control/servo_frame.h"
#include "fakes/recording_servo.h"

namespace {

TYPED_TEST(ServoMapTest, FrameWritesEveryChannelWithTrims) {
  using S = TypeParam;
  strider_test::RecordingServo out;
  Pca9685Timing timing;
  strider::Settings settings = strider::default_settings();
  settings.pca_osc_hz = 26000000;
  ASSERT_EQ(strider::configure_servo_pwm(out, timing, settings), strider::PwmTimingStatus::kOk);
  EXPECT_EQ(out.prescale, 126);  // round(26e6 / 204800) - 1
  const strider::ServoChannel<S> ch[3] = {strider::make_servo_channel<S>(0, 1, 0.0),
                                          strider::make_servo_channel<S>(1, -1, 0.0),
                                          strider::make_servo_channel<S>(17, 1, 0.0, 10.0, 10.0)};
  settings.trim_decideg[4] = 45;  // trims of joints 3..5 apply with first_trim = 3
  const S q[3] = {S(0), S(0), strider::deg_to_rad<S>(20)};
  const auto st = strider::write_servo_frame(out, ch, q, 3, settings, timing, 3);
  EXPECT_EQ(st, ServoStatus::kLimited);  // 20 deg on a +-10 deg channel
  ASSERT_EQ(out.writes.size(), 3u);
  EXPECT_EQ(out.writes[0].channel, 0);
  EXPECT_EQ(out.writes[0].ticks, timing.pulse_ticks(1500));
  EXPECT_EQ(out.writes[1].channel, 1);
  EXPECT_EQ(out.writes[1].ticks, timing.pulse_ticks(1550));  // +4.5 deg trim = +50 us
  EXPECT_EQ(out.writes[2].channel, 17);
  // Clamped at +10 deg: 1611 us, the tick at or below it (the limit rounded
  // inward; the nearest tick, 330, would be 1612 us).
  EXPECT_EQ(out.writes[2].ticks, timing.pulse_ticks_toward(1611, false));
  EXPECT_EQ(out.writes[2].ticks, 329);
  settings.pca_osc_hz = 1;
  EXPECT_EQ(strider::configure_servo_pwm(out, timing, settings), strider::PwmTimingStatus::kBadOscillator);
  EXPECT_EQ(out.prescale, 126);  // untouched
}

}  // namespace

namespace {

// pulse_ticks_toward(): the tick at or above (up) / at or below (down) the
// width, against the formula, over every width and several oscillators and
// frequencies; the nearest tick is one of the two.
TEST(Pca9685Timing, TicksTowardTheInside) {
  Pca9685Timing t;
  for (uint32_t osc : {25000000u, 23500000u, 26800000u})
    for (int f : {40, 50, 60, 200, 330}) {
      ASSERT_EQ(t.configure(osc, uint16_t(f)), strider::PwmTimingStatus::kOk) << osc << " " << f;
      const double tick_us = double(t.period_x64()) / 64.0 / 4096.0;
      for (uint32_t w = 1; w < 65535; w += 13) {
        const uint16_t up = t.pulse_ticks_toward(uint16_t(w), true), down = t.pulse_ticks_toward(uint16_t(w), false);
        if (up >= 4095) break;
        ASSERT_GE(up * tick_us, w - 1e-6) << osc << " " << f << " Hz " << w << " us";
        ASSERT_LT((up - 1) * tick_us, w - 1e-9) << w;
        ASSERT_LE(down * tick_us, w + 1e-6) << w;
        ASSERT_GT((down + 1) * tick_us, w + 1e-9) << w;
        ASSERT_LE(up - down, 1);
        const uint16_t near = t.pulse_ticks(uint16_t(w));
        ASSERT_TRUE(near == up || near == down) << w;
      }
    }
}

// Both pulse_ticks paths (one division below 16000 us, two above) against the formula.
TEST(Pca9685Timing, LongWidthsExact) {
  Pca9685Timing t;
  for (int f : {24, 30, 40}) {
    ASSERT_EQ(t.configure(23500000, uint16_t(f)), strider::PwmTimingStatus::kOk);
    const double period_us = (t.prescale() + 1.0) * 4096.0 * 1e6 / 23500000.0;
    for (uint32_t w = 15900; w <= 42000; w += 7) {
      const double exact = std::min(4095.0, w * 4096.0 / period_us);
      ASSERT_LE(std::fabs(t.pulse_ticks(uint16_t(w)) - exact), kMaxTickError) << f << " Hz " << w << " us";
    }
  }
}

}  // namespace

#include "control/channel_map.h"
#include "robots/all_robots.h"

namespace {

// Every built-in model's every joint, pushed far past both limits and swept
// across them, at several PWM frequencies and oscillators: the pulse sent
// (ticks x tick length) never passes the exact limit pulse by more than the
// half microsecond of servo_pulse_us()'s rounding; at the limits it is at
// most one tick inside.
double as_double(float v) { return double(v); }
double as_double(Fixed v) { return v.to_double(); }

template <typename S>
void expect_limits_kept() {
  for (const strider::RobotModel* m : strider::kAllRobots)
    for (uint32_t osc : {25000000u, 26000000u})
      for (int f : {50, 60, 200}) {
        Pca9685Timing timing;
        ASSERT_EQ(timing.configure(osc, uint16_t(f)), strider::PwmTimingStatus::kOk);
        const double tick_us = double(timing.period_x64()) / 64.0 / 4096.0;
        for (uint8_t i = 0; i < m->leg_count; ++i)
          for (uint8_t j = 0; j < m->dof(); ++j) {
            const auto ch = strider::make_joint_channel<S>(*m, i, j);
            const double a = double(ch.min_pulse_us) + as_double(ch.min_rad) * as_double(ch.us_per_rad);
            const double b = double(ch.min_pulse_us) + as_double(ch.max_rad) * as_double(ch.us_per_rad);
            const double lo = std::min(a, b), hi = std::max(a, b);
            double seen_lo = 1e9, seen_hi = -1e9;
            for (int k = -1000; k <= 1000; ++k) {
              const S q = strider::scalar<S>(k * 0.01);  // -10 .. 10 rad
              const double us = strider::map_joint(ch, q, S(0), timing).ticks * tick_us;
              ASSERT_GE(us, lo - 0.5 - 1e-6) << m->name << " leg " << int(i) << " joint " << int(j) << " " << f << " Hz";
              ASSERT_LE(us, hi + 0.5 + 1e-6) << m->name << " leg " << int(i) << " joint " << int(j) << " " << f << " Hz";
              seen_lo = std::min(seen_lo, us);
              seen_hi = std::max(seen_hi, us);
            }
            EXPECT_LT(seen_lo, lo + tick_us + 0.5) << m->name;  // the limit itself is reached
            EXPECT_GT(seen_hi, hi - tick_us - 0.5) << m->name;
          }
      }
}

TEST(ServoMapLimits, NeverPastAJointLimit) {
  expect_limits_kept<float>();
  expect_limits_kept<Fixed>();
}

}  // namespace
