// Every leg type under hostile input: a fixed-seed stream of targets mixing
// points near the workspace, exact axis points, tiny and huge values, with
// several option sets and unusual geometries. checked_ik() verifies the
// contract each time: no NaN, untouched outputs on kUnreachable, joints
// within limits, reached = fk(q), miss within the status' bound.
#include <random>

#include "kinematics/abduction_leg.h"
#include "kinematics/coxa_femur_tibia_leg.h"
#include "kinematics/planar_leg.h"
#include "kinematics/sprawl_leg.h"
#include "leg_test_util.h"

namespace {

using namespace legtest;
using strider::AbductionLeg;
using strider::CoxaFemurTibiaLeg;
using strider::IkOptions;
using strider::JointLimits;
using strider::KneeBranch;
using strider::LegSide;
using strider::PlanarLeg;
using strider::SprawlLeg;

//! A coordinate [mm] from a mixture: near the leg, exact specials, wild.
double hostile(std::mt19937& rng, double reach) {
  static const double kSpecial[] = {0.0, -0.0, 1e-6, -1e-6, 2e-5, 1.0, -1.0, 44.0, -44.0, 1e3, -1e3,
                                    32767.0, -32768.0, 1e6, -1e6, 1e30, -1e30};
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  switch (kind(rng)) {
    case 0: return kSpecial[std::uniform_int_distribution<size_t>(0, sizeof(kSpecial) / sizeof(double) - 1)(rng)];
    case 1: return u(rng) * 1e-3;
    case 2: return u(rng) * 10 * reach;
    default: return u(rng) * 1.3 * reach;
  }
}

template <typename S>
IkOptions<S> options(int i) {
  IkOptions<S> opt;
  if (i % 3 == 1) opt.max_clamp_mm = S(0);
  if (i % 3 == 2) opt.max_clamp_mm = sc<S>(1000);
  if (i % 5 == 4) opt.tolerance_mm = sc<S>(1);
  return opt;
}

template <typename Leg>
void hammer(const Leg& leg, double reach, uint32_t seed) {
  using S = decltype(leg.limits.lo[0] + leg.limits.lo[0]);
  std::mt19937 rng(seed);
  long statuses[4] = {0, 0, 0, 0};
  for (int i = 0; i < 10 * STRIDER_RANDOM_CASES; ++i) {
    const Vec3<S> t = vec<S>(hostile(rng, reach), hostile(rng, reach), hostile(rng, reach));
    typename Leg::Joints q;
    Vec3<S> reached;
    const IkStatus st = checked_ik(leg, t, q, reached, options<S>(i));
    ++statuses[uint8_t(st)];
    if (::testing::Test::HasFailure()) FAIL() << "case " << i << ": " << describe(ev(t));
  }
  EXPECT_GT(statuses[0] + statuses[1], 100);
  EXPECT_GT(statuses[3], 100);
}

template <typename S>
JointLimits<S, 3> some_limits3() {
  JointLimits<S, 3> l;
  const double lo[3] = {-1.0, -1.5, -2.5}, hi[3] = {1.0, 1.5, 0.5};
  for (uint8_t i = 0; i < 3; ++i) l.lo[i] = sc<S>(lo[i]), l.hi[i] = sc<S>(hi[i]);
  return l;
}
template <typename S>
JointLimits<S, 2> some_limits2() {
  JointLimits<S, 2> l;
  l.lo[0] = sc<S>(-2.0), l.hi[0] = sc<S>(0.5), l.lo[1] = sc<S>(0.0), l.hi[1] = sc<S>(2.5);
  return l;
}

template <typename S>
class LegRobustnessTest : public ::testing::Test {};
TYPED_TEST_SUITE(LegRobustnessTest, Scalars);

TYPED_TEST(LegRobustnessTest, Sprawl) {
  using S = TypeParam;
  hammer(SprawlLeg<S>::make(sc<S>(55), sc<S>(90), JointLimits<S, 2>::unlimited()), 145, 1);
  hammer(SprawlLeg<S>::make(sc<S>(55), sc<S>(90), some_limits2<S>()), 145, 2);
  hammer(SprawlLeg<S>::make(sc<S>(90), sc<S>(20), JointLimits<S, 2>::unlimited()), 110, 3);
}

TYPED_TEST(LegRobustnessTest, Planar) {
  using S = TypeParam;
  hammer(PlanarLeg<S>::make(sc<S>(70), sc<S>(70), JointLimits<S, 2>::unlimited()), 140, 4);
  hammer(PlanarLeg<S>::make(sc<S>(70), sc<S>(70), some_limits2<S>(), KneeBranch::kNegative), 140, 5);
  hammer(PlanarLeg<S>::make(sc<S>(90), sc<S>(50), JointLimits<S, 2>::unlimited()), 140, 6);
  hammer(PlanarLeg<S>::make(sc<S>(30), sc<S>(0), JointLimits<S, 2>::unlimited()), 30, 7);  // no shank
}

TYPED_TEST(LegRobustnessTest, CoxaFemurTibia) {
  using S = TypeParam;
  hammer(CoxaFemurTibiaLeg<S>::make(sc<S>(32), sc<S>(30), sc<S>(85), sc<S>(125), JointLimits<S, 3>::unlimited()),
         240, 8);
  hammer(CoxaFemurTibiaLeg<S>::make(sc<S>(32), sc<S>(30), sc<S>(85), sc<S>(125), some_limits3<S>()), 240, 9);
  hammer(CoxaFemurTibiaLeg<S>::make(sc<S>(-12), sc<S>(0), sc<S>(55), sc<S>(77.5), JointLimits<S, 3>::unlimited(),
                                    KneeBranch::kPositive),
         133, 10);
  hammer(CoxaFemurTibiaLeg<S>::make(sc<S>(0), sc<S>(60), sc<S>(40), sc<S>(40), JointLimits<S, 3>::unlimited()), 140,
         11);
}

TYPED_TEST(LegRobustnessTest, Abduction) {
  using S = TypeParam;
  for (LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    hammer(AbductionLeg<S>::make(sc<S>(44), sc<S>(280), sc<S>(277), JointLimits<S, 3>::unlimited(), side), 601, 12);
    hammer(AbductionLeg<S>::make(sc<S>(44), sc<S>(280), sc<S>(277), some_limits3<S>(), side), 601, 13);
    hammer(AbductionLeg<S>::make(sc<S>(20), sc<S>(60), sc<S>(90), JointLimits<S, 3>::unlimited(), side), 170, 14);
  }
}

}  // namespace
