// DH transforms: Eigen reference and the printed matrices of the seeds
// (seed 003 eqs 1-3, seed 000 eqs 1-6, seed 002 eqs 1-7 with table 3, seed 001
// eqs 3.2-3.6).
#include <gtest/gtest.h>

#include <random>

#include "chain_reference.h"
#include "kinematics/dh_chain.h"
#include "math/dh.h"

namespace {

using namespace chain_test;
using strider::DhChain;
using strider::DhParams;
using strider::JointVector;
using strider::Transform;
using strider::Vec3;

constexpr double kPi = 3.14159265358979323846;

template <typename S>
class DhTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(DhTyped, Scalars);

template <typename S>
S sc(double v) { return strider::scalar<S>(v); }

// Max |entry| difference of the 3x4 parts.
double diff34(const Eigen::Isometry3d& a, const Eigen::Matrix<double, 3, 4>& b) {
  return (a.matrix().topRows<3>() - b).cwiseAbs().maxCoeff();
}

TYPED_TEST(DhTyped, TransformMatchesEigenOnRandomParameters) {
  using S = TypeParam;
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> ang(-3.14159, 3.14159), len(-120.0, 120.0);
  const double pos_bound = Bounds<S>::kPosMm;
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    const S th = sc<S>(ang(rng)), al = sc<S>(ang(rng)), a = sc<S>(len(rng)), d = sc<S>(len(rng));
    const Eigen::Isometry3d ref = dh_reference(dbl(th), dbl(d), dbl(a), dbl(al));
    const Eigen::Isometry3d got = to_eigen(strider::dh_transform(th, d, a, al));
    ASSERT_LE(max_abs_diff(got.linear(), ref.linear()), 2 * Bounds<S>::kRotEntry) << i;
    ASSERT_LE((got.translation() - ref.translation()).cwiseAbs().maxCoeff(), pos_bound) << i;
  }
}

TYPED_TEST(DhTyped, ParamsOverloadAddsTheOffset) {
  using S = TypeParam;
  const DhParams<S> p{sc<S>(40), sc<S>(0.5), sc<S>(-12), sc<S>(0.25)};
  const Eigen::Isometry3d ref = dh_reference(dbl(sc<S>(0.5)) + dbl(p.theta_offset_rad), dbl(p.d_mm), dbl(p.a_mm),
                                             dbl(p.alpha_rad));
  EXPECT_LE((to_eigen(strider::dh_transform(p, sc<S>(0.5))).matrix() - ref.matrix()).cwiseAbs().maxCoeff(),
            Bounds<S>::kPosMm);
}

// Seed 003 eq 1, entry by entry.
TEST(Dh, IsSeed003Eq1) {
  const double th = 0.7, al = -1.1, a = 33.0, d = 7.0;
  const double ct = std::cos(th), st = std::sin(th), ca = std::cos(al), sa = std::sin(al);
  Eigen::Matrix<double, 3, 4> eq1;
  eq1 << ct, -st * ca, st * sa, a * ct, st, ct * ca, -ct * sa, a * st, 0, sa, ca, d;
  EXPECT_LE(diff34(to_eigen(strider::dh_transform(float(th), float(d), float(a), float(al))), eq1), 1e-5);
}

// Seed 000 table 1 (a1 = 55, alpha1 = 90 deg; a2 = 90 mm): H1 H2 = eq 3, the
// position is eqs 4-6.
TYPED_TEST(DhTyped, Seed000TotalMatrixIsEq3) {
  using S = TypeParam;
  const double a1 = 55.0, a2 = 90.0;
  const DhParams<S> links[2] = {{sc<S>(a1), strider::half_pi<S>(), S(0), S(0)}, {sc<S>(a2), S(0), S(0), S(0)}};
  const DhChain<S, 2> leg(links);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ang(-3.0, 3.0);
  for (int i = 0; i < 200; ++i) {
    const JointVector<S, 2> q{{sc<S>(ang(rng)), sc<S>(ang(rng))}};
    const double c1 = std::cos(dbl(q[0])), s1 = std::sin(dbl(q[0])), c2 = std::cos(dbl(q[1])), s2 = std::sin(dbl(q[1]));
    Eigen::Matrix<double, 3, 4> eq3;
    eq3 << c1 * c2, -c1 * s2, s1, c1 * (a1 + a2 * c2),  //
        s1 * c2, -s1 * s2, -c1, s1 * (a1 + a2 * c2),    //
        s2, c2, 0, a2 * s2;
    const Eigen::Isometry3d got = to_eigen(leg.fk_pose(q));
    ASSERT_LE(max_abs_diff(got.linear(), eq3.leftCols<3>()), 2 * Bounds<S>::kRotEntry);
    ASSERT_LE((got.translation() - eq3.col(3)).cwiseAbs().maxCoeff(), Bounds<S>::kPosMm);
    // Eqs 4-6.
    const Vec3<S> p = leg.fk(q);
    ASSERT_NEAR(dbl(p.x), (a1 + a2 * c2) * c1, Bounds<S>::kPosMm);
    ASSERT_NEAR(dbl(p.y), (a1 + a2 * c2) * s1, Bounds<S>::kPosMm);
    ASSERT_NEAR(dbl(p.z), a2 * s2, Bounds<S>::kPosMm);
  }
  // Eqs 1-2 themselves.
  const double c = std::cos(0.4), s = std::sin(0.4);
  Eigen::Matrix<double, 3, 4> h1;
  h1 << c, 0, s, a1 * c, s, 0, -c, a1 * s, 0, 1, 0, 0;
  EXPECT_LE(diff34(to_eigen(leg.link_transform(0, sc<S>(0.4))), h1), Bounds<S>::kPosMm);
}

// Seed 002 table 3 in mm (alpha1 = 90 deg, a1 = 30, d1 = 32, a2 = 85, a3 =
// 125): the chain's tip is eqs 5-7 and its first link eq 1.
TYPED_TEST(DhTyped, Seed002LegIsEqs5To7WithTable3) {
  using S = TypeParam;
  const double l1 = 30, d1 = 32, l2 = 85, l3 = 125;
  const DhParams<S> links[3] = {{sc<S>(l1), strider::half_pi<S>(), sc<S>(d1), S(0)},
                                {sc<S>(l2), S(0), S(0), S(0)},
                                {sc<S>(l3), S(0), S(0), S(0)}};
  const DhChain<S, 3> leg(links);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ang(-2.5, 2.5);
  for (int i = 0; i < STRIDER_RANDOM_CASES / 4; ++i) {
    const JointVector<S, 3> q{{sc<S>(ang(rng)), sc<S>(ang(rng)), sc<S>(ang(rng))}};
    const double t1 = dbl(q[0]), t2 = dbl(q[1]), t3 = dbl(q[2]);
    const double r = std::cos(t2 + t3) * l3 + std::cos(t2) * l2 + l1;
    const Eigen::Vector3d eq567(std::cos(t1) * r, std::sin(t1) * r, std::sin(t2 + t3) * l3 + std::sin(t2) * l2 + d1);
    ASSERT_LE((to_eigen(leg.fk(q)) - eq567).cwiseAbs().maxCoeff(), Bounds<S>::kPosMm) << i;
  }
  const double c = std::cos(-0.8), s = std::sin(-0.8);
  Eigen::Matrix<double, 3, 4> eq1;
  eq1 << c, 0, s, l1 * c, s, 0, -c, l1 * s, 0, 1, 0, d1;
  EXPECT_LE(diff34(to_eigen(leg.link_transform(0, sc<S>(-0.8))), eq1), Bounds<S>::kPosMm);
}

// Seed 003 eq 2 (a1 = a2 = 70 mm, alpha = 0) and eq 3.
TYPED_TEST(DhTyped, Seed003PlanarLegIsEq2) {
  using S = TypeParam;
  const double a = 70.0;
  const DhParams<S> links[2] = {{sc<S>(a), S(0), S(0), S(0)}, {sc<S>(a), S(0), S(0), S(0)}};
  const DhChain<S, 2> leg(links);
  for (double t1 : {-1.0, 0.0, 0.2328, 1.3})
    for (double t2 : {-2.0, 0.3019, 0.9}) {
      const JointVector<S, 2> q{{sc<S>(t1), sc<S>(t2)}};
      const double c1 = std::cos(dbl(q[0])), s1 = std::sin(dbl(q[0]));
      const double c12 = std::cos(dbl(q[0]) + dbl(q[1])), s12 = std::sin(dbl(q[0]) + dbl(q[1]));
      Eigen::Matrix<double, 3, 4> eq2;
      eq2 << c12, -s12, 0, a * c1 + a * c12, s12, c12, 0, a * s1 + a * s12, 0, 0, 1, 0;
      EXPECT_LE(diff34(to_eigen(leg.fk_pose(q)), eq2), Bounds<S>::kPosMm) << t1 << " " << t2;
    }
}

// Seed 001 eqs 3.2-3.6 (La = 44, Lb = 280, Lc = 277 mm): T01 is a quarter turn
// about y, T12..T34 are DH links; the product is the printed S and R, except
// that the printed R row 2 column 2 reads cos(theta3) where the product gives
// -sin(theta1) sin(theta2 + theta3): the test checks the product and that the
// printed entry is indeed different.
TYPED_TEST(DhTyped, Seed001ProductIsPrintedSAndR) {
  using S = TypeParam;
  const double la = 44, lb = 280, lc = 277;
  // Eq 3.2 as a transform: rotation by +90 deg about y.
  Transform<S> t01 = Transform<S>::identity();
  t01.rotation = strider::rot_y(strider::half_pi<S>());
  Eigen::Matrix3d eq32;
  eq32 << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  EXPECT_LE(max_abs_diff(to_eigen(t01.rotation), eq32), Bounds<S>::kRotEntry);

  const DhParams<S> links[3] = {{sc<S>(la), strider::half_pi<S>(), S(0), S(0)},  // eq 3.3
                                {sc<S>(lb), S(0), S(0), S(0)},                   // eq 3.4
                                {sc<S>(lc), S(0), S(0), S(0)}};                  // eq 3.5
  const DhChain<S, 3> leg(links, strider::JointLimits<S, 3>::unlimited(), t01);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ang(-3.0, 3.0);
  int printed_entry_differs = 0;
  for (int i = 0; i < 500; ++i) {
    const JointVector<S, 3> q{{sc<S>(ang(rng)), sc<S>(ang(rng)), sc<S>(ang(rng))}};
    const double t1 = dbl(q[0]), t2 = dbl(q[1]), t3 = dbl(q[2]);
    const double s1 = std::sin(t1), c1 = std::cos(t1), s23 = std::sin(t2 + t3), c23 = std::cos(t2 + t3);
    const double k = la + lc * c23 + lb * std::cos(t2);
    const Eigen::Vector3d s_printed(lc * s23 + lb * std::sin(t2), k * s1, -c1 * k);
    Eigen::Matrix3d r_corrected;
    r_corrected << s23, c23, 0,  //
        c23 * s1, -s1 * s23, -c1,  // printed: cos(theta3) in the middle
        -c23 * c1, s23 * c1, -s1;
    const Eigen::Isometry3d got = to_eigen(leg.fk_pose(q));
    // Product of the four printed matrices, position scale ~600 mm.
    ASSERT_LE((got.translation() - s_printed).cwiseAbs().maxCoeff(), 2 * Bounds<S>::kPosMm) << i;
    ASSERT_LE(max_abs_diff(got.linear(), r_corrected), 2 * Bounds<S>::kRotEntry) << i;
    if (std::abs(got.linear()(1, 1) - std::cos(t3)) > 1e-2) ++printed_entry_differs;
  }
  EXPECT_GT(printed_entry_differs, 450);
}

}  // namespace
