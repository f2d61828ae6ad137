// Every leg of every model through AnyLeg, in float and Fixed: the standing
// pose, and FK(IK(p)) = p and IK(FK(q)) = q over dense joint grids inside
// the model's limits, against the double-precision reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "robot_reference.h"

using namespace strider;
using robot_ref::Vector3d;

namespace {

// Joints of the standing pose keep at least this far from their limits [deg].
constexpr double kStandMarginDeg = 10.0;

// Grid points per joint: 2-DOF legs get a finer grid for the same cost.
constexpr int kGrid3 = 22;
constexpr int kGrid2 = 90;

// Poses whose foot is within this of the first joint's axis, or behind it,
// are skipped by the round trip: there the solvers' unique answer is the
// other configuration (t1 + 180 deg) or t1 is undefined [mm].
constexpr double kMinAxisReachMm = 5.0;

template <typename S>
class RobotKinematics : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(RobotKinematics, Scalars);

template <typename S>
AnyLeg<S> leg_of(const RobotModel& m, uint8_t i) {
  AnyLeg<S> leg;
  EXPECT_TRUE(AnyLeg<S>::from_model(m, i, leg));
  return leg;
}

TYPED_TEST(RobotKinematics, StandingPoseIsOkWithMargin) {
  using S = TypeParam;
  for (const RobotModel* m : kAllRobots) {
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      const LegModel& lm = m->legs[i];
      const AnyLeg<S> leg = leg_of<S>(*m, i);
      typename AnyLeg<S>::Joints q{};
      Vec3<S> reached;
      const IkStatus s = leg.ik_body(Vec3<S>::from(lm.stand_mm), q, reached);
      ASSERT_EQ(s, IkStatus::kOk) << m->name << " leg " << int(i);
      double qd[3] = {0, 0, 0};
      for (uint8_t j = 0; j < m->dof(); ++j) {
        qd[j] = to_double(q[j]);
        const double deg = robot_ref::deg(qd[j]);
        EXPECT_GE(deg - lm.joint[j].min_deg, kStandMarginDeg) << m->name << " leg " << int(i) << " joint " << int(j);
        EXPECT_GE(lm.joint[j].max_deg - deg, kStandMarginDeg) << m->name << " leg " << int(i) << " joint " << int(j);
      }
      const Vector3d want(lm.stand_mm.x, lm.stand_mm.y, lm.stand_mm.z);
      EXPECT_LT((robot_ref::body_fk(*m, lm, qd) - want).norm(), robot_ref::Bounds<S>::kPositionMm)
          << m->name << " leg " << int(i);
      EXPECT_LT((robot_ref::to_eigen(reached) - want).norm(), robot_ref::Bounds<S>::kPositionMm);
    }
  }
}

// The worst errors of one model's sweep.
struct Worst {
  double fk_mm = 0, ik_mm = 0, joint_deg = 0;
  long poses = 0, skipped = 0;
};

template <typename S>
Worst sweep(const RobotModel& m, uint8_t i) {
  Worst w;
  const LegModel& lm = m.legs[i];
  const AnyLeg<S> leg = leg_of<S>(m, i);
  const int n = m.dof() == 3 ? kGrid3 : kGrid2;
  const int n2 = m.dof() == 3 ? n : 1;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n2; ++c) {
        // Cell centres: strictly inside the limits, so a correct solver
        // never needs to clamp.
        const int idx[3] = {a, b, c};
        double q[3] = {0, 0, 0};
        for (uint8_t j = 0; j < m.dof(); ++j) {
          const JointRange& r = lm.joint[j];
          q[j] = robot_ref::rad(r.min_deg + (r.max_deg - r.min_deg) * (idx[j] + 0.5) / n);
        }
        if (robot_ref::first_axis_reach(m, q) < kMinAxisReachMm) {
          ++w.skipped;
          continue;
        }
        ++w.poses;
        const Vector3d p = robot_ref::body_fk(m, lm, q);
        typename AnyLeg<S>::Joints qs{};
        for (uint8_t j = 0; j < m.dof(); ++j) qs[j] = scalar<S>(q[j]);
        w.fk_mm = std::max(w.fk_mm, (robot_ref::to_eigen(leg.fk_body(qs)) - p).norm());

        typename AnyLeg<S>::Joints got{};
        Vec3<S> reached;
        const IkStatus s = leg.ik_body(robot_ref::from_eigen<S>(p), got, reached);
        if (s != IkStatus::kOk) {
          ADD_FAILURE() << m.name << " leg " << int(i) << " q_deg " << robot_ref::deg(q[0]) << " "
                        << robot_ref::deg(q[1]) << " " << robot_ref::deg(q[2]) << ": " << to_string(s);
          return w;
        }
        double qg[3] = {0, 0, 0};
        for (uint8_t j = 0; j < m.dof(); ++j) {
          qg[j] = to_double(got[j]);
          w.joint_deg = std::max(w.joint_deg, std::fabs(robot_ref::angle_diff_deg(robot_ref::deg(qg[j]),
                                                                                   robot_ref::deg(q[j]))));
        }
        w.ik_mm = std::max(w.ik_mm, (robot_ref::body_fk(m, lm, qg) - p).norm());
        w.ik_mm = std::max(w.ik_mm, (robot_ref::to_eigen(reached) - p).norm());
      }
  return w;
}

TYPED_TEST(RobotKinematics, RoundTripsOverJointGrids) {
  using S = TypeParam;
  using B = robot_ref::Bounds<S>;
  for (const RobotModel* m : kAllRobots) {
    Worst all;
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      const Worst w = sweep<S>(*m, i);
      EXPECT_LT(w.fk_mm, B::kPositionMm) << m->name << " leg " << int(i) << ": FK vs reference";
      EXPECT_LT(w.ik_mm, B::kPositionMm) << m->name << " leg " << int(i) << ": FK(IK(p)) vs p";
      EXPECT_LT(w.joint_deg, B::kJointDeg) << m->name << " leg " << int(i) << ": IK(FK(q)) vs q";
      // The exclusion must stay a small corner of the grid.
      EXPECT_LT(w.skipped, (w.poses + w.skipped) / 5) << m->name << " leg " << int(i);
      all.fk_mm = std::max(all.fk_mm, w.fk_mm);
      all.ik_mm = std::max(all.ik_mm, w.ik_mm);
      all.joint_deg = std::max(all.joint_deg, w.joint_deg);
      all.poses += w.poses;
      all.skipped += w.skipped;
    }
    std::printf("[ measured ] %-9s %-5s %6ld poses (%ld skipped): FK %.2e mm, FK(IK) %.2e mm, IK(FK) %.2e deg\n",
                m->name, ScalarTraits<S>::name(), all.poses, all.skipped, all.fk_mm, all.ik_mm, all.joint_deg);
  }
}

// Seed 002 tables 4-9: every desired foot of the hexapod's tests, in the leg
// frame, is reachable with status ok on the leg it was tested on.
TYPED_TEST(RobotKinematics, Seed002TablePointsAreReachable) {
  using S = TypeParam;
  const double x[7] = {70, 80, 90, 100, 110, 120, 130};
  const double z[7] = {-50, -40, -30, -20, -10, 10, 20};
  const double y_corner[7] = {10, 20, 30, 40, 50, 60, 70};  // tables 4, 6, 7, 9 (legs 1, 3, 4, 6)
  const double y_middle[7] = {-30, -20, -10, 10, 20, 30, 40};  // tables 5, 8 (legs 2, 5)
  for (uint8_t i = 0; i < 6; ++i) {
    const AnyLeg<S> leg = leg_of<S>(kHexapod18, i);
    const double* y = (i == 1 || i == 4) ? y_middle : y_corner;
    for (int k = 0; k < 7; ++k) {
      typename AnyLeg<S>::Joints q{};
      Vec3<S> reached;
      const Vec3<S> p(scalar<S>(x[k]), scalar<S>(y[k]), scalar<S>(z[k]));
      EXPECT_EQ(leg.ik(p, q, reached), IkStatus::kOk) << "leg " << int(i) << " point " << k;
    }
  }
}

}  // namespace
