// SprawlLeg (seed 000, sprawl8: a1 = 55, a2 = 90 mm) against seed 000's
// equations and a double-precision DH reference.
#include <random>

#include "kinematics/sprawl_leg.h"
#include "leg_test_support.h"

namespace {

using namespace legtest;
using strider::JointLimits;
using strider::SprawlLeg;

constexpr double kA1 = 55.0, kA2 = 90.0;

template <typename S>
SprawlLeg<S> sprawl8(const JointLimits<S, 2>& lim = JointLimits<S, 2>::unlimited()) {
  return SprawlLeg<S>::make(sc<S>(kA1), sc<S>(kA2), lim);
}

// Reference FK: seed 000 table 1 through the DH product H1 H2 (eqs 1-3).
Eigen::Vector3d ref_fk(double t1, double t2) {
  return origin_of(dh(t1, 0.0, kA1, kPi / 2) * dh(t2, 0.0, kA2, 0.0));
}

// Reference IK: eqs 7-8 in double, with the nearest torus point and its distance.
struct RefIk {
  double t1, t2, miss, rho, knee_dist;
  double side_gap;  // how much nearer the chosen half of the torus is [mm]
  Eigen::Vector3d nearest;
};
// Both halves of the torus: facing the target (eqs 7-8) and facing away.
RefIk ref_ik(const Eigen::Vector3d& p) {
  RefIk r;
  r.rho = std::hypot(p.x(), p.y());
  r.t1 = r.rho > 0.0 ? std::atan2(p.y(), p.x()) : 0.0;
  double dr = r.rho - kA1;
  r.knee_dist = std::hypot(dr, p.z());
  r.miss = std::fabs(r.knee_dist - kA2);
  const double far_dist = std::hypot(-r.rho - kA1, p.z());
  r.side_gap = r.rho > 0.0 ? std::fabs(std::fabs(far_dist - kA2) - r.miss) : 1e9;
  if (r.rho > 0.0 && std::fabs(far_dist - kA2) < r.miss) {
    dr = -r.rho - kA1;
    r.t1 += kPi;
    r.knee_dist = far_dist;
    r.miss = std::fabs(far_dist - kA2);
  }
  r.t2 = std::atan2(p.z(), dr);
  r.nearest = ref_fk(r.t1, r.t2);
  return r;
}

template <typename S>
class SprawlLegTest : public ::testing::Test {};
TYPED_TEST_SUITE(SprawlLegTest, Scalars);

TYPED_TEST(SprawlLegTest, Eqs4To6KnownAnswers) {
  using S = TypeParam;
  const auto leg = sprawl8<S>();
  struct Case {
    double t1_deg, t2_deg, x, y, z;
  };
  const double r45 = std::sqrt(0.5);
  const Case cases[] = {
      {0, 0, 145, 0, 0},           {90, 0, 0, 145, 0},  {0, -90, 55, 0, -90},
      {180, 90, -55, 0, 90},       {-90, 180, 0, 35, 0}, {45, -60, 100 * r45, 100 * r45, -90 * std::sqrt(0.75)},
      {-135, -30, -(55 + 45 * std::sqrt(3.0)) * r45, -(55 + 45 * std::sqrt(3.0)) * r45, -45},
  };
  for (const Case& c : cases) {
    typename SprawlLeg<S>::Joints q{{sc<S>(c.t1_deg * kDeg), sc<S>(c.t2_deg * kDeg)}};
    const Eigen::Vector3d got = ev(leg.fk(q));
    EXPECT_LE((got - Eigen::Vector3d(c.x, c.y, c.z)).norm(), Bounds<S>::kFootMm) << c.t1_deg << ", " << c.t2_deg;
  }
}

TYPED_TEST(SprawlLegTest, Eqs7To8KnownAnswers) {
  using S = TypeParam;
  const auto leg = sprawl8<S>();
  struct Case {
    double x, y, z, t1_deg, t2_deg;
  };
  const Case cases[] = {
      {145, 0, 0, 0, 0}, {0, 145, 0, 90, 0}, {55, 0, -90, 0, -90}, {55, 0, 90, 0, 90},
      {-145, 0, 0, 180, 0}, {0, -55 - 45, 90 * std::sqrt(0.75), -90, 60},
  };
  for (const Case& c : cases) {
    typename SprawlLeg<S>::Joints q;
    Vec3<S> reached;
    ASSERT_EQ(checked_ik(leg, vec<S>(c.x, c.y, c.z), q, reached), IkStatus::kOk) << c.x << ", " << c.y;
    EXPECT_LE(angle_diff(dbl(q[0]), c.t1_deg * kDeg) / kDeg, Bounds<S>::kJointDeg) << c.x << ", " << c.y;
    EXPECT_LE(angle_diff(dbl(q[1]), c.t2_deg * kDeg) / kDeg, Bounds<S>::kJointDeg) << c.x << ", " << c.y;
  }
}

TYPED_TEST(SprawlLegTest, FkMatchesDhProduct) {
  using S = TypeParam;
  const auto leg = sprawl8<S>();
  Worst foot("sprawl " + scalar_name<S>() + " fk vs DH product [mm]");
  for (double t1 = -180; t1 <= 180; t1 += 2.5)
    for (double t2 = -180; t2 <= 180; t2 += 2.5) {
      typename SprawlLeg<S>::Joints q{{sc<S>(t1 * kDeg), sc<S>(t2 * kDeg)}};
      const Eigen::Vector3d ref = ref_fk(dbl(q[0]), dbl(q[1]));
      foot.add((ev(leg.fk(q)) - ref).norm(), [&] { return describe(ref); });
    }
  EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
}

// IK(FK(q)) = q over a dense joint grid (every point lies on the torus).
template <typename S>
void round_trip(const SprawlLeg<S>& leg, double t1, double t2, Worst& joint, Worst& foot) {
  const Eigen::Vector3d p = quantised<S>(ref_fk(t1, t2));
  typename SprawlLeg<S>::Joints q;
  Vec3<S> reached;
  const IkStatus st = checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached);
  ASSERT_EQ(st, IkStatus::kOk) << describe(p);
  foot.add((ev(leg.fk(q)) - p).norm(), [&] { return describe(p); });
  if (std::hypot(p.x(), p.y()) < kAxisMarginMm) return;  // t1 is free on the yaw axis
  const double e = std::max(angle_diff(dbl(q[0]), t1), angle_diff(dbl(q[1]), t2)) / kDeg;
  joint.add(e, [&] { return describe(p); });
}

TYPED_TEST(SprawlLegTest, IkOfFkRoundTripDenseGrid) {
  using S = TypeParam;
  const auto leg = sprawl8<S>();
  Worst joint("sprawl " + scalar_name<S>() + " IK(FK(q)) joint error [deg]");
  Worst foot("sprawl " + scalar_name<S>() + " FK(IK(p)) - p on the torus [mm]");
  for (double t1 = -179; t1 <= 180; t1 += 2)
    for (double t2 = -179; t2 <= 180; t2 += 1) round_trip(leg, t1 * kDeg, t2 * kDeg, joint, foot);
  EXPECT_LE(joint.max(), Bounds<S>::kJointDeg) << joint.where();
  EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
}

TYPED_TEST(SprawlLegTest, IkOfFkRoundTripRandom) {
  using S = TypeParam;
  const auto leg = sprawl8<S>();
  Worst joint("sprawl " + scalar_name<S>() + " IK(FK(q)) random joint error [deg]");
  Worst foot("sprawl " + scalar_name<S>() + " FK(IK(p)) - p random [mm]");
  std::mt19937 rng(1000);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) round_trip(leg, angle(rng), angle(rng), joint, foot);
  EXPECT_LE(joint.max(), Bounds<S>::kJointDeg) << joint.where();
  EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
}

// Off the torus: the nearest point, the miss distance and the status, against
// the double reference, over a Cartesian box around the leg.
TYPED_TEST(SprawlLegTest, CartesianGridMatchesReference) {
  using S = TypeParam;
  const auto leg = sprawl8<S>();
  ReferenceSweep<S> sweep("sprawl " + scalar_name<S>() + " IK joint error off the torus [deg]",
                          "sprawl " + scalar_name<S>() + " reached - nearest torus point [mm]");
  Worst miss("sprawl " + scalar_name<S>() + " |reached - p| - distance to torus [mm]");
  constexpr double kTieMm = 0.05;  // both halves about as near: either answer is right
  for (double x = -180; x <= 180; x += 6)
    for (double y = -180; y <= 180; y += 6)
      for (double z = -130; z <= 130; z += 6.5) {
        const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(x, y, z));
        const RefIk r = ref_ik(p);
        const double q_ref[2] = {r.t1, r.t2};
        // The point itself where one half of the torus is clearly nearer; the
        // distance to the torus (below) everywhere.
        const Compare compare = r.side_gap < kTieMm                                     ? Compare::kStatus
                                : r.rho < kAxisMarginMm || r.knee_dist < kAxisMarginMm ? Compare::kFoot
                                                                                         : Compare::kFootAndJoints;
        const IkStatus want = r.knee_dist == 0.0 ? IkStatus::kUnreachable : expected_status<S>(r.miss);
        const auto got = sweep.check(leg, p, want, r.miss, r.nearest, q_ref, compare);
        if (got.status == IkStatus::kUnreachable) continue;
        miss.add(std::fabs((ev(got.reached) - p).norm() - r.miss), [&] { return describe(p); });
      }
  sweep.expect_results(0, 100, 100);
  EXPECT_LE(miss.max(), Bounds<S>::kFootMm) << miss.where();
}

TYPED_TEST(SprawlLegTest, EdgeTable) {
  using S = TypeParam;
  const auto leg = sprawl8<S>();
  const double tol = dbl(strider::IkOptions<S>().tolerance_mm);
  const EdgeRow cases[] = {
      {"fully stretched", 145, 0, 0, IkStatus::kOk, 0},
      {"stretched, within tolerance", 145 + 0.5 * tol, 0, 0, IkStatus::kOk, 0.5 * tol},
      {"just outside reach", 150, 0, 0, IkStatus::kClamped, 5},
      {"outside by more than max_clamp", 171, 0, 0, IkStatus::kUnreachable, -1},
      {"knee folded onto the thigh", 0, -35, 0, IkStatus::kOk, 0},
      {"foot on the yaw axis", 0, 0, -90, IkStatus::kClamped, std::hypot(55.0, 90.0) - 90},
      {"foot at the origin", 0, 0, 0, IkStatus::kUnreachable, -1},
      {"on the knee circle", 55, 0, 0, IkStatus::kUnreachable, -1},
      {"on the knee circle, +y", 0, 55, 0, IkStatus::kUnreachable, -1},
      {"far away", 1e6, 0, 0, IkStatus::kUnreachable, -1},
      {"far away, all axes", -1e6, 1e6, -1e6, IkStatus::kUnreachable, -1},
      {"huge z", 100, 0, 1e30, IkStatus::kUnreachable, -1},
      {"Fixed's largest value", 32767, -32768, 32767, IkStatus::kUnreachable, -1},
  };
  for (const EdgeRow& c : cases) expect_edge_row(leg, c);
}

TEST(SprawlLegFloat, NonFiniteTargetsAreUnreachable) {
  expect_non_finite_targets_unreachable(sprawl8<float>(), Vec3<float>(100.0f, 0.0f, -50.0f));
}

TYPED_TEST(SprawlLegTest, JointLimits) {
  using S = TypeParam;
  JointLimits<S, 2> lim;
  lim.lo[0] = sc<S>(-45 * kDeg), lim.hi[0] = sc<S>(45 * kDeg);
  lim.lo[1] = sc<S>(-100 * kDeg), lim.hi[1] = sc<S>(30 * kDeg);
  const auto leg = sprawl8<S>(lim);
  struct Case {
    double t1_deg, t2_deg;       // the pose the target comes from
    IkStatus want;
    double want_t1, want_t2;     // joints returned [deg]
  };
  const Case cases[] = {
      {30, -30, IkStatus::kOk, 30, -30},
      {60, -30, IkStatus::kJointLimit, 45, -30},
      {-170, -30, IkStatus::kJointLimit, -45, -30},
      {0, 60, IkStatus::kJointLimit, 0, 30},
      {0, -150, IkStatus::kJointLimit, 0, -100},
  };
  for (const Case& c : cases) {
    const Eigen::Vector3d p = ref_fk(c.t1_deg * kDeg, c.t2_deg * kDeg);
    typename SprawlLeg<S>::Joints q;
    Vec3<S> reached;
    ASSERT_EQ(checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached), c.want) << c.t1_deg << ", " << c.t2_deg;
    EXPECT_NEAR(dbl(q[0]) / kDeg, c.want_t1, Bounds<S>::kJointDeg) << c.t1_deg << ", " << c.t2_deg;
    EXPECT_NEAR(dbl(q[1]) / kDeg, c.want_t2, Bounds<S>::kJointDeg) << c.t1_deg << ", " << c.t2_deg;
  }
  // A leg whose yaw range is behind it: atan2's -170 deg is reported as 190 deg.
  lim.lo[0] = sc<S>(90 * kDeg), lim.hi[0] = sc<S>(270 * kDeg);
  const auto back = sprawl8<S>(lim);
  const Eigen::Vector3d p = ref_fk(190 * kDeg, -30 * kDeg);
  typename SprawlLeg<S>::Joints q;
  Vec3<S> reached;
  ASSERT_EQ(checked_ik(back, vec<S>(p.x(), p.y(), p.z()), q, reached), IkStatus::kOk);
  EXPECT_NEAR(dbl(q[0]) / kDeg, 190.0, Bounds<S>::kJointDeg);
}

TYPED_TEST(SprawlLegTest, AggregateAndMakeAgree) {
  using S = TypeParam;
  const SprawlLeg<S> plain{sc<S>(kA1), sc<S>(kA2), JointLimits<S, 2>::unlimited()};
  const auto made = sprawl8<S>();
  typename SprawlLeg<S>::Joints q1, q2;
  Vec3<S> r1, r2;
  const Vec3<S> t = vec<S>(90, -40, -70);
  EXPECT_EQ(plain.ik(t, q1, r1), made.ik(t, q2, r2));
  EXPECT_EQ(q1[0], q2[0]);
  EXPECT_EQ(q1[1], q2[1]);
}

}  // namespace
