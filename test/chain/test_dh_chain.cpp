// DhChain: frames, tip and positional Jacobian of random 3- and 6-joint
// chains against an Eigen double reference and finite differences.
#include <gtest/gtest.h>

#include <random>

#include "chain_random.h"
#include "kinematics/dh_chain.h"
#include "math/working_units.h"

namespace {

using namespace chain_test;
using strider::DhChain;
using strider::DhParams;
using strider::JointVector;
using strider::Vec3;

template <typename S>
class ChainTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(ChainTyped, Scalars);

// Position bounds grow with the number of links (errors add up per frame).
template <typename S, uint8_t N>
double pos_bound() { return Bounds<S>::kPosMm * N / 3.0; }

template <typename S, uint8_t N>
void check_frames_and_tip(uint32_t seed, bool with_base) {
  std::mt19937 rng(seed);
  double worst = 0.0;
  for (int c = 0; c < STRIDER_RANDOM_CASES / 10; ++c) {
    const RandomChain<S, N> rc = random_chain<S, N>(rng, with_base);
    for (int k = 0; k < 10; ++k) {
      const JointVector<S, N> q = random_joints<S, N>(rng);
      const std::vector<Eigen::Isometry3d> ref = rc.ref.frames(to_vector(q));
      strider::Transform<S> f[N + 1];
      rc.chain.frames(q, f);
      for (uint8_t i = 0; i <= N; ++i) {
        const Eigen::Isometry3d got = to_eigen(f[i]);
        const double ep = (got.translation() - ref[i].translation()).cwiseAbs().maxCoeff();
        worst = std::max(worst, ep);
        ASSERT_LE(ep, (pos_bound<S, N>())) << "frame " << int(i) << " chain " << c;
        ASSERT_LE(max_abs_diff(got.linear(), ref[i].linear()), N * Bounds<S>::kRotEntry) << "frame " << int(i);
      }
      const Eigen::Vector3d tip = to_eigen(rc.chain.fk(q));
      ASSERT_LE((tip - ref[N].translation()).cwiseAbs().maxCoeff(), (pos_bound<S, N>()));
      ASSERT_EQ(to_eigen(rc.chain.fk_pose(q).translation), tip);
    }
  }
  ::testing::Test::RecordProperty("worst_position_error_mm", std::to_string(worst));
}

TYPED_TEST(ChainTyped, ThreeJointFramesMatchEigen) { check_frames_and_tip<TypeParam, 3>(101, false); }
TYPED_TEST(ChainTyped, ThreeJointFramesWithBaseMatchEigen) { check_frames_and_tip<TypeParam, 3>(102, true); }
TYPED_TEST(ChainTyped, SixJointFramesMatchEigen) { check_frames_and_tip<TypeParam, 6>(103, false); }
TYPED_TEST(ChainTyped, SixJointFramesWithBaseMatchEigen) { check_frames_and_tip<TypeParam, 6>(104, true); }

template <typename S, uint8_t N>
void check_jacobian(uint32_t seed) {
  std::mt19937 rng(seed);
  for (int c = 0; c < STRIDER_RANDOM_CASES / 10; ++c) {
    const RandomChain<S, N> rc = random_chain<S, N>(rng, true);
    for (int k = 0; k < 10; ++k) {
      const JointVector<S, N> q = random_joints<S, N>(rng);
      strider::PositionJacobian<S, N> jac;
      const Vec3<S> tip = rc.chain.jacobian(q, jac);
      const auto num = rc.ref.numeric_jacobian(to_vector(q));
      ASSERT_EQ(to_eigen(tip), to_eigen(rc.chain.fk(q)));
      for (uint8_t i = 0; i < N; ++i)
        ASSERT_LE((to_eigen(jac.col[i]) - num.col(i)).cwiseAbs().maxCoeff(), N * Bounds<S>::kJacMmRad / 3.0 + 1e-4)
            << "column " << int(i) << " chain " << c;
    }
  }
}

TYPED_TEST(ChainTyped, ThreeJointJacobianMatchesFiniteDifferences) { check_jacobian<TypeParam, 3>(201); }
TYPED_TEST(ChainTyped, SixJointJacobianMatchesFiniteDifferences) { check_jacobian<TypeParam, 6>(202); }

TYPED_TEST(ChainTyped, ReachBoundHoldsEverywhere) {
  using S = TypeParam;
  std::mt19937 rng(303);
  for (int c = 0; c < 50; ++c) {
    const RandomChain<S, 6> rc = random_chain<S, 6>(rng, true);
    const double bound = dbl(rc.chain.reach_bound_mm());
    double sum = 0.0;
    for (const auto& l : rc.ref.links) sum += std::abs(l.a_mm) + std::abs(l.d_mm);
    ASSERT_NEAR(bound, sum, 1e-3);
    for (int k = 0; k < 40; ++k) {
      const Eigen::Vector3d tip = rc.ref.tip(to_vector(random_joints<S, 6>(rng)));
      ASSERT_LE((tip - rc.ref.base.translation()).norm(), bound + 1e-6);
    }
  }
}

// A planar two-link arm (seed 003 geometry): the Jacobian in closed form.
TYPED_TEST(ChainTyped, PlanarJacobianKnownAnswer) {
  using S = TypeParam;
  const DhParams<S> links[2] = {{S(70), S(0), S(0), S(0)}, {S(70), S(0), S(0), S(0)}};
  const DhChain<S, 2> leg(links);
  const double t1 = 0.4, t2 = 0.9;
  const JointVector<S, 2> q{{strider::scalar<S>(t1), strider::scalar<S>(t2)}};
  strider::PositionJacobian<S, 2> j;
  leg.jacobian(q, j);
  const double s1 = std::sin(t1), c1 = std::cos(t1), s12 = std::sin(t1 + t2), c12 = std::cos(t1 + t2);
  const double tol = Bounds<S>::kJacMmRad;
  EXPECT_NEAR(dbl(j.col[0].x), -70 * s1 - 70 * s12, tol);
  EXPECT_NEAR(dbl(j.col[0].y), 70 * c1 + 70 * c12, tol);
  EXPECT_NEAR(dbl(j.col[1].x), -70 * s12, tol);
  EXPECT_NEAR(dbl(j.col[1].y), 70 * c12, tol);
  EXPECT_EQ(j.col[0].z, S(0));
  EXPECT_EQ(j.col[1].z, S(0));
}

TYPED_TEST(ChainTyped, SettersKeepTheCacheConsistent) {
  using S = TypeParam;
  DhChain<S, 2> chain;
  const JointVector<S, 2> q{{S(0), S(0)}};
  EXPECT_EQ(chain.fk(q), Vec3<S>());
  chain.set_link(0, DhParams<S>{S(10), strider::half_pi<S>(), S(5), S(0)});
  chain.set_link(1, DhParams<S>{S(20), S(0), S(0), strider::half_pi<S>()});
  // Link 1: frame 1 at (10, 0, 5), its z along -y0; link 2 turns +90 deg
  // about it: x1 = x0 turns to y1 = z0, so the tip is (10, 0, 25).
  const Eigen::Vector3d tip = to_eigen(chain.fk(q));
  EXPECT_LE((tip - Eigen::Vector3d(10, 0, 25)).cwiseAbs().maxCoeff(), 100 * Bounds<S>::kRotEntry);
  strider::JointLimits<S, 2> lim;
  lim.lo[0] = lim.lo[1] = S(-1);
  lim.hi[0] = lim.hi[1] = S(1);
  chain.set_limits(lim);
  EXPECT_EQ(chain.limits().hi[1], S(1));
  strider::Transform<S> base = strider::Transform<S>::identity();
  base.translation = Vec3<S>(S(1), S(2), S(3));
  chain.set_base(base);
  EXPECT_LE((to_eigen(chain.fk(q)) - Eigen::Vector3d(11, 2, 28)).cwiseAbs().maxCoeff(), 100 * Bounds<S>::kRotEntry);
}

// norm_safe: no overflow for Fixed far above 181 mm, precision kept for
// small vectors.
TEST(ChainNorm, FixedNormIsOverflowSafeAndPrecise) {
  using strider::Fixed;
  const struct {
    double x, y, z;
  } cases[] = {{300, 400, 0}, {-1200, 500, 0}, {20000, 0, 0}, {0.01, 0, 0}, {0.003, -0.004, 0},
               {0, 0, 0},     {181, 181, 181}, {1e-4, 1e-4, 1e-4}, {25.5, -17.25, 3.5}};
  for (const auto& c : cases) {
    const Vec3<Fixed> v(Fixed(c.x), Fixed(c.y), Fixed(c.z));
    const double exact = std::sqrt(dbl(v.x) * dbl(v.x) + dbl(v.y) * dbl(v.y) + dbl(v.z) * dbl(v.z));
    const double got = strider::units::norm(v).to_double();
    EXPECT_NEAR(got, exact, 2e-4 * exact + 2.0 / 65536) << c.x << " " << c.y << " " << c.z;
    const double exact_f = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
    EXPECT_NEAR(strider::units::norm(Vec3<float>(float(c.x), float(c.y), float(c.z))), exact_f, 1e-6 * exact_f + 1e-9);
  }
  EXPECT_NEAR(strider::units::distance(Vec3<Fixed>(Fixed(-300), Fixed(0), Fixed(0)),
                                     Vec3<Fixed>(Fixed(300), Fixed(0), Fixed(0))).to_double(),
              600.0, 0.05);
}

}  // namespace
