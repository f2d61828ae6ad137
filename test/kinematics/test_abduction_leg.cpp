// AbductionLeg (seed 001 dog12: La = 44, Lb = 280, Lc = 277 mm), left and
// right, against seed 001's IK equations (4.1-4.21, algorithm 1) and an
// independent double-precision chain of rotations.
#include <random>

#include "kinematics/abduction_leg.h"
#include "leg_test_support.h"

namespace {

using namespace legtest;
using strider::AbductionLeg;
using strider::JointLimits;
using strider::LegSide;

constexpr double kLa = 44.0, kLb = 280.0, kLc = 277.0;

template <typename S>
AbductionLeg<S> dog12(LegSide side, const JointLimits<S, 3>& lim = JointLimits<S, 3>::unlimited()) {
  return AbductionLeg<S>::make(sc<S>(kLa), sc<S>(kLb), sc<S>(kLc), lim, side);
}

const char* name(LegSide side) { return side == LegSide::kLeft ? "left" : "right"; }

Eigen::Matrix4d rot_x(double a) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return m;
}
Eigen::Matrix4d rot_y(double a) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return m;
}
Eigen::Matrix4d shift(double x, double y, double z) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 3) = Eigen::Vector3d(x, y, z);
  return m;
}

// Reference FK: abduction about x turns La (along +y at t1 = 0); hip and
// knee turn about the leg-plane normal; the femur starts backward (-x) and
// turns toward the leg's down side (-z before abduction on a left leg, +z on
// a right leg, so both hang down at t1 = 0 / pi).
Eigen::Vector3d ref_fk(LegSide side, const double* q) {
  const double s = side == LegSide::kLeft ? -1.0 : 1.0;
  return origin_of(rot_x(q[0]) * shift(0, kLa, 0) * rot_y(s * q[1]) * shift(-kLb, 0, 0) * rot_y(s * q[2]) *
                   shift(-kLc, 0, 0));
}

double wrap_2pi(double a) {
  a = std::fmod(a, 2 * kPi);
  return a < 0 ? a + 2 * kPi : a;
}

// Reference IK in double, seed 001 section 2.2 as written (with the fixes the
// header names): A, alpha1..3, algorithm 1, then R, R1..R3 in the tilted leg
// plane. A foot inside the abduction cylinder is first moved out to A = La.
struct RefIk {
  double q[3];
  double miss;
  double boundary;  // distance to the nearest singular boundary [mm]
  Eigen::Vector3d nearest;
};
RefIk ref_ik(LegSide side, const Eigen::Vector3d& p) {
  RefIk r;
  double a = std::hypot(p.y(), p.z());                                               // 4.1
  double alpha1 = a > 0 ? wrap_2pi(std::atan2(p.z(), p.y())) : (side == LegSide::kLeft ? 0.0 : kPi);
  const double a_c = std::max(a, kLa);
  const double alpha2 = std::asin(kLa / a_c);                                        // 4.6
  const double alpha3 = kPi / 2 - alpha2;                                            // 4.7
  r.q[0] = wrap_2pi(side == LegSide::kLeft ? alpha1 + alpha3 : alpha1 - alpha3);    // algorithm 1
  const double zp = -std::sqrt(a_c * a_c - kLa * kLa);
  const double big_r = std::hypot(p.x(), zp);                                        // 4.12
  const double r_c = std::min(kLb + kLc, std::max(kLb - kLc, big_r));
  const double r1 = big_r > 0 ? wrap_2pi(std::atan2(-zp, -p.x())) : kPi / 2;
  auto acos_clamped = [](double c) { return std::acos(std::max(-1.0, std::min(1.0, c))); };
  const double r2 = acos_clamped((kLb * kLb + r_c * r_c - kLc * kLc) / (2 * kLb * r_c));  // 4.15
  const double r3 = acos_clamped((kLb * kLb + kLc * kLc - r_c * r_c) / (2 * kLb * kLc));  // 4.16
  r.q[1] = r1 - r2;  // 4.17
  r.q[2] = kPi - r3;  // 4.21
  r.nearest = ref_fk(side, r.q);
  r.miss = (r.nearest - p).norm();
  r.boundary = std::min({a - kLa, big_r - (kLb - kLc), kLb + kLc - big_r});
  return r;
}

template <typename S>
class AbductionLegTest : public ::testing::Test {};
TYPED_TEST_SUITE(AbductionLegTest, Scalars);

TYPED_TEST(AbductionLegTest, FkKnownAnswers) {
  using S = TypeParam;
  struct Case {
    LegSide side;
    double t1, t2, t3;  // [deg]
    double x, y, z;
  };
  const Case cases[] = {
      {LegSide::kLeft, 0, 90, 0, 0, 44, -557},      // standing
      {LegSide::kRight, 180, 90, 0, 0, -44, -557},  // standing
      {LegSide::kLeft, 0, 90, 90, 277, 44, -280},   // knee bent: tibia forward
      {LegSide::kLeft, 0, 0, 0, -557, 44, 0},       // stretched backward
      {LegSide::kLeft, 0, 180, 0, 557, 44, 0},      // stretched forward
      {LegSide::kLeft, 90, 90, 0, 0, 557, 44},      // abducted 90 deg: leg out to the left, La up
      {LegSide::kRight, 90, 90, 0, 0, -557, 44},    // abducted: leg out to the right, La up
      {LegSide::kRight, 270, 90, 0, 0, 557, -44},   // La down, leg under the body to the left
      {LegSide::kLeft, 0, 90, 180, 0, 44, -3},      // fully folded
      {LegSide::kRight, 180, 45, 0, -557 * std::sqrt(0.5), -44, -557 * std::sqrt(0.5)},
  };
  for (const Case& c : cases) {
    const auto leg = dog12<S>(c.side);
    typename AbductionLeg<S>::Joints q{{sc<S>(c.t1 * kDeg), sc<S>(c.t2 * kDeg), sc<S>(c.t3 * kDeg)}};
    EXPECT_LE((ev(leg.fk(q)) - Eigen::Vector3d(c.x, c.y, c.z)).norm(), Bounds<S>::kFootMm)
        << name(c.side) << " " << c.t1 << ", " << c.t2 << ", " << c.t3;
  }
}

TYPED_TEST(AbductionLegTest, FkMatchesRotationChainAndMirrors) {
  using S = TypeParam;
  const auto left = dog12<S>(LegSide::kLeft), right = dog12<S>(LegSide::kRight);
  Worst foot("abduction " + scalar_name<S>() + " fk vs rotation chain [mm]");
  Worst mirror("abduction " + scalar_name<S>() + " right fk - mirrored left fk [mm]");
  for (double t1 = 0; t1 < 360; t1 += 10)
    for (double t2 = -180; t2 <= 180; t2 += 5)
      for (double t3 = 0; t3 <= 180; t3 += 5) {
        typename AbductionLeg<S>::Joints q{{sc<S>(t1 * kDeg), sc<S>(t2 * kDeg), sc<S>(t3 * kDeg)}};
        const double qd[3] = {dbl(q[0]), dbl(q[1]), dbl(q[2])};
        const Eigen::Vector3d l = ref_fk(LegSide::kLeft, qd), r = ref_fk(LegSide::kRight, qd);
        foot.add((ev(left.fk(q)) - l).norm(), [&] { return describe(l); });
        foot.add((ev(right.fk(q)) - r).norm(), [&] { return describe(r); });
        // A right leg is a left leg mirrored in the x-z plane, at t1' = pi - t1.
        typename AbductionLeg<S>::Joints qm = q;
        qm[0] = sc<S>(kPi - qd[0]);
        const Eigen::Vector3d m = ev(right.fk(qm));
        mirror.add((m - Eigen::Vector3d(l.x(), -l.y(), l.z())).norm(), [&] { return describe(l); });
      }
  EXPECT_LE(foot.max(), Bounds<S>::kFootMm) << foot.where();
  EXPECT_LE(mirror.max(), Bounds<S>::kFootMm) << mirror.where();
}

// Seed 001 eqs 4.2-4.5: alpha1 by quadrant. The printed ratio is y/z; only
// z/y gives the angle from +y that table 3 defines (y = 1, z = 0.1 is
// almost on +y: atan(z/y) = 5.7 deg, atan(y/z) = 84 deg), so z/y is used.
double alpha1_cases(double y, double z) {
  const double t = std::atan(z / y);
  if (y > 0 && z >= 0) return t;                     // case 1, eq 4.2
  if (y < 0 && z >= 0) return -std::fabs(t) + kPi;   // case 2, eq 4.3
  if (y < 0 && z < 0) return std::fabs(t) + kPi;     // case 3, eq 4.4
  return -std::fabs(t) + 2 * kPi;                    // case 4, eq 4.5
}

// Eqs 4.8-4.11 (left legs: theta1 = alpha1 + 90 deg - asin(La / A)) and
// algorithm 1 (right legs: theta1 = alpha1 - alpha3), wrapped to [0, 2 pi).
TYPED_TEST(AbductionLegTest, Eqs4_1To4_11AndAlgorithm1InAllQuadrants) {
  using S = TypeParam;
  Worst err("abduction " + scalar_name<S>() + " t1 vs eqs 4.2-4.11 / algorithm 1 [deg]");
  long quadrant_hits[4] = {0, 0, 0, 0};
  for (LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const auto leg = dog12<S>(side);
    for (double x = -300; x <= 300; x += 100)
      for (double y = -500; y <= 500; y += 25)
        for (double z = -500; z <= 500; z += 25) {
          if (y == 0) continue;  // eqs 4.2-4.5 divide by y
          const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(x, y, z));
          const double a = std::hypot(p.y(), p.z());             // 4.1
          if (a < kLa + kBoundaryMarginMm) continue;
          const double alpha1 = alpha1_cases(p.y(), p.z());     // 4.2-4.5
          EXPECT_NEAR(alpha1, wrap_2pi(std::atan2(p.z(), p.y())), 1e-12);
          const double alpha2 = std::asin(kLa / a);             // 4.6
          const double alpha3 = kPi / 2 - alpha2;               // 4.7
          const double theta1 = side == LegSide::kLeft ? wrap_2pi(alpha1 + kPi / 2 - std::asin(kLa / a))  // 4.8-4.11
                                                       : wrap_2pi(alpha1 - alpha3);                       // alg. 1
          typename AbductionLeg<S>::Joints q;
          Vec3<S> reached;
          const IkStatus st = checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached);
          if (st == IkStatus::kUnreachable) continue;
          ++quadrant_hits[(p.y() > 0 ? 0 : 1) + (p.z() >= 0 ? 0 : 2)];
          EXPECT_GE(dbl(q[0]), 0.0);
          EXPECT_LT(dbl(q[0]), 2 * kPi);
          err.add(angle_diff(dbl(q[0]), theta1) / kDeg, [&] { return std::string(name(side)) + describe(p); });
        }
  }
  for (long hits : quadrant_hits) EXPECT_GT(hits, 100);
  EXPECT_LE(err.max(), Bounds<S>::kJointDeg) << err.where();
}

// Eqs 4.12-4.21 hold verbatim when La is horizontal (t1 = 0 left, pi right):
// then the tilted plane's vertical is z. Eq 4.13 (R1 = atan(z/x) + pi) is the
// x > 0 case; eq 4.15 needs L_c^2 where the seed prints L_c.
TYPED_TEST(AbductionLegTest, Eqs4_12To4_21WithLaHorizontal) {
  using S = TypeParam;
  Worst err("abduction " + scalar_name<S>() + " t2, t3 vs eqs 4.12-4.21 [deg]");
  for (LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const auto leg = dog12<S>(side);
    const double y = side == LegSide::kLeft ? kLa : -kLa;
    for (double x = 5; x <= 550; x += 5)
      for (double z = -550; z <= -5; z += 5) {
        const double r = std::sqrt(x * x + z * z);  // 4.12
        if (r > kLb + kLc - kBoundaryMarginMm) continue;
        const double r1 = std::atan(z / x) + kPi;                                               // 4.13
        const double r2 = std::acos((kLb * kLb + r * r - kLc * kLc) / (2 * kLb * r));            // 4.15
        const double r3 = std::acos((kLb * kLb + kLc * kLc - r * r) / (2 * kLb * kLc));          // 4.16
        const double t2 = r1 - r2, t3 = kPi - r3;                                                // 4.17, 4.21
        typename AbductionLeg<S>::Joints q;
        Vec3<S> reached;
        ASSERT_EQ(checked_ik(leg, vec<S>(x, y, z), q, reached), IkStatus::kOk) << x << ", " << z;
        EXPECT_LE(angle_diff(dbl(q[0]), side == LegSide::kLeft ? 0.0 : kPi), Bounds<S>::kJointDeg * kDeg);
        err.add(std::max(angle_diff(dbl(q[1]), t2), angle_diff(dbl(q[2]), t3)) / kDeg,
                [&] { return std::string(name(side)) + describe(Eigen::Vector3d(x, y, z)); });
        // The printed "- L_c" would give another angle.
        const double r2_printed = std::acos(std::max(-1.0, std::min(1.0, (kLb * kLb + r * r - kLc) / (2 * kLb * r))));
        EXPECT_GT(std::fabs(r2_printed - r2), 0.01) << x << ", " << z;
      }
  }
  EXPECT_LE(err.max(), Bounds<S>::kJointDeg) << err.where();
}

// IK(FK(q)) = q over a dense joint grid, both sides, every abduction angle
// (all four y-z quadrants). Poses whose foot is "above" the leg plane's hip
// (d < 0) are reached by the other solution, which the reference gives.
TYPED_TEST(AbductionLegTest, IkOfFkRoundTripDenseGrid) {
  using S = TypeParam;
  for (LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const auto leg = dog12<S>(side);
    RoundTrip rt("abduction " + std::string(name(side)) + " " + scalar_name<S>());
    long same_solution = 0;
    for (double t1 = 0; t1 < 360; t1 += 30)
      for (double t2 = -179; t2 < 180; t2 += 3)
        for (double t3 = 0; t3 <= 180; t3 += 3) {
          const double q[3] = {t1 * kDeg, t2 * kDeg, t3 * kDeg};
          const Eigen::Vector3d p = ref_fk(side, q);
          const RefIk r = ref_ik(side, p);
          const bool regular = r.boundary >= kBoundaryMarginMm;
          if (regular && angle_diff(r.q[0], q[0]) < 1e-9) ++same_solution;
          round_trip(leg, r.q, p, regular, rt);
        }
    EXPECT_GT(same_solution, 10000);
    rt.expect_within_bounds<S>();
  }
}

TYPED_TEST(AbductionLegTest, IkOfFkRoundTripRandom) {
  using S = TypeParam;
  std::mt19937 rng(1001);
  std::uniform_real_distribution<double> turn(0, 2 * kPi), hip(-kPi, kPi), knee(0, kPi);
  for (LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const auto leg = dog12<S>(side);
    RoundTrip rt("abduction " + std::string(name(side)) + " " + scalar_name<S>() + " random");
    for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
      const double q[3] = {turn(rng), hip(rng), knee(rng)};
      const Eigen::Vector3d p = ref_fk(side, q);
      const RefIk r = ref_ik(side, p);
      round_trip(leg, r.q, p, r.boundary >= kBoundaryMarginMm, rt);
    }
    rt.expect_within_bounds<S>();
  }
}

// A Cartesian box over all four y-z quadrants: nearest point, miss and
// status against the reference.
TYPED_TEST(AbductionLegTest, CartesianGridMatchesReference) {
  using S = TypeParam;
  for (LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    const auto leg = dog12<S>(side);
    const std::string leg_name = "abduction " + std::string(name(side)) + " " + scalar_name<S>();
    ReferenceSweep<S> sweep(leg_name + " IK joint error, grid [deg]", leg_name + " reached - nearest [mm]");
    for (double x = -600; x <= 600; x += 40)
      for (double y = -640; y <= 640; y += 40)
        for (double z = -640; z <= 640; z += 40) {
          const Eigen::Vector3d p = quantised<S>(Eigen::Vector3d(x, y, z) + Eigen::Vector3d(0.5, 0.25, 0.125));
          const RefIk r = ref_ik(side, p);
          sweep.check(leg, p, expected_status<S>(r.miss), r.miss, r.nearest, r.q,
                      r.boundary < kBoundaryMarginMm ? Compare::kFoot : Compare::kFootAndJoints);
        }
    sweep.expect_results(1000, 100, 1000);
  }
}

TYPED_TEST(AbductionLegTest, EdgeTable) {
  using S = TypeParam;
  const double tol = dbl(strider::IkOptions<S>().tolerance_mm);
  strider::IkOptions<S> wide;
  wide.max_clamp_mm = sc<S>(50);
  struct Case {
    const char* what;
    LegSide side;
    double x, y, z;
    bool wide_clamp;
    IkStatus want;
    double rx, ry, rz;  // expected reached point, NAN: not checked
  };
  const Case cases[] = {
      {"standing, left", LegSide::kLeft, 0, 44, -557, false, IkStatus::kOk, 0, 44, -557},
      {"standing, right", LegSide::kRight, 0, -44, -557, false, IkStatus::kOk, 0, -44, -557},
      {"stretched, within tolerance", LegSide::kLeft, 0, 44, -557 - 0.5 * tol, false, IkStatus::kOk, NAN, 0, 0},
      {"just outside reach", LegSide::kLeft, 0, 44, -560, false, IkStatus::kClamped, 0, 44, -557},
      {"outside by more than max_clamp", LegSide::kLeft, 0, 44, -600, false, IkStatus::kUnreachable, NAN, 0, 0},
      {"fully folded", LegSide::kLeft, 0, 44, -3, false, IkStatus::kOk, 0, 44, -3},
      {"inside the folded circle", LegSide::kLeft, 0, 44, -1, false, IkStatus::kClamped, 0, 44, -3},
      {"inside the abduction cylinder", LegSide::kLeft, 100, 20, 0, false, IkStatus::kClamped, 100, 44, 0},
      {"inside the cylinder, right", LegSide::kRight, 100, 0, -20, false, IkStatus::kClamped, 100, 0, -44},
      {"too deep inside the cylinder", LegSide::kLeft, 100, 10, 0, false, IkStatus::kUnreachable, NAN, 0, 0},
      {"on the abduction axis", LegSide::kLeft, 100, 0, 0, false, IkStatus::kUnreachable, NAN, 0, 0},
      {"on the axis, wide clamp, left", LegSide::kLeft, 100, 0, 0, true, IkStatus::kClamped, 100, 44, 0},
      {"on the axis, wide clamp, right", LegSide::kRight, 100, 0, 0, true, IkStatus::kClamped, 100, -44, 0},
      {"foot level with the hip", LegSide::kLeft, 300, 44, 0, false, IkStatus::kOk, 300, 44, 0},
      {"quadrant y>0 z>0", LegSide::kLeft, 50, 300, 300, false, IkStatus::kOk, 50, 300, 300},
      {"quadrant y<0 z>0", LegSide::kLeft, 50, -300, 300, false, IkStatus::kOk, 50, -300, 300},
      {"quadrant y<0 z<0", LegSide::kRight, 50, -300, -300, false, IkStatus::kOk, 50, -300, -300},
      {"quadrant y>0 z<0", LegSide::kRight, 50, 300, -300, false, IkStatus::kOk, 50, 300, -300},
      {"far away", LegSide::kLeft, 1e6, 0, 0, false, IkStatus::kUnreachable, NAN, 0, 0},
      {"far away, all axes", LegSide::kRight, -1e6, 1e6, -1e6, false, IkStatus::kUnreachable, NAN, 0, 0},
      {"huge", LegSide::kRight, 0, 1e30, 0, false, IkStatus::kUnreachable, NAN, 0, 0},
      {"Fixed's largest value", LegSide::kLeft, 32767, -32768, 32767, true, IkStatus::kUnreachable, NAN, 0, 0},
  };
  for (const Case& c : cases) {
    const auto leg = dog12<S>(c.side);
    typename AbductionLeg<S>::Joints q;
    Vec3<S> reached;
    const Vec3<S> target = vec<S>(c.x, c.y, c.z);
    EXPECT_EQ(checked_ik(leg, target, q, reached, c.wide_clamp ? wide : strider::IkOptions<S>()), c.want)
        << c.what;
    if (!std::isnan(c.rx)) {
      EXPECT_LE((ev(reached) - Eigen::Vector3d(c.rx, c.ry, c.rz)).norm(), Bounds<S>::kFootMm) << c.what;
    }
    if (c.want != IkStatus::kUnreachable) {
      EXPECT_GE(dbl(q[0]), 0.0) << c.what;
      EXPECT_LT(dbl(q[0]), 2 * kPi) << c.what;
    }
  }
}

TEST(AbductionLegFloat, NonFiniteTargetsAreUnreachable) {
  for (LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    SCOPED_TRACE(name(side));
    expect_non_finite_targets_unreachable(dog12<float>(side), Vec3<float>(50.0f, 44.0f, -400.0f));
  }
}

// Limits pick t1's representative: a left leg limited to [-30, 30] deg gets
// -10 deg (not 350); past a limit it is clamped to the nearer one.
TYPED_TEST(AbductionLegTest, JointLimitsAndT1Representative) {
  using S = TypeParam;
  struct Case {
    LegSide side;
    double lo1, hi1;   // t1 limits [deg]
    double q[3];       // pose the target comes from [deg]
    IkStatus want;
    double want_q[3];  // joints returned [deg]
  };
  const Case cases[] = {
      {LegSide::kLeft, -30, 30, {350, 80, 30}, IkStatus::kOk, {-10, 80, 30}},
      {LegSide::kLeft, -30, 30, {10, 80, 30}, IkStatus::kOk, {10, 80, 30}},
      {LegSide::kLeft, -30, 30, {40, 80, 30}, IkStatus::kJointLimit, {30, 80, 30}},
      {LegSide::kLeft, -30, 30, {300, 80, 30}, IkStatus::kJointLimit, {-30, 80, 30}},
      {LegSide::kRight, 150, 210, {200, 80, 30}, IkStatus::kOk, {200, 80, 30}},
      {LegSide::kRight, 150, 210, {140, 80, 30}, IkStatus::kJointLimit, {150, 80, 30}},
      {LegSide::kRight, 150, 210, {180, 100, 5}, IkStatus::kJointLimit, {180, 100, 10}},
  };
  for (const Case& c : cases) {
    JointLimits<S, 3> lim;
    lim.lo[0] = sc<S>(c.lo1 * kDeg), lim.hi[0] = sc<S>(c.hi1 * kDeg);
    lim.lo[1] = sc<S>(-170 * kDeg), lim.hi[1] = sc<S>(170 * kDeg);
    lim.lo[2] = sc<S>(10 * kDeg), lim.hi[2] = sc<S>(150 * kDeg);
    const auto leg = dog12<S>(c.side, lim);
    const double qr[3] = {c.q[0] * kDeg, c.q[1] * kDeg, c.q[2] * kDeg};
    const Eigen::Vector3d p = ref_fk(c.side, qr);
    typename AbductionLeg<S>::Joints q;
    Vec3<S> reached;
    ASSERT_EQ(checked_ik(leg, vec<S>(p.x(), p.y(), p.z()), q, reached), c.want) << c.q[0] << ", " << c.q[1];
    for (uint8_t i = 0; i < 3; ++i) {
      EXPECT_NEAR(dbl(q[i]) / kDeg, c.want_q[i], Bounds<S>::kJointDeg) << c.q[0] << ", " << c.q[1];
    }
  }
}

}  // namespace
