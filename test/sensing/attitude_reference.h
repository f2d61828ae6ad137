// The attitude filter of lib/strider/sensing/attitude_filter.h written again
// in double with Eigen, step for step (the same trust window, clamps, gap
// and re-levelling rules), as the reference the float and Fixed builds are
// compared with.
#ifndef STRIDER_TEST_SENSING_ATTITUDE_REFERENCE_H
#define STRIDER_TEST_SENSING_ATTITUDE_REFERENCE_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace strider_test {

constexpr double kG = 9.80665;  // [m/s^2]

struct RefGains {
  double kp = 1.0, ki = 0.25, trust_g = 0.1, reject_g = 0.3;
};

class AttitudeReference {
 public:
  enum Status { kOk, kGyroOnly, kLevelled, kHeld };

  explicit AttitudeReference(const RefGains& g = RefGains()) : g_(g) {}

  void set_gyro_bias(const Eigen::Vector3d& b) { bias_ = clamp3(b, kMaxBias); }

  Status update(const Eigen::Vector3d& accel_m_s2, const Eigen::Vector3d& gyro_rad_s, double dt) {
    if (!(dt > 0)) return kHeld;
    bool accel_bad = false;
    Eigen::Vector3d a, w;
    for (int i = 0; i < 3; ++i) {
      const double ai = accel_m_s2[i] / kG;
      if (!std::isfinite(ai)) accel_bad = true;
      a[i] = std::isfinite(ai) ? std::clamp(ai, -kMaxAccelG, kMaxAccelG) : 0.0;
      w[i] = std::isfinite(gyro_rad_s[i]) ? std::clamp(gyro_rad_s[i], -kMaxRate, kMaxRate) : 0.0;
    }
    const double mag = accel_bad ? 0.0 : a.norm();
    const double dev = std::fabs(mag - 1.0);
    const double k = accel_bad ? 0.0 : std::clamp((g_.reject_g - dev) / (g_.reject_g - g_.trust_g), 0.0, 1.0);
    const bool full = !accel_bad && dev <= g_.trust_g;
    const Eigen::Vector3d a_unit = k > 0 ? Eigen::Vector3d(a / mag) : Eigen::Vector3d::Zero();
    if (!has_ || dt > kMaxDt || (full && a_unit.dot(up_) < 0)) {
      if (!full) return kHeld;
      up_ = a_unit;
      last_w_ = w;
      has_ = true;
      return kLevelled;
    }
    const Eigen::Vector3d r = clamp3((w + last_w_) / 2 * dt - bias_ * dt, kMaxTurn);
    last_w_ = w;
    const Eigen::Vector3d c = up_.cross(r);
    const Eigen::Vector3d pred = up_ + c + c.cross(r) / 2;
    const Eigen::Vector3d e = k * a_unit.cross(pred);
    bias_ = clamp3(bias_ - g_.ki * dt * e, kMaxBias);
    const Eigen::Vector3d u = pred + up_.cross(g_.kp * dt * e);
    up_ = u / u.norm();
    return k > 0 ? kOk : kGyroOnly;
  }

  bool has_attitude() const { return has_; }
  const Eigen::Vector3d& up() const { return up_; }
  const Eigen::Vector3d& bias() const { return bias_; }
  double roll() const { return std::atan2(up_.y(), up_.z()); }
  double pitch() const { return std::atan2(-up_.x(), std::hypot(up_.y(), up_.z())); }

 private:
  static constexpr double kMaxAccelG = 16.0, kMaxRate = 34.91, kMaxBias = 0.6, kMaxDt = 0.2, kMaxTurn = 0.5;
  static Eigen::Vector3d clamp3(const Eigen::Vector3d& v, double lim) {
    return v.unaryExpr([lim](double x) { return std::clamp(x, -lim, lim); });
  }

  RefGains g_;
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d bias_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_w_ = Eigen::Vector3d::Zero();
  bool has_ = false;
};

}  // namespace strider_test

#endif  // STRIDER_TEST_SENSING_ATTITUDE_REFERENCE_H
