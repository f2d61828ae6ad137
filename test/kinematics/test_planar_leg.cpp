// PlanarLeg (seed 003, mammal8: a1 = a2 = 70 mm) against seed 003's
// equations and a double-precision DH reference.
#include <random>

#include "kinematics/planar_leg.h"
#include "leg_test_support.h"

namespace {

using namespace legtest;
using strider::JointLimits;
using strider::KneeBranch;
using strider::PlanarLeg;

constexpr double kA = 70.0;  // a1 = a2

template <typename S>
PlanarLeg<S> mammal8(KneeBranch branch = KneeBranch::kPositive,
                     const JointLimits<S, 2>& lim = JointLimits<S, 2>::unlimited()) {
  return PlanarLeg<S>::make(sc<S>(kA), sc<S>(kA), lim, branch);
}

// Reference FK: seed 003 table 2 through the DH product A1 A2 (eqs 1-2); the
// DH x-y plane is the leg's x-z plane.
Eigen::Vector3d ref_fk(double t1, double t2) {
  const Eigen::Vector3d dh_p = origin_of(dh(t1, 0.0, kA, 0.0) * dh(t2, 0.0, kA, 0.0));
  return Eigen::Vector3d(dh_p.x(), -dh_p.z(), dh_p.y());
}

// Reference IK in double: eq 5 (acos) and eq 4 with the sign of its branch.
struct RefIk {
  double t1, t2, miss, dist;
  Eigen::Vector3d nearest;
};
RefIk ref_ik(const Eigen::Vector3d& p, KneeBranch branch) {
  RefIk r;
  r.dist = std::hypot(p.x(), p.z());
  const double d = std::min(r.dist, 2 * kA);  // nearest point of the disc
  const double abs_t2 = std::acos(std::max(-1.0, std::min(1.0, (d * d - 2 * kA * kA) / (2 * kA * kA))));  // eq 5
  const double lean = std::atan2(kA * std::sin(abs_t2), kA + kA * std::cos(abs_t2));
  const double phi = r.dist > 0 ? std::atan2(p.z(), p.x()) : 0.0;
  r.t2 = branch == KneeBranch::kNegative ? -abs_t2 : abs_t2;
  r.t1 = branch == KneeBranch::kNegative ? phi + lean : phi - lean;  // eq 4: "+" is the negative branch
  r.nearest = ref_fk(r.t1, r.t2);
  r.miss = (r.nearest - p).norm();
  return r;
}

template <typename S>
class PlanarLegTest : public ::testing::Test {};
TYPED_TEST_SUITE(PlanarLegTest, Scalars);

TYPED_TEST(PlanarLegTest, Eq3KnownAnswers) {
  using S = TypeParam;
  const auto leg = mammal8<S>();
  struct Case {
    double t1_deg, t2_deg, x, z;
  };
  const double c30 = std::sqrt(0.75);
  const Case cases[] = {
      {0, 0, 140, 0},     {0, 90, 70, 70},     {-90, 0, 0, -140},      {-90, 90, 70, -70},
      {30, -60, 140 * c30, 0}, {180, 0, -140, 0}, {-60, 120, 70, 0},
  };
  for (const Case& c : cases) {
    typename PlanarLeg<S>::Joints q{{sc<S>(c.t1_deg * kDeg), sc<S>(c.t2_deg * kDeg)}};
    EXPECT_LE((ev(leg.fk(q)) - Eigen::Vector3d(c.x, 0, c.z)).norm(), Bounds<S>::kFootMm) << c.t1_deg << ", "
                                                                                         << c.t2_deg;
  }
}

// Eqs 4-5 verbatim (atan, not atan2): eq 5's t2 = +acos fed to eq 4 gives the
// hip angle of the solution whose knee is -acos (the task's check: a1 = a2 =
// 1, foot (1, 1) -> eq 4 gives 90 deg, and (90, -90) deg reaches (1, 1)).
TYPED_TEST(PlanarLegTest, Eqs4And5AsPrinted) {
  using S = TypeParam;
  const auto neg = mammal8<S>(KneeBranch::kNegative);
  const auto pos = mammal8<S>(KneeBranch::kPositive);
  auto eq5 = [](double x, double z) { return std::acos((x * x + z * z - 2 * kA * kA) / (2 * kA * kA)); };
  auto eq4 = [](double x, double z, double t2) {
    return std::atan(z / x) + std::atan(kA * std::sin(t2) / (kA + kA * std::cos(t2)));
  };
  // The check point, scaled by a1 = a2 = 70.
  EXPECT_NEAR(eq5(70, 70) / kDeg, 90.0, 1e-9);
  EXPECT_NEAR(eq4(70, 70, eq5(70, 70)) / kDeg, 90.0, 1e-9);
  EXPECT_LE((ref_fk(90 * kDeg, -90 * kDeg) - Eigen::Vector3d(70, 0, 70)).norm(), 1e-9);
  EXPECT_GT((ref_fk(90 * kDeg, 90 * kDeg) - Eigen::Vector3d(70, 0, 70)).norm(), 100.0);

  Worst err("planar " + scalar_name<S>() + " IK vs eqs 4-5 as printed [deg]");
  for (double x = 5; x <= 135; x += 10)
    for (double z = -130; z <= 130; z += 10) {
      if (std::hypot(x, z) > 139) continue;
      const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(x, 0, z));
      const double t2 = eq5(p.x(), p.z()), t1 = eq4(p.x(), p.z(), t2);
      typename PlanarLeg<S>::Joints q;
      Vec3<S> reached;
      ASSERT_EQ(checked_ik(neg, vec<S>(p.x(), 0, p.z()), q, reached), IkStatus::kOk) << describe(p);
      err.add(std::max(angle_diff(dbl(q[0]), t1), angle_diff(dbl(q[1]), -t2)) / kDeg, [&] { return describe(p); });
      ASSERT_EQ(checked_ik(pos, vec<S>(p.x(), 0, p.z()), q, reached), IkStatus::kOk) << describe(p);
      const double t1_pos = std::atan(p.z() / p.x()) - std::atan(kA * std::sin(t2) / (kA + kA * std::cos(t2)));
      err.add(std::max(angle_diff(dbl(q[0]), t1_pos), angle_diff(dbl(q[1]), t2)) / kDeg,
              [&] { return describe(p); });
    }
  EXPECT_LE(err.max(), Bounds<S>::kJointDeg) << err.where();
}

TYPED_TEST(PlanarLegTest, FkMatchesDhProduct) {
  using S = TypeParam;
  const auto leg = mammal8<S>();
  Worst foot("planar " + scalar_name<S>() + " fk vs DH product [mm]");
  for (double t1 = -180; t1 <= 180; t1 += 2.5)
    for (double t2 = -180; t2 <= 180; t2 += 2.5) {
      typename PlanarLeg<S>::Joints q{{sc<S>(t1 * kDeg), sc<S>(t2 * kDeg)}};
      const Eigen::Vector3d ref = ref_fk(dbl(q[0]), dbl(q[1]));
      foot.add((ev(leg.fk(q)) - ref).norm(), [&] { return describe(ref); });
    }
  EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
}

// Joint errors are checked kBoundaryMarginMm away from the stretched and the
// folded leg (the foot on the hip axis for a1 = a2).
bool regular(const Eigen::Vector3d& p) {
  const double d = std::hypot(p.x(), p.z());
  return d >= kBoundaryMarginMm && d <= 2 * kA - kBoundaryMarginMm;
}

// IK(FK(q)) = q on both branches.
TYPED_TEST(PlanarLegTest, IkOfFkRoundTripDenseGrid) {
  using S = TypeParam;
  for (KneeBranch branch : {KneeBranch::kPositive, KneeBranch::kNegative}) {
    const auto leg = mammal8<S>(branch);
    const double sign = branch == KneeBranch::kNegative ? -1.0 : 1.0;
    RoundTrip rt("planar " + scalar_name<S>() + (branch == KneeBranch::kNegative ? " t2<=0" : " t2>=0"));
    for (double t1 = -180; t1 < 180; t1 += 1)
      for (double k = 0; k <= 180; k += 0.5) {
        const double q[2] = {t1 * kDeg, sign * k * kDeg};
        const Eigen::Vector3d p = ref_fk(q[0], q[1]);
        round_trip(leg, q, p, regular(p), rt);
      }
    rt.expect_within_bounds<S>();
  }
}

TYPED_TEST(PlanarLegTest, IkOfFkRoundTripRandom) {
  using S = TypeParam;
  const auto leg = mammal8<S>();
  RoundTrip rt("planar " + scalar_name<S>() + " random");
  std::mt19937 rng(3000);
  std::uniform_real_distribution<double> hip(-kPi, kPi), knee(0.0, kPi);
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    const double q[2] = {hip(rng), knee(rng)};
    const Eigen::Vector3d p = ref_fk(q[0], q[1]);
    round_trip(leg, q, p, regular(p), rt);
  }
  rt.expect_within_bounds<S>();
}

// A Cartesian box around the leg, also off its plane: nearest point, miss and
// status against the reference.
TYPED_TEST(PlanarLegTest, CartesianGridMatchesReference) {
  using S = TypeParam;
  const auto leg = mammal8<S>(KneeBranch::kNegative);
  ReferenceSweep<S> sweep("planar " + scalar_name<S>() + " IK joint error, Cartesian grid [deg]",
                          "planar " + scalar_name<S>() + " reached - nearest reachable point [mm]");
  for (double x = -180; x <= 180; x += 3)
    for (double z = -180; z <= 180; z += 3)
      for (double y : {0.0, 0.004, 3.0, 24.0, 26.0}) {
        const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(x, y, z));
        const RefIk r = ref_ik(p, KneeBranch::kNegative);
        const double q_ref[2] = {r.t1, r.t2};
        sweep.check(leg, p, expected_status<S>(r.miss), r.miss, r.nearest, q_ref,
                    regular(p) ? Compare::kFootAndJoints : Compare::kFoot);
      }
  sweep.expect_results(1000, 1000, 1000);
}

TYPED_TEST(PlanarLegTest, EdgeTable) {
  using S = TypeParam;
  const auto leg = mammal8<S>();
  const double tol = dbl(strider::IkOptions<S>().tolerance_mm);
  struct Case {
    const char* what;
    double x, y, z;
    IkStatus want;
    double miss;  // expected |reached - target| [mm], < 0: not checked
    double t2_deg;  // expected knee [deg], NAN: not checked
  };
  const Case cases[] = {
      {"fully stretched", 140, 0, 0, IkStatus::kOk, 0, 0},
      {"stretched down", 0, 0, -140, IkStatus::kOk, 0, 0},
      {"fully folded (foot on the hip axis)", 0, 0, 0, IkStatus::kOk, 0, 180},
      {"just outside reach", 0, 0, -145, IkStatus::kClamped, 5, 0},
      {"outside, within tolerance", 140 + 0.5 * tol, 0, 0, IkStatus::kOk, 0.5 * tol, 0},
      {"outside by more than max_clamp", 100, 0, -140, IkStatus::kUnreachable, -1, NAN},
      {"off the plane", 50, 5, -60, IkStatus::kClamped, 5, NAN},
      {"off the plane, within tolerance", 50, 0.5 * tol, -60, IkStatus::kOk, 0.5 * tol, NAN},
      {"off the plane by more than max_clamp", 50, 26, -60, IkStatus::kUnreachable, -1, NAN},
      {"far away", 1e6, 0, 0, IkStatus::kUnreachable, -1, NAN},
      {"far away, all axes", -1e6, -1e6, 1e6, IkStatus::kUnreachable, -1, NAN},
      {"huge", 1e30, 0, -1e30, IkStatus::kUnreachable, -1, NAN},
      {"Fixed's largest value", -32768, 0, 32767, IkStatus::kUnreachable, -1, NAN},
  };
  for (const Case& c : cases) {
    const typename PlanarLeg<S>::Joints q = expect_edge_row(leg, c);
    if (!std::isnan(c.t2_deg)) {
      EXPECT_NEAR(dbl(q[1]) / kDeg, c.t2_deg, Bounds<S>::kJointDeg) << c.what;
    }
  }
}

TEST(PlanarLegFloat, NonFiniteTargetsAreUnreachable) {
  expect_non_finite_targets_unreachable(mammal8<float>(), Vec3<float>(50.0f, 0.0f, -80.0f));
}

// Seed 003's joint constraints (table 1): 0 <= t1, t2 <= 20 deg.
TYPED_TEST(PlanarLegTest, SeedJointConstraints) {
  using S = TypeParam;
  JointLimits<S, 2> lim;
  for (int i = 0; i < 2; ++i) lim.lo[i] = S(0), lim.hi[i] = sc<S>(20 * kDeg);
  const auto leg = mammal8<S>(KneeBranch::kPositive, lim);
  struct Case {
    double t1_deg, t2_deg;
    IkStatus want;
    double want_t1, want_t2;
  };
  const Case cases[] = {
      {10, 15, IkStatus::kOk, 10, 15},
      {0, 20, IkStatus::kOk, 0, 20},
      {30, 10, IkStatus::kJointLimit, 20, 10},
      {-5, 10, IkStatus::kJointLimit, 0, 10},
      {10, 40, IkStatus::kJointLimit, 10, 20},
  };
  for (const Case& c : cases) {
    const Eigen::Vector3d p = ref_fk(c.t1_deg * kDeg, c.t2_deg * kDeg);
    typename PlanarLeg<S>::Joints q;
    Vec3<S> reached;
    ASSERT_EQ(checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached), c.want) << c.t1_deg << ", " << c.t2_deg;
    EXPECT_NEAR(dbl(q[0]) / kDeg, c.want_t1, Bounds<S>::kJointDeg) << c.t1_deg << ", " << c.t2_deg;
    EXPECT_NEAR(dbl(q[1]) / kDeg, c.want_t2, Bounds<S>::kJointDeg) << c.t1_deg << ", " << c.t2_deg;
  }
}

// make() works in constant expressions (robot models are constexpr data).
TEST(PlanarLegMake, IsConstexpr) {
  constexpr JointLimits<float, 2> lim_f{{0.0f, 0.0f}, {0.35f, 0.35f}};
  constexpr auto leg_f = PlanarLeg<float>::make(70.0f, 70.0f, lim_f);
  static_assert(leg_f.unit_shift == 0, "float works in millimetres");
  constexpr JointLimits<Fixed, 2> lim_x{{Fixed(0), Fixed(0)}, {Fixed(0.35), Fixed(0.35)}};
  constexpr auto leg_x = PlanarLeg<Fixed>::make(Fixed(70), Fixed(70), lim_x);
  static_assert(leg_x.unit_shift == 5, "140 mm / 2^5 = 4.375 units");
  static_assert(leg_x.link.a1 == Fixed(70.0 / 32), "links in working units");
  EXPECT_EQ(leg_x.branch, KneeBranch::kPositive);
}

}  // namespace
