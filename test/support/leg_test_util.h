// Shared helpers of the leg kinematics tests: scalar conversions, error
// bounds per scalar, angle differences, worst-case trackers that print the
// measured maxima, and sentinels for "outputs left untouched".
#ifndef STRIDER_TEST_SUPPORT_LEG_TEST_UTIL_H
#define STRIDER_TEST_SUPPORT_LEG_TEST_UTIL_H

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "kinematics/ik_status.h"
#include "kinematics/joints.h"
#include "math/scalar.h"
#include "math/vec3.h"
#include "scalar_conv.h"

namespace legtest {

using strider::Fixed;
using strider::IkStatus;
using strider::Vec3;
using Scalars = ::testing::Types<float, Fixed>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

//! Error bounds the task sets per scalar.
template <typename S>
struct Bounds;
template <>
struct Bounds<float> {
  static constexpr double kJointDeg = 0.001;  //!< joint error against the double reference
  static constexpr double kFootMm = 0.001;    //!< FK(IK(p)) - p, and fk against the DH reference
};
template <>
struct Bounds<Fixed> {
  static constexpr double kJointDeg = 0.05;
  static constexpr double kFootMm = 0.1;
};

//! Joint-error checks skip targets closer than this to a singular boundary
//! of the workspace (leg stretched or folded, foot on a joint axis, an
//! abduction foot level with its hip): there a joint angle moves by
//! ~1/sqrt(distance) and no scalar resolves it. Foot errors are checked
//! everywhere.
constexpr double kBoundaryMarginMm = 1.0;
constexpr double kAxisMarginMm = 1.0;

using strider_test::dbl;
using strider_test::sc;

template <typename S>
Vec3<S> vec(double x, double y, double z) {
  return Vec3<S>(sc<S>(x), sc<S>(y), sc<S>(z));
}
template <typename S>
Eigen::Vector3d ev(const Vec3<S>& v) {
  return Eigen::Vector3d(dbl(v.x), dbl(v.y), dbl(v.z));
}
//! The double point an S point stands for exactly (inputs are quantised first,
//! so quantisation of the target is not counted as solver error).
template <typename S>
Eigen::Vector3d quantised(const Eigen::Vector3d& p) {
  return ev(vec<S>(p.x(), p.y(), p.z()));
}

//! |a - b| as angles [rad], in [0, pi].
inline double angle_diff(double a, double b) {
  double d = std::fmod(a - b, 2.0 * kPi);
  if (d > kPi) d -= 2.0 * kPi;
  if (d < -kPi) d += 2.0 * kPi;
  return std::fabs(d);
}

template <typename S>
bool finite(S v) {
  return std::isfinite(dbl(v));
}
template <typename S>
bool finite(const Vec3<S>& v) {
  return finite(v.x) && finite(v.y) && finite(v.z);
}

//! Values written into outputs before a call, to see whether it touched them.
template <typename S>
S sentinel() {
  return sc<S>(12345.5);
}
template <typename Joints, typename S>
void fill_sentinel(Joints& q, Vec3<S>& reached) {
  for (uint8_t i = 0; i < Joints::size(); ++i) q[i] = sentinel<S>();
  reached = Vec3<S>(sentinel<S>(), sentinel<S>(), sentinel<S>());
}
template <typename Joints, typename S>
bool untouched(const Joints& q, const Vec3<S>& reached) {
  for (uint8_t i = 0; i < Joints::size(); ++i)
    if (!(q[i] == sentinel<S>())) return false;
  return reached == Vec3<S>(sentinel<S>(), sentinel<S>(), sentinel<S>());
}

//! Worst value seen and where; prints "[measure] name = value (at ...)" at
//! the end so the figures can be collected from the test log.
class Worst {
 public:
  explicit Worst(std::string name) : name_(std::move(name)) {}
  ~Worst() {
    std::printf("[measure] %-58s = %.3g  (n=%ld%s%s)\n", name_.c_str(), max_, count_, where_.empty() ? "" : ", at ",
                where_.c_str());
  }
  template <typename Describe>
  void add(double v, Describe&& describe) {
    ++count_;
    if (!(v <= max_)) {  // NaN is the worst of all
      max_ = v;
      where_ = describe();
    }
  }
  void add(double v) {
    add(v, [] { return std::string(); });
  }
  double max() const { return max_; }
  long count() const { return count_; }
  const std::string& where() const { return where_; }

 private:
  std::string name_;
  double max_ = 0.0;
  long count_ = 0;
  std::string where_;
};

inline std::string describe(const Eigen::Vector3d& p) {
  std::ostringstream os;
  os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return os.str();
}

//! The standard DH transform Rz(theta) Tz(d) Tx(a) Rx(alpha) (seed 003 eq 1,
//! seed 002 eqs 1-3, seed 000 eqs 1-2) in double: the independent reference
//! for the FK of the DH-described legs.
inline Eigen::Matrix4d dh(double theta, double d, double a, double alpha) {
  const double ct = std::cos(theta), st = std::sin(theta), ca = std::cos(alpha), sa = std::sin(alpha);
  Eigen::Matrix4d m;
  m << ct, -st * ca, st * sa, a * ct,  //
      st, ct * ca, -ct * sa, a * st,   //
      0.0, sa, ca, d,                  //
      0.0, 0.0, 0.0, 1.0;
  return m;
}
inline Eigen::Vector3d origin_of(const Eigen::Matrix4d& m) { return m.block<3, 1>(0, 3); }

//! Runs leg.ik on sentinel-filled outputs and checks the contract every
//! analytic leg keeps: no NaN; kUnreachable leaves the outputs untouched;
//! otherwise joints within limits, reached = fk(q), and reached within the
//! tolerance (kOk) or max_clamp (kClamped) of the target.
template <typename Leg, typename S>
IkStatus checked_ik(const Leg& leg, const Vec3<S>& target, typename Leg::Joints& q, Vec3<S>& reached,
                    const strider::IkOptions<S>& opt = strider::IkOptions<S>()) {
  fill_sentinel(q, reached);
  const IkStatus st = leg.ik(target, q, reached, opt);
  const Eigen::Vector3d t = ev(target);
  EXPECT_LE(uint8_t(st), 3) << describe(t);
  if (st == IkStatus::kUnreachable) {
    EXPECT_TRUE(untouched(q, reached)) << describe(t);
    return st;
  }
  for (uint8_t i = 0; i < Leg::kDof; ++i) EXPECT_TRUE(finite(q[i])) << describe(t);
  EXPECT_TRUE(finite(reached)) << describe(t);
  EXPECT_TRUE(leg.limits.contains(q)) << describe(t);
  EXPECT_LE((ev(leg.fk(q)) - ev(reached)).norm(), Bounds<S>::kFootMm) << describe(t);
  const double miss = (ev(reached) - t).norm();
  if (st == IkStatus::kOk) {
    EXPECT_LE(miss, dbl(opt.tolerance_mm) + Bounds<S>::kFootMm) << describe(t);
  }
  if (st == IkStatus::kClamped) {
    EXPECT_LE(miss, dbl(opt.max_clamp_mm) + Bounds<S>::kFootMm) << describe(t);
    EXPECT_GE(miss, dbl(opt.tolerance_mm) - Bounds<S>::kFootMm) << describe(t);
  }
  return st;
}

//! The status a miss distance [mm] should give; kJointLimit when the miss is
//! too close to a threshold to call (the caller then skips the check).
template <typename S>
IkStatus expected_status(double miss, const strider::IkOptions<S>& opt = strider::IkOptions<S>()) {
  const double tol = dbl(opt.tolerance_mm), clamp = dbl(opt.max_clamp_mm), fuzz = Bounds<S>::kFootMm;
  if (std::fabs(miss - tol) < fuzz || std::fabs(miss - clamp) < fuzz) return IkStatus::kJointLimit;
  return miss > clamp ? IkStatus::kUnreachable : miss > tol ? IkStatus::kClamped : IkStatus::kOk;
}

//! Worst cases of an IK(FK(q)) = q / FK(IK(p)) = p sweep.
struct RoundTrip {
  explicit RoundTrip(const std::string& name)
      : joint(name + " IK(FK(q)) joint error [deg]"), foot(name + " FK(IK(p)) - p [mm]") {}
  Worst joint, foot;
  long bad_status = 0;
  std::string first_bad;

  template <typename S>
  void expect_within_bounds() const {
    EXPECT_EQ(bad_status, 0) << "first at " << first_bad;
    EXPECT_LE(joint.max(), Bounds<S>::kJointDeg) << joint.where();
    EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
  }
};

//! One round trip: p_ref = FK_ref(q_ref) (double) is quantised to S, solved,
//! and must give kOk, fk(q) = p, and (when check_joints) q = q_ref.
template <typename S, template <typename> class LegT>
void round_trip(const LegT<S>& leg, const double* q_ref, const Eigen::Vector3d& p_ref, bool check_joints,
                RoundTrip& rt) {
  const Eigen::Vector3d p = quantised<S>(p_ref);
  typename LegT<S>::Joints q;
  Vec3<S> reached;
  const IkStatus st = checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached);
  if (st != IkStatus::kOk) {
    if (rt.bad_status++ == 0) rt.first_bad = describe(p) + " status " + strider::to_string(st);
    return;
  }
  rt.foot.add((ev(leg.fk(q)) - p).norm(), [&] { return describe(p); });
  if (!check_joints) return;
  double e = 0.0;
  for (uint8_t i = 0; i < LegT<S>::kDof; ++i) e = std::max(e, angle_diff(dbl(q[i]), q_ref[i]));
  rt.joint.add(e / kDeg, [&] {
    std::ostringstream os;
    os << describe(p) << " q_ref_deg";
    for (uint8_t i = 0; i < LegT<S>::kDof; ++i) os << " " << q_ref[i] / kDeg;
    return os.str();
  });
}

//! Name of the scalar for messages.
template <typename S>
std::string scalar_name() {
  return strider::ScalarTraits<S>::name();
}

}  // namespace legtest

#endif  // STRIDER_TEST_SUPPORT_LEG_TEST_UTIL_H
