// CoxaFemurTibiaLeg (seed 002 hexapod18: d1 32, coxa 30, femur 85, tibia
// 125 mm; a spider-like leg: d1 0, coxa 27.5, femur 55, tibia 77.5 mm) against
// seed 002's equations and tables, seed 004's IK, and a double-precision DH
// reference.
#include <random>

#include "kinematics/coxa_femur_tibia_leg.h"
#include "leg_test_support.h"

namespace {

using namespace legtest;
using strider::CoxaFemurTibiaLeg;
using strider::JointLimits;
using strider::KneeBranch;

struct Geometry {
  const char* name;
  double d1, l1, l2, l3;
};
constexpr Geometry kHexapod{"hexapod18", 32.0, 30.0, 85.0, 125.0};  // seed 002 table 3 (cm -> mm)
constexpr Geometry kSpider{"spider", 0.0, 27.5, 55.0, 77.5};

template <typename S>
CoxaFemurTibiaLeg<S> make_leg(const Geometry& g, KneeBranch branch = KneeBranch::kNegative,
                              const JointLimits<S, 3>& lim = JointLimits<S, 3>::unlimited()) {
  return CoxaFemurTibiaLeg<S>::make(sc<S>(g.d1), sc<S>(g.l1), sc<S>(g.l2), sc<S>(g.l3), lim, branch);
}

// Reference FK: table 2 through the DH product 0T1 1T2 2T3 (eqs 1-4).
Eigen::Vector3d ref_fk(const Geometry& g, const double* q) {
  return origin_of(dh(q[0], g.d1, g.l1, kPi / 2) * dh(q[1], 0.0, g.l2, 0.0) * dh(q[2], 0.0, g.l3, 0.0));
}

// Reference IK in double: eq 12, then the textbook two-link solution with
// acos in the plane of eq 11; the far side (t1 + pi) when it is nearer.
struct RefIk {
  double q[3];
  double miss;
  double boundary;  // distance to the nearest singular boundary [mm]
  double side_gap;  // how much nearer the chosen side is [mm]
  Eigen::Vector3d nearest;
};
RefIk ref_ik(const Geometry& g, const Eigen::Vector3d& p, KneeBranch branch) {
  RefIk r;
  const double rho = std::hypot(p.x(), p.y());
  const double lo = std::fabs(g.l2 - g.l3), hi = g.l2 + g.l3;
  auto miss_of = [&](double d) { return d > hi ? d - hi : d < lo ? lo - d : 0.0; };
  double t1 = rho > 0 ? std::atan2(p.y(), p.x()) : 0.0;
  double h = rho - g.l1;
  const double v = p.z() - g.d1;
  // Only a target in the hole of the near side's annulus is tried facing away.
  const bool in_hole = g.l1 > 0 && rho > 0 && std::hypot(h, v) < lo;
  const double miss_far = miss_of(std::hypot(-rho - g.l1, v));
  r.side_gap = in_hole ? std::fabs(miss_far - miss_of(std::hypot(h, v))) : 1e9;
  if (in_hole && miss_far < miss_of(std::hypot(h, v))) {
    h = -rho - g.l1;
    t1 += kPi;
  }
  const double d = std::hypot(h, v);
  const double dc = std::min(hi, std::max(lo, d));  // nearest annulus radius
  const double c3 = (dc * dc - g.l2 * g.l2 - g.l3 * g.l3) / (2 * g.l2 * g.l3);
  const double t3 = (branch == KneeBranch::kNegative ? -1 : 1) * std::acos(std::max(-1.0, std::min(1.0, c3)));
  const double t2 = std::atan2(v, h) - std::atan2(g.l3 * std::sin(t3), g.l2 + g.l3 * std::cos(t3));
  r.q[0] = t1, r.q[1] = t2, r.q[2] = t3;
  r.nearest = ref_fk(g, r.q);
  r.miss = (r.nearest - p).norm();
  r.boundary = std::min({std::fabs(d - lo), std::fabs(hi - d), rho});
  return r;
}

// Joint errors are checked away from the stretched and folded leg and from
// the coxa axis (kBoundaryMarginMm).
bool regular(const Geometry& g, const Eigen::Vector3d& p) {
  return ref_ik(g, p, KneeBranch::kNegative).boundary >= kBoundaryMarginMm;
}

template <typename S>
class CftLegTest : public ::testing::Test {};
TYPED_TEST_SUITE(CftLegTest, Scalars);

TYPED_TEST(CftLegTest, Eqs5To7KnownAnswers) {
  using S = TypeParam;
  const auto leg = make_leg<S>(kHexapod);
  struct Case {
    double t1, t2, t3, x, y, z;  // [deg], [mm]
  };
  const Case cases[] = {
      {0, 0, 0, 240, 0, 32},          {90, 0, 0, 0, 240, 32},     {0, 90, -90, 155, 0, 117},
      {0, 0, -90, 115, 0, -93},       {180, 0, 0, -240, 0, 32},   {0, -90, 90, 155, 0, -53},
      {45, 0, -180, -10 * std::sqrt(0.5), -10 * std::sqrt(0.5), 32},
      {-30, 30, -120, (30 + 85 * std::sqrt(0.75)) * std::sqrt(0.75), -(30 + 85 * std::sqrt(0.75)) * 0.5, -50.5},
  };
  for (const Case& c : cases) {
    typename CoxaFemurTibiaLeg<S>::Joints q{{sc<S>(c.t1 * kDeg), sc<S>(c.t2 * kDeg), sc<S>(c.t3 * kDeg)}};
    EXPECT_LE((ev(leg.fk(q)) - Eigen::Vector3d(c.x, c.y, c.z)).norm(), Bounds<S>::kFootMm)
        << c.t1 << ", " << c.t2 << ", " << c.t3;
  }
}

// Seed 002 tables 4-9: the desired points (cm -> mm) of the six legs are IK
// targets of the table 3 leg: each is reachable, and FK(IK(p)) = p.
TYPED_TEST(CftLegTest, Tables4To9DesiredPoints) {
  using S = TypeParam;
  const auto leg = make_leg<S>(kHexapod);
  const double xs[7] = {7, 8, 9, 10, 11, 12, 13};
  const double zs[7] = {-5, -4, -3, -2, -1, 1, 2};
  const double ys_leg_1_3_4_6[7] = {1, 2, 3, 4, 5, 6, 7};  // tables 4, 6, 7, 9
  const double ys_leg_2_5[7] = {-3, -2, -1, 1, 2, 3, 4};   // tables 5, 8
  Worst joint("cft hexapod18 " + scalar_name<S>() + " tables 4-9 joint error [deg]");
  Worst foot("cft hexapod18 " + scalar_name<S>() + " tables 4-9 FK(IK(p)) - p [mm]");
  for (int table = 4; table <= 9; ++table) {
    const double* ys = (table == 5 || table == 8) ? ys_leg_2_5 : ys_leg_1_3_4_6;
    for (int i = 0; i < 7; ++i) {
      const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(xs[i], ys[i], zs[i]) * 10.0);
      typename CoxaFemurTibiaLeg<S>::Joints q;
      Vec3<S> reached;
      ASSERT_EQ(checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached), IkStatus::kOk)
          << "table " << table << " " << describe(p);
      EXPECT_LE(dbl(q[2]), 0.0) << "t3 <= 0 for z < 0 (seed 002 fig. 4)";
      foot.add((ev(leg.fk(q)) - p).norm(), [&] { return describe(p); });
      const RefIk r = ref_ik(kHexapod, p, KneeBranch::kNegative);
      double e = 0;
      for (uint8_t j = 0; j < 3; ++j) e = std::max(e, angle_diff(dbl(q[j]), r.q[j]));
      joint.add(e / kDeg, [&] { return describe(p); });
      // Eq 12 verbatim.
      EXPECT_NEAR(dbl(q[0]), std::atan2(p.y(), p.x()), Bounds<S>::kJointDeg * kDeg);
    }
  }
  EXPECT_LE(joint.max(), Bounds<S>::kJointDeg) << joint.where();
  EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
}

TYPED_TEST(CftLegTest, FkMatchesDhProduct) {
  using S = TypeParam;
  for (const Geometry& g : {kHexapod, kSpider}) {
    const auto leg = make_leg<S>(g);
    Worst foot(std::string("cft ") + g.name + " " + scalar_name<S>() + " fk vs DH product [mm]");
    for (double t1 = -180; t1 <= 180; t1 += 15)
      for (double t2 = -180; t2 <= 180; t2 += 5)
        for (double t3 = -180; t3 <= 180; t3 += 5) {
          typename CoxaFemurTibiaLeg<S>::Joints q{{sc<S>(t1 * kDeg), sc<S>(t2 * kDeg), sc<S>(t3 * kDeg)}};
          const double qd[3] = {dbl(q[0]), dbl(q[1]), dbl(q[2])};
          const Eigen::Vector3d ref = ref_fk(g, qd);
          foot.add((ev(leg.fk(q)) - ref).norm(), [&] { return describe(ref); });
        }
    EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
  }
}

// IK(FK(q)) = q over a dense joint grid, both geometries and both branches.
TYPED_TEST(CftLegTest, IkOfFkRoundTripDenseGrid) {
  using S = TypeParam;
  for (const Geometry& g : {kHexapod, kSpider})
    for (KneeBranch branch : {KneeBranch::kNegative, KneeBranch::kPositive}) {
      const auto leg = make_leg<S>(g, branch);
      const double sign = branch == KneeBranch::kNegative ? -1 : 1;
      RoundTrip rt(std::string("cft ") + g.name + " " + scalar_name<S>() +
                   (branch == KneeBranch::kNegative ? " t3<=0" : " t3>=0"));
      for (double t1 = -175; t1 < 180; t1 += 35)
        for (double t2 = -180; t2 < 180; t2 += 2)
          for (double k = 0; k <= 180; k += 2) {
            const double q[3] = {t1 * kDeg, t2 * kDeg, sign * k * kDeg};
            const Eigen::Vector3d p = ref_fk(g, q);
            // Feet tucked behind the yaw axis are reached facing away (other q).
            const RefIk r = ref_ik(g, p, branch);
            const bool same_side = angle_diff(r.q[0], q[0]) < 1e-6;
            if (!same_side && r.side_gap < kBoundaryMarginMm) continue;
            round_trip(leg, same_side ? q : r.q, p, regular(g, p) && r.side_gap >= kBoundaryMarginMm, rt);
          }
      rt.expect_within_bounds<S>();
    }
}

TYPED_TEST(CftLegTest, IkOfFkRoundTripRandom) {
  using S = TypeParam;
  const auto leg = make_leg<S>(kHexapod);
  RoundTrip rt("cft hexapod18 " + scalar_name<S>() + " random");
  std::mt19937 rng(2002);
  std::uniform_real_distribution<double> yaw(-kPi, kPi), knee(-kPi, 0.0);
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    const double q[3] = {yaw(rng), yaw(rng), knee(rng)};
    const Eigen::Vector3d p = ref_fk(kHexapod, q);
    const RefIk r = ref_ik(kHexapod, p, KneeBranch::kNegative);
    if (r.side_gap < kBoundaryMarginMm) continue;
    round_trip(leg, r.q, p, regular(kHexapod, p), rt);
  }
  rt.expect_within_bounds<S>();
}

// A Cartesian box around the leg: nearest point, miss and status against the
// reference.
TYPED_TEST(CftLegTest, CartesianGridMatchesReference) {
  using S = TypeParam;
  for (const Geometry& g : {kHexapod, kSpider}) {
    const auto leg = make_leg<S>(g);
    const double reach = g.l1 + g.l2 + g.l3 + 30;
    const std::string leg_name = std::string("cft ") + g.name + " " + scalar_name<S>();
    ReferenceSweep<S> sweep(leg_name + " IK joint error, Cartesian grid [deg]",
                            leg_name + " reached - nearest reachable [mm]");
    const double step = reach / 20;
    for (double x = -reach; x <= reach; x += step)
      for (double y = -reach; y <= reach; y += step)
        for (double z = g.d1 - reach; z <= g.d1 + reach; z += step) {
          const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(x, y, z));
          const RefIk r = ref_ik(g, p, KneeBranch::kNegative);
          const Compare compare = r.side_gap < 0.05 ? Compare::kStatus
                                  : r.boundary < kBoundaryMarginMm || r.side_gap < kBoundaryMarginMm
                                      ? Compare::kFoot
                                      : Compare::kFootAndJoints;
          sweep.check(leg, p, expected_status<S>(r.miss), r.miss, r.nearest, r.q, compare);
        }
    sweep.expect_results(1000, 100, 1000);
  }
}

// Seed 004's IK as printed (theta1 = atan(y/x), theta2 = acos((alpha^2 - fm^2
// - tb^2) / (-2 fm tb)), theta3 = pi - phi1 - phi2), valid where it was drawn:
// x > 0, the foot below the hip (z + cx > 0 with seed 004's z measured
// downward), and an acute hip angle (asin). Mapping to this leg with coxa = 0,
// d1 = cx and z_seed004 = -z: t1 = theta1, t2 = pi/2 - theta3,
// t3 = theta2 - pi (branch t3 <= 0).
struct Seed004 {
  double theta1, theta2, theta3;
};
Seed004 seed004_ik(double x, double y, double z_seed, double cx, double fm, double tb) {
  Seed004 s;
  s.theta1 = std::atan(y / x);
  const double r = std::sqrt(x * x + y * y);
  const double alpha = std::sqrt((z_seed + cx) * (z_seed + cx) + r * r);
  s.theta2 = std::acos((alpha * alpha - fm * fm - tb * tb) / (-2 * fm * tb));
  const double phi1 = std::atan(r / (z_seed + cx));
  const double phi2 = std::asin(tb * std::sin(s.theta2) / alpha);
  s.theta3 = kPi - phi1 - phi2;
  return s;
}

TYPED_TEST(CftLegTest, Seed004IkIsThisLegWithoutCoxa) {
  using S = TypeParam;
  const double cx = 20.0, fm = 55.0, tb = 77.5;
  const Geometry g{"seed004", cx, 0.0, fm, tb};  // d1 = cx, coxa = 0
  const auto leg = make_leg<S>(g);
  Worst joint("cft seed004 " + scalar_name<S>() + " IK vs seed 004's IK [deg]");
  Worst foot("cft seed004 " + scalar_name<S>() + " fk(seed 004 angles) - p [mm]");
  long used = 0;
  for (double x = 5; x <= 130; x += 5)
    for (double y = -120; y <= 120; y += 5)
      for (double z = -120; z < cx; z += 5) {
        const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(x, y, z));
        const double z_seed = -p.z();
        const double r = std::hypot(p.x(), p.y());
        const double alpha = std::hypot(z_seed + cx, r);
        if (alpha > fm + tb - kBoundaryMarginMm || alpha < tb - fm + kBoundaryMarginMm) continue;
        if (fm * fm + alpha * alpha - tb * tb <= 0) continue;  // obtuse hip angle: asin picks the wrong one
        const Seed004 s = seed004_ik(p.x(), p.y(), z_seed, cx, fm, tb);
        const double mapped[3] = {s.theta1, kPi / 2 - s.theta3, s.theta2 - kPi};
        // The mapped seed 004 angles reach the point through this leg's FK ...
        foot.add((ref_fk(g, mapped) - p).norm(), [&] { return describe(p); });
        // ... and are what this leg's IK returns.
        typename CoxaFemurTibiaLeg<S>::Joints q;
        Vec3<S> reached;
        ASSERT_EQ(checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached), IkStatus::kOk) << describe(p);
        double e = 0;
        for (uint8_t j = 0; j < 3; ++j) e = std::max(e, angle_diff(dbl(q[j]), mapped[j]));
        joint.add(e / kDeg, [&] { return describe(p); });
        ++used;
      }
  EXPECT_GT(used, 5000);
  EXPECT_LE(foot.max(), 1e-9) << foot.where();
  EXPECT_LE(joint.max(), Bounds<S>::kJointDeg) << joint.where();
}

TYPED_TEST(CftLegTest, EdgeTable) {
  using S = TypeParam;
  const auto leg = make_leg<S>(kHexapod);
  const double tol = dbl(strider::IkOptions<S>().tolerance_mm);
  const EdgeRow cases[] = {
      {"fully stretched", 240, 0, 32, IkStatus::kOk, 0},
      {"stretched, within tolerance", 240 + 0.5 * tol, 0, 32, IkStatus::kOk, 0.5 * tol},
      {"stretched straight down", 30, 0, 32 - 210, IkStatus::kOk, 0},
      {"fully folded, foot behind the yaw axis", -10, 0, 32, IkStatus::kOk, 0},
      {"fully folded, foot in front", 70, 0, 32, IkStatus::kOk, 0},
      {"inside the folded circle, reached facing away", 40, 0, 32, IkStatus::kOk, 0},
      {"inside the folded circle on both sides", 5, 0, 32, IkStatus::kClamped, 5},
      {"foot on the yaw axis", 0, 0, -100, IkStatus::kOk, 0},
      {"foot on the yaw axis, out of reach", 0, 0, 32 + 220, IkStatus::kClamped, -1},
      {"foot at the leg origin", 0, 0, 0, IkStatus::kOk, 0},
      {"just outside reach", 245, 0, 32, IkStatus::kClamped, 5},
      {"outside by more than max_clamp", 0, 270, 32, IkStatus::kUnreachable, -1},
      {"far away", 1e6, 0, 0, IkStatus::kUnreachable, -1},
      {"far away, all axes", -1e6, 1e6, -1e6, IkStatus::kUnreachable, -1},
      {"huge", 0, 0, -1e30, IkStatus::kUnreachable, -1},
      {"Fixed's largest value", 32767, 32767, -32768, IkStatus::kUnreachable, -1},
  };
  for (const EdgeRow& c : cases) expect_edge_row(leg, c);
  // On the yaw axis t1 is free: 0, or the nearest limit when 0 is outside.
  JointLimits<S, 3> lim = JointLimits<S, 3>::unlimited();
  lim.lo[0] = sc<S>(20 * kDeg), lim.hi[0] = sc<S>(60 * kDeg);
  typename CoxaFemurTibiaLeg<S>::Joints q;
  Vec3<S> reached;
  EXPECT_EQ(checked_ik(make_leg<S>(kHexapod, KneeBranch::kNegative, lim), vec<S>(0, 0, -100), q, reached),
            IkStatus::kOk);
  EXPECT_NEAR(dbl(q[0]) / kDeg, 20.0, 1e-3);
}

TEST(CftLegFloat, NonFiniteTargetsAreUnreachable) {
  expect_non_finite_targets_unreachable(make_leg<float>(kHexapod), Vec3<float>(100.0f, 20.0f, -50.0f));
}

TYPED_TEST(CftLegTest, JointLimits) {
  using S = TypeParam;
  JointLimits<S, 3> lim;
  const double lo[3] = {-45, -60, -150}, hi[3] = {45, 90, -20};  // [deg]
  for (int i = 0; i < 3; ++i) lim.lo[i] = sc<S>(lo[i] * kDeg), lim.hi[i] = sc<S>(hi[i] * kDeg);
  const auto leg = make_leg<S>(kHexapod, KneeBranch::kNegative, lim);
  struct Case {
    double q[3];       // pose the target comes from [deg]
    IkStatus want;
    double want_q[3];  // joints returned [deg]
  };
  const Case cases[] = {
      {{10, 20, -100}, IkStatus::kOk, {10, 20, -100}},
      {{45, 90, -20}, IkStatus::kOk, {45, 90, -20}},
      {{60, 20, -100}, IkStatus::kJointLimit, {45, 20, -100}},
      {{-120, 20, -100}, IkStatus::kJointLimit, {-45, 20, -100}},
      {{10, 20, -10}, IkStatus::kJointLimit, {10, 20, -20}},
      {{10, -70, -30}, IkStatus::kJointLimit, {10, -60, -30}},
  };
  for (const Case& c : cases) {
    const double qr[3] = {c.q[0] * kDeg, c.q[1] * kDeg, c.q[2] * kDeg};
    const Eigen::Vector3d p = ref_fk(kHexapod, qr);
    typename CoxaFemurTibiaLeg<S>::Joints q;
    Vec3<S> reached;
    ASSERT_EQ(checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached), c.want) << c.q[0] << ", " << c.q[1];
    for (uint8_t i = 0; i < 3; ++i) EXPECT_NEAR(dbl(q[i]) / kDeg, c.want_q[i], Bounds<S>::kJointDeg) << c.q[0];
  }
}

}  // namespace
