// The simulator's IMU and battery (tools/sim/imu_model.h, battery_model.h,
// sim_sensors.h): the IMU model on made-up body motions (at rest, tilted,
// rotating, accelerating, its noise, offsets and low-pass), on a robot
// resting in the Bullet world, and the battery model's sag, drain and the
// servos' current; then a library-mode run's trace and metrics.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <vector>

#include "battery_model.h"
#include "imu_model.h"
#include "robots/all_robots.h"
#include "sim_run.h"
#include "world.h"

namespace {

using strider_sim::BatteryConfig;
using strider_sim::BatteryModel;
using strider_sim::BodyMotion;
using strider_sim::ImuConfig;
using strider_sim::ImuModel;
using strider_sim::Vec;

constexpr double kGravity = 9.81;  // the world's
constexpr double kDeg = M_PI / 180.0;

BodyMotion motion(const Eigen::Matrix3d& rot, const Vec& vel_mm_s = Vec{}, const Vec& omega = Vec{}) {
  BodyMotion m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.rot[i][j] = rot(i, j);
  m.vel_mm_s = vel_mm_s;
  m.omega_body_rad_s = omega;
  m.gravity_m_s2 = Vec{0, 0, -kGravity};
  return m;
}

Eigen::Matrix3d zyx(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

void expect_vec(const Vec& got, double x, double y, double z, double tol, const char* what) {
  EXPECT_NEAR(got.x, x, tol) << what;
  EXPECT_NEAR(got.y, y, tol) << what;
  EXPECT_NEAR(got.z, z, tol) << what;
}

// At rest and level the IMU reads +1 g on z and no rate.
TEST(SimImuModel, StaticBodyReadsOneGOnZ) {
  ImuModel imu(ImuConfig::ideal());
  for (int k = 0; k < 3; ++k) {
    const auto& r = imu.update(motion(Eigen::Matrix3d::Identity()), 0.004);
    expect_vec(r.accel_m_s2, 0, 0, kGravity, 1e-12, "accel");
    expect_vec(r.gyro_rad_s, 0, 0, 0, 1e-12, "gyro");
  }
}

// Tilted at rest: gravity's components in the body frame, for Z-Y-X roll,
// pitch and any yaw.
TEST(SimImuModel, TiltedBodyReadsGravityComponents) {
  for (double roll : {-170.0, -45.0, 0.0, 10.0, 90.0})
    for (double pitch : {-80.0, -20.0, 0.0, 35.0})
      for (double yaw : {0.0, 123.0}) {
        ImuModel imu(ImuConfig::ideal());
        const auto& r = imu.update(motion(zyx(roll * kDeg, pitch * kDeg, yaw * kDeg)), 0.004);
        const double sr = std::sin(roll * kDeg), cr = std::cos(roll * kDeg);
        const double sp = std::sin(pitch * kDeg), cp = std::cos(pitch * kDeg);
        expect_vec(r.accel_m_s2, -kGravity * sp, kGravity * sr * cp, kGravity * cr * cp, 1e-9, "tilt");
      }
}

// A rotating body reads its body-frame rate; the rate of a point off the
// axis does not change what the gyro reads.
TEST(SimImuModel, RotatingBodyReadsTheRate) {
  ImuModel imu(ImuConfig::ideal());
  const Vec omega{0.3, -0.2, 1.0};
  const auto& r = imu.update(motion(zyx(0.2, 0.1, 0.5), Vec{}, omega), 0.004);
  expect_vec(r.gyro_rad_s, 0.3, -0.2, 1.0, 1e-12, "gyro");
}

// Accelerating at a (world) while tilted: the specific force a - g in the body frame.
TEST(SimImuModel, AcceleratingBodyReadsSpecificForce) {
  ImuModel imu(ImuConfig::ideal());
  const Eigen::Matrix3d rot = zyx(0.3, -0.2, 1.0);
  const Eigen::Vector3d a(2.0, -1.0, 3.0);  // [m/s^2]
  const double dt = 0.004;
  for (int k = 0; k < 5; ++k) {
    const Eigen::Vector3d v = a * (k * dt) * 1000.0;  // [mm/s]
    const auto& r = imu.update(motion(rot, Vec{v.x(), v.y(), v.z()}), dt);
    if (k == 0) continue;  // no velocity before the first reading: no acceleration yet
    const Eigen::Vector3d want = rot.transpose() * (a + Eigen::Vector3d(0, 0, kGravity));
    expect_vec(r.accel_m_s2, want.x(), want.y(), want.z(), 1e-9, "specific force");
  }
}

// The part's errors: drawn offsets within the data sheet's tolerances,
// reproducible per seed; white noise of density x sqrt(bandwidth).
TEST(SimImuModel, NoiseAndOffsetsAsDocumented) {
  ImuModel a{ImuConfig()}, b{ImuConfig()};
  ImuConfig other;
  other.seed = 2;
  ImuModel c(other);
  EXPECT_EQ(a.gyro_bias_dps().x, b.gyro_bias_dps().x);
  EXPECT_NE(a.gyro_bias_dps().x, c.gyro_bias_dps().x);
  for (const ImuModel* m : {&a, &c}) {
    EXPECT_LE(std::fabs(m->gyro_bias_dps().x), 20.0);
    EXPECT_LE(std::fabs(m->gyro_bias_dps().z), 20.0);
    EXPECT_LE(std::fabs(m->accel_bias_mg().x), 50.0);
    EXPECT_LE(std::fabs(m->accel_bias_mg().y), 50.0);
    EXPECT_LE(std::fabs(m->accel_bias_mg().z), 80.0);
  }
  ImuConfig given;
  given.random_bias = false;
  given.gyro_bias_dps = Vec{1, -2, 3};
  given.accel_bias_mg = Vec{10, 20, -30};
  ImuModel d(given);
  const int n = 20000;
  double sum[6] = {}, sq[6] = {};
  for (int k = 0; k < n; ++k) {
    const auto& r = d.update(motion(Eigen::Matrix3d::Identity()), 0.004);
    const double v[6] = {r.gyro_rad_s.x, r.gyro_rad_s.y, r.gyro_rad_s.z, r.accel_m_s2.x, r.accel_m_s2.y, r.accel_m_s2.z};
    for (int i = 0; i < 6; ++i) {
      sum[i] += v[i];
      sq[i] += v[i] * v[i];
    }
  }
  const double gyro_sigma = 0.005 * std::sqrt(260.0) * kDeg, accel_sigma = 400e-6 * 9.80665 * std::sqrt(260.0);
  const double mean_want[6] = {1 * kDeg, -2 * kDeg, 3 * kDeg, 0.010 * 9.80665, 0.020 * 9.80665, kGravity - 0.030 * 9.80665};
  for (int i = 0; i < 6; ++i) {
    const double mean = sum[i] / n, sigma = std::sqrt(sq[i] / n - mean * mean);
    const double want_sigma = i < 3 ? gyro_sigma : accel_sigma;
    EXPECT_NEAR(mean, mean_want[i], 5 * want_sigma / std::sqrt(double(n))) << i;
    EXPECT_NEAR(sigma, want_sigma, 0.03 * want_sigma) << i;
  }
}

// The low-pass: a step in rate reaches 1 - exp(-2 pi f t) of it; the
// DLPF_CFG table.
TEST(SimImuModel, LowPassFollowsTheBandwidth) {
  ImuConfig c = ImuConfig::ideal();
  c.bandwidth_hz = 10;
  ImuModel imu(c);
  imu.update(motion(Eigen::Matrix3d::Identity()), 0.004);
  for (int k = 1; k <= 25; ++k) {
    const auto& r = imu.update(motion(Eigen::Matrix3d::Identity(), Vec{}, Vec{1, 0, 0}), 0.004);
    EXPECT_NEAR(r.gyro_rad_s.x, 1 - std::exp(-2 * M_PI * 10 * 0.004 * k), 1e-9) << k;
  }
  EXPECT_EQ(ImuModel::dlpf_bandwidth_hz(0), 256);
  EXPECT_EQ(ImuModel::dlpf_bandwidth_hz(4), 20);
  EXPECT_EQ(ImuModel::dlpf_bandwidth_hz(6), 5);
}

// In the Bullet world: sprawl8 lying limp on the ground reads +1 g along its
// up axis (whatever its small tilt) and no rate once settled.
TEST(SimImuModel, RobotRestingInTheWorld) {
  strider_sim::WorldConfig cfg;
  strider_sim::World w(strider::kSprawl8, cfg, {});
  strider_sim::ChannelPulse off[strider_sim::kMaxChannels];
  w.set_pulses(off);
  ImuModel imu(ImuConfig::ideal());
  for (int k = 0; k < 3000; ++k) {  // 12 s: the limp legs creep for about 9
    w.step();
    imu.update(w.body_motion(Vec{}), cfg.step_s);
  }
  const strider_sim::BodyState b = w.body();
  const double sr = std::sin(b.roll_deg * kDeg), cr = std::cos(b.roll_deg * kDeg);
  const double sp = std::sin(b.pitch_deg * kDeg), cp = std::cos(b.pitch_deg * kDeg);
  expect_vec(imu.reading().accel_m_s2, -kGravity * sp, kGravity * sr * cp, kGravity * cr * cp, 0.02, "resting");
  expect_vec(imu.reading().gyro_rad_s, 0, 0, 0, 1e-3, "resting rate");
}

// --- battery ---------------------------------------------------------------

TEST(SimBattery, LipoOpenCircuitVoltage) {
  EXPECT_DOUBLE_EQ(strider_sim::lipo_cell_ocv(1.0), 4.20);
  EXPECT_DOUBLE_EQ(strider_sim::lipo_cell_ocv(0.0), 3.27);
  EXPECT_DOUBLE_EQ(strider_sim::lipo_cell_ocv(0.5), 3.82);
  EXPECT_DOUBLE_EQ(strider_sim::lipo_cell_ocv(2.0), 4.20);
  for (double s = 0; s < 1; s += 0.01) EXPECT_LT(strider_sim::lipo_cell_ocv(s), strider_sim::lipo_cell_ocv(s + 0.01));
}

// Under load the terminal voltage solves V = Voc - R (P / V + I_logic); the
// charge drops with the current; a load beyond the pack collapses it.
TEST(SimBattery, SagAndDrain) {
  BatteryConfig c;
  BatteryModel idle(c);
  idle.step(0.0, 1.0);
  EXPECT_NEAR(idle.current_a(), c.logic_current_a, 1e-9);
  EXPECT_NEAR(idle.volts(), 8.4 - c.internal_ohm * c.logic_current_a, 1e-9);
  EXPECT_NEAR(idle.pin_volts(), idle.volts() / 3.0, 1e-12);
  BatteryModel loaded(c);
  loaded.step(5.0, 0.004);  // 5 A at 6 V: 35.3 W from the pack
  const double p = 5.0 * 6.0 / 0.85, v = loaded.volts();
  EXPECT_NEAR(v, 8.4 - c.internal_ohm * (p / v + c.logic_current_a), 1e-9);
  EXPECT_NEAR(loaded.current_a(), p / v + c.logic_current_a, 1e-9);
  EXPECT_LT(v, 8.4 - 0.2);
  // 2 A from the pack for half an hour: 1000 mAh of 2200.
  c.logic_current_a = 2.0;
  c.internal_ohm = 0.0;
  BatteryModel drain(c);
  for (int k = 0; k < 1800; ++k) drain.step(0.0, 1.0);
  EXPECT_NEAR(drain.used_mah(), 1000.0, 1e-6);
  EXPECT_NEAR(drain.soc(), 1.0 - 1000.0 / 2200.0, 1e-9);
  // (the voltage of a step is taken at the charge it starts with)
  EXPECT_NEAR(drain.volts(), 2 * strider_sim::lipo_cell_ocv(1.0 - 1000.0 / 2200.0), 1e-3);
  BatteryModel overload(BatteryConfig{});
  overload.step(1000.0, 0.004);
  EXPECT_TRUE(overload.collapsed());
  EXPECT_TRUE(std::isfinite(overload.volts()));
  EXPECT_EQ(strider_sim::battery_for(strider::kDog12).cells, 3);
  EXPECT_EQ(strider_sim::battery_for(strider::kHexapod18).cells, 2);
}

// A servo's supply current from its torque and speed (MG996R: 11 kg cm,
// 0.14 s/60 deg, 2.5 A stall at 6 V).
TEST(SimBattery, ServoCurrentFromTorqueAndSpeed) {
  const strider_sim::ServoModel s = strider_sim::servo_model(strider::ServoPart::kMg996r);
  const strider_sim::ServoElectrical e = strider_sim::servo_electrical(strider::ServoPart::kMg996r);
  EXPECT_EQ(e.stall_current_a, 2.5);
  auto amps = [&](double tau, double w, bool on = true) { return strider_sim::servo_supply_current_a(s, e, tau, w, on); };
  EXPECT_NEAR(amps(0, 0), 0.01, 1e-12);                        // idle
  EXPECT_NEAR(amps(s.torque_nm, 0), 2.5 + 0.01, 1e-9);          // stall
  EXPECT_NEAR(amps(-s.torque_nm / 2, 0), 2.5 / 4 + 0.01, 1e-9); // holding half the stall torque
  // Driving at half speed with a quarter of the torque: I = 0.625 A, V_m = 0.625 x 2.4 + 3 = 4.5 V.
  EXPECT_NEAR(amps(s.torque_nm / 4, s.speed_rad_s / 2), 0.625 * 4.5 / 6 + 0.01, 1e-9);
  // Back-driven at the same speed (braking): V_m = 1.5 - 3 < 0, no draw beyond idle.
  EXPECT_NEAR(amps(s.torque_nm / 4, -s.speed_rad_s / 2), 0.01, 1e-9);
  // The bridge gives at most the supply: at stall torque and full speed, the stall current.
  EXPECT_NEAR(amps(s.torque_nm, s.speed_rad_s), 2.5 + 0.01, 1e-9);
  EXPECT_NEAR(amps(s.torque_nm, 0, false), 0.01, 1e-12);        // no pulses: idle
}

// A library-mode run: the trace carries the IMU, the filter and the
// battery; an ideal IMU's filter follows the body; the servos sag the pack.
TEST(SimSensors, LibraryRunTraceAndMetrics) {
  strider_sim::Scenario sc;
  std::string err;
  ASSERT_TRUE(strider_sim::parse_scenario("robot hexapod18\nduration 8\nimu on\nat 0.2 send $deadman off*cb77\\n\n"
                                          "at 5 send walk 80\\n\n",
                                          &sc, &err))
      << err;
  EXPECT_TRUE(sc.imu);
  strider_sim::RunOptions o;
  o.sensors.imu = ImuConfig::ideal();
  const strider_sim::RunResult r = strider_sim::run_scenario(sc, o);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.metrics.imu_fitted);
  EXPECT_GT(r.metrics.imu_calibrated_s, 0.0);
  EXPECT_LT(r.metrics.imu_max_error_deg, 1.0);
  EXPECT_NEAR(r.metrics.battery_start_v, 8.4, 0.05);
  EXPECT_LT(r.metrics.battery_min_v, r.metrics.battery_start_v - 0.1);
  EXPECT_GT(r.metrics.battery_used_mah, 0.5);
  const strider_sim::TraceRow& last = r.trace.back();
  EXPECT_NEAR(std::hypot(std::hypot(last.imu.accel_m_s2.x, last.imu.accel_m_s2.y), last.imu.accel_m_s2.z), kGravity, 3.0);
  EXPECT_NEAR(last.imu_roll_deg, last.body.roll_deg, 1.0);
  EXPECT_NEAR(last.imu_pitch_deg, last.body.pitch_deg, 1.0);
  EXPECT_GT(last.battery_v, 6.0);
  EXPECT_GT(last.battery_a, 0.15);
  EXPECT_NE(strider_sim::metrics_json(r.metrics).find("\"battery_used_mah\""), std::string::npos);
}

// The robot's code reads them in library mode as the firmware does: the
// status line carries the filter's roll and pitch (near the body's) and the
// pack's voltage (near the model's).
TEST(SimSensors, LibraryModeRobotReadsTheImuAndTheBattery) {
  strider_sim::Scenario sc;
  std::string err;
  ASSERT_TRUE(strider_sim::parse_scenario("robot sprawl8\nduration 6\nimu on\nat 5.5 send status\\n\n", &sc, &err)) << err;
  strider_sim::RunOptions o;
  o.sensors.imu = ImuConfig::ideal();
  const strider_sim::RunResult r = strider_sim::run_scenario(sc, o);
  ASSERT_TRUE(r.ok) << r.error;
  std::string status, battery;
  for (const auto& l : r.log) {
    if (l.text.rfind("ok status", 0) == 0) status = l.text;
    if (l.text.rfind("info battery", 0) == 0) battery = l.text;
  }
  ASSERT_FALSE(status.empty());
  EXPECT_NE(status.find(" imu=ok roll="), std::string::npos) << status;
  EXPECT_EQ(battery.rfind("info battery ok mv=", 0), 0u) << battery;
  const size_t at = status.find("battery_mv=");
  ASSERT_NE(at, std::string::npos) << status;
  EXPECT_NEAR(std::stoi(status.substr(at + 11)), 1000.0 * r.trace.back().battery_v, 150.0) << status;
  const size_t roll = status.find("roll=");
  EXPECT_NEAR(std::stod(status.substr(roll + 5)), r.trace.back().body.roll_deg, 1.5) << status;
}

}  // namespace
