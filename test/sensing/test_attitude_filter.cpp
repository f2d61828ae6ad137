// AttitudeFilter (lib/strider/sensing/attitude_filter.h), typed over float
// and Fixed, on synthetic motions: against the same filter in double
// (attitude_reference.h: how much the scalar's arithmetic costs) and against
// the true attitude (how good the filter is). The measured maxima are
// printed ([measured] lines) and quoted in docs/imu.md.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <limits>
#include <string>
#include <vector>

#include "attitude_reference.h"
#include "imu_motion.h"
#include "math_test_util.h"
#include "scalar_conv.h"
#include "sensing/attitude_filter.h"
#include "sensing/gyro_calibration.h"

using strider::AttitudeFilter;
using strider::AttitudeStatus;
using strider::Fixed;
using strider::Vec3;
using strider_test::AttitudeReference;
using strider_test::dbl;
using strider_test::kDeg;
using strider_test::kG;
using strider_test::MaxError;
using strider_test::sc;
using strider_test::TruthSample;

namespace {

constexpr double kDt = 0.02;  // the firmware's 50 Hz tick [s]

// Named error bounds [rad; the bias: rad/s], about twice what was measured
// (docs/imu.md quotes the measured figures).
template <typename S>
struct Tol;
template <>
struct Tol<float> {
  static constexpr double kVsReference = 2e-6;   // any motion here: float against double
  static constexpr double kStatic = 5e-7;        // a static tilt, from its first sample
  static constexpr double kConverged = 1.5e-3;   // 20 s after a tilt change seen by the accelerometer only
  static constexpr double kRate30 = 2e-5;        // constant rate, 30 deg/s
  static constexpr double kRate90 = 4e-4;        // 90 deg/s
  static constexpr double kRate360 = 0.025;      // 360 deg/s (7 deg a sample)
  static constexpr double kRocking = 4e-4;       // rocking, no linear acceleration
  static constexpr double kRockingSway = 0.035;  // rocking with 0.05-0.1 g of sway and bounce
  static constexpr double kNoisy = 6e-3;         // MPU-6050 noise and a gyro bias, after 20 s
  static constexpr double kBias = 6e-3;          // its bias estimate, across the vertical
  static constexpr double kRecordedHexapod = 0.017; // recorded: hexapod18's tripod
  static constexpr double kRecordedSprawl = 0.15;   // recorded: sprawl8's trot
};
template <>
struct Tol<Fixed> {
  static constexpr double kVsReference = 1.5e-3;
  static constexpr double kStatic = 1e-4;
  static constexpr double kConverged = 2.5e-3;
  static constexpr double kRate30 = 1.2e-3;
  static constexpr double kRate90 = 1.2e-3;
  static constexpr double kRate360 = 0.025;
  static constexpr double kRocking = 1.2e-3;
  static constexpr double kRockingSway = 0.035;
  static constexpr double kNoisy = 6e-3;
  static constexpr double kBias = 6e-3;
  static constexpr double kRecordedHexapod = 0.017;
  static constexpr double kRecordedSprawl = 0.15;
};

template <typename S>
Vec3<S> to_s(const Eigen::Vector3d& v) {
  return Vec3<S>(sc<S>(v.x()), sc<S>(v.y()), sc<S>(v.z()));
}
template <typename S>
Eigen::Vector3d to_e(const Vec3<S>& v) {
  return Eigen::Vector3d(dbl(v.x), dbl(v.y), dbl(v.z));
}

template <typename S>
std::string named(const char* what) {
  return std::string(strider::ScalarTraits<S>::name()) + " " + what;
}

// One filter in scalar S and the double reference, fed the same quantised
// samples; errors are measured from `settle_s` on.
template <typename S>
struct Pair {
  AttitudeFilter<S> f;
  AttitudeReference ref;
  MaxError vs_ref, vs_truth, roll, pitch;
  double settle_s;

  Pair(const char* name, double settle = 0)
      : vs_ref(named<S>(name) + ": up vs double reference [rad]"),
        vs_truth(named<S>(name) + ": up vs truth [rad]"),
        roll(named<S>(name) + ": roll vs truth [rad]"),
        pitch(named<S>(name) + ": pitch vs truth [rad]"),
        settle_s(settle) {}

  AttitudeStatus step(const TruthSample& s, double dt) {
    const Vec3<S> a = to_s<S>(s.accel), w = to_s<S>(s.gyro);
    const S dts = sc<S>(dt);
    const AttitudeStatus st = f.update(a, w, dts);
    const AttitudeReference::Status rs = ref.update(to_e(a), to_e(w), dbl(dts));
    EXPECT_EQ(int(st), int(rs)) << "t = " << s.t;
    if (s.t + 1e-9 >= settle_s) measure(s);
    return st;
  }
  void measure(const TruthSample& s) {
    const Eigen::Vector3d up = to_e(f.up());
    vs_ref.add(strider_test::angle_between(up, ref.up()), s.t);
    vs_truth.add(strider_test::angle_between(up, s.up), s.t);
    pitch.add(dbl(f.pitch_rad()) - strider_test::pitch_of(s.up), s.t);
    if (std::fabs(strider_test::pitch_of(s.up)) < 80 * kDeg)  // roll is ill-defined near +-90 deg pitch
      roll.add(double(strider_test::angle_diff(dbl(f.roll_rad()), strider_test::roll_of(s.up))), s.t);
  }
  void run(const std::vector<TruthSample>& trace, double dt) {
    for (const TruthSample& s : trace) step(s, dt);
  }
};

template <typename S>
class AttitudeFilterTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(AttitudeFilterTest, Scalars);

// The generator itself: the Euler-rate formula is the rate of the rotation
// (R^T dR/dt = [w]x, by central differences).
TEST(ImuMotion, EulerRatesAreBodyRates) {
  strider_test::EulerMotion m;
  m.angles = [](double t) -> Eigen::Vector3d { return Eigen::Vector3d(0.7 * std::sin(t), 0.5 * std::cos(1.3 * t), 2.0 * t); };
  m.rates = [](double t) -> Eigen::Vector3d { return Eigen::Vector3d(0.7 * std::cos(t), -0.65 * std::sin(1.3 * t), 2.0); };
  for (double t = 0; t < 5; t += 0.37) {
    const double h = 1e-6;
    const Eigen::Vector3d e0 = m.angles(t - h), e1 = m.angles(t + h), e = m.angles(t);
    const Eigen::Matrix3d dr = (strider_test::rotation_zyx(e1[0], e1[1], e1[2]) -
                                strider_test::rotation_zyx(e0[0], e0[1], e0[2])) / (2 * h);
    const Eigen::Matrix3d k = strider_test::rotation_zyx(e[0], e[1], e[2]).transpose() * dr;
    const Eigen::Vector3d w(k(2, 1), k(0, 2), k(1, 0));
    EXPECT_LT((w - m.at(t).gyro).norm(), 1e-6) << t;
    EXPECT_NEAR(strider_test::roll_of(m.at(t).up), e[0], 1e-12);
    EXPECT_NEAR(strider_test::pitch_of(m.at(t).up), e[1], 1e-12);
  }
}

// Every static tilt on a 5 deg grid (roll all the way round, pitch to +-85):
// the first sample levels the filter, 25 more keep it there.
TYPED_TEST(AttitudeFilterTest, StaticTiltSweep) {
  using S = TypeParam;
  Pair<S> p("static tilt sweep");
  long n = 0;
  for (int r = -180; r < 180; r += 5)
    for (int q = -85; q <= 85; q += 5) {
      p.f = AttitudeFilter<S>();
      p.ref = AttitudeReference();
      const strider_test::EulerMotion m{[=](double) -> Eigen::Vector3d { return Eigen::Vector3d(r * kDeg, q * kDeg, 0.3); },
                                        [](double) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); }};
      for (int k = 0; k <= 25; ++k) {
        const AttitudeStatus st = p.step(m.at(k * kDt), kDt);
        EXPECT_EQ(st, k == 0 ? AttitudeStatus::kLevelled : AttitudeStatus::kOk);
      }
      ++n;
    }
  EXPECT_EQ(n, 72 * 35);
  p.vs_ref.expect_below(Tol<S>::kVsReference);
  p.vs_truth.expect_below(Tol<S>::kStatic);
  p.roll.expect_below(Tol<S>::kStatic);
  p.pitch.expect_below(Tol<S>::kStatic);
}

// Started level, then the accelerometer alone reports a tilt (no rate: the
// case of a bias the filter does not know about yet): the error obeys the
// loop's e'' + kp e' + ki e = 0 with e'(0) = -kp e(0), for kp = 1, ki = 0.25
// e(t) = e0 (1 - t/2) exp(-t/2) (it overshoots: the bias integral takes part
// of the step for a bias, and gives it back), and is gone after 20 s. Tilts
// beyond 90 deg are re-levelled.
TYPED_TEST(AttitudeFilterTest, ConvergesToATiltSeenByTheAccelerometer) {
  using S = TypeParam;
  Pair<S> p("accel-only tilt change, at 20 s", 20.0);
  MaxError linear(named<S>("10 deg step: error vs e0 (1 - t/2) exp(-t/2) [rad]"));
  for (int r = -165; r < 180; r += 15)
    for (int q = -75; q <= 75; q += 15) {
      p.f = AttitudeFilter<S>();
      p.ref = AttitudeReference();
      TruthSample level;
      level.accel = kG * Eigen::Vector3d::UnitZ();
      level.gyro.setZero();
      level.up = Eigen::Vector3d::UnitZ();
      level.t = -1;
      p.step(level, kDt);
      const strider_test::EulerMotion m{[=](double) -> Eigen::Vector3d { return Eigen::Vector3d(r * kDeg, q * kDeg, 0); },
                                        [](double) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); }};
      p.run(strider_test::record([&](double t) { return m.at(t); }, 20.0, kDt), kDt);
    }
  p.vs_ref.expect_below(Tol<S>::kVsReference);
  p.vs_truth.expect_below(Tol<S>::kConverged);
  // The small-angle response, one 10 deg roll step.
  AttitudeFilter<S> f;
  f.update(to_s<S>(kG * Eigen::Vector3d::UnitZ()), Vec3<S>(), sc<S>(kDt));
  const Eigen::Vector3d tilted = kG * strider_test::rotation_zyx(10 * kDeg, 0, 0).transpose().col(2);
  for (int k = 1; k <= 500; ++k) {
    f.update(to_s<S>(tilted), Vec3<S>(), sc<S>(kDt));
    const double t = k * kDt, e0 = 10 * kDeg;
    const double want = e0 * (1 - t / 2) * std::exp(-t / 2);
    linear.add(e0 - dbl(f.roll_rad()) - want, t);
  }
  linear.expect_below(0.01 * 10 * kDeg);  // 1 % of the step: the linear model holds
}

// Constant rates about body axes and oblique axes, from a tilted start;
// the accelerometer agrees with the rotation (IMU at the centre).
TYPED_TEST(AttitudeFilterTest, ConstantRateRotation) {
  using S = TypeParam;
  const std::vector<Eigen::Vector3d> axes = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                             Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, 1, 0).normalized(),
                                             Eigen::Vector3d(1, -2, 0.5).normalized()};
  const Eigen::Matrix3d r0 = strider_test::rotation_zyx(10 * kDeg, 5 * kDeg, 0);
  for (double rate_dps : {30.0, 90.0, 360.0}) {
    Pair<S> p((std::to_string(int(rate_dps)) + " deg/s rotation").c_str());
    for (const Eigen::Vector3d& axis : axes) {
      p.f = AttitudeFilter<S>();
      p.ref = AttitudeReference();
      p.run(strider_test::record([&](double t) { return strider_test::constant_rate_at(r0, axis * rate_dps * kDeg, t); },
                                 10.0, kDt),
            kDt);
    }
    p.vs_ref.expect_below(Tol<S>::kVsReference);
    p.vs_truth.expect_below(rate_dps < 50 ? Tol<S>::kRate30 : rate_dps < 100 ? Tol<S>::kRate90 : Tol<S>::kRate360);
  }
}

// Rocking in roll, pitch and yaw at different frequencies with sway and
// bounce (0.05-0.1 g): what a walking body does to the accelerometer.
TYPED_TEST(AttitudeFilterTest, SinusoidalRocking) {
  using S = TypeParam;
  const double w1 = 2 * M_PI * 0.5, w2 = 2 * M_PI * 0.8, w3 = 2 * M_PI * 0.3;
  strider_test::EulerMotion m;
  m.angles = [=](double t) -> Eigen::Vector3d {
    return Eigen::Vector3d(15 * kDeg * std::sin(w1 * t), 10 * kDeg * std::sin(w2 * t + 1), 20 * kDeg * std::sin(w3 * t));
  };
  m.rates = [=](double t) -> Eigen::Vector3d {
    return Eigen::Vector3d(15 * kDeg * w1 * std::cos(w1 * t), 10 * kDeg * w2 * std::cos(w2 * t + 1),
                           20 * kDeg * w3 * std::cos(w3 * t));
  };
  m.accel_world = [](double t) -> Eigen::Vector3d {
    return kG * Eigen::Vector3d(0.05 * std::sin(2 * M_PI * 1.5 * t + 0.3), 0.1 * std::sin(2 * M_PI * t),
                                0.05 * std::sin(4 * M_PI * t));
  };
  Pair<S> p("rocking with sway", 2.0);
  p.run(strider_test::record([&](double t) { return m.at(t); }, 30.0, kDt), kDt);
  p.vs_ref.expect_below(Tol<S>::kVsReference);
  p.vs_truth.expect_below(Tol<S>::kRockingSway);
  p.roll.expect_below(Tol<S>::kRockingSway);
  p.pitch.expect_below(Tol<S>::kRockingSway);
  // Without the sway the error is the integration's alone.
  Pair<S> q("rocking without sway", 2.0);
  m.accel_world = [](double) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); };
  q.run(strider_test::record([&](double t) { return m.at(t); }, 30.0, kDt), kDt);
  q.vs_truth.expect_below(Tol<S>::kRocking);
}

// MPU-6050 noise and an uncalibrated gyro bias (2, -3, 1.5 deg/s), still
// for 30 s and then rocking: the bias estimate converges (the part of it the
// attitude can show: across the vertical) and the tilt error stays small.
// (An accelerometer offset tilts the gravity it measures, 1 deg per 17 mg:
// no filter removes that, a level calibration does.)
TYPED_TEST(AttitudeFilterTest, NoiseAndGyroBiasConvergence) {
  using S = TypeParam;
  strider_test::ImuErrors err;
  err.gyro_bias = Eigen::Vector3d(2, -3, 1.5) * kDeg;
  strider_test::EulerMotion m;
  m.angles = [](double t) -> Eigen::Vector3d {
    return t < 30 ? Eigen::Vector3d(10 * kDeg, -5 * kDeg, 0)
                  : Eigen::Vector3d(10 * kDeg + 8 * kDeg * std::sin(2 * M_PI * 0.4 * (t - 30)), -5 * kDeg, 0);
  };
  m.rates = [](double t) -> Eigen::Vector3d {
    return t < 30 ? Eigen::Vector3d::Zero()
                  : Eigen::Vector3d(8 * kDeg * 2 * M_PI * 0.4 * std::cos(2 * M_PI * 0.4 * (t - 30)), 0, 0);
  };
  auto trace = strider_test::record([&](double t) { return m.at(t); }, 60.0, kDt);
  strider_test::add_errors(trace, err, 42);
  Pair<S> p("noise and gyro bias, from 20 s", 20.0);
  MaxError bias(named<S>("bias estimate across the vertical, from 20 s [rad/s]"));
  for (const TruthSample& s : trace) {
    p.step(s, kDt);
    if (s.t < 20) continue;
    Eigen::Vector3d d = to_e(p.f.gyro_bias_rad_s()) - err.gyro_bias;
    d -= d.dot(s.up) * s.up;
    bias.add(d.norm(), s.t);
  }
  p.vs_ref.expect_below(Tol<S>::kVsReference);
  p.vs_truth.expect_below(Tol<S>::kNoisy);
  bias.expect_below(Tol<S>::kBias);
}

// Recorded in the simulator (test/sensing/data: the IMU model's tick means
// while hexapod18 walks its tripod and sprawl8 trots, with MPU-6050 noise and
// a 2/-3/1.5 deg/s gyro offset): calibrated on the first still second
// (GyroCalibration), then the filter from the accelerometer's attitude, as a
// firmware would run it. Against the double reference fed the same, and
// against the body's true roll and pitch (which include the walking body's
// accelerations: the sprawl8 trot's are the roughest here).
struct Recorded {
  std::vector<double> t, roll, pitch;
  std::vector<Eigen::Vector3d> accel, gyro;
};

Recorded load_recorded(const std::string& name) {
  Recorded r;
  std::ifstream in(std::string(STRIDER_SENSING_DATA) + "/" + name);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;
    std::istringstream f(line);
    double v[9];
    char comma;
    for (int i = 0; i < 9; ++i) {
      f >> v[i];
      if (i < 8) f >> comma;
    }
    r.t.push_back(v[0]);
    r.accel.emplace_back(v[1], v[2], v[3]);
    r.gyro.emplace_back(v[4], v[5], v[6]);
    r.roll.push_back(v[7] * kDeg);
    r.pitch.push_back(v[8] * kDeg);
  }
  return r;
}

template <typename S>
void run_recorded(const char* name, double bound_truth) {
  const Recorded rec = load_recorded(name);
  ASSERT_GT(rec.t.size(), 500u) << name;
  AttitudeFilter<S> f;
  AttitudeReference ref;
  strider::GyroCalibration<S> cal;
  MaxError vs_ref(named<S>(name) + ": up vs double reference [rad]");
  MaxError vs_truth(named<S>(name) + ": roll and pitch vs the body, after calibrating [rad]");
  double calibrated_t = -1;
  for (size_t k = 0; k < rec.t.size(); ++k) {
    const Vec3<S> a = to_s<S>(rec.accel[k]), w = to_s<S>(rec.gyro[k]);
    if (calibrated_t < 0 && cal.add(w) == strider::GyroCalibrationStatus::kDone) {
      f = AttitudeFilter<S>();
      f.set_gyro_bias(cal.offset());
      ref = AttitudeReference();
      ref.set_gyro_bias(to_e(f.gyro_bias_rad_s()));
      calibrated_t = rec.t[k];
    }
    f.update(a, w, sc<S>(kDt));
    ref.update(to_e(a), to_e(w), dbl(sc<S>(kDt)));
    if (calibrated_t < 0) continue;
    vs_ref.add(strider_test::angle_between(to_e(f.up()), ref.up()), rec.t[k]);
    vs_truth.add(dbl(f.roll_rad()) - rec.roll[k], rec.t[k]);
    vs_truth.add(dbl(f.pitch_rad()) - rec.pitch[k], rec.t[k]);
  }
  EXPECT_GT(calibrated_t, 0) << name;
  EXPECT_LT(calibrated_t, 5) << name;
  EXPECT_NEAR(dbl(cal.offset().x), 2 * kDeg, 0.2 * kDeg);
  EXPECT_NEAR(dbl(cal.offset().y), -3 * kDeg, 0.2 * kDeg);
  vs_ref.expect_below(Tol<S>::kVsReference);
  vs_truth.expect_below(bound_truth);
}

TYPED_TEST(AttitudeFilterTest, RecordedSimulatorTraces) {
  using S = TypeParam;
  run_recorded<S>("hexapod18_tripod_imu.csv", Tol<S>::kRecordedHexapod);
  run_recorded<S>("sprawl8_forward_imu.csv", Tol<S>::kRecordedSprawl);
}

// --- edge cases ---------------------------------------------------------

template <typename S>
bool finite_unit(const AttitudeFilter<S>& f) {
  const Eigen::Vector3d u = to_e(f.up());
  const double r = dbl(f.roll_rad()), p = dbl(f.pitch_rad()), t = dbl(f.tilt_rad());
  return u.allFinite() && std::fabs(u.norm() - 1) < 1e-3 && std::isfinite(r) && std::isfinite(p) && std::isfinite(t) &&
         std::fabs(r) <= M_PI + 1e-4 && std::fabs(p) <= M_PI / 2 + 1e-4 && t >= 0 && t <= M_PI + 1e-4;
}

template <typename S>
Vec3<S> up_accel() {
  return to_s<S>(kG * Eigen::Vector3d::UnitZ());
}

TYPED_TEST(AttitudeFilterTest, NothingBeforeATrustedSample) {
  using S = TypeParam;
  AttitudeFilter<S> f;
  EXPECT_FALSE(f.has_attitude());
  EXPECT_EQ(f.update(Vec3<S>(), Vec3<S>(sc<S>(1), S(), S()), sc<S>(kDt)), AttitudeStatus::kHeld);  // free fall
  EXPECT_EQ(f.update(to_s<S>(Eigen::Vector3d(0, 0, 1.25 * kG)), Vec3<S>(), sc<S>(kDt)), AttitudeStatus::kHeld);
  EXPECT_FALSE(f.has_attitude());
  EXPECT_EQ(dbl(f.roll_rad()), 0.0);
  EXPECT_EQ(dbl(f.pitch_rad()), 0.0);
  // Between trust (0.1 g) and reject (0.3 g) a sample would correct, but it
  // cannot start the attitude.
  EXPECT_EQ(f.update(to_s<S>(Eigen::Vector3d(0, 0.5 * kG, 1.0 * kG)), Vec3<S>(), sc<S>(kDt)), AttitudeStatus::kHeld);
  EXPECT_EQ(f.update(to_s<S>(Eigen::Vector3d(0, 0.5 * kG, 0.866 * kG)), Vec3<S>(), sc<S>(kDt)), AttitudeStatus::kLevelled);
  EXPECT_TRUE(f.has_attitude());
  EXPECT_NEAR(dbl(f.roll_rad()), std::atan2(0.5, 0.866), 1e-4);
}

// Free fall (zero accel) and saturated readings: gyro only, no NaN.
TYPED_TEST(AttitudeFilterTest, FreeFallAndSaturationUseTheGyroOnly) {
  using S = TypeParam;
  AttitudeFilter<S> f;
  ASSERT_EQ(f.update(up_accel<S>(), Vec3<S>(), sc<S>(kDt)), AttitudeStatus::kLevelled);
  const Vec3<S> roll_rate(sc<S>(1.0), S(), S());  // 1 rad/s about x
  for (int k = 0; k < 25; ++k) ASSERT_EQ(f.update(Vec3<S>(), roll_rate, sc<S>(kDt)), AttitudeStatus::kGyroOnly);
  EXPECT_NEAR(dbl(f.roll_rad()), 0.49, 2e-3);  // 0.5 s at 1 rad/s, the first 20 ms ramping up from rest
  EXPECT_TRUE(finite_unit(f));
  // Every axis clipped at +-2 g: |a| = 3.5 g, not gravity.
  const double c = 2 * kG;
  for (int k = 0; k < 25; ++k)
    ASSERT_EQ(f.update(to_s<S>(Eigen::Vector3d(c, -c, c)), Vec3<S>(), sc<S>(kDt)), AttitudeStatus::kGyroOnly);
  EXPECT_NEAR(dbl(f.roll_rad()), 0.5, 2e-3);  // and ramping down
  // The gyro pinned at its limit for a second, then beyond anything real.
  const Vec3<S> pinned = to_s<S>(Eigen::Vector3d(34.9, -34.9, 34.9));
  for (int k = 0; k < 50; ++k) f.update(to_s<S>(Eigen::Vector3d(c, c, c)), pinned, sc<S>(kDt));
  EXPECT_TRUE(finite_unit(f));
  for (int k = 0; k < 50; ++k) f.update(up_accel<S>(), to_s<S>(Eigen::Vector3d(1e4, -1e4, 3e4)), sc<S>(kDt));
  EXPECT_TRUE(finite_unit(f));
  // Still again, it finds the level.
  for (int k = 0; k < 1000; ++k) f.update(up_accel<S>(), Vec3<S>(), sc<S>(kDt));
  EXPECT_NEAR(dbl(f.tilt_rad()), 0.0, 1e-2);
}

TYPED_TEST(AttitudeFilterTest, ZeroAndNegativeTimeStepsChangeNothing) {
  using S = TypeParam;
  AttitudeFilter<S> f;
  f.update(to_s<S>(Eigen::Vector3d(1, 2, 9)), Vec3<S>(), sc<S>(kDt));
  for (int k = 0; k < 10; ++k) f.update(to_s<S>(Eigen::Vector3d(1, 2, 9)), to_s<S>(Eigen::Vector3d(0.1, 0, 0)), sc<S>(kDt));
  const Vec3<S> up = f.up(), bias = f.gyro_bias_rad_s();
  for (double dt : {0.0, -kDt, -1e3}) {
    EXPECT_EQ(f.update(Vec3<S>(), to_s<S>(Eigen::Vector3d(5, 5, 5)), sc<S>(dt)), AttitudeStatus::kHeld);
    EXPECT_TRUE(f.up() == up && f.gyro_bias_rad_s() == bias) << "dt " << dt;
  }
  if (!strider::ScalarTraits<S>::kIsFixed) {
    EXPECT_EQ(f.update(up_accel<S>(), Vec3<S>(), sc<S>(std::nan(""))), AttitudeStatus::kHeld);
    EXPECT_TRUE(f.up() == up && f.gyro_bias_rad_s() == bias);
  }
}

// A gap longer than kAttitudeMaxDtS is not integrated: the attitude comes
// from the accelerometer again, or is held when it is not trusted.
TYPED_TEST(AttitudeFilterTest, HugeTimeStepRelevels) {
  using S = TypeParam;
  AttitudeFilter<S> f;
  f.update(up_accel<S>(), Vec3<S>(), sc<S>(kDt));
  const Vec3<S> tilted = to_s<S>(kG * strider_test::rotation_zyx(0.3, -0.2, 0).transpose().col(2));
  const Vec3<S> spin = to_s<S>(Eigen::Vector3d(3, 3, 3));
  for (double dt : {0.25, 10.0, 3e4}) {
    AttitudeFilter<S> g = f;
    EXPECT_EQ(g.update(tilted, spin, sc<S>(dt)), AttitudeStatus::kLevelled) << dt;
    EXPECT_NEAR(dbl(g.roll_rad()), 0.3, 1e-4);
    EXPECT_NEAR(dbl(g.pitch_rad()), -0.2, 1e-4);
    AttitudeFilter<S> h = f;
    EXPECT_EQ(h.update(Vec3<S>(), spin, sc<S>(dt)), AttitudeStatus::kHeld) << dt;
    EXPECT_NEAR(dbl(h.tilt_rad()), 0.0, 1e-6);
  }
  // The largest dt a scalar holds.
  AttitudeFilter<S> g = f;
  const S huge = sc<S>(strider::ScalarTraits<S>::kIsFixed ? 40000.0 : 3e38);  // Fixed: saturates to max()
  EXPECT_EQ(g.update(tilted, spin, huge), AttitudeStatus::kLevelled);
  EXPECT_TRUE(finite_unit(g));
}

// Upside down while the estimate says upright (a fall with the gyro
// saturated): more than 90 deg off, the filter re-levels.
TYPED_TEST(AttitudeFilterTest, MoreThan90DegreesOffRelevels) {
  using S = TypeParam;
  AttitudeFilter<S> f;
  f.update(up_accel<S>(), Vec3<S>(), sc<S>(kDt));
  const Vec3<S> upside_down = to_s<S>(Eigen::Vector3d(0.1, 0, -kG));
  EXPECT_EQ(f.update(upside_down, Vec3<S>(), sc<S>(kDt)), AttitudeStatus::kLevelled);
  EXPECT_NEAR(std::fabs(dbl(f.roll_rad())), M_PI, 1e-4);
  EXPECT_NEAR(dbl(f.tilt_rad()), M_PI - 0.0102, 1e-3);
  EXPECT_EQ(f.update(upside_down, Vec3<S>(), sc<S>(kDt)), AttitudeStatus::kOk);
}

TYPED_TEST(AttitudeFilterTest, GainsAreChecked) {
  using S = TypeParam;
  AttitudeFilter<S> f;
  using G = strider::AttitudeGains<S>;
  EXPECT_FALSE(f.set_gains(G{sc<S>(-1), sc<S>(0.1), sc<S>(0.1), sc<S>(0.3)}));
  EXPECT_FALSE(f.set_gains(G{sc<S>(11), sc<S>(0.1), sc<S>(0.1), sc<S>(0.3)}));
  EXPECT_FALSE(f.set_gains(G{sc<S>(1), sc<S>(-0.1), sc<S>(0.1), sc<S>(0.3)}));
  EXPECT_FALSE(f.set_gains(G{sc<S>(1), sc<S>(0.1), sc<S>(0.3), sc<S>(0.3)}));
  EXPECT_FALSE(f.set_gains(G{sc<S>(1), sc<S>(0.1), sc<S>(0.1), sc<S>(0.95)}));
  EXPECT_EQ(dbl(f.gains().kp), 1.0);
  EXPECT_TRUE(f.set_gains(G{sc<S>(2), sc<S>(1), S(), sc<S>(0.5)}));
  EXPECT_EQ(dbl(f.gains().kp), 2.0);
  // A seeded bias is clamped and read back.
  f.set_gyro_bias(to_s<S>(Eigen::Vector3d(0.01, -0.02, 5)));
  EXPECT_NEAR(dbl(f.gyro_bias_rad_s().x), 0.01, 1e-4);
  EXPECT_NEAR(dbl(f.gyro_bias_rad_s().y), -0.02, 1e-4);
  EXPECT_NEAR(dbl(f.gyro_bias_rad_s().z), strider::kAttitudeMaxBiasRadS, 1e-4);
}

Fixed any_value(strider_test::Xorshift& rng, Fixed*) { return Fixed::from_raw(rng.raw_any()); }
float any_value(strider_test::Xorshift& rng, float*) {
  const uint32_t pick = rng.next() % 8;
  if (pick == 0) return std::numeric_limits<float>::quiet_NaN();
  if (pick == 1) return (rng.next() & 1) ? INFINITY : -INFINITY;
  const uint32_t bits = rng.next();
  float v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

// Seeded random inputs of every magnitude (and for float NaN, infinities,
// denormals): the estimate stays a unit vector and every output finite.
TYPED_TEST(AttitudeFilterTest, GarbageInNoNaNOut) {
  using S = TypeParam;
  strider_test::Xorshift rng(2024);
  AttitudeFilter<S> f;
  auto any = [&]() { return any_value(rng, static_cast<S*>(nullptr)); };
  long levelled = 0;
  for (int k = 0; k < STRIDER_RANDOM_CASES * 50; ++k) {
    const bool sane = rng.next() % 4 == 0;  // now and then gravity, so the filter has an attitude
    const Vec3<S> a = sane ? to_s<S>(kG * Eigen::Vector3d(0.1, -0.2, 1).normalized()) : Vec3<S>(any(), any(), any());
    const Vec3<S> w(any(), any(), any());
    const S dt = rng.next() % 2 ? sc<S>(kDt) : any();
    if (f.update(a, w, dt) == AttitudeStatus::kLevelled) ++levelled;
    ASSERT_TRUE(finite_unit(f)) << k;
    const Eigen::Vector3d b = to_e(f.gyro_bias_rad_s());
    ASSERT_TRUE(b.allFinite() && b.cwiseAbs().maxCoeff() <= strider::kAttitudeMaxBiasRadS + 1e-4) << k;
  }
  EXPECT_GT(levelled, 0);
}

}  // namespace
