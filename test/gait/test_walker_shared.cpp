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
