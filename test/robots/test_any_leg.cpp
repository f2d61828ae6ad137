// AnyLeg: the dispatch gives exactly what the leg type gives, and the edges
// of its own interface (bad index, 2-DOF third slot, unreachable targets).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "robot_reference.h"

using namespace strider;

namespace {

template <typename S>
class AnyLegTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(AnyLegTest, Scalars);

// The first N joint limits of a leg model, for a leg type with N joints.
template <typename S, uint8_t N>
JointLimits<S, N> limits(const LegModel& lm) {
  JointLimits<S, N> l;
  for (uint8_t j = 0; j < N; ++j) {
    l.lo[j] = deg_to_rad<S>(lm.joint[j].min_deg);
    l.hi[j] = deg_to_rad<S>(lm.joint[j].max_deg);
  }
  return l;
}

// A few leg-frame targets around the standing foot, some out of reach.
template <typename S>
std::vector<Vec3<S>> probes(const LegModel& lm) {
  const Vec3<float> s = body_point_in_leg(lm, lm.stand_mm);
  std::vector<Vec3<S>> out;
  for (float dx : {-30.0f, 0.0f, 25.0f})
    for (float dz : {-40.0f, 0.0f, 35.0f, 900.0f})
      out.push_back(Vec3<S>(scalar<S>(s.x + dx), scalar<S>(s.y + 0.5f * dx), scalar<S>(s.z + dz)));
  return out;
}

template <typename S, typename Leg>
void expect_same(const AnyLeg<S>& any, const Leg& direct, const std::vector<Vec3<S>>& targets, const char* name) {
  for (const Vec3<S>& t : targets) {
    typename Leg::Joints qd{};
    Vec3<S> rd(S(7), S(7), S(7));
    typename AnyLeg<S>::Joints qa{};
    Vec3<S> ra(S(7), S(7), S(7));
    const IkStatus sd = direct.ik(t, qd, rd);
    const IkStatus sa = any.ik(t, qa, ra);
    ASSERT_EQ(sa, sd) << name;
    EXPECT_EQ(ra, rd) << name;
    for (uint8_t j = 0; j < Leg::kDof; ++j) EXPECT_EQ(qa[j], qd[j]) << name;
    if (Leg::kDof == 2 && sa != IkStatus::kUnreachable) {
      EXPECT_EQ(qa[2], S(0)) << name;
    }
    typename AnyLeg<S>::Joints q3{};
    for (uint8_t j = 0; j < Leg::kDof; ++j) q3[j] = qd[j];
    EXPECT_EQ(any.fk(q3), direct.fk(qd)) << name;
  }
}

TYPED_TEST(AnyLegTest, DispatchesToTheModelsLegType) {
  using S = TypeParam;
  for (const RobotModel* m : kAllRobots) {
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      const LegModel& lm = m->legs[i];
      AnyLeg<S> any;
      ASSERT_TRUE(AnyLeg<S>::from_model(*m, i, any));
      EXPECT_EQ(any.kind(), m->kind);
      EXPECT_EQ(any.dof(), m->dof());
      EXPECT_EQ(any.side(), lm.side);
      const S l1 = scalar<S>(m->links.l1_mm), l2 = scalar<S>(m->links.l2_mm);
      const S l3 = scalar<S>(m->links.l3_mm), d1 = scalar<S>(m->links.d1_mm);
      switch (m->kind) {
        case LegKind::kSprawl:
          expect_same(any, SprawlLeg<S>::make(l1, l2, limits<S, 2>(lm)), probes<S>(lm), m->name);
          break;
        case LegKind::kPlanar:
          expect_same(any, PlanarLeg<S>::make(l1, l2, limits<S, 2>(lm)), probes<S>(lm), m->name);
          break;
        case LegKind::kCoxaFemurTibia:
          expect_same(any, CoxaFemurTibiaLeg<S>::make(d1, l1, l2, l3, limits<S, 3>(lm)), probes<S>(lm), m->name);
          break;
        case LegKind::kAbduction:
          expect_same(any,
                      AbductionLeg<S>::make(l1, l2, l3, limits<S, 3>(lm),
                                            lm.side == BodySide::kLeft ? LegSide::kLeft : LegSide::kRight),
                      probes<S>(lm), m->name);
          break;
      }
    }
  }
}

TYPED_TEST(AnyLegTest, BodyFrameGoesThroughTheMount) {
  using S = TypeParam;
  for (const RobotModel* m : kAllRobots) {
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      AnyLeg<S> any;
      ASSERT_TRUE(AnyLeg<S>::from_model(*m, i, any));
      for (const Vec3<S>& t : probes<S>(m->legs[i])) {
        typename AnyLeg<S>::Joints ql{}, qb{};
        Vec3<S> rl, rb;
        const Vec3<S> tb = any.mount().leg_to_body(t);
        const IkStatus sl = any.ik(t, ql, rl);
        const IkStatus sb = any.ik_body(tb, qb, rb);
        if (sl == IkStatus::kUnreachable) {
          EXPECT_EQ(sb, IkStatus::kUnreachable);
          continue;
        }
        // Same status; the round trip through the mount costs at most rounding.
        EXPECT_EQ(sb, sl) << m->name;
        const double tol = robot_ref::Bounds<S>::kPositionMm;
        EXPECT_LT((robot_ref::to_eigen(any.mount().leg_to_body(rl)) - robot_ref::to_eigen(rb)).norm(), tol);
        EXPECT_LT((robot_ref::to_eigen(any.fk_body(qb)) - robot_ref::to_eigen(rb)).norm(), tol) << m->name;
      }
    }
  }
}

TYPED_TEST(AnyLegTest, EdgesOfTheInterface) {
  using S = TypeParam;
  AnyLeg<S> leg;
  ASSERT_TRUE(AnyLeg<S>::from_model(kHexapod18, 5, leg));
  const Vec3<S> before_mount = leg.mount().origin_mm;
  AnyLeg<S> untouched = leg;
  EXPECT_FALSE(AnyLeg<S>::from_model(kHexapod18, 6, untouched));  // past leg_count
  EXPECT_FALSE(AnyLeg<S>::from_model(kSprawl8, 4, untouched));
  EXPECT_EQ(untouched.mount().origin_mm, before_mount);

  // Unreachable: outputs untouched, in both frames.
  typename AnyLeg<S>::Joints q{};
  q[0] = q[1] = q[2] = S(1);
  Vec3<S> r(S(3), S(4), S(5));
  EXPECT_EQ(leg.ik(Vec3<S>(S(2000), S(0), S(0)), q, r), IkStatus::kUnreachable);
  EXPECT_EQ(leg.ik_body(Vec3<S>(S(-3000), S(100), S(0)), q, r), IkStatus::kUnreachable);
  EXPECT_EQ(q[0], S(1));
  EXPECT_EQ(q[2], S(1));
  EXPECT_EQ(r, Vec3<S>(S(3), S(4), S(5)));

  // Limits and within_limits.
  const JointLimits<S, 3> l = leg.limits();
  EXPECT_NEAR(to_double(l.lo[2]), robot_ref::rad(-150.0), 1e-4);
  EXPECT_NEAR(to_double(l.hi[1]), robot_ref::rad(90.0), 1e-4);
  typename AnyLeg<S>::Joints inside{};
  inside[1] = S(0);
  inside[2] = deg_to_rad<S>(-90.0);
  EXPECT_TRUE(leg.within_limits(inside));
  inside[2] = S(0);
  EXPECT_FALSE(leg.within_limits(inside));

  // 2-DOF: slot 2 of the limits is empty and ignored by within_limits.
  AnyLeg<S> two;
  ASSERT_TRUE(AnyLeg<S>::from_model(kMammal8, 0, two));
  EXPECT_EQ(two.dof(), 2);
  EXPECT_EQ(two.limits().lo[2], S(0));
  typename AnyLeg<S>::Joints qm{};
  qm[0] = deg_to_rad<S>(-100.0);
  qm[1] = deg_to_rad<S>(60.0);
  qm[2] = S(3);  // ignored
  EXPECT_TRUE(two.within_limits(qm));
  EXPECT_EQ(two.fk(qm), [&] {
    typename AnyLeg<S>::Joints z = qm;
    z[2] = S(0);
    return two.fk(z);
  }());
}

}  // namespace

namespace {

// Seeded random body-frame targets around every leg (inside, near and far
// outside its workspace): whatever the status, the contract holds.
TYPED_TEST(AnyLegTest, RandomTargetsKeepTheContract) {
  using S = TypeParam;
  std::mt19937 rng(20240607);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int counts[4] = {0, 0, 0, 0};
  for (const RobotModel* m : kAllRobots) {
    const double reach = m->links.l1_mm + m->links.l2_mm + m->links.l3_mm + std::fabs(m->links.d1_mm);
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      AnyLeg<S> leg;
      ASSERT_TRUE(AnyLeg<S>::from_model(*m, i, leg));
      const LegModel& lm = m->legs[i];
      for (int k = 0; k < STRIDER_RANDOM_CASES; ++k) {
        const double scale = (k % 3 == 0) ? 0.3 * reach : 1.3 * reach;
        const Vec3<S> t(scalar<S>(lm.mount_mm.x + scale * unit(rng)), scalar<S>(lm.mount_mm.y + scale * unit(rng)),
                        scalar<S>(lm.mount_mm.z + scale * unit(rng)));
        typename AnyLeg<S>::Joints q{};
        q[0] = q[1] = q[2] = S(2);
        Vec3<S> r(S(9), S(9), S(9));
        const IkStatus s = leg.ik_body(t, q, r);
        ++counts[int(s)];
        if (s == IkStatus::kUnreachable) {
          EXPECT_EQ(q[0], S(2));
          EXPECT_EQ(r, Vec3<S>(S(9), S(9), S(9)));
          continue;
        }
        const Eigen::Vector3d tr = robot_ref::to_eigen(t), rr = robot_ref::to_eigen(r);
        ASSERT_TRUE(std::isfinite(rr.x()) && std::isfinite(rr.y()) && std::isfinite(rr.z()));
        EXPECT_TRUE(leg.within_limits(q)) << m->name;
        // reached is where the returned joints put the foot...
        EXPECT_LT((robot_ref::to_eigen(leg.fk_body(q)) - rr).norm(), 2 * robot_ref::Bounds<S>::kPositionMm)
            << m->name << " " << to_string(s);
        // ...and is the target itself exactly when the status is ok.
        const double miss = (rr - tr).norm();
        if (s == IkStatus::kOk) {
          EXPECT_LT(miss, 0.2) << m->name;
        } else if (s == IkStatus::kClamped) {
          EXPECT_LT(miss, 25.5) << m->name;
        }
        if (m->dof() == 2) {
          EXPECT_EQ(q[2], S(0));
        }
      }
    }
  }
  // The stream must exercise every status.
  for (int c : counts) EXPECT_GT(c, 0);
}

}  // namespace

namespace {

// ik_body_fast(), the walker's path for a body-frame target without the turn
// into the leg frame: when it answers, the joints are ik_body()'s within the
// Fixed bounds, inside the limits, and put the foot (double reference) on the
// target; when it does not, q is untouched. Also for mounts turned by about
// 180 degrees, where t1 = target angle - yaw wraps around.
TYPED_TEST(AnyLegTest, BodyFastPathIsTheBodyIk) {
  using S = TypeParam;
  RobotModel turned = kHexapod18;
  const float yaws[3] = {180.0f, -172.5f, 170.0f};
  for (uint8_t i = 0; i < 3; ++i) {  // standing 120 mm out along the new direction
    LegModel& lm = turned.legs[i];
    lm.mount_yaw_deg = yaws[i];
    lm.stand_mm.x = lm.mount_mm.x + float(120.0 * std::cos(robot_ref::rad(yaws[i])));
    lm.stand_mm.y = lm.mount_mm.y + float(120.0 * std::sin(robot_ref::rad(yaws[i])));
  }
  const RobotModel* models[] = {&kHexapod18, &kSpider12, &turned, &kDog12, &kSprawl8};
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int fast = 0, wrapped_up = 0, wrapped_down = 0;
  for (const RobotModel* m : models) {
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      AnyLeg<S> leg;
      ASSERT_TRUE(AnyLeg<S>::from_model(*m, i, leg));
      const LegModel& lm = m->legs[i];
      for (int k = 0; k < STRIDER_RANDOM_CASES; ++k) {
        // Around the standing foot, most within reach, some beyond the limits.
        const Vec3<S> t(scalar<S>(lm.stand_mm.x + 70.0 * unit(rng)), scalar<S>(lm.stand_mm.y + 70.0 * unit(rng)),
                        scalar<S>(lm.stand_mm.z + 60.0 * unit(rng)));
        typename AnyLeg<S>::Joints q{};
        q[0] = q[1] = q[2] = S(2);
        if (!leg.ik_body_fast(t, q, IkOptions<S>())) {
          EXPECT_EQ(q[0], S(2));
          EXPECT_EQ(q[1], S(2));
          EXPECT_EQ(q[2], S(2));
          continue;
        }
        ++fast;
        ASSERT_TRUE((std::is_same<S, Fixed>::value)) << "float has no fast path";
        EXPECT_EQ(m->kind, LegKind::kCoxaFemurTibia);
        typename AnyLeg<S>::Joints qb{};
        Vec3<S> rb;
        ASSERT_EQ(leg.ik_body(t, qb, rb), IkStatus::kOk) << m->name << " leg " << int(i);
        EXPECT_TRUE(leg.within_limits(q));
        const double jt = robot_ref::Bounds<S>::kJointDeg;
        for (uint8_t j = 0; j < 3; ++j)
          EXPECT_LT(std::fabs(robot_ref::angle_diff_deg(robot_ref::deg(to_double(q[j])), robot_ref::deg(to_double(qb[j])))), jt)
              << m->name << " leg " << int(i) << " joint " << int(j);
        EXPECT_GT(to_double(q[0]), -robot_ref::kPi);
        EXPECT_LE(to_double(q[0]), robot_ref::kPi);
        const double qd[3] = {to_double(q[0]), to_double(q[1]), to_double(q[2])};
        EXPECT_LT((robot_ref::body_fk(*m, lm, qd) - robot_ref::to_eigen(t)).norm(), robot_ref::Bounds<S>::kPositionMm)
            << m->name << " leg " << int(i);
        const double dir = std::atan2(to_double(t.y) - lm.mount_mm.y, to_double(t.x) - lm.mount_mm.x);
        const double t1 = dir - robot_ref::rad(lm.mount_yaw_deg);
        if (t1 > robot_ref::kPi) ++wrapped_down;
        if (t1 < -robot_ref::kPi) ++wrapped_up;
      }
    }
  }
  if (std::is_same<S, Fixed>::value) {
    // Most targets of the coxa/femur/tibia legs take it, some across +-180 deg.
    EXPECT_GT(fast, 3 * 6 * STRIDER_RANDOM_CASES / 2);
    EXPECT_GT(wrapped_up, 0);
    EXPECT_GT(wrapped_down, 0);
  }
}

}  // namespace
