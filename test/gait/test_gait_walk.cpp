// Whole walks of every model in every one of its gaits, at its default
// parameters, in every direction, turning both ways and walking while
// turning, from standing back to standing, in float and Fixed:
// - every foot target is reachable: IK status ok on every tick (a 2-DOF
//   leg's target after its reachable-set projection, whose distance is
//   reported and bounded here);
// - foot paths are continuous: no foot moves more than the step bound of
//   gait_test_util.h in one tick;
// - the static stability margin stays positive for walk, crawl and wave
//   (and the hexapods' tripod and ripple);
// - the walk ends standing on all feet at home.
#include "gait_test_util.h"

namespace gaittest {
namespace {

// How far a 2-DOF leg's projection may move a target [mm]: no farther than
// the target is from home (home is on the reachable set, and both
// projections keep the height: a planar leg drops the sideways offset, a
// sprawling leg slides along its own direction), plus, for a sprawling foot
// in the air, how far its reach grows when the knee lifts it by the step
// height (seed 000 eq 8: rho = a1 + sqrt(a2^2 - z^2)).
double lift_reach_mm(const RobotModel& m) {
  if (m.kind != strider::LegKind::kSprawl) return 0.0;
  const double a1 = m.links.l1_mm, a2 = m.links.l2_mm;
  const double z = m.legs[0].stand_mm.z - m.legs[0].mount_mm.z;
  const double h = strider::gait_params_for(m)->step_height_mm;
  return (a1 + std::sqrt(a2 * a2 - (z + h) * (z + h))) - (a1 + std::sqrt(a2 * a2 - z * z));
}

// Gaits that must keep the CoM inside the support polygon: walk, crawl and
// wave (the issue), and the hexapods' tripod and ripple too (three or more
// feet down, on both sides).
bool static_gait(const GaitTable& g) {
  const std::string n = g.name;
  return n == "walk" || n == "crawl" || n == "wave" || n == "tripod" || n == "ripple";
}

struct SweepResult {
  double least_margin = 1e9, worst_step_ratio = 0.0, worst_clamp = 0.0, worst_shift = 0.0;
  int ticks = 0;
};

template <typename S>
void sweep(const Case& c, SweepResult& res) {
  Rig<S> rig(*c.model, *c.gait);
  const GaitConfig<S>& cfg = rig.config;
  const double lift_reach = lift_reach_mm(*c.model);
  for (const Command& cmd : sweep_commands()) {
    SCOPED_TRACE(c.name() + " command " + std::to_string(cmd.vx) + "," + std::to_string(cmd.vy) + "," +
                 std::to_string(cmd.wz_deg));
    rig.reset();
    GaitEngine<S>& e = rig.engine();
    e.set_command(sc<S>(cmd.vx), sc<S>(cmd.vy), sc<S>(cmd.wz_deg * kPi / 180.0));
    const strider::VelocityPlan<S> plan = e.target_plan();
    const double hz = dbl(plan.step_hz), duty = c.gait->duty;
    double longest = 0.0;
    for (uint8_t i = 0; i < c.model->leg_count; ++i) {
      const double hx = dbl(cfg.home[i].x), hy = dbl(cfg.home[i].y);
      const double rx = dbl(plan.vx_mm_s) - dbl(plan.wz_rad_s) * hy, ry = dbl(plan.vy_mm_s) + dbl(plan.wz_rad_s) * hx;
      longest = std::max(longest, std::hypot(rx, ry) * duty / hz);
    }
    longest += 2.0 * dbl(cfg.shift_budget_mm) + 2.0;
    const double bound = step_bound_mm(cfg, dbl(plan.vx_mm_s), dbl(plan.vy_mm_s), dbl(plan.wz_rad_s),
                                       std::max(hz, dbl(cfg.limits.min_hz)), duty, longest);
    std::vector<Tick> run;
    run.reserve(4000);
    run.push_back(rig.snapshot());
    rig.run(4.0 / hz, run);  // the ramp (one cycle) and three cycles
    e.set_command(S(0), S(0), S(0));
    ASSERT_TRUE(rig.run_until_standing(run, 4.0 / std::min(hz, dbl(cfg.limits.min_hz)) + 2.0));
    for (size_t k = 0; k < run.size(); ++k) {
      const Tick& t = run[k];
      for (uint8_t i = 0; i < c.model->leg_count; ++i) {
        ASSERT_EQ(t.ik[i], IkStatus::kOk) << "leg " << int(i) << " t=" << t.t;
        if (c.model->dof() == 3) {
          ASSERT_EQ(t.status[i], IkStatus::kOk) << "leg " << int(i) << " t=" << t.t;
        }
        ASSERT_TRUE(t.status[i] == IkStatus::kOk || t.status[i] == IkStatus::kClamped);
        const double off = std::hypot(t.body[i].x - dbl(cfg.home[i].x), t.body[i].y - dbl(cfg.home[i].y));
        ASSERT_LE(t.clamp[i], off + (t.contact[i] ? 0.0 : lift_reach) + 0.05) << "leg " << int(i) << " t=" << t.t;
        res.worst_clamp = std::max(res.worst_clamp, t.clamp[i]);
        if (k > 0) {
          const double d = dist(t.body[i], run[k - 1].body[i]);
          res.worst_step_ratio = std::max(res.worst_step_ratio, d / bound);
          ASSERT_LE(d, bound) << "leg " << int(i) << " t=" << t.t;
        }
      }
      if (static_gait(*c.gait)) {
        ASSERT_GT(t.margin, 0.0) << "t=" << t.t;
      }
      res.least_margin = std::min(res.least_margin, t.margin);
      res.worst_shift = std::max(res.worst_shift, std::hypot(t.shift_x, t.shift_y));
      ++res.ticks;
    }
    const Tick& last = run.back();
    for (uint8_t i = 0; i < c.model->leg_count; ++i) {
      EXPECT_TRUE(last.contact[i]);
      EXPECT_LE(std::fabs(last.foot[i].x - dbl(cfg.home[i].x)), dbl(cfg.home_tolerance_mm) + 1e-3);
      EXPECT_LE(std::fabs(last.foot[i].y - dbl(cfg.home[i].y)), dbl(cfg.home_tolerance_mm) + 1e-3);
    }
    EXPECT_EQ(last.shift_x, 0.0);
    EXPECT_EQ(last.shift_y, 0.0);
  }
  // The body shift stays within the reach kept for it.
  if (c.gait->shift_body) {
    EXPECT_LE(res.worst_shift, dbl(cfg.shift_budget_mm) + 1e-6) << c.name();
  }
}

class WalkSweep : public ::testing::TestWithParam<int> {};

template <typename S>
void run_sweep(int index) {
  const Case c = all_cases()[size_t(index)];
  SweepResult r;
  sweep<S>(c, r);
  std::printf("[ measured ] %-16s %-5s least margin %7.2f mm, largest step %.2f of bound, shift %.1f mm, "
              "clamp %.1f mm, %d ticks\n",
              c.name().c_str(), strider::ScalarTraits<S>::name(), r.least_margin, r.worst_step_ratio, r.worst_shift,
              r.worst_clamp, r.ticks);
}

TEST_P(WalkSweep, Float) { run_sweep<float>(GetParam()); }
TEST_P(WalkSweep, Fixed) { run_sweep<Fixed>(GetParam()); }

INSTANTIATE_TEST_SUITE_P(AllModelsAndGaits, WalkSweep, ::testing::Range(0, int(all_cases().size())),
                         [](const ::testing::TestParamInfo<int>& param) {
                           std::string n = all_cases()[size_t(param.param)].name();
                           for (char& ch : n)
                             if (ch == '/') ch = '_';
                           return n;
                         });

// A configuration built before, for a model passed at the address of
// another one (a copy overwritten in place): the walker builds its legs from
// what the model is now, not from what was at that address before.
TEST(WalkerPrebuiltConfig, LegsFollowTheModelNotItsAddress) {
  auto config_of = [](const RobotModel& m) {
    strider::AnyLeg<float> legs[6];
    for (uint8_t i = 0; i < m.leg_count; ++i) strider::AnyLeg<float>::from_model(m, i, legs[i]);
    return strider::make_gait_config(m, legs, *strider::gait_params_for(m), strider::gait_params_for(m)->shape);
  };
  static Walker<float> w;  // large: not on the stack
  RobotModel m = strider::kMammal8;
  ASSERT_TRUE(w.configure(m, strider::kGaitTrot, config_of(m)));
  EXPECT_EQ(w.leg_model(0).kind(), strider::LegKind::kPlanar);
  m = strider::kSpider12;  // four legs too, of another kind
  ASSERT_TRUE(w.configure(m, strider::kGaitWalk, config_of(m)));
  EXPECT_EQ(w.leg_model(0).kind(), strider::kSpider12.kind);
  ASSERT_NE(strider::kSpider12.kind, strider::LegKind::kPlanar);
  // and its feet are where the spider's legs reach
  w.tick(0.02f);
  for (uint8_t i = 0; i < m.leg_count; ++i) EXPECT_EQ(w.leg(i).status, IkStatus::kOk) << int(i);
}

}  // namespace
}  // namespace gaittest
