// The gait engine's behaviour, typed over float and Fixed:
// - each leg swings exactly once per cycle, for its gait's duty factor;
// - feet on the ground reproduce the commanded velocity kinematically;
// - start from standing, stop back to standing on all feet;
// - transitions (velocity and gait changes mid-walk, body pose, stand-up and
//   sit-down) move no foot farther than the step bound in one tick;
// - float and Fixed agree;
// - moves of a given distance or angle (seed 003's 10/20/100/200 cm runs);
// - seed 000's crawl: the body moves along the support diagonal, left/right
//   walking by relabelled legs, and the rotation variant.
#include <Eigen/Dense>

#include "gait/move.h"
#include "gait_test_util.h"

namespace gaittest {
namespace {

using strider::GaitState;

template <typename S>
class GaitEngineTest : public ::testing::Test {};
TYPED_TEST_SUITE(GaitEngineTest, Scalars);

//! A command at `share` of the robot's top speed along (dx, dy), plus yaw.
template <typename S>
Command share_of_top(Rig<S>& rig, double dx, double dy, double share, double wz_deg = 0.0) {
  const GaitConfig<S>& c = rig.config;
  const double duty = rig.gait->duty;
  const S budget = rig.gait->shift_body ? c.shift_budget_mm : S(0);
  const double top =
      dx == 0.0 && dy == 0.0 ? 0.0
                             : dbl(c.limits.max_speed_mm_s(c.home, sc<S>(dx), sc<S>(dy), sc<S>(duty), budget,
                                                           rig.gait->shift_body));
  const double n = std::hypot(dx, dy);
  return Command{n > 0 ? top * share * dx / n : 0.0, n > 0 ? top * share * dy / n : 0.0, wz_deg};
}

template <typename S>
void command(Rig<S>& rig, const Command& c) {
  rig.engine().set_command(sc<S>(c.vx), sc<S>(c.vy), sc<S>(c.wz_deg * kPi / 180.0));
}

// ---- swing once per cycle, duty ------------------------------------------------------

TYPED_TEST(GaitEngineTest, EachLegSwingsOncePerCycleWithItsDuty) {
  using S = TypeParam;
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(c.name());
    Rig<S> rig(*c.model, *c.gait);
    command(rig, share_of_top(rig, 1, 0, 0.6, 5.0));
    std::vector<Tick> run;
    rig.run(3.0 * rig.cycle_s() + 1.0, run);  // past the ramp
    const double cycle = rig.cycle_s();
    run.clear();
    run.push_back(rig.snapshot());
    rig.run(6.0 * cycle, run);
    // Whole cycles between the first and the last wrap of the phase clock.
    std::vector<size_t> wraps;
    for (size_t k = 1; k < run.size(); ++k)
      if (run[k].phase < run[k - 1].phase) wraps.push_back(k);
    ASSERT_GE(wraps.size(), 5u);
    const uint8_t n = c.model->leg_count;
    for (size_t w = 0; w + 1 < wraps.size(); ++w) {
      for (uint8_t i = 0; i < n; ++i) {
        int lifts = 0, down = 0;
        for (size_t k = wraps[w]; k < wraps[w + 1]; ++k) {
          if (run[k - 1].contact[i] && !run[k].contact[i]) ++lifts;
          if (run[k].contact[i]) ++down;
        }
        const double ticks = double(wraps[w + 1] - wraps[w]);
        EXPECT_EQ(lifts, 1) << "leg " << int(i) << " cycle " << w;
        // One tick of quantisation at lift-off and one at touch-down.
        EXPECT_NEAR(down / ticks, c.gait->duty, 2.0 / ticks + 1e-9) << "leg " << int(i) << " cycle " << w;
      }
    }
    // Lift-offs happen at each leg's offset (within one tick of phase).
    for (size_t k = 1; k < run.size(); ++k)
      for (uint8_t i = 0; i < n; ++i)
        if (run[k - 1].contact[i] && !run[k].contact[i]) {
          const double off = rig.engine().table().offset[i];
          double d = run[k].phase / 65536.0 - off;
          d -= std::floor(d);
          EXPECT_LT(d, kDt / cycle + 1e-3) << "leg " << int(i);
        }
  }
}

// ---- stance feet reproduce the command -------------------------------------------------

TYPED_TEST(GaitEngineTest, StanceFeetReproduceTheCommand) {
  using S = TypeParam;
  // Float: the arc step is exact to 1e-7; Fixed: dt = 1311/65536 s and the
  // products' rounding, on steps of up to a few mm.
  const double tol = strider::ScalarTraits<S>::kIsFixed ? 0.02 : 1e-3;  // [mm]
  double worst = 0.0, worst_odo = 0.0;
  for (const Case& c : all_cases()) {
    Rig<S> rig(*c.model, *c.gait);
    for (const Command& dir : {Command{1, 0, 0}, Command{0, 1, 0}, Command{-1, 1, 0}, Command{0, 0, 30},
                               Command{1, 0.5, -20}}) {
      SCOPED_TRACE(c.name() + " dir " + std::to_string(dir.vx) + "," + std::to_string(dir.vy) + "," +
                   std::to_string(dir.wz_deg));
      rig.reset();
      const Command cmd = share_of_top(rig, dir.vx, dir.vy, 0.5, dir.wz_deg);
      command(rig, cmd);
      const strider::VelocityPlan<S> plan = rig.engine().target_plan();
      std::vector<Tick> run;
      rig.run(2.0 * rig.cycle_s() + 0.5, run);
      // Walked as planned (and as commanded unless the robot had to limit it);
      // the engine keeps stride per cycle x rate, so v comes back rounded.
      EXPECT_NEAR(run.back().vx, dbl(plan.vx_mm_s), 1e-4 * std::fabs(dbl(plan.vx_mm_s)) + 1e-3);
      EXPECT_NEAR(run.back().wz, dbl(plan.wz_rad_s), 1e-4 * std::fabs(dbl(plan.wz_rad_s)) + 1e-4);
      if (!plan.limited) {
        EXPECT_NEAR(dbl(plan.vx_mm_s), cmd.vx, 0.01 + std::fabs(cmd.vx) * 1e-4);
        EXPECT_NEAR(dbl(plan.vy_mm_s), cmd.vy, 0.01 + std::fabs(cmd.vy) * 1e-4);
      }
      const double x0 = dbl(rig.engine().odometry_x()), y0 = dbl(rig.engine().odometry_y());
      const double yaw0 = dbl(rig.engine().odometry_yaw());
      const size_t first = run.size();
      rig.run(2.0 * rig.cycle_s(), run);
      for (size_t k = first; k < run.size(); ++k) {
        const Tick& a = run[k - 1];
        const Tick& b = run[k];
        const double t = b.wz * kDt;
        Eigen::Vector2d d(b.vx * kDt, b.vy * kDt);  // the body's arc this tick
        if (std::fabs(t) > 1e-12)
          d = Eigen::Vector2d(std::sin(t) * b.vx - (1 - std::cos(t)) * b.vy,
                              (1 - std::cos(t)) * b.vx + std::sin(t) * b.vy) / b.wz;
        for (uint8_t i = 0; i < c.model->leg_count; ++i) {
          if (!a.contact[i] || !b.contact[i] || a.foot[i].z != b.foot[i].z) continue;
          const Eigen::Vector2d p(a.foot[i].x, a.foot[i].y);
          const Eigen::Vector2d q = Eigen::Rotation2Dd(-t) * (p - d);
          const double e = std::hypot(q.x() - b.foot[i].x, q.y() - b.foot[i].y);
          worst = std::max(worst, e);
          ASSERT_LT(e, tol) << "leg " << int(i) << " t=" << b.t;
        }
      }
      // Odometry: the body moved at the command for the whole time.
      const double secs = double(run.size() - first) * kDt;
      const double yaw = dbl(plan.wz_rad_s) * secs;
      // Fixed: the yaw of a tick (a few hundred raw units) rounds the same
      // way every tick, up to half a unit each.
      const double yaw_rounding = strider::ScalarTraits<S>::kIsFixed ? double(run.size() - first) * 0.5 / 65536.0 : 0.0;
      EXPECT_NEAR(dbl(rig.engine().odometry_yaw()) - yaw0, yaw, 1e-3 + std::fabs(yaw) * 1e-3 + yaw_rounding);
      if (dir.wz_deg == 0.0) {
        const double ex = std::fabs(dbl(rig.engine().odometry_x()) - x0 - dbl(plan.vx_mm_s) * secs);
        const double ey = std::fabs(dbl(rig.engine().odometry_y()) - y0 - dbl(plan.vy_mm_s) * secs);
        worst_odo = std::max({worst_odo, ex, ey});
        EXPECT_LT(ex, 0.05 + std::fabs(dbl(plan.vx_mm_s)) * secs * 1e-3);
        EXPECT_LT(ey, 0.05 + std::fabs(dbl(plan.vy_mm_s)) * secs * 1e-3);
      }
    }
  }
  std::printf("[ measured ] %s: stance foot vs body motion %.2e mm (bound %.0e), odometry %.3f mm\n",
              strider::ScalarTraits<S>::name(), worst, tol, worst_odo);
}

// ---- start from standing, stop to standing ---------------------------------------------

TYPED_TEST(GaitEngineTest, StartsAndStopsStandingOnAllFeet) {
  using S = TypeParam;
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(c.name());
    Rig<S> rig(*c.model, *c.gait);
    std::vector<Tick> run;
    run.push_back(rig.snapshot());
    EXPECT_EQ(run.back().state, "standing");
    command(rig, share_of_top(rig, 1, 0, 0.8));
    rig.tick();
    EXPECT_EQ(rig.snapshot().state, "walking");
    rig.run(3.0 * rig.cycle_s(), run);
    rig.engine().set_command(S(0), S(0), S(0));
    const double cycle = rig.cycle_s();
    const size_t stop_at = run.size();
    ASSERT_TRUE(rig.run_until_standing(run, 10.0 * cycle));
    // A stop takes the ramp down (at least one cycle) and at most two more
    // cycles of steps home.
    const double stop_s = double(run.size() - stop_at) * kDt;
    EXPECT_LE(stop_s, 6.0 * cycle + 1.0);
    const Tick& last = run.back();
    for (uint8_t i = 0; i < c.model->leg_count; ++i) {
      EXPECT_TRUE(last.contact[i]);
      EXPECT_LE(std::fabs(last.foot[i].x - dbl(rig.config.home[i].x)), dbl(rig.config.home_tolerance_mm) + 1e-4);
      EXPECT_LE(std::fabs(last.foot[i].y - dbl(rig.config.home[i].y)), dbl(rig.config.home_tolerance_mm) + 1e-4);
    }
    EXPECT_GT(last.margin, 0.0);
    EXPECT_EQ(last.vx, 0.0);
    // Standing still: ticks change nothing.
    const Tick before = rig.snapshot();
    rig.run(1.0, run);
    for (uint8_t i = 0; i < c.model->leg_count; ++i) EXPECT_EQ(dist(run.back().foot[i], before.foot[i]), 0.0);
  }
}

// A cycle set while standing (`set cycle`, a preset) is the rate the next
// walk starts from. A gait change while standing slows the rate by the
// duties' ratio, meant for a walking robot whose stances keep their travel:
// mammal8's walk (duty 0.85) -> trot (0.5) leaves 0.29 Hz of its 0.5, and a
// trot then set to a 0.9 s cycle started there and ramped for two seconds,
// 37 mm short of a 100 mm walk's odometry (4 mm now). A plain gait change
// keeps its gentler start (sprawl8's trot veers 7 deg without it).
TYPED_TEST(GaitEngineTest, ACycleSetWhileStandingIsTheRateTheWalkStartsFrom) {
  using S = TypeParam;
  Rig<S> rig(strider::kMammal8, *strider::find_gait(strider::kMammal8, "walk"));
  rig.engine().set_gait(*strider::find_gait(strider::kMammal8, "trot"));
  EXPECT_NEAR(dbl(rig.engine().step_hz()), 0.5 * 0.5 / 0.85, 0.01);
  const S hz = S(1) / sc<S>(0.9);
  rig.engine().set_step(rig.engine().config().limits.preferred_stride_mm, hz);
  EXPECT_NEAR(dbl(rig.engine().step_hz()), 1.0 / 0.9, 1e-3);
  command(rig, Command{50, 0, 0});
  std::vector<Tick> run;
  rig.run(0.5, run);
  for (const Tick& t : run) EXPECT_GE(t.hz, 1.0 / 0.9 - 1e-3);  // ramps up from there, not from 0.29
  // Walking, a new cycle waits for the ramp: the rate is not reset.
  const double walking_hz = run.back().hz;
  rig.engine().set_step(rig.engine().config().limits.preferred_stride_mm, S(1) / sc<S>(2.0));
  EXPECT_NEAR(dbl(rig.engine().step_hz()), walking_hz, 1e-6);
}

// ---- transitions --------------------------------------------------------------------------

//! A scenario of changes while walking: velocity steps, gait changes, body
//! pose, stop, sit down, stand up. Returns the run.
template <typename S>
std::vector<Command> scenario_commands(Rig<S>& rig) {
  return {share_of_top(rig, 1, 0, 0.7), share_of_top(rig, 0, 1, 0.5), share_of_top(rig, -1, 0, 0.6),
          Command{0, 0, 25}, share_of_top(rig, 1, 0.3, 0.4, -15)};
}

template <typename S>
std::vector<Tick> transition_scenario(Rig<S>& rig, double& bound, std::vector<Command> cmds = {}) {
  const RobotModel& m = *rig.model;
  const strider::GaitList gaits = strider::gaits_for(m);
  const GaitConfig<S>& cfg = rig.config;
  if (cmds.empty()) cmds = scenario_commands(rig);
  // The step bound over every command and gait the scenario walks.
  bound = 0.0;
  for (uint8_t g = 0; g < gaits.count; ++g) {
    const double duty = gaits.items[g]->duty;
    const S budget = gaits.items[g]->shift_body ? cfg.shift_budget_mm : S(0);
    for (const Command& c : cmds) {
      const strider::VelocityPlan<S> p = cfg.limits.plan(cfg.home, sc<S>(c.vx), sc<S>(c.vy), sc<S>(c.wz_deg * kPi / 180),
                                                         sc<S>(duty), budget, gaits.items[g]->shift_body);
      double longest = 0.0;
      for (uint8_t i = 0; i < m.leg_count; ++i) {
        const double rx = dbl(p.vx_mm_s) - dbl(p.wz_rad_s) * dbl(cfg.home[i].y);
        const double ry = dbl(p.vy_mm_s) + dbl(p.wz_rad_s) * dbl(cfg.home[i].x);
        longest = std::max(longest, std::hypot(rx, ry) * duty / dbl(p.step_hz));
      }
      // A gait change can stretch one step by up to a stride of the old gait.
      longest = 2.0 * longest + 2.0 * dbl(cfg.shift_budget_mm) + 2.0;
      bound = std::max(bound, step_bound_mm(cfg, dbl(p.vx_mm_s), dbl(p.vy_mm_s), dbl(p.wz_rad_s),
                                            std::max(dbl(p.step_hz), dbl(cfg.limits.min_hz)), duty, longest));
    }
  }
  bound += 1.5 * dbl(cfg.sit_drop_mm) / dbl(cfg.transition_s) * kDt;  // smoothstep's steepest slope
  std::vector<Tick> run;
  rig.reset(true);  // sitting
  run.push_back(rig.snapshot());
  EXPECT_EQ(run.back().state, "sitting");
  rig.engine().stand_up();
  rig.run(dbl(cfg.transition_s) + 0.2, run);
  EXPECT_EQ(run.back().state, "standing");
  for (size_t k = 0; k < cmds.size(); ++k) {
    command(rig, cmds[k]);
    if (k == 2) {  // body lower by 10 mm and rolled 4 deg while walking
      strider::BodyOffsets<S> o = strider::BodyOffsets<S>::zero();
      o.translation_mm.z = sc<S>(-10);
      o.roll_rad = sc<S>(4 * kPi / 180);
      rig.engine().set_body_offsets(o);
    }
    rig.run(3.0, run);  // fixed times, so that float and Fixed runs line up tick by tick
    rig.engine().set_gait(*gaits.items[(k + 1) % gaits.count]);  // a new gait mid-walk
    rig.run(1.3, run);
  }
  rig.engine().set_body_offsets(strider::BodyOffsets<S>::zero());
  rig.engine().sit_down();  // while walking: stops first
  for (int k = 0; k < 5000 && rig.engine().state() != GaitState::kSitting; ++k) {
    Tick t = rig.tick();
    t.t = run.back().t + kDt;
    run.push_back(t);
  }
  EXPECT_EQ(run.back().state, "sitting");
  return run;
}

TYPED_TEST(GaitEngineTest, TransitionsAreBounded) {
  using S = TypeParam;
  for (const RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    Rig<S> rig(*m, *strider::gaits_for(*m).items[0]);
    double bound = 0.0;
    const std::vector<Tick> run = transition_scenario(rig, bound);
    double worst = 0.0;
    for (size_t k = 1; k < run.size(); ++k)
      for (uint8_t i = 0; i < m->leg_count; ++i) {
        const double d = dist(run[k].body[i], run[k - 1].body[i]);
        worst = std::max(worst, d);
        ASSERT_LE(d, bound) << "leg " << int(i) << " t=" << run[k].t << " " << run[k].state;
        if (m->dof() == 3) {
          ASSERT_EQ(run[k].ik[i], IkStatus::kOk) << "leg " << int(i) << " t=" << run[k].t;
        } else {
          ASSERT_NE(run[k].ik[i], IkStatus::kUnreachable) << "leg " << int(i) << " t=" << run[k].t;
        }
      }
    std::printf("[ measured ] %-9s %s: transitions, largest foot step %.2f mm per tick (bound %.2f)\n", m->name,
                strider::ScalarTraits<S>::name(), worst, bound);
  }
}

// Each body offset moves toward its goal by at most its rate per tick (the
// three lengths at pose_speed_mm_s, the three angles at pose_rate_rad_s),
// each exactly as move_toward() moves it, and the pose is at its goal only
// after a tick that found every offset there.
TYPED_TEST(GaitEngineTest, BodyOffsetsMoveAtTheirRates) {
  using S = TypeParam;
  Rig<S> rig(strider::kHexapod18, strider::kGaitTripod);
  strider::BodyOffsets<S> goal = strider::BodyOffsets<S>::zero();
  goal.translation_mm = strider::Vec3<S>(sc<S>(6), sc<S>(-4), sc<S>(-12));
  goal.roll_rad = sc<S>(0.08);
  goal.pitch_rad = sc<S>(-0.05);
  goal.yaw_rad = sc<S>(0.11);
  rig.engine().set_body_offsets(goal);
  const S dt = sc<S>(kDt);
  const S dp = rig.config.pose_speed_mm_s * dt, da = rig.config.pose_rate_rad_s * dt;
  strider::BodyOffsets<S> want = strider::BodyOffsets<S>::zero();
  S* w[6] = {&want.translation_mm.x, &want.translation_mm.y, &want.translation_mm.z,
             &want.roll_rad, &want.pitch_rad, &want.yaw_rad};
  const S g[6] = {goal.translation_mm.x, goal.translation_mm.y, goal.translation_mm.z,
                  goal.roll_rad, goal.pitch_rad, goal.yaw_rad};
  bool reached = false;
  for (int k = 0; k < 500 && !reached; ++k) {
    bool there = true;
    for (int j = 0; j < 6; ++j) there &= strider::move_toward(*w[j], g[j], j < 3 ? dp : da);
    rig.tick();
    const strider::BodyPose<S> bp = rig.engine().body_pose();
    ASSERT_EQ(bp.translation_mm.x, want.translation_mm.x) << k;
    ASSERT_EQ(bp.translation_mm.y, want.translation_mm.y) << k;
    ASSERT_EQ(bp.translation_mm.z, want.translation_mm.z) << k;
    ASSERT_EQ(bp.roll_rad, want.roll_rad) << k;
    ASSERT_EQ(bp.pitch_rad, want.pitch_rad) << k;
    ASSERT_EQ(bp.yaw_rad, want.yaw_rad) << k;
    reached = there;
  }
  EXPECT_TRUE(reached);
  EXPECT_EQ(rig.engine().body_pose().yaw_rad, goal.yaw_rad);
  EXPECT_EQ(rig.engine().body_pose().translation_mm.z, goal.translation_mm.z);
}

TYPED_TEST(GaitEngineTest, StandUpAndSitDown) {
  using S = TypeParam;
  Rig<S> rig(strider::kHexapod18, strider::kGaitTripod);
  rig.reset(true);
  const double drop = dbl(rig.config.sit_drop_mm);
  EXPECT_NEAR(dbl(rig.engine().body_pose().translation_mm.z), -drop, 1e-3);
  rig.engine().set_command(sc<S>(50), S(0), S(0));  // waits while sitting
  std::vector<Tick> run;
  rig.run(0.5, run);
  EXPECT_EQ(rig.engine().state(), GaitState::kSitting);
  rig.engine().stand_up();
  double last = -drop;
  for (int k = 0; k < 200 && rig.engine().state() != GaitState::kStanding; ++k) {
    rig.tick();
    const double z = dbl(rig.engine().body_pose().translation_mm.z);
    EXPECT_GE(z, last - 1e-6);  // rises monotonically
    last = z;
  }
  EXPECT_NEAR(last, 0.0, 1e-6);
  // Standing with a command pending: it walks off.
  rig.tick();
  EXPECT_EQ(rig.engine().state(), GaitState::kWalking);
}

// ---- float and Fixed agree ----------------------------------------------------------------

//! The float configuration in Fixed, value by value: both engines then run
//! on the same numbers (the limits' own float/Fixed agreement is checked in
//! VelocityLimitsAgree).
GaitConfig<Fixed> to_fixed(const GaitConfig<float>& f) {
  GaitConfig<Fixed> x;
  auto X = [](float v) { return Fixed(double(v)); };
  x.leg_count = f.leg_count;
  for (int i = 0; i < strider::kMaxLegs; ++i) {
    x.home[i] = Vec3<Fixed>::from(f.home[i]);
    x.edge_mm[i] = X(f.edge_mm[i]);
    for (int k = 0; k < strider::VelocityLimits<float>::kDirections; ++k)
      x.limits.set_stride_mm(uint8_t(i), uint8_t(k), X(f.limits.stride_mm(uint8_t(i), uint8_t(k))));
  }
  x.shape = f.shape;
  x.step_height_mm = X(f.step_height_mm);
  x.stance_depth_mm = X(f.stance_depth_mm);
  x.foot_radius_mm = X(f.foot_radius_mm);
  x.com_x_mm = X(f.com_x_mm);
  x.com_y_mm = X(f.com_y_mm);
  x.margin_mm = X(f.margin_mm);
  x.shift_budget_mm = X(f.shift_budget_mm);
  x.sit_drop_mm = X(f.sit_drop_mm);
  x.transition_s = X(f.transition_s);
  x.accel_mm_s2 = X(f.accel_mm_s2);
  x.yaw_accel_rad_s2 = X(f.yaw_accel_rad_s2);
  x.shift_speed_mm_s = X(f.shift_speed_mm_s);
  x.target_speed_mm_s = X(f.target_speed_mm_s);
  x.pose_speed_mm_s = X(f.pose_speed_mm_s);
  x.pose_rate_rad_s = X(f.pose_rate_rad_s);
  x.home_tolerance_mm = X(f.home_tolerance_mm);
  x.shift_x_only = f.shift_x_only;
  x.min_support = f.min_support;
  double reach = 0.0;
  for (int i = 0; i < f.leg_count; ++i) reach = std::max({reach, std::fabs(double(f.home[i].x)), std::fabs(double(f.home[i].y))});
  x.unit_shift = strider::units::unit_shift(Fixed(2.0 * reach));
  x.limits.leg_count = f.limits.leg_count;
  x.limits.sideways = f.limits.sideways;
  x.limits.min_hz = X(f.limits.min_hz);
  x.limits.preferred_stride_mm = X(f.limits.preferred_stride_mm);
  x.limits.lift_ms = X(f.limits.lift_ms);
  x.limits.swing_ms_per_mm = X(f.limits.swing_ms_per_mm);
  x.limits.stance_ms_per_mm = X(f.limits.stance_ms_per_mm);
  return x;
}

TEST(GaitEngineScalars, FloatAndFixedAgree) {
  // Named bounds for the same configuration and command, walking every gait
  // of every model from standing for five cycles and back to standing: in
  // Fixed dt = 0.02 s is 1311 / 65536 s (2e-4 longer), so its phase runs
  // ahead of float's by a fraction of a tick over the run; a lift-off or
  // touch-down may fall one tick apart (kContactShare of ticks agree) and a
  // foot stays up to one tick of travel apart. Feet that agree within
  // kFootMm (most) have joints within kJointDeg (0.5 mm on the shortest
  // link, 55 mm, is 0.5 deg; Fixed IK error on top).
  const double kFootMm = 0.5, kJointDeg = 1.0, kContactShare = 0.99;
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(c.name());
    Rig<float> rf(*c.model, *c.gait);
    Rig<Fixed> rx(*c.model, *c.gait);
    rx.config = to_fixed(rf.config);
    rx.reset();
    const Command cmd = share_of_top(rf, 1, 0.4, 0.8, 10.0);
    command(rf, cmd);
    command(rx, cmd);
    std::vector<Tick> a, b;
    const double cycle = 1.0 / double(rf.engine().target_plan().step_hz);
    rf.run(5.0 * cycle, a);
    rx.run(5.0 * cycle, b);
    rf.engine().set_command(0.0f, 0.0f, 0.0f);
    rx.engine().set_command(Fixed(), Fixed(), Fixed());
    rf.run(6.0 * cycle + 1.0, a);
    rx.run(6.0 * cycle + 1.0, b);
    EXPECT_EQ(a.back().state, "standing");
    EXPECT_EQ(b.back().state, "standing");
    double tick_travel = 0.0;  // the most a foot moves in a tick
    for (size_t k = 1; k < a.size(); ++k)
      for (uint8_t i = 0; i < c.model->leg_count; ++i)
        tick_travel = std::max(tick_travel, dist(a[k].body[i], a[k - 1].body[i]));
    size_t same = 0, close = 0, feet = 0;
    double foot = 0.0, joint = 0.0;
    for (size_t k = 0; k < a.size(); ++k) {
      if (a[k].contact != b[k].contact) continue;
      ++same;
      for (uint8_t i = 0; i < c.model->leg_count; ++i) {
        const double d = dist(a[k].body[i], b[k].body[i]);
        foot = std::max(foot, d);
        ++feet;
        if (d > kFootMm) continue;
        ++close;
        for (uint8_t j = 0; j < c.model->dof(); ++j)
          joint = std::max(joint, std::fabs(a[k].q[i][j] - b[k].q[i][j]) * 180.0 / kPi);
      }
    }
    std::printf("[ measured ] %-16s float vs Fixed: same contacts %.4f of ticks, feet %.3f mm (one tick %.2f), "
                "%.3f of feet within %.1f mm, their joints %.3f deg\n",
                c.name().c_str(), double(same) / double(a.size()), foot, tick_travel, double(close) / double(feet),
                kFootMm, joint);
    EXPECT_GE(double(same) / double(a.size()), kContactShare);
    EXPECT_LE(foot, tick_travel + kFootMm);
    // 0.87: dog12's trot moves a foot 23 mm a tick, so a phase a fraction
    // of a tick apart puts more of its feet past kFootMm (0.8999 measured);
    // mammal8's trot and pace turn faster since a planar leg's turn limit
    // counts only the stride its feet make (velocity_limits.h), their feet
    // 5.6-5.8 mm a tick (0.881-0.882 measured).
    EXPECT_GE(double(close) / double(feet), 0.87);
    EXPECT_LE(joint, kJointDeg);
  }
}

TEST(GaitEngineScalars, VelocityLimitsAgree) {
  // The configuration computed in Fixed (binary searches with Fixed IK)
  // against float: strides within 1 mm or 1 %, servo figures within 1 %.
  // Both searched (a Rig takes the stored table, the same for both).
  for (const RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    const strider::GaitParams& p = *strider::gait_params_for(*m);
    strider::AnyLeg<float> lf[strider::kMaxLegs];
    strider::AnyLeg<Fixed> lx[strider::kMaxLegs];
    for (uint8_t i = 0; i < m->leg_count; ++i) {
      strider::AnyLeg<float>::from_model(*m, i, lf[i]);
      strider::AnyLeg<Fixed>::from_model(*m, i, lx[i]);
    }
    const auto cf = strider::make_gait_config(*m, lf, p, p.shape, strider::LimitsSource::kSearch);
    const auto cx = strider::make_gait_config(*m, lx, p, p.shape, strider::LimitsSource::kSearch);
    const auto& a = cf.limits;
    const auto& b = cx.limits;
    double worst = 0.0;
    for (uint8_t i = 0; i < m->leg_count; ++i)
      for (int k = 0; k < strider::VelocityLimits<float>::kDirections; ++k) {
        const double d = std::fabs(double(a.stride_mm(i, uint8_t(k))) - dbl(b.stride_mm(i, uint8_t(k))));
        worst = std::max(worst, d);
        EXPECT_LE(d, std::max(1.0, 0.01 * double(a.stride_mm(i, uint8_t(k)))));
      }
    EXPECT_NEAR(dbl(b.lift_ms), double(a.lift_ms), 0.01 * double(a.lift_ms));
    EXPECT_NEAR(dbl(b.swing_ms_per_mm), double(a.swing_ms_per_mm), 0.01 * double(a.swing_ms_per_mm) + 1e-3);
    EXPECT_NEAR(dbl(b.stance_ms_per_mm), double(a.stance_ms_per_mm), 0.01 * double(a.stance_ms_per_mm) + 1e-3);
    std::printf("[ measured ] %-9s limits float vs Fixed: strides within %.3f mm\n", m->name, worst);
  }
}

// ---- moves (seed 003 section 5) -----------------------------------------------------------

TYPED_TEST(GaitEngineTest, MovesOfSeed003Distances) {
  using S = TypeParam;
  // Seed 003 table 5 walks 10, 20, 100 and 200 cm in walk, trot and pace.
  // Named bound: stopping from the ramp lands within 1 % or 2 mm.
  for (const char* gait : {"walk", "trot", "pace"}) {
    Rig<S> rig(strider::kMammal8, *strider::find_gait(strider::kMammal8, gait));
    for (double d : {100.0, 200.0, 1000.0, 2000.0}) {
      rig.reset();
      strider::Move<S> move;
      move.start_distance(rig.engine(), sc<S>(d), S(1), S(0), sc<S>(500));
      int k = 0;
      for (; k < 200000; ++k) {
        rig.engine().tick(sc<S>(kDt));  // the engine alone: no IK needed
        if (!move.update(rig.engine())) break;
      }
      const double done = dbl(move.done(rig.engine()));
      std::printf("[ measured ] mammal8 %-5s %s %5.0f mm: %8.2f mm in %6.1f s\n", gait,
                  strider::ScalarTraits<S>::name(), d, done, k * kDt);
      EXPECT_NEAR(done, d, std::max(2.0, 0.01 * d)) << gait;
      EXPECT_EQ(rig.engine().state(), GaitState::kStanding);
    }
  }
}

TYPED_TEST(GaitEngineTest, TurnsOfAGivenAngle) {
  using S = TypeParam;
  struct T {
    const RobotModel* m;
    const GaitTable* g;
    double deg;
  };
  for (const T& t : {T{&strider::kSprawl8, &strider::kGaitCrawl, 360.0}, T{&strider::kHexapod18, &strider::kGaitTripod, -90.0},
                     T{&strider::kSpider12, &strider::kGaitWalk, 45.0}}) {
    GaitEngine<S> e;
    strider::AnyLeg<S> legs[6];
    for (uint8_t i = 0; i < t.m->leg_count; ++i) strider::AnyLeg<S>::from_model(*t.m, i, legs[i]);
    const strider::GaitParams& p = *strider::gait_params_for(*t.m);
    e.configure(strider::make_gait_config(*t.m, legs, p, p.shape), *t.g);
    strider::Move<S> move;
    move.start_turn(e, sc<S>(t.deg * kPi / 180), sc<S>(10.0));
    int k = 0;
    for (; k < 100000; ++k) {
      e.tick(sc<S>(kDt));
      if (!move.update(e)) break;
    }
    const double turned = dbl(e.odometry_yaw()) * 180 / kPi;
    std::printf("[ measured ] %-9s %-6s %s turn %6.1f deg: %7.2f deg in %5.1f s\n", t.m->name, t.g->name,
                strider::ScalarTraits<S>::name(), t.deg, turned, k * kDt);
    EXPECT_NEAR(turned, t.deg, 0.5);
    EXPECT_EQ(e.state(), GaitState::kStanding);
  }
}

// ---- seed 000's crawl ------------------------------------------------------------------------

TYPED_TEST(GaitEngineTest, CrawlCarriesTheBodyAlongTheSupportDiagonal) {
  using S = TypeParam;
  Rig<S> rig(strider::kSprawl8, strider::kGaitCrawl);
  command(rig, share_of_top(rig, 1, 0, 1.0));
  std::vector<Tick> run;
  rig.run(4.0 * rig.cycle_s(), run);
  // While legs 0 and 2 (front left, rear right) are up, the body stands on
  // the rear-left/front-right diagonal and moves forward-right along it: its
  // shift to the side decreases; with the other pair up, forward-left.
  double right = 0, left = 0;
  int n_right = 0, n_left = 0;
  for (size_t k = run.size() / 2; k < run.size(); ++k) {
    const Tick& a = run[k - 1];
    const Tick& b = run[k];
    const double dy = b.shift_y - a.shift_y;
    if (!a.contact[0] && !b.contact[0] && !a.contact[2] && !b.contact[2]) {
      right += dy;
      ++n_right;
    }
    if (!a.contact[1] && !b.contact[1] && !a.contact[3] && !b.contact[3]) {
      left += dy;
      ++n_left;
    }
    // The CoM stays on the support diagonal within the pads (margin >= 4 mm).
    EXPECT_GE(b.margin, dbl(rig.config.margin_mm) - 0.05);
  }
  ASSERT_GT(n_right, 10);
  ASSERT_GT(n_left, 10);
  EXPECT_LT(right, -1.0);
  EXPECT_GT(left, 1.0);
}

TYPED_TEST(GaitEngineTest, CrawlLeftAndRightByRelabelledLegs) {
  using S = TypeParam;
  Rig<S> rig(strider::kSprawl8, strider::kGaitCrawl);
  auto first_pair = [&](double vx, double vy) {
    rig.reset();
    rig.engine().set_command(sc<S>(vx), sc<S>(vy), S(0));
    for (int k = 0; k < 500; ++k) {
      const Tick t = rig.tick();
      for (uint8_t i = 0; i < 4; ++i)
        if (!t.contact[i]) return int(i % 2);  // 0: legs {0, 2}; 1: legs {1, 3}
    }
    return -1;
  };
  // Seed 000: "to move right ... limb 4 will be 1": the roles turn with the
  // direction, so sideways the other diagonal pair leads.
  EXPECT_EQ(first_pair(60, 0), 0);
  EXPECT_EQ(first_pair(-60, 0), 0);
  EXPECT_EQ(first_pair(0, -60), 1);
  EXPECT_EQ(first_pair(0, 60), 1);
  EXPECT_EQ(rig.engine().table().offset[1], 0.0f);
}

TYPED_TEST(GaitEngineTest, CrawlRotationVariant) {
  using S = TypeParam;
  // Seed 000 section 3.3: for rotation all legs move one way in step C and
  // the other way in step E. Here: turning in place counter-clockwise, a leg
  // on the ground turns clockwise about the body centre and a leg in the air
  // counter-clockwise, so each leg reverses between C and E and the two
  // pairs always move opposite ways.
  Rig<S> rig(strider::kSprawl8, strider::kGaitCrawl);
  rig.engine().set_command(S(0), S(0), sc<S>(0.5));
  std::vector<Tick> run;
  rig.run(4.0 * rig.cycle_s(), run);
  int checked = 0;
  for (size_t k = run.size() / 2; k < run.size(); ++k)
    for (uint8_t i = 0; i < 4; ++i) {
      const Tick& a = run[k - 1];
      const Tick& b = run[k];
      if (a.contact[i] != b.contact[i]) continue;
      const double turn = std::atan2(b.foot[i].y, b.foot[i].x) - std::atan2(a.foot[i].y, a.foot[i].x);
      if (std::fabs(turn) < 1e-6) continue;
      EXPECT_EQ(turn > 0, !b.contact[i]) << "leg " << int(i) << " t=" << b.t;
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace gaittest
