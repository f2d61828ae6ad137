// ImuModel (see imu_model.h).
#include "imu_model.h"

#include <cmath>

namespace strider_sim {

namespace {

constexpr double kG = 9.80665;  // [m/s^2] per g, as the data sheet's mg
constexpr double kDeg = M_PI / 180.0;

// v_body = rot^T v_world.
Vec to_body(const double rot[3][3], const Vec& v) {
  return Vec{rot[0][0] * v.x + rot[1][0] * v.y + rot[2][0] * v.z, rot[0][1] * v.x + rot[1][1] * v.y + rot[2][1] * v.z,
             rot[0][2] * v.x + rot[1][2] * v.y + rot[2][2] * v.z};
}

}  // namespace

ImuModel::ImuModel(const ImuConfig& config) : config_(config), rng_(config.seed) {
  if (config_.random_bias) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double g = config_.gyro_bias_max_dps;
    gyro_bias_dps_ = Vec{g * u(rng_), g * u(rng_), g * u(rng_)};
    const Vec& a = config_.accel_bias_max_mg;
    accel_bias_mg_ = Vec{a.x * u(rng_), a.y * u(rng_), a.z * u(rng_)};
  } else {
    gyro_bias_dps_ = config_.gyro_bias_dps;
    accel_bias_mg_ = config_.accel_bias_mg;
  }
}

const ImuReading& ImuModel::update(const BodyMotion& m, double dt) {
  Vec accel_world;  // [m/s^2]
  if (have_velocity_ && dt > 0) {
    accel_world = Vec{(m.vel_mm_s.x - last_vel_mm_s_.x) * 1e-3 / dt, (m.vel_mm_s.y - last_vel_mm_s_.y) * 1e-3 / dt,
                      (m.vel_mm_s.z - last_vel_mm_s_.z) * 1e-3 / dt};
  }
  have_velocity_ = true;
  last_vel_mm_s_ = m.vel_mm_s;
  const Vec specific{accel_world.x - m.gravity_m_s2.x, accel_world.y - m.gravity_m_s2.y,
                     accel_world.z - m.gravity_m_s2.z};
  const Vec a_body = to_body(m.rot, specific);
  // The part's low-pass: exact first order for a signal held over the step.
  // 256-260 Hz is DLPF_CFG 0 (or 7): the filter is off.
  const double alpha = dt > 0 && config_.bandwidth_hz < 250 ? 1.0 - std::exp(-2.0 * M_PI * config_.bandwidth_hz * dt) : 1.0;
  auto lp = [&](Vec& state, const Vec& in) {
    if (!have_filtered_) state = in;
    state = Vec{state.x + alpha * (in.x - state.x), state.y + alpha * (in.y - state.y), state.z + alpha * (in.z - state.z)};
    return state;
  };
  ideal_.accel_m_s2 = lp(lp_accel_, a_body);
  ideal_.gyro_rad_s = lp(lp_gyro_, m.omega_body_rad_s);
  have_filtered_ = true;
  ideal_.temp_c = config_.temp_c;
  const double gyro_sigma = config_.gyro_noise_dps_rthz * std::sqrt(config_.bandwidth_hz) * kDeg;
  const double accel_sigma = config_.accel_noise_ug_rthz * 1e-6 * kG * std::sqrt(config_.bandwidth_hz);
  std::normal_distribution<double> n(0.0, 1.0);
  auto noisy = [&](double ideal, double bias, double sigma) { return ideal + bias + (sigma > 0 ? sigma * n(rng_) : 0.0); };
  reading_.accel_m_s2 = Vec{noisy(ideal_.accel_m_s2.x, accel_bias_mg_.x * 1e-3 * kG, accel_sigma),
                            noisy(ideal_.accel_m_s2.y, accel_bias_mg_.y * 1e-3 * kG, accel_sigma),
                            noisy(ideal_.accel_m_s2.z, accel_bias_mg_.z * 1e-3 * kG, accel_sigma)};
  reading_.gyro_rad_s = Vec{noisy(ideal_.gyro_rad_s.x, gyro_bias_dps_.x * kDeg, gyro_sigma),
                            noisy(ideal_.gyro_rad_s.y, gyro_bias_dps_.y * kDeg, gyro_sigma),
                            noisy(ideal_.gyro_rad_s.z, gyro_bias_dps_.z * kDeg, gyro_sigma)};
  reading_.temp_c = config_.temp_c;
  return reading_;
}

double ImuModel::dlpf_bandwidth_hz(int dlpf_cfg) {
  static const double kGyroHz[8] = {256, 188, 98, 42, 20, 10, 5, 256};
  return kGyroHz[dlpf_cfg & 7];
}

}  // namespace strider_sim
