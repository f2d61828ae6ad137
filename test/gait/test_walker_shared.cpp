// The firmware's layouts on the host: legs of one geometry sharing one IK
// solver (kSolvers 1), leg results without feet (kFeet false) and the
// servo tick map's ranges shared by the joints of a slot (kTickSlots 3),
// against the per-leg solvers (AnyLeg::from_model) and a tick map with a
// range per joint.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "control/servo_stage.h"
#include "gait/gait_library.h"
#include "gait/walker.h"
#include "robots/all_robots.h"

namespace {

using strider::AnyLeg;
using strider::Fixed;
using strider::IkStatus;
using strider::RobotModel;
using strider::Vec3;
template <typename S>
struct Shared : strider::HostProfile<S> {
  static constexpr uint8_t kSolvers = 1;
  static constexpr bool kFeet = false;
  static constexpr uint8_t kTickSlots = 3;
};
template <typename S>
using Walker = strider::Walker<S, Shared<S>>;
template <typename S>
using WalkerLegs = strider::WalkerLegs<S, 6, 1>;

template <typename S>
class WalkerShared : public ::testing::Test {};
using Scalars = ::testing::Types<float, Fixed>;
TYPED_TEST_SUITE(WalkerShared, Scalars);

template <typename S>
bool configure(Walker<S>& w, const RobotModel& m) {
  strider::GaitParams p;
  if (!strider::gait_params_of(m, &p)) return false;
  const strider::GaitTable* g = strider::find_gait(m, p.default_gait);
  return g != nullptr && w.configure(m, *g, p, p.shape);
}

template <typename S>
bool same_bits(S a, S b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(WalkerSharedCount, LegSolversPerModel) {
  EXPECT_EQ(strider::leg_solver_count(strider::kSprawl8), 4);  // limits differ leg by leg
  EXPECT_EQ(strider::leg_solver_count(strider::kMammal8), 1);
  EXPECT_EQ(strider::leg_solver_count(strider::kDog12), 2);    // abduction legs: left and right
  EXPECT_EQ(strider::leg_solver_count(strider::kHexapod18), 1);
  EXPECT_EQ(strider::leg_solver_count(strider::kSpider12), 1);
}

TYPED_TEST(WalkerShared, RefusesAModelWithMoreGeometries) {
  using S = TypeParam;
  Walker<S> w;
  EXPECT_FALSE(configure(w, strider::kSprawl8));
  EXPECT_FALSE(configure(w, strider::kDog12));
  EXPECT_TRUE(configure(w, strider::kHexapod18));
}

// Every leg: the model's own mount, and the shared solver gives the IK of
// the leg's own AnyLeg, bit for bit, for targets around its standing foot.
TYPED_TEST(WalkerShared, LegsAreTheirOwnAnyLegs) {
  using S = TypeParam;
  for (const RobotModel* m : {&strider::kHexapod18, &strider::kSpider12, &strider::kMammal8}) {
    Walker<S> w;
    ASSERT_TRUE(configure(w, *m)) << m->name;
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      AnyLeg<S> ref;
      ASSERT_TRUE(AnyLeg<S>::from_model(*m, i, ref));
      const strider::LegMount<S>& mount = w.leg_mount(i);
      EXPECT_TRUE(same_bits(mount.origin_mm.x, ref.mount().origin_mm.x) && same_bits(mount.origin_mm.y, ref.mount().origin_mm.y) &&
                  same_bits(mount.cos_yaw, ref.mount().cos_yaw) && same_bits(mount.sin_yaw, ref.mount().sin_yaw))
          << m->name << " leg " << int(i);
      EXPECT_EQ(w.leg_model(i).side(), ref.side());
      const Vec3<S> home = ref.mount().body_to_leg(Vec3<S>::from(m->legs[i].stand_mm));
      for (int k = 0; k < 27; ++k) {
        const Vec3<S> t(home.x + strider::scalar<S>(10.0 * (k % 3 - 1)), home.y + strider::scalar<S>(10.0 * (k / 3 % 3 - 1)),
                        home.z + strider::scalar<S>(10.0 * (k / 9 - 1)));
        typename AnyLeg<S>::Joints q, q_ref;
        Vec3<S> at, at_ref;
        const IkStatus s = w.leg_ik(i, t, q, at), s_ref = ref.ik(t, q_ref, at_ref);
        ASSERT_EQ(s, s_ref);
        if (s == IkStatus::kUnreachable) continue;
        for (uint8_t j = 0; j < m->dof(); ++j) EXPECT_TRUE(same_bits(q[j], q_ref[j])) << m->name << " leg " << int(i);
        const Vec3<S> fk = w.leg_model(i).fk_body(q), fk_ref = ref.fk_body(q_ref);
        EXPECT_TRUE(same_bits(fk.x, fk_ref.x) && same_bits(fk.y, fk_ref.y) && same_bits(fk.z, fk_ref.z));
      }
    }
  }
}

// The legs as compile-time constants (walker_legs: the firmware's) in this
// layout are the legs converted from the model at run time, bit for bit:
// mounts, sides, limits, IK and FK; and the walker walks alike with them.
constexpr WalkerLegs<Fixed> kHexapodLegs = strider::walker_legs<Fixed, 6, 1>(strider::kHexapod18);
constexpr WalkerLegs<Fixed> kSpiderLegs = strider::walker_legs<Fixed, 6, 1>(strider::kSpider12);
constexpr WalkerLegs<Fixed> kMammalLegs = strider::walker_legs<Fixed, 6, 1>(strider::kMammal8);
constexpr WalkerLegs<float> kHexapodLegsFloat = strider::walker_legs<float, 6, 1>(strider::kHexapod18);
static_assert(kHexapodLegs.ok && kSpiderLegs.ok && kMammalLegs.ok && kHexapodLegsFloat.ok, "walker_legs: one solver");
static_assert(!strider::walker_legs<Fixed, 6, 1>(strider::kDog12).ok && !strider::walker_legs<Fixed, 6, 1>(strider::kSprawl8).ok,
              "walker_legs: more geometries than solvers");

template <typename S>
void expect_constant_legs_alike(const RobotModel& m, const WalkerLegs<S>& legs) {
  SCOPED_TRACE(m.name);
  strider::GaitParams p;
  ASSERT_TRUE(strider::gait_params_of(m, &p));
  const strider::GaitTable* g = strider::find_gait(m, p.default_gait);
  ASSERT_NE(g, nullptr);
  const uint8_t r = strider::stored_limits_index(m, p, p.shape);
  ASSERT_LT(r, strider::kRobotCount);
  const strider::GaitConfig<S> cfg = strider::stored_gait_config<S>(r);
  Walker<S> converted, constant;
  ASSERT_TRUE(converted.configure_stored(m, *g, &cfg));
  ASSERT_TRUE(constant.configure_stored(&legs, *g, &cfg));
  ASSERT_EQ(converted.dof(), constant.dof());
  ASSERT_EQ(converted.leg_count(), constant.leg_count());
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    const strider::LegMount<S>& a = converted.leg_mount(i);
    const strider::LegMount<S>& b = constant.leg_mount(i);
    EXPECT_TRUE(same_bits(a.origin_mm.x, b.origin_mm.x) && same_bits(a.origin_mm.y, b.origin_mm.y) &&
                same_bits(a.origin_mm.z, b.origin_mm.z) && same_bits(a.yaw_rad, b.yaw_rad) &&
                same_bits(a.cos_yaw, b.cos_yaw) && same_bits(a.sin_yaw, b.sin_yaw))
        << "leg " << int(i);
    const AnyLeg<S> la = converted.leg_model(i), lb = constant.leg_model(i);
    EXPECT_EQ(la.kind(), lb.kind());
    EXPECT_EQ(la.side(), lb.side());
    for (uint8_t j = 0; j < strider::kMaxLegDof; ++j)
      EXPECT_TRUE(same_bits(la.limits().lo[j], lb.limits().lo[j]) && same_bits(la.limits().hi[j], lb.limits().hi[j]));
    const Vec3<S> home = la.mount().body_to_leg(Vec3<S>::from(m.legs[i].stand_mm));
    for (int k = 0; k < 125; ++k) {
      const Vec3<S> t(home.x + strider::scalar<S>(12.0 * (k % 5 - 2)), home.y + strider::scalar<S>(12.0 * (k / 5 % 5 - 2)),
                      home.z + strider::scalar<S>(12.0 * (k / 25 - 2)));
      typename AnyLeg<S>::Joints qa, qb;
      Vec3<S> at_a, at_b;
      const IkStatus sa = converted.leg_ik(i, t, qa, at_a), sb = constant.leg_ik(i, t, qb, at_b);
      ASSERT_EQ(sa, sb);
      if (sa == IkStatus::kUnreachable) continue;
      for (uint8_t j = 0; j < m.dof(); ++j) EXPECT_TRUE(same_bits(qa[j], qb[j])) << "leg " << int(i);
      const Vec3<S> fa = la.fk_body(qa), fb = lb.fk_body(qb);
      EXPECT_TRUE(same_bits(fa.x, fb.x) && same_bits(fa.y, fb.y) && same_bits(fa.z, fb.z));
    }
  }
  converted.engine().set_command(strider::scalar<S>(40.0), strider::scalar<S>(10.0), strider::scalar<S>(0.2));
  constant.engine().set_command(strider::scalar<S>(40.0), strider::scalar<S>(10.0), strider::scalar<S>(0.2));
  converted.engine().stand_up();
  constant.engine().stand_up();
  for (int tick = 0; tick < 300; ++tick) {
    converted.tick(strider::scalar<S>(0.02));
    constant.tick(strider::scalar<S>(0.02));
    for (uint8_t i = 0; i < m.leg_count; ++i) {
      ASSERT_EQ(converted.leg(i).status, constant.leg(i).status);
      for (uint8_t j = 0; j < m.dof(); ++j)
        ASSERT_TRUE(same_bits(converted.leg(i).q[j], constant.leg(i).q[j])) << "tick " << tick << " leg " << int(i);
    }
  }
}
TEST(WalkerSharedConstants, LegsAreTheModelsConvertedAtRunTime) {
  expect_constant_legs_alike<Fixed>(strider::kHexapod18, kHexapodLegs);
  expect_constant_legs_alike<Fixed>(strider::kSpider12, kSpiderLegs);
  expect_constant_legs_alike<Fixed>(strider::kMammal8, kMammalLegs);
  expect_constant_legs_alike<float>(strider::kHexapod18, kHexapodLegsFloat);
}

// The stage's channels as constants in this layout (a range per slot) are
// the channels made from the model at run time, and map alike.
constexpr strider::JointChannels<Fixed, 18, 3> kHexapodChannels = strider::joint_channels<Fixed, 18, 3>(strider::kHexapod18);
static_assert(kHexapodChannels.count == 18 && strider::JointChannels<Fixed, 18, 3>::kRanges == 3, "joint_channels: slots");
static_assert(strider::joint_channels<Fixed, 18, 3>(strider::kDog12).count == 0, "joint_channels: legs of two geometries");
struct HexapodChannels : Shared<Fixed> {
  static constexpr bool kStoredChannels = true;
  static constexpr const strider::JointChannels<Fixed, 18, 3>& kChannels = kHexapodChannels;
};
TEST(ServoTickSlots, ConstantChannelsAreTheModelsConvertedAtRunTime) {
  strider::ServoStage<Fixed, Shared<Fixed>> converted;
  strider::ServoStage<Fixed, HexapodChannels> constant;
  ASSERT_TRUE(converted.configure(strider::kHexapod18));
  ASSERT_TRUE(constant.configure(strider::kHexapod18));
  ASSERT_EQ(converted.joint_count(), constant.joint_count());
  for (uint8_t k = 0; k < 18; ++k) {
    const strider::ServoChannel<Fixed> a = converted.channel(k), b = constant.channel(k);
    EXPECT_TRUE(a.channel == b.channel && a.direction == b.direction && a.zero_rad == b.zero_rad &&
                a.centre_rad == b.centre_rad && a.min_rad == b.min_rad && a.max_rad == b.max_rad &&
                a.us_per_rad == b.us_per_rad && a.min_pulse_us == b.min_pulse_us && a.max_pulse_us == b.max_pulse_us)
        << int(k);
  }
}

// Walking: every tick's joints are the IK of the engine's foot (body pose
// applied) by the leg's own AnyLeg.
TYPED_TEST(WalkerShared, WalkingJointsAreEachLegsIk) {
  using S = TypeParam;
  const RobotModel& m = strider::kHexapod18;
  Walker<S> w;
  ASSERT_TRUE(configure(w, m));
  w.engine().set_command(strider::scalar<S>(40.0), strider::scalar<S>(10.0), strider::scalar<S>(0.2));
  AnyLeg<S> ref[6];
  for (uint8_t i = 0; i < 6; ++i) ASSERT_TRUE(AnyLeg<S>::from_model(m, i, ref[i]));
  int checked = 0;
  for (int tick = 0; tick < 200; ++tick) {
    w.tick(strider::scalar<S>(0.02));
    const strider::Transform<S> body = strider::body_transform(w.engine().body_pose());
    for (uint8_t i = 0; i < 6; ++i) {
      const strider::LegResult<S, false>& r = w.leg(i);
      if (r.status == IkStatus::kUnreachable) continue;
      typename AnyLeg<S>::Joints q;
      Vec3<S> at;
      const IkStatus s = ref[i].ik_body(strider::foot_in_body(body, w.engine().foot(i)), q, at);
      ASSERT_NE(s, IkStatus::kUnreachable);
      EXPECT_EQ(s, r.status) << "tick " << tick << " leg " << int(i);
      for (uint8_t j = 0; j < 3; ++j) EXPECT_NEAR(strider::to_double(q[j]), strider::to_double(r.q[j]), 2e-3);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 200 * 6);
}

// The tick map with a range per slot maps every joint as one with a range
// per joint, trims and both directions included.
template <typename S>
void expect_slots_map_alike() {
  const RobotModel& m = strider::kHexapod18;
  strider::ServoChannel<S> ch[18];
  ASSERT_EQ(strider::make_channel_map(m, ch), 18);
  strider::Settings settings = strider::default_settings();
  for (uint8_t k = 0; k < 18; ++k) settings.trim_decideg[k] = int16_t(int(k * 37 % 101) - 50);
  strider::Pca9685Timing timing;
  strider::ServoTickMap<S, 18, 3> shared;
  strider::ServoTickMap<S, 18, 0> own;
  ASSERT_EQ(shared.configure(ch, 18, settings, timing), strider::ServoTickStatus::kOk);
  ASSERT_EQ(own.configure(ch, 18, settings, timing), strider::ServoTickStatus::kOk);
  EXPECT_LT(sizeof shared, sizeof own);
  for (uint8_t k = 0; k < 18; ++k) {
    EXPECT_EQ(shared.channel(k), own.channel(k));
    for (int a = -200; a <= 200; ++a) {
      const S q = strider::scalar<S>(a * 0.01);
      const strider::ServoCommand x = shared.map(k, uint8_t(k % 3), q), y = own.map(k, q);
      ASSERT_EQ(x.ticks, y.ticks) << int(k) << " " << a;
      ASSERT_EQ(x.status, y.status);
      ASSERT_EQ(x.channel, y.channel);
    }
  }
}
TEST(ServoTickSlots, MapLikeARangePerJointFloat) { expect_slots_map_alike<float>(); }
TEST(ServoTickSlots, MapLikeARangePerJointFixed) { expect_slots_map_alike<Fixed>(); }

TEST(ServoTickSlots, StageRefusesLegsOfOtherGeometries) {
  strider::ServoStage<Fixed, Shared<Fixed>> stage;
  EXPECT_TRUE(stage.configure(strider::kHexapod18));
  EXPECT_TRUE(stage.configure(strider::kSpider12));
  EXPECT_FALSE(stage.configure(strider::kMammal8));  // 2 joints a leg, not 3
  EXPECT_FALSE(stage.configure(strider::kDog12));    // left and right legs differ
}

}  // namespace
