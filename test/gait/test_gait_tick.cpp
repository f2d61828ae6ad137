// The per-tick shortcuts of the gait engine and walker against the general
// computations they skip, and the stored velocity limits against the
// search they replace:
// - stored limits = a fresh float search (the table is not stale), within
//   1 mm or 1 % of the Fixed search, used only for built-in models at their
//   defaults; the walker configured in place = configured from a copy;
// - beyond_edge() (diamond and circle pre-tests) = the exact test;
// - the foot a walker reports without the transform back = FK of its joints;
// - the support polygon built when first asked = a fresh one (to rounding).
#include <cmath>
#include <cstdio>
#include <cstring>

#include "gait/stored_velocity_limits.h"
#include "gait_test_util.h"

namespace gaittest {
namespace {

template <typename S>
void legs_of(const RobotModel& m, strider::AnyLeg<S>* legs) {
  for (uint8_t i = 0; i < m.leg_count; ++i) strider::AnyLeg<S>::from_model(m, i, legs[i]);
}

TEST(StoredVelocityLimits, MatchTheSearch) {
  for (uint8_t r = 0; r < strider::kRobotCount; ++r) {
    const RobotModel& m = *strider::kAllRobots[r];
    SCOPED_TRACE(m.name);
    const strider::GaitParams& p = strider::kGaitParams[r];
    ASSERT_EQ(strider::stored_limits_index(m, p, p.shape), r);
    strider::AnyLeg<float> lf[strider::kMaxLegs];
    strider::AnyLeg<Fixed> lx[strider::kMaxLegs];
    legs_of(m, lf);
    legs_of(m, lx);
    const auto sf = strider::make_gait_config(m, lf, p, p.shape).limits;
    const auto qf = strider::make_gait_config(m, lf, p, p.shape, strider::LimitsSource::kSearch).limits;
    const auto sx = strider::make_gait_config(m, lx, p, p.shape).limits;
    const auto qx = strider::make_gait_config(m, lx, p, p.shape, strider::LimitsSource::kSearch).limits;
    // Float: the table is the search rounded to 1/64 mm and Q16.16; if this
    // fails, regenerate it (velocity_limit_table.h says how).
    for (uint8_t i = 0; i < m.leg_count; ++i)
      for (int k = 0; k < strider::VelocityLimits<float>::kDirections; ++k) {
        ASSERT_NEAR(sf.stride_mm(i, uint8_t(k)), qf.stride_mm(i, uint8_t(k)), 1.0 / 64 + 1e-4) << "leg " << int(i) << " dir " << k;
        const double d = std::fabs(dbl(sx.stride_mm(i, uint8_t(k))) - dbl(qx.stride_mm(i, uint8_t(k))));
        EXPECT_LE(d, std::max(1.0, 0.01 * dbl(qx.stride_mm(i, uint8_t(k))))) << "leg " << int(i) << " dir " << k;
      }
    EXPECT_NEAR(sf.lift_ms, qf.lift_ms, 1e-4 * qf.lift_ms + 1e-4);
    EXPECT_NEAR(sf.swing_ms_per_mm, qf.swing_ms_per_mm, 1e-4 * qf.swing_ms_per_mm + 1e-4);
    EXPECT_NEAR(sf.stance_ms_per_mm, qf.stance_ms_per_mm, 1e-4 * qf.stance_ms_per_mm + 1e-4);
    EXPECT_EQ(sf.min_hz, qf.min_hz);
    EXPECT_EQ(sf.preferred_stride_mm, qf.preferred_stride_mm);
    EXPECT_EQ(sf.sideways, qf.sideways);
    EXPECT_EQ(sf.leg_count, qf.leg_count);
    EXPECT_NEAR(dbl(sx.lift_ms), dbl(qx.lift_ms), 0.01 * dbl(qx.lift_ms));
    EXPECT_NEAR(dbl(sx.swing_ms_per_mm), dbl(qx.swing_ms_per_mm), 0.01 * dbl(qx.swing_ms_per_mm) + 1e-3);
    EXPECT_NEAR(dbl(sx.stance_ms_per_mm), dbl(qx.stance_ms_per_mm), 0.01 * dbl(qx.stance_ms_per_mm) + 1e-3);
  }
}

// The fingerprint's 1/16 mm from the float's bits = the float formula
// int16_t(mm * 16 +- 0.5), halves and both signs included, over the range of
// a model's sizes. Through int32_t: +-2047.96875 rounds to +-32768, which a
// float converted straight to int16_t would overflow (undefined); its low
// 16 bits are what sixteenths() gives.
TEST(StoredVelocityLimits, SixteenthsFromBitsMatchTheFloatFormula) {
  const auto formula = [](float mm) { return uint16_t(int32_t(mm * 16.0f + (mm < 0.0f ? -0.5f : 0.5f))); };
  const float edges[] = {0.0f, -0.0f, 1e-30f, 0.03124f, 0.03125f, 0.0625f, 0.09375f, 1.0f, -1.03125f,
                         87.5f, -77.5f, 120.0f, -90.0f, 2047.96875f, -2047.96875f, 1e-3f, -1e-3f};
  for (const float v : edges) {
    EXPECT_EQ(strider::velocity_limit_encoding::sixteenths(v), formula(v)) << v;
  }
  uint32_t seed = 12345;
  for (int n = 0; n < 200000; ++n) {
    seed = seed * 1664525u + 1013904223u;
    const float v = (float(seed >> 8) / float(1u << 24) - 0.5f) * 4090.0f;
    ASSERT_EQ(strider::velocity_limit_encoding::sixteenths(v), formula(v)) << v;
    const float h = float((int32_t(seed >> 15) - 65536) | 1) / 32.0f;  // on the halves: odd 1/32 mm
    ASSERT_EQ(strider::velocity_limit_encoding::sixteenths(h), formula(h)) << h;
  }
}

TEST(StoredVelocityLimits, OnlyForBuiltInModelsAtTheirDefaults) {
  const RobotModel& m = *strider::kAllRobots[3];
  strider::GaitParams p = strider::kGaitParams[3];
  strider::VelocityLimits<float> out;
  EXPECT_TRUE(strider::stored_velocity_limits(m, p, p.shape, out));
  EXPECT_FALSE(strider::stored_velocity_limits(m, p, strider::SwingShape(uint8_t(p.shape) == 0 ? 1 : 0), out));
  p.step_height_mm += 1.0f;
  EXPECT_FALSE(strider::stored_velocity_limits(m, p, p.shape, out));
  p = strider::kGaitParams[3];
  p.cycle_s *= 2.0f;
  EXPECT_FALSE(strider::stored_velocity_limits(m, p, p.shape, out));
  // A copy with the same name and numbers has the same limits: stored. One
  // with the same name but another geometry is searched.
  const RobotModel copy = m;
  EXPECT_TRUE(strider::stored_velocity_limits(copy, strider::kGaitParams[3], strider::kGaitParams[3].shape, out));
  RobotModel longer = m;
  longer.links.l2_mm += 5.0f;
  EXPECT_FALSE(strider::stored_velocity_limits(longer, strider::kGaitParams[3], strider::kGaitParams[3].shape, out));
  RobotModel wider = m;
  wider.legs[0].stand_mm.x += 1.0f;
  EXPECT_FALSE(strider::stored_velocity_limits(wider, strider::kGaitParams[3], strider::kGaitParams[3].shape, out));
  EXPECT_FALSE(strider::stored_velocity_limits(*strider::kAllRobots[2], strider::kGaitParams[3],
                                               strider::kGaitParams[3].shape, out));
}

template <typename S>
class GaitTickTest : public ::testing::Test {};
TYPED_TEST_SUITE(GaitTickTest, Scalars);

TYPED_TEST(GaitTickTest, ConfiguredInPlaceLikeFromACopy) {
  using S = TypeParam;
  for (const RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    const GaitTable& g = *strider::find_gait(*m, p.default_gait);
    std::unique_ptr<Walker<S>> a(new Walker<S>()), b(new Walker<S>());
    ASSERT_TRUE(a->configure(*m, g, p, p.shape));
    strider::AnyLeg<S> legs[strider::kMaxLegs];
    legs_of(*m, legs);
    ASSERT_TRUE(b->configure(*m, g, strider::make_gait_config(*m, legs, p, p.shape)));
    const auto& la = a->engine().config().limits;
    const auto& lb = b->engine().config().limits;
    for (uint8_t i = 0; i < m->leg_count; ++i)
      for (int k = 0; k < strider::VelocityLimits<S>::kDirections; ++k) ASSERT_EQ(la.stride_mm(i, uint8_t(k)), lb.stride_mm(i, uint8_t(k)));
    EXPECT_EQ(la.lift_ms, lb.lift_ms);
    EXPECT_EQ(la.swing_ms_per_mm, lb.swing_ms_per_mm);
    EXPECT_EQ(la.stance_ms_per_mm, lb.stance_ms_per_mm);
    EXPECT_EQ(a->engine().config().accel_mm_s2, b->engine().config().accel_mm_s2);
    a->engine().set_command(sc<S>(30.0), S(0), sc<S>(0.1));
    b->engine().set_command(sc<S>(30.0), S(0), sc<S>(0.1));
    for (int t = 0; t < 100; ++t) {
      a->tick(sc<S>(kDt));
      b->tick(sc<S>(kDt));
    }
    for (uint8_t i = 0; i < m->leg_count; ++i)
      for (uint8_t j = 0; j < m->dof(); ++j) ASSERT_EQ(a->leg(i).q[j], b->leg(i).q[j]);
  }
}

// The exact edge test that beyond_edge() short-cuts.
template <typename S>
bool edge_exact(const GaitEngine<S>& e, uint8_t i, const Vec3<S>& p) {
  const auto& c = e.config();
  const S dx = p.x - c.home[i].x, dy = p.y - c.home[i].y;
  if (dx == S(0) && dy == S(0)) return false;
  const S stride = c.limits.leg_stride(i, dx, dy);
  const S d = strider::units::norm_in(dx, dy, S(0), c.unit_shift);
  return d > stride * strider::scalar<S>(GaitEngine<S>::edge_share());
}

TYPED_TEST(GaitTickTest, BeyondEdgeIsTheExactTest) {
  using S = TypeParam;
  for (const Case& c : all_cases()) {
    if (c.gait != strider::gaits_for(*c.model).items[0]) continue;
    SCOPED_TRACE(c.name());
    Rig<S> rig(*c.model, *c.gait);
    const GaitEngine<S>& e = rig.engine();
    int beyond = 0, total = 0;
    for (uint8_t i = 0; i < c.model->leg_count; ++i) {
      const Vec3<S>& h = e.config().home[i];
      double longest = 0.0;
      for (int k = 0; k < strider::VelocityLimits<S>::kDirections; ++k)
        longest = std::max(longest, dbl(e.config().limits.stride_mm(i, uint8_t(k))));
      for (int a = 0; a < 72; ++a)
        for (int r = 1; r <= 60; ++r) {
          const double ang = a * kPi / 36.0, len = r * longest / 60.0;  // up to the longest stride from home
          const Vec3<S> p(h.x + sc<S>(len * std::cos(ang)), h.y + sc<S>(len * std::sin(ang)), h.z);
          const bool fast = e.beyond_edge(i, p);
          ASSERT_EQ(fast, edge_exact(e, i, p)) << "leg " << int(i) << " angle " << a << " r " << len;
          beyond += fast;
          ++total;
        }
    }
    EXPECT_GT(beyond, 0);
    EXPECT_LT(beyond, total);
  }
}

TYPED_TEST(GaitTickTest, ReportedFootIsWhereTheJointsPutIt) {
  using S = TypeParam;
  const double tol = std::is_same<S, float>::value ? 1e-3 : 0.05;  // [mm]
  for (const RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    Rig<S> rig(*m, *strider::find_gait(*m, p.default_gait));
    rig.engine().set_command(sc<S>(20.0), sc<S>(5.0), sc<S>(0.05));
    double worst = 0.0;
    for (int t = 0; t < 150; ++t) {
      rig.walker->tick(sc<S>(kDt));
      for (uint8_t i = 0; i < m->leg_count; ++i) {
        const strider::LegResult<S>& r = rig.walker->leg(i);
        if (r.ik_status == IkStatus::kUnreachable) continue;
        const Vec3<S> fk = rig.walker->leg_model(i).fk_body(r.q);
        worst = std::max(worst, dist(p2(fk), p2(r.foot_mm)));
      }
    }
    EXPECT_LE(worst, tol + (m->dof() == 2 ? 0.05 : 0.0));
  }
}

TYPED_TEST(GaitTickTest, SupportBuiltWhenAskedIsTheSupportOfTheFeetDown) {
  using S = TypeParam;
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(c.name());
    Rig<S> rig(*c.model, *c.gait);
    rig.engine().set_command(sc<S>(15.0), S(0), S(0));
    for (int t = 0; t < 120; ++t) {
      rig.walker->tick(sc<S>(kDt));
      if (t % 7 != 0) continue;  // asked now and then: built late
      const GaitEngine<S>& e = rig.engine();
      strider::SupportPolygon<S> fresh;
      fresh.build(e.feet(), e.contacts(), e.leg_count(), e.config().foot_radius_mm, e.config().unit_shift);
      ASSERT_EQ(fresh.size(), e.support().size()) << "tick " << t;
      for (uint8_t k = 0; k < fresh.size(); ++k) ASSERT_EQ(fresh.vertex(k), e.support().vertex(k));
      const strider::BodyPose<S> bp = e.body_pose();
      const S cx = bp.translation_mm.x + e.config().com_x_mm, cy = bp.translation_mm.y + e.config().com_y_mm;
      // Feet on the ground move rigidly: a polygon built a few ticks ago
      // differs from a fresh one by rounding only.
      const double tol = std::is_same<S, float>::value ? 1e-3 : 0.01;  // [mm]
      if (bp.roll_rad == S(0) && bp.pitch_rad == S(0) && bp.yaw_rad == S(0)) {
        ASSERT_NEAR(dbl(fresh.margin(e.feet(), cx, cy)), dbl(e.margin_mm()), tol) << "tick " << t;
      }
    }
  }
}

}  // namespace
}  // namespace gaittest

namespace gaittest {
namespace {

TYPED_TEST(GaitTickTest, LegFrameTransformIsTheMounts) {
  using S = TypeParam;
  // Fixed: the +-45 degree mounts round once less (one product instead of
  // two): within a few raw units. Float: within rounding.
  const double tol = std::is_same<S, float>::value ? 1e-4 : 4.0 / 65536.0;  // [mm]
  for (const RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    std::unique_ptr<Walker<S>> w(new Walker<S>());
    ASSERT_TRUE(w->configure(*m, *strider::find_gait(*m, p.default_gait), p, p.shape));
    for (uint8_t i = 0; i < m->leg_count; ++i)
      for (int a = 0; a < 36; ++a)
        for (int r = 0; r <= 300; r += 25) {
          const Vec3<S> q(sc<S>(r * std::cos(a * kPi / 18)), sc<S>(r * std::sin(a * kPi / 18)), sc<S>(-40.0 + r * 0.1));
          const P2 fast = p2(w->to_leg(i, q)), ref = p2(w->leg_model(i).mount().body_to_leg(q));
          ASSERT_LE(dist(fast, ref), tol) << "leg " << int(i) << " a " << a << " r " << r;
        }
  }
}

}  // namespace
}  // namespace gaittest

namespace gaittest {
namespace {

TYPED_TEST(GaitTickTest, StraightBodyStepIsTheSeriesStep) {
  using S = TypeParam;
  using strider::BodyStep;
  // BodyStep::make skips the turn's series when wz is 0: the same step as
  // the series at theta = 0, exactly (sign of a zero aside).
  const double speeds[] = {0.0, 1.0, -37.5, 80.25, 212.0};
  const double dts[] = {0.02, 0.013, 0.1};
  for (double vx : speeds)
    for (double vy : speeds)
      for (double dt : dts) {
        const S svx = sc<S>(vx), svy = sc<S>(vy), sdt = sc<S>(dt);
        const BodyStep<S> fast = BodyStep<S>::make(svx, svy, S(0), sdt);
        const S th = S(0) * sdt;
        S a, b, c, s;
        strider::small_angle_arc(th, a, b);
        strider::small_angle_cos_sin(th, c, s);
        EXPECT_TRUE(fast.dx_mm == (a * svx - b * svy) * sdt) << vx << " " << vy << " " << dt;
        EXPECT_TRUE(fast.dy_mm == (a * svy + b * svx) * sdt) << vx << " " << vy << " " << dt;
        EXPECT_TRUE(fast.dyaw == th);
        EXPECT_TRUE(fast.cos_yaw == c);
        EXPECT_TRUE(fast.sin_yaw == s);
      }
}

}  // namespace
}  // namespace gaittest
