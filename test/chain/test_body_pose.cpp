// Body pose kinematics (seed 001 section 2.3, seed 000 eqs 9-11): zero pose,
// pure translation, rotations against Eigen, seed 001's extreme poses on a
// dog-sized stance, and six legs.
#include <gtest/gtest.h>

#include <random>

#include "chain_reference.h"
#include "kinematics/body_pose.h"

namespace {

using namespace chain_test;
using strider::BodyPose;
using strider::LegMount;
using strider::RotationOrder;
using strider::Vec3;

constexpr double kPi = 3.14159265358979323846;

template <typename S>
struct PoseBounds;
template <>
struct PoseBounds<float> {
  static constexpr double kMm = 1e-3;  // leg-frame target, bodies up to ~700 mm
};
template <>
struct PoseBounds<Fixed> {
  static constexpr double kMm = 0.25;
};

template <typename S>
class BodyPoseTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(BodyPoseTyped, Scalars);

template <typename S>
S sc(double v) { return strider::scalar<S>(v); }

// A stance: hips at (+-half_length, +-half_width, 0), feet `drop` below and
// `out` further out; mounts on the hips, leg x pointing outward (left +90
// deg, right -90 deg), or yaw 0 when `aligned`.
template <typename S>
struct Stance {
  Vec3<S> feet[6];
  LegMount<S> mounts[6];
  uint8_t count;
};

template <typename S>
Stance<S> quad_stance(double half_length, double half_width, double drop, double out, bool aligned) {
  Stance<S> st;
  st.count = 4;
  const double xs[4] = {half_length, half_length, -half_length, -half_length};
  const double ys[4] = {half_width, -half_width, half_width, -half_width};
  for (int i = 0; i < 4; ++i) {
    const double side = ys[i] > 0 ? 1.0 : -1.0;
    st.feet[i] = Vec3<S>(sc<S>(xs[i]), sc<S>(ys[i] + side * out), sc<S>(-drop));
    st.mounts[i] = LegMount<S>::make(Vec3<S>(sc<S>(xs[i]), sc<S>(ys[i]), S(0)), aligned ? S(0) : sc<S>(side * kPi / 2));
  }
  return st;
}

// Seed 002's hexapod: body 175 x 155 mm, legs at the corners and mid-sides,
// each pointing radially.
template <typename S>
Stance<S> hex_stance() {
  Stance<S> st;
  st.count = 6;
  const double xs[6] = {87.5, 0.0, -87.5, 87.5, 0.0, -87.5};
  const double ys[6] = {77.5, 77.5, 77.5, -77.5, -77.5, -77.5};
  for (int i = 0; i < 6; ++i) {
    const double yaw = std::atan2(ys[i], xs[i]);
    st.mounts[i] = LegMount<S>::make(Vec3<S>(sc<S>(xs[i]), sc<S>(ys[i]), S(0)), sc<S>(yaw));
    st.feet[i] = Vec3<S>(sc<S>(xs[i] + 120 * std::cos(yaw)), sc<S>(ys[i] + 120 * std::sin(yaw)), sc<S>(-90));
  }
  return st;
}

// The leg-frame target in double: R^T (p - t), then the mount's inverse.
template <typename S>
Eigen::Vector3d reference_leg(const Eigen::Matrix3d& r, const Eigen::Vector3d& t, const Vec3<S>& foot,
                              const LegMount<S>& m) {
  const Eigen::Vector3d body = r.transpose() * (to_eigen(foot) - t);
  return rz(dbl(m.yaw_rad)).transpose() * (body - to_eigen(m.origin_mm));
}

TYPED_TEST(BodyPoseTyped, ZeroPoseIsIdentity) {
  using S = TypeParam;
  const Stance<S> st = quad_stance<S>(300, 140, 400, 0, false);
  Vec3<S> leg[6], body[6];
  strider::body_pose_feet(BodyPose<S>::zero(), st.feet, st.mounts, st.count, leg, body);
  for (uint8_t i = 0; i < st.count; ++i) {
    EXPECT_EQ(body[i], st.feet[i]);
    EXPECT_EQ(leg[i], st.mounts[i].body_to_leg(st.feet[i]));
  }
  const strider::Transform<S> t = strider::body_transform(BodyPose<S>::zero());
  EXPECT_EQ(to_eigen(t).matrix(), Eigen::Matrix4d::Identity());
}

// Seed 000 eqs 9-11 with the body moved by t: x = xc - x0, y = yc - y0,
// z = zc, where (xc, yc, zc) = p - t is the foot in the moved body frame.
TYPED_TEST(BodyPoseTyped, PureTranslationIsSeed000Eqs9To11) {
  using S = TypeParam;
  const Stance<S> st = quad_stance<S>(35, 35, 60, 55, true);  // sprawl8: square body 70 mm
  const Vec3<S> t(sc<S>(12.5), sc<S>(-7.25), sc<S>(20));
  Vec3<S> leg[6];
  strider::body_pose_feet(BodyPose<S>::make(t, S(0), S(0), S(0)), st.feet, st.mounts, st.count, leg);
  for (uint8_t i = 0; i < st.count; ++i) {
    const double xc = dbl(st.feet[i].x) - dbl(t.x), yc = dbl(st.feet[i].y) - dbl(t.y), zc = dbl(st.feet[i].z) - dbl(t.z);
    EXPECT_NEAR(dbl(leg[i].x), xc - dbl(st.mounts[i].origin_mm.x), 1e-4);  // eq 9
    EXPECT_NEAR(dbl(leg[i].y), yc - dbl(st.mounts[i].origin_mm.y), 1e-4);  // eq 10
    EXPECT_NEAR(dbl(leg[i].z), zc, 1e-4);                                   // eq 11
  }
}

TYPED_TEST(BodyPoseTyped, RandomPosesMatchEigenAndRoundTrip) {
  using S = TypeParam;
  const Stance<S> st = hex_stance<S>();
  std::mt19937 rng(808);
  std::uniform_real_distribution<double> ang(-0.6, 0.6), mm(-40.0, 40.0);
  double worst = 0.0;
  for (int c = 0; c < STRIDER_RANDOM_CASES / 2; ++c) {
    const RotationOrder order = kAllOrders[c % 6];
    const BodyPose<S> pose = BodyPose<S>::make(Vec3<S>(sc<S>(mm(rng)), sc<S>(mm(rng)), sc<S>(mm(rng))), sc<S>(ang(rng)),
                                               sc<S>(ang(rng)), sc<S>(ang(rng)), order);
    const Eigen::Matrix3d r = rpy_reference(dbl(pose.roll_rad), dbl(pose.pitch_rad), dbl(pose.yaw_rad), order);
    const Eigen::Vector3d t = to_eigen(pose.translation_mm);
    Vec3<S> leg[6], body[6];
    strider::body_pose_feet(pose, st.feet, st.mounts, st.count, leg, body);
    const strider::Transform<S> bt = strider::body_transform(pose);
    for (uint8_t i = 0; i < st.count; ++i) {
      const double e = (to_eigen(leg[i]) - reference_leg(r, t, st.feet[i], st.mounts[i])).norm();
      worst = std::max(worst, e);
      ASSERT_LT(e, PoseBounds<S>::kMm) << "case " << c << " leg " << int(i);
      // Round trip: R p' + t = p and the mount maps back.
      ASSERT_LT((to_eigen(bt.apply(body[i])) - to_eigen(st.feet[i])).norm(), PoseBounds<S>::kMm);
      ASSERT_LT((to_eigen(st.mounts[i].leg_to_body(leg[i])) - to_eigen(body[i])).norm(), PoseBounds<S>::kMm);
    }
  }
  std::printf("[ body pose %s, hexapod, random poses ] worst leg-frame error %.2e mm\n",
              strider::ScalarTraits<S>::name(), worst);
}

// Seed 001 table 4's extremes, one angle at a time, on a dog-sized stance
// (body 600 x 280 mm, feet 400 mm below the hips). One-axis rotations are the
// same in every order, which is checked too.
TYPED_TEST(BodyPoseTyped, Seed001ExtremePosesOnDogStance) {
  using S = TypeParam;
  const Stance<S> st = quad_stance<S>(300, 140, 400, 0, false);
  const struct {
    double roll, pitch, yaw;
  } poses[] = {{28, 0, 0}, {-28, 0, 0}, {0, 21, 0}, {0, -21, 0}, {0, 0, 21}, {0, 0, -21}};
  double worst = 0.0;
  for (const auto& pd : poses) {
    const double d2r = kPi / 180.0;
    Vec3<S> first[6];
    for (RotationOrder order : kAllOrders) {
      const BodyPose<S> pose = BodyPose<S>::make(Vec3<S>(), strider::deg_to_rad<S>(pd.roll),
                                                 strider::deg_to_rad<S>(pd.pitch), strider::deg_to_rad<S>(pd.yaw), order);
      const Eigen::Matrix3d r = rz(pd.yaw * d2r) * ry(pd.pitch * d2r) * rx(pd.roll * d2r);
      Vec3<S> leg[6];
      strider::body_pose_feet(pose, st.feet, st.mounts, st.count, leg);
      for (uint8_t i = 0; i < st.count; ++i) {
        const double e = (to_eigen(leg[i]) - reference_leg(r, Eigen::Vector3d::Zero(), st.feet[i], st.mounts[i])).norm();
        worst = std::max(worst, e);
        EXPECT_LT(e, PoseBounds<S>::kMm) << pd.roll << " " << pd.pitch << " " << pd.yaw << " leg " << int(i);
        if (order == RotationOrder::kXYZ) first[i] = leg[i];
        EXPECT_EQ(leg[i], first[i]);
      }
    }
  }
  std::printf("[ body pose %s, dog stance, seed 001 extremes ] worst leg-frame error %.2e mm\n",
              strider::ScalarTraits<S>::name(), worst);
}

// A 28 deg roll about x lifts the right feet relative to the body and lowers
// the left ones (right-handed: +roll turns y toward z).
TEST(BodyPose, RollSignConvention) {
  const Stance<float> st = quad_stance<float>(300, 140, 400, 0, true);
  Vec3<float> leg[6], body[6];
  strider::body_pose_feet(BodyPose<float>::make(Vec3<float>(), float(28 * kPi / 180), 0.f, 0.f), st.feet, st.mounts,
                          st.count, leg, body);
  // Foot 0 is front-left (y > 0): in the rolled body it sits lower.
  EXPECT_LT(body[0].z, st.feet[0].z);
  EXPECT_GT(body[1].z, st.feet[1].z);
  EXPECT_NEAR(body[0].z, -140 * std::sin(28 * kPi / 180) - 400 * std::cos(28 * kPi / 180), 1e-3);
}

}  // namespace
