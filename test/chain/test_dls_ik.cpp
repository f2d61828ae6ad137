// Damped-least-squares IK on DH chains: convergence on random reachable
// targets (3 and 6 joints), nearest-point clamping, joint limits, unreachable
// targets and degenerate inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "chain_random.h"
#include "kinematics/dls_ik.h"

namespace {

using namespace chain_test;
using strider::DhChain;
using strider::DhParams;
using strider::DlsOptions;
using strider::DlsReport;
using strider::IkStatus;
using strider::JointLimits;
using strider::JointVector;
using strider::Vec3;

// Float: the solver stops at half of this; the double-precision FK of the
// returned joints must be within it.
constexpr double kFloatResidualMm = 1e-3;
// Fixed: the default Fixed tolerance (0.1 mm) plus FK rounding.
constexpr double kFixedResidualMm = 0.15;
// The random-chain tests give the solver this budget and 16 restarts: random
// DH chains include nearly degenerate ones whose targets sit in small basins
// (with the defaults, 200 steps and 8 restarts, about 2 in 10^4 of them fail;
// robot legs do not, see the sweep below).
constexpr int kMaxIterations = 800;
constexpr uint8_t kRestarts = 16;
// Mean steps per solve over a random stream.
constexpr double kMeanIterations = 25.0;

template <typename S>
struct DlsCase;
template <>
struct DlsCase<float> {
  static constexpr double kResidual = kFloatResidualMm;
  static constexpr double kNearestMm = 0.02;  // reached vs the exact nearest point
  static DlsOptions<float> options() {
    DlsOptions<float> o;
    o.tolerance_mm = float(kFloatResidualMm / 2);
    return o;
  }
  static DlsOptions<float> random_options() {
    DlsOptions<float> o = options();
    o.max_iterations = kMaxIterations;
    o.restarts = kRestarts;
    return o;
  }
};
template <>
struct DlsCase<strider::Fixed> {
  static constexpr double kResidual = kFixedResidualMm;
  static constexpr double kNearestMm = 0.3;
  static DlsOptions<strider::Fixed> options() { return DlsOptions<strider::Fixed>(); }
  static DlsOptions<strider::Fixed> random_options() {
    DlsOptions<strider::Fixed> o = options();
    o.max_iterations = kMaxIterations;
    o.restarts = kRestarts;
    return o;
  }
};

template <typename S>
class DlsTyped : public ::testing::Test {};
using Scalars = ::testing::Types<float, strider::Fixed>;
TYPED_TEST_SUITE(DlsTyped, Scalars);

template <typename S>
S sc(double v) { return strider::scalar<S>(v); }

template <typename S, uint8_t N>
bool all_finite(const JointVector<S, N>& q, const Vec3<S>& p) {
  for (uint8_t i = 0; i < N; ++i)
    if (!std::isfinite(dbl(q[i]))) return false;
  return std::isfinite(dbl(p.x)) && std::isfinite(dbl(p.y)) && std::isfinite(dbl(p.z));
}

// Random chains and joints; the target is the double FK of random joints, so
// it is reachable. The solver starts from zero joints.
template <typename S, uint8_t N>
void random_reachable(uint32_t seed, int cases) {
  std::mt19937 rng(seed);
  int ok = 0, worst_it = 0;
  double worst_res = 0.0, sum_it = 0.0;
  for (int c = 0; c < cases; ++c) {
    const RandomChain<S, N> rc = random_chain<S, N>(rng, c % 2 == 1);
    const Eigen::Vector3d target = rc.ref.tip(to_vector(random_joints<S, N>(rng)));
    JointVector<S, N> q;
    for (uint8_t i = 0; i < N; ++i) q[i] = S(0);
    Vec3<S> reached;
    DlsReport<S> rep;
    const IkStatus st =
        strider::dls_ik(rc.chain, from_eigen<S>(target), q, reached, DlsCase<S>::random_options(), &rep);
    const double res = (rc.ref.tip(to_vector(q)) - target).norm();
    ASSERT_TRUE(all_finite(q, reached));
    ASSERT_EQ(to_eigen(reached), to_eigen(rc.chain.fk(q)));
    if (st == IkStatus::kOk && res < DlsCase<S>::kResidual) ++ok;
    EXPECT_EQ(st, IkStatus::kOk) << "case " << c << " residual " << res << " iterations " << rep.iterations;
    EXPECT_LT(res, DlsCase<S>::kResidual) << "case " << c;
    worst_res = std::max(worst_res, res);
    worst_it = std::max(worst_it, int(rep.iterations));
    sum_it += rep.iterations;
  }
  EXPECT_EQ(ok, cases);  // 100 % success on reachable targets
  EXPECT_LE(worst_it, kMaxIterations);
  EXPECT_LT(sum_it / cases, kMeanIterations);
  std::printf("[ dls %s N=%d ] %d/%d reached, worst residual %.2e mm, iterations mean %.1f worst %d\n",
              strider::ScalarTraits<S>::name(), int(N), ok, cases, worst_res, sum_it / cases, worst_it);
}

TYPED_TEST(DlsTyped, ThreeJointRandomReachableTargets) { random_reachable<TypeParam, 3>(401, STRIDER_RANDOM_CASES / 4); }
TYPED_TEST(DlsTyped, SixJointRandomReachableTargets) { random_reachable<TypeParam, 6>(402, STRIDER_RANDOM_CASES / 4); }

// Seed 002 leg, table 3 in mm.
template <typename S>
DhChain<S, 3> hexapod_leg() {
  const DhParams<S> links[3] = {{S(30), strider::half_pi<S>(), S(32), S(0)},
                                {S(85), S(0), S(0), S(0)},
                                {S(125), S(0), S(0), S(0)}};
  return DhChain<S, 3>(links);
}

// Out of reach: the nearest point lies in the coxa's vertical plane, the leg
// stretched from the femur joint F toward the target.
TYPED_TEST(DlsTyped, ClampsToTheNearestPointOfTheHexapodLeg) {
  using S = TypeParam;
  const DhChain<S, 3> leg = hexapod_leg<S>();
  std::mt19937 rng(500);
  std::uniform_real_distribution<double> az(-3.0, 3.0), el(-1.2, 1.2), beyond(1.0, 20.0);
  const double tol = DlsCase<S>::kNearestMm;
  for (int c = 0; c < 200; ++c) {
    const double a = az(rng), e = el(rng), r = 210.0 + beyond(rng);
    const Eigen::Vector3d f(30 * std::cos(a), 30 * std::sin(a), 32);
    const Eigen::Vector3d dir(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
    const Eigen::Vector3d target = f + r * dir, nearest = f + 210.0 * dir;
    JointVector<S, 3> q{{S(0), S(0), S(0)}};
    Vec3<S> reached;
    const IkStatus st = strider::dls_ik(leg, from_eigen<S>(target), q, reached, DlsCase<S>::options());
    ASSERT_EQ(st, IkStatus::kClamped) << c;
    EXPECT_LT((to_eigen(reached) - nearest).norm(), tol) << c << " r " << r;
  }
}

// A planar 3R arm (alpha = 0, 50 + 40 + 30 mm) in reach of nothing beyond
// 120 mm: the nearest point is at 120 mm along the target direction.
TYPED_TEST(DlsTyped, ClampsPlanarArmAlongTheTargetDirection) {
  using S = TypeParam;
  const DhParams<S> links[3] = {{S(50), S(0), S(0), S(0)}, {S(40), S(0), S(0), S(0)}, {S(30), S(0), S(0), S(0)}};
  const DhChain<S, 3> arm(links);
  for (double ang : {-2.8, -1.0, 0.0, 0.5, 2.0}) {
    for (double r : {121.0, 130.0, 144.0}) {
      const Eigen::Vector3d u(std::cos(ang), std::sin(ang), 0.0);
      JointVector<S, 3> q{{S(0.3), S(-0.2), S(0.4)}};
      Vec3<S> reached;
      DlsReport<S> rep;
      const IkStatus st = strider::dls_ik(arm, from_eigen<S>(r * u), q, reached, DlsCase<S>::options(), &rep);
      EXPECT_EQ(st, IkStatus::kClamped) << ang << " " << r;
      EXPECT_LT((to_eigen(reached) - 120.0 * u).norm(), DlsCase<S>::kNearestMm) << ang << " " << r;
      EXPECT_NEAR(dbl(rep.residual_mm), r - 120.0, DlsCase<S>::kNearestMm);
    }
  }
}

TYPED_TEST(DlsTyped, FarTargetIsUnreachableAndOutputsUntouched) {
  using S = TypeParam;
  const DhChain<S, 3> leg = hexapod_leg<S>();
  // 400 mm: beyond the reach bound (272) + max_clamp (25): rejected at once.
  // 280 mm straight up: within the bound, but 38 mm from the workspace.
  for (const Vec3<S>& target : {Vec3<S>(S(400), S(0), S(0)), Vec3<S>(S(0), S(0), S(280)),
                                Vec3<S>(S(-150), S(-150), S(-200))}) {
    JointVector<S, 3> q{{S(0.25), S(0.5), S(-0.75)}};
    const JointVector<S, 3> q0 = q;
    Vec3<S> reached(S(1), S(2), S(3));
    EXPECT_EQ(strider::dls_ik(leg, target, q, reached, DlsCase<S>::options()), IkStatus::kUnreachable);
    for (uint8_t i = 0; i < 3; ++i) EXPECT_EQ(q[i], q0[i]);
    EXPECT_EQ(reached, Vec3<S>(S(1), S(2), S(3)));
  }
}

// The femur limited to +-0.5 rad: a target that needs 0.7 rad is missed
// with the femur on its limit; one inside the limits is reached.
TYPED_TEST(DlsTyped, JointLimitsClampAndReport) {
  using S = TypeParam;
  DhChain<S, 3> leg = hexapod_leg<S>();
  JointLimits<S, 3> lim;
  lim.lo[0] = sc<S>(-1.0);
  lim.hi[0] = sc<S>(1.0);
  lim.lo[1] = sc<S>(-0.5);
  lim.hi[1] = sc<S>(0.5);
  lim.lo[2] = sc<S>(-2.5);
  lim.hi[2] = sc<S>(0.0);
  leg.set_limits(lim);
  const JointVector<S, 3> q_far{{sc<S>(0.2), sc<S>(0.7), sc<S>(-0.3)}};
  const JointVector<S, 3> q_in{{sc<S>(0.2), sc<S>(0.3), sc<S>(-1.2)}};
  JointVector<S, 3> q{{S(0), S(0), S(-1)}};
  Vec3<S> reached;
  EXPECT_EQ(strider::dls_ik(leg, leg.fk(q_far), q, reached, DlsCase<S>::options()), IkStatus::kJointLimit);
  EXPECT_TRUE(lim.contains(q));
  EXPECT_EQ(q[1], lim.hi[1]);
  EXPECT_EQ(reached, leg.fk(q));
  q = JointVector<S, 3>{{S(0), S(0), S(-1)}};
  EXPECT_EQ(strider::dls_ik(leg, leg.fk(q_in), q, reached, DlsCase<S>::options()), IkStatus::kOk);
  EXPECT_TRUE(lim.contains(q));
  EXPECT_LT(dbl(strider::units::distance(reached, leg.fk(q_in))), DlsCase<S>::kResidual);
}

// A dense sweep of the seed 002 leg's workspace, IK(FK(q)) from a neutral
// stance: every point reached.
TYPED_TEST(DlsTyped, HexapodLegWorkspaceSweep) {
  using S = TypeParam;
  const DhChain<S, 3> leg = hexapod_leg<S>();
  int n = 0;
  double worst = 0.0;
  for (double t1 = -1.2; t1 <= 1.2; t1 += 0.3)
    for (double t2 = -1.2; t2 <= 1.2; t2 += 0.2)
      for (double t3 = -2.6; t3 <= -0.1; t3 += 0.25) {
        const JointVector<S, 3> qt{{sc<S>(t1), sc<S>(t2), sc<S>(t3)}};
        const Vec3<S> target = leg.fk(qt);
        JointVector<S, 3> q{{S(0), sc<S>(0.3), sc<S>(-1.2)}};
        Vec3<S> reached;
        ASSERT_EQ(strider::dls_ik(leg, target, q, reached, DlsCase<S>::options()), IkStatus::kOk)
            << t1 << " " << t2 << " " << t3;
        worst = std::max(worst, dbl(strider::units::distance(reached, target)));
        ++n;
      }
  EXPECT_LT(worst, DlsCase<S>::kResidual);
  std::printf("[ dls %s hexapod sweep ] %d points, worst residual %.2e mm\n", strider::ScalarTraits<S>::name(), n,
              worst);
}

TYPED_TEST(DlsTyped, DegenerateInputsNeverGiveNaN) {
  using S = TypeParam;
  // Target on the base origin: the seed 003 leg folds (q2 = pi).
  const DhParams<S> planar[2] = {{S(70), S(0), S(0), S(0)}, {S(70), S(0), S(0), S(0)}};
  const DhChain<S, 2> leg(planar);
  JointVector<S, 2> q{{S(0), S(0)}};
  Vec3<S> reached;
  const IkStatus st = strider::dls_ik(leg, Vec3<S>(), q, reached, DlsCase<S>::options());
  EXPECT_TRUE(st == IkStatus::kOk || st == IkStatus::kClamped);
  EXPECT_TRUE(all_finite(q, reached));
  EXPECT_LT(dbl(strider::units::norm(reached)), 1.0);
  // A chain of zero-length links: the tip never moves.
  const DhChain<S, 2> point;
  q = JointVector<S, 2>{{S(0), S(0)}};
  EXPECT_EQ(strider::dls_ik(point, Vec3<S>(), q, reached, DlsCase<S>::options()), IkStatus::kOk);
  EXPECT_EQ(strider::dls_ik(point, Vec3<S>(S(3), S(0), S(0)), q, reached, DlsCase<S>::options()), IkStatus::kClamped);
  EXPECT_TRUE(all_finite(q, reached));
  // Straight out along the leg: the singular stretched pose.
  q = JointVector<S, 2>{{S(0), S(0)}};
  EXPECT_EQ(strider::dls_ik(leg, Vec3<S>(S(140), S(0), S(0)), q, reached, DlsCase<S>::options()), IkStatus::kOk);
  EXPECT_EQ(strider::dls_ik(leg, Vec3<S>(S(150), S(0), S(0)), q, reached, DlsCase<S>::options()), IkStatus::kClamped);
  EXPECT_TRUE(all_finite(q, reached));
}

TEST(Dls, NonFiniteInputs) {
  const DhParams<float> planar[2] = {{70, 0, 0, 0}, {70, 0, 0, 0}};
  const DhChain<float, 2> leg(planar);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  JointVector<float, 2> q{{0.1f, 0.2f}};
  Vec3<float> reached(7, 7, 7);
  EXPECT_EQ(strider::dls_ik(leg, Vec3<float>(nan, 0, 0), q, reached), IkStatus::kUnreachable);
  EXPECT_EQ(strider::dls_ik(leg, Vec3<float>(0, inf, 0), q, reached), IkStatus::kUnreachable);
  EXPECT_EQ(q[0], 0.1f);
  EXPECT_EQ(reached, Vec3<float>(7, 7, 7));
  // A NaN start is replaced, the solve goes on.
  q = JointVector<float, 2>{{nan, inf}};
  EXPECT_EQ(strider::dls_ik(leg, Vec3<float>(100, 20, 0), q, reached), IkStatus::kOk);
  EXPECT_TRUE(all_finite(q, reached));
}

TEST(Dls, DeterministicAndReportsWork) {
  const DhChain<float, 3> leg = hexapod_leg<float>();
  const Vec3<float> target(120, -40, -60);
  JointVector<float, 3> a{{0, 0, 0}}, b{{0, 0, 0}};
  Vec3<float> ra, rb;
  DlsReport<float> rep;
  EXPECT_EQ(strider::dls_ik(leg, target, a, ra, DlsOptions<float>(), &rep), IkStatus::kOk);
  EXPECT_EQ(strider::dls_ik(leg, target, b, rb), IkStatus::kOk);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  EXPECT_GT(rep.iterations, 0);
  EXPECT_LE(rep.iterations, DlsOptions<float>().max_iterations);
  EXPECT_LE(rep.residual_mm, DlsOptions<float>().tolerance_mm);
  // Options from the analytic legs' IkOptions.
  strider::IkOptions<float> io;
  io.tolerance_mm = 0.5f;
  EXPECT_EQ(DlsOptions<float>::from(io).tolerance_mm, 0.5f);
}

}  // namespace
