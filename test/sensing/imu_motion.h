// Synthetic motions for the attitude filter's tests, in double: the true
// attitude (Z-Y-X Euler angles, as the simulator reports them) and what an
// ideal IMU at the body's origin reads (specific force, body rates), plus
// MPU-6050-like noise and bias.
#ifndef STRIDER_TEST_SENSING_IMU_MOTION_H
#define STRIDER_TEST_SENSING_IMU_MOTION_H

#include <Eigen/Dense>

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "attitude_reference.h"

namespace strider_test {

constexpr double kDeg = M_PI / 180.0;

struct TruthSample {
  double t = 0;
  Eigen::Vector3d accel;  // specific force, body frame [m/s^2]
  Eigen::Vector3d gyro;   // body rates [rad/s]
  Eigen::Vector3d up;     // world z in the body frame
};

// Body -> world rotation of Z-Y-X Euler angles.
inline Eigen::Matrix3d rotation_zyx(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

inline double roll_of(const Eigen::Vector3d& up) { return std::atan2(up.y(), up.z()); }
inline double pitch_of(const Eigen::Vector3d& up) { return std::atan2(-up.x(), std::hypot(up.y(), up.z())); }
// Angle between two directions [rad].
inline double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// A motion given by its Euler angles (roll, pitch, yaw) and their rates as
// functions of time, and the body's acceleration in the world frame.
struct EulerMotion {
  std::function<Eigen::Vector3d(double)> angles;
  std::function<Eigen::Vector3d(double)> rates;
  std::function<Eigen::Vector3d(double)> accel_world = [](double) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); };

  TruthSample at(double t) const {
    const Eigen::Vector3d e = angles(t), d = rates(t);
    const double sr = std::sin(e[0]), cr = std::cos(e[0]), sp = std::sin(e[1]), cp = std::cos(e[1]);
    TruthSample s;
    s.t = t;
    const Eigen::Matrix3d r = rotation_zyx(e[0], e[1], e[2]);
    s.up = r.transpose() * Eigen::Vector3d::UnitZ();
    // Body rates of Z-Y-X Euler angles.
    s.gyro = Eigen::Vector3d(d[0] - d[2] * sp, d[1] * cr + d[2] * sr * cp, -d[1] * sr + d[2] * cr * cp);
    s.accel = r.transpose() * (accel_world(t) + kG * Eigen::Vector3d::UnitZ());
    return s;
  }
};

// A constant rate omega_b [rad/s] about a body-fixed axis from the attitude r0.
inline TruthSample constant_rate_at(const Eigen::Matrix3d& r0, const Eigen::Vector3d& omega_b, double t) {
  const double w = omega_b.norm();
  const Eigen::Matrix3d r =
      w > 0 ? Eigen::Matrix3d(r0 * Eigen::AngleAxisd(w * t, omega_b / w).toRotationMatrix()) : r0;
  TruthSample s;
  s.t = t;
  s.up = r.transpose() * Eigen::Vector3d::UnitZ();
  s.gyro = omega_b;
  s.accel = kG * s.up;
  return s;
}

template <typename Fn>
std::vector<TruthSample> record(Fn at, double duration_s, double dt) {
  std::vector<TruthSample> out;
  const long n = std::lround(duration_s / dt);
  for (long k = 0; k <= n; ++k) out.push_back(at(double(k) * dt));
  return out;
}

// MPU-6050 figures (product specification rev 3.4, table 6.1/6.2): noise
// density 0.005 deg/s/rtHz (gyro) and 400 ug/rtHz (accel) over the 260 Hz
// bandwidth the Adafruit library selects.
struct ImuErrors {
  double gyro_sigma_rad_s = 0.005 * std::sqrt(260.0) * kDeg;
  double accel_sigma_m_s2 = 400e-6 * kG * std::sqrt(260.0);
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();   // [rad/s]
  Eigen::Vector3d accel_bias = Eigen::Vector3d::Zero();  // [m/s^2]
};

inline void add_errors(std::vector<TruthSample>& trace, const ImuErrors& e, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  for (TruthSample& s : trace)
    for (int i = 0; i < 3; ++i) {
      s.gyro[i] += e.gyro_bias[i] + e.gyro_sigma_rad_s * n(rng);
      s.accel[i] += e.accel_bias[i] + e.accel_sigma_m_s2 * n(rng);
    }
}

}  // namespace strider_test

#endif  // STRIDER_TEST_SENSING_IMU_MOTION_H
