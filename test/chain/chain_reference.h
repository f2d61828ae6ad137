// Double-precision references (Eigen) and shared helpers for the chain tests.
#ifndef STRIDER_TEST_CHAIN_REFERENCE_H
#define STRIDER_TEST_CHAIN_REFERENCE_H

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "math/dh.h"
#include "math/fixed.h"
#include "math/rotation.h"
#include "math/scalar.h"

namespace chain_test {

using strider::Fixed;

// Error bounds. Fixed resolution is 2^-16 = 1.5e-5; its sin/cos are assumed
// within 2e-4 of the exact value, which the Fixed bounds below allow for.
template <typename S>
struct Bounds;
template <>
struct Bounds<float> {
  static constexpr double kRotEntry = 2e-6;   // rotation matrix entry
  static constexpr double kPosMm = 2e-4;      // position of a robot-sized chain [mm]
  static constexpr double kJacMmRad = 5e-4;   // Jacobian entry [mm/rad]
};
template <>
struct Bounds<Fixed> {
  static constexpr double kRotEntry = 1e-3;
  static constexpr double kPosMm = 0.25;
  static constexpr double kJacMmRad = 0.25;
};

inline double dbl(float v) { return double(v); }
inline double dbl(Fixed v) { return v.to_double(); }
inline double dbl(double v) { return v; }

template <typename S>
Eigen::Vector3d to_eigen(const strider::Vec3<S>& v) {
  return Eigen::Vector3d(dbl(v.x), dbl(v.y), dbl(v.z));
}
template <typename S>
Eigen::Matrix3d to_eigen(const strider::Mat3<S>& m) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = dbl(m.m[i][j]);
  return r;
}
template <typename S>
Eigen::Isometry3d to_eigen(const strider::Transform<S>& t) {
  Eigen::Isometry3d r = Eigen::Isometry3d::Identity();
  r.linear() = to_eigen(t.rotation);
  r.translation() = to_eigen(t.translation);
  return r;
}
template <typename S>
strider::Vec3<S> from_eigen(const Eigen::Vector3d& v) {
  return strider::Vec3<S>(strider::scalar<S>(v.x()), strider::scalar<S>(v.y()), strider::scalar<S>(v.z()));
}

inline Eigen::Matrix3d rx(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix(); }
inline Eigen::Matrix3d ry(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix(); }
inline Eigen::Matrix3d rz(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

// The product named by the order, factors left to right.
inline Eigen::Matrix3d rpy_reference(double roll, double pitch, double yaw, strider::RotationOrder o) {
  using strider::RotationOrder;
  const Eigen::Matrix3d x = rx(roll), y = ry(pitch), z = rz(yaw);
  switch (o) {
    case RotationOrder::kXYZ: return x * y * z;
    case RotationOrder::kXZY: return x * z * y;
    case RotationOrder::kYXZ: return y * x * z;
    case RotationOrder::kYZX: return y * z * x;
    case RotationOrder::kZXY: return z * x * y;
    case RotationOrder::kZYX: return z * y * x;
  }
  return Eigen::Matrix3d::Identity();
}

constexpr strider::RotationOrder kAllOrders[] = {
    strider::RotationOrder::kXYZ, strider::RotationOrder::kXZY, strider::RotationOrder::kYXZ,
    strider::RotationOrder::kYZX, strider::RotationOrder::kZXY, strider::RotationOrder::kZYX};

// Standard DH: Rz(theta) Tz(d) Tx(a) Rx(alpha).
inline Eigen::Isometry3d dh_reference(double theta, double d, double a, double alpha) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.rotate(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()));
  t.translate(Eigen::Vector3d(0, 0, d));
  t.translate(Eigen::Vector3d(a, 0, 0));
  t.rotate(Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX()));
  return t;
}

// A chain in double: links as (a, alpha, d, offset) and a base.
struct RefChain {
  std::vector<strider::DhParams<double>> links;
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();

  std::vector<Eigen::Isometry3d> frames(const std::vector<double>& q) const {
    std::vector<Eigen::Isometry3d> f(1, base);
    for (size_t i = 0; i < links.size(); ++i)
      f.push_back(f.back() * dh_reference(q[i] + links[i].theta_offset_rad, links[i].d_mm, links[i].a_mm,
                                          links[i].alpha_rad));
    return f;
  }
  Eigen::Vector3d tip(const std::vector<double>& q) const { return frames(q).back().translation(); }
  // Central differences [mm/rad].
  Eigen::Matrix<double, 3, Eigen::Dynamic> numeric_jacobian(const std::vector<double>& q) const {
    Eigen::Matrix<double, 3, Eigen::Dynamic> j(3, q.size());
    const double h = 1e-6;
    for (size_t i = 0; i < q.size(); ++i) {
      std::vector<double> a = q, b = q;
      a[i] += h;
      b[i] -= h;
      j.col(long(i)) = (tip(a) - tip(b)) / (2 * h);
    }
    return j;
  }
};

inline double max_abs_diff(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

}  // namespace chain_test

#endif  // STRIDER_TEST_CHAIN_REFERENCE_H
