// gait_tune: tunes a robot's gait (step length, step height, cycle time) for
// forward speed under stability constraints with Strider's own PSO
// (kinematics/pso.h), every candidate scored by a rollout in strider-sim's
// Bullet world (docs/results.md, "Gait tuning by PSO").
//
// A rollout is library mode, the firmware's chain compiled for the host:
// protocol bytes -> strider::RobotApp (controller, walker, servo stage) ->
// PCA9685 ticks -> pulse widths -> the world's servo motors. The one change is
// the walker's GaitParams: RobotApp takes them from the constexpr table
// (gait_params.h), so after begin() the walker is configured again with the
// candidate's step length, height and cycle (the robot is still sitting then,
// as at power-up).
//
// Score: forward speed [mm/s] over the tuning window of a `walk 500` (the
// gait engine caps the speed at what the candidate allows). A candidate is
// feasible when the robot does not fall, tilts at most 10 degrees, drifts
// sideways at most 10 % of the distance and turns at most 1 deg/s, each
// checked at every checkpoint of its rollout: half the window and the whole
// window (a gait that turns slowly drifts more the longer it walks, so a
// single short window passes gaits that fail on a longer walk). Drift and
// turning are tuned with a 30 % margin; an infeasible candidate costs 1000 +
// its violation.
//
// usage: gait_tune [--robot R] [--gait G] [--swarm N] [--iterations N]
//                  [--walk-s S] [--seed N] [--vx MM_S]
// Output: one JSON object on stdout: "default" and "tuned" over the tuning
// window (S, default 20 s), and "windows": both over S / 2, S and a walk
// twice as long as the window (2 S, not seen by the tuning).
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "control/robot_app.h"
#include "kinematics/pso.h"
#include "robots/all_robots.h"
#include "world.h"

namespace {

using strider_sim::ChannelPulse;
using strider_sim::kMaxChannels;
using strider_sim::World;
using strider_sim::WorldConfig;

// PCA9685 boards as RobotApp's ServoOutput sees them (as in tools/sim's
// library driver): 12-bit off counts and the prescale.
struct Boards {
  uint16_t ticks[kMaxChannels] = {};
  bool on[kMaxChannels] = {};
  uint8_t prescale = 121;
  void write_ticks(uint8_t ch, uint16_t off_ticks) {
    if (ch >= kMaxChannels) return;
    ticks[ch] = off_ticks;
    on[ch] = true;
  }
  void set_prescale(uint8_t p) { prescale = p; }
  void relax(uint8_t ch) {
    if (ch < kMaxChannels) on[ch] = false;
  }
  void flush() {}
};

struct Replies {
  int err = 0;
  void send_line(uint8_t, const char* line) { err += std::strncmp(line, "err", 3) == 0; }
};

using Store = strider::ArrayByteStore<4096>;
using App = strider::RobotApp<float, Boards, Store>;

struct Candidate {
  float step_length_mm, step_height_mm, cycle_s;
};

// One checkpoint of a rollout: the walk from the window's start to there.
struct Rollout {
  bool ok = false;
  std::string error;
  double walk_s = 0;      // measured time
  double speed_mm_s = 0;  // forward, body frame at the window's start
  double lateral_pct = 0;
  double heading_deg = 0;
  double max_tilt_deg = 0;
  bool fell = false;
};

struct Options {
  double walk_at_s = 3.0;  // soft start and stand-up are over by then (sprawl8: 2.3 s)
  double settle_s = 1.5;   // acceleration, not measured
  double walk_s = 20.0;    // tuning window
  double max_tilt_deg = 10.0;
  double max_lateral_pct = 10.0;
  double max_heading_deg_s = 1.0;  // turning while asked to walk straight [deg/s]
  std::string walk = "walk 500\n";  // the command walked
  std::string gait;                  // gait to switch to ("" = the model's default)
};

std::vector<double> sitting_joints(const strider::RobotModel& model) {
  strider::WalkerMotion<float> motion;
  std::vector<double> q;
  if (!motion.configure(model)) return q;
  for (int i = 0; i < model.leg_count; ++i)
    for (int j = 0; j < model.dof(); ++j) q.push_back(double(motion.walker().leg(uint8_t(i)).q[uint8_t(j)]));
  return q;
}

// Body displacement from `start` to `end` as a checkpoint over `walk_s`.
void measure(const strider_sim::BodyState& start, const strider_sim::BodyState& end, double walk_s, Rollout& r) {
  const double yaw = start.yaw_deg * M_PI / 180.0;
  const double dx = end.pos_mm.x - start.pos_mm.x, dy = end.pos_mm.y - start.pos_mm.y;
  const double fwd = dx * std::cos(yaw) + dy * std::sin(yaw);
  const double lat = -dx * std::sin(yaw) + dy * std::cos(yaw);
  double dyaw = end.yaw_deg - start.yaw_deg;
  while (dyaw > 180) dyaw -= 360;
  while (dyaw < -180) dyaw += 360;
  r.walk_s = walk_s;
  r.speed_mm_s = fwd / walk_s;
  r.lateral_pct = std::fabs(fwd) > 1e-6 ? 100.0 * std::fabs(lat) / std::fabs(fwd) : 0.0;
  r.heading_deg = dyaw;
}

double violation(const Rollout& r, const Options& o);

// One rollout, measured at each of `checkpoints_s` (ascending, seconds of
// walking after the settling time); the rollout ends at the last, or at the
// first checkpoint that violates `stop_if_violated` (when given: the tuning
// need not walk an infeasible candidate to the end), and returns the
// checkpoints measured.
std::vector<Rollout> rollout(const strider::RobotModel& model, const strider::GaitParams& params, const Options& o,
                             const std::vector<double>& checkpoints_s, const Options* stop_if_violated = nullptr) {
  std::vector<Rollout> out(checkpoints_s.size());
  auto fail = [&](const char* why) {
    for (Rollout& r : out) r.error = why;
    return out;
  };
  WorldConfig wc;
  wc.initial_joints_rad = sitting_joints(model);
  World world(model, wc, {});
  Boards boards;
  Store store;
  store.erase();
  App app(model, boards, store);
  Replies link;
  if (!app.begin(0, link)) return fail("robot did not start");
  if (!app.set_gait_params(params)) return fail("walker refused the parameters");
  struct Send {
    double at_s;
    const char* text;
  };
  // `gait NAME` switches the gait table and keeps the engine's (candidate's)
  // configuration (WalkerMotion::set_gait).
  const std::string gait_line = o.gait.empty() ? std::string("stop\n") : "gait " + o.gait + "\n";
  const Send sends[] = {{0.4, gait_line.c_str()}, {0.5, "deadman 0\n"}, {0.6, "avoid off\n"},
                        {o.walk_at_s, o.walk.c_str()}};
  size_t next_send = 0;
  const double dt = wc.step_s;
  const double t_start = o.walk_at_s + o.settle_s;
  const long steps = std::lround((t_start + checkpoints_s.back()) / dt);
  size_t next_check = 0;
  uint64_t next_tick_us = strider::kTickPeriodUs;
  ChannelPulse pulses[kMaxChannels];
  strider_sim::BodyState start{};
  bool started = false, fell = false;
  double max_tilt = 0;
  for (long k = 0; k < steps; ++k) {
    const double t = double(k) * dt;
    const uint64_t t_us = uint64_t(std::llround(t * 1e6));
    while (next_send < sizeof sends / sizeof sends[0] && sends[next_send].at_s <= t + 1e-12) {
      for (const char* c = sends[next_send].text; *c != '\0'; ++c) app.on_byte(1, uint8_t(*c), uint32_t(t_us), link);
      ++next_send;
    }
    while (next_tick_us <= t_us) {
      app.tick(uint32_t(next_tick_us), link);
      next_tick_us += strider::kTickPeriodUs;
    }
    const double tick_us = (double(boards.prescale) + 1.0) * 1e6 / wc.osc_hz;
    for (int ch = 0; ch < kMaxChannels; ++ch) {
      pulses[ch].on = boards.on[ch];
      pulses[ch].pulse_us = double(boards.ticks[ch]) * tick_us;
    }
    world.set_pulses(pulses);
    world.step();
    const double t_after = double(k + 1) * dt;
    if (t_after < o.walk_at_s) continue;
    const strider_sim::BodyState b = world.body();
    max_tilt = std::max(max_tilt, b.tilt_deg);
    fell = fell || world.body_on_ground();
    if (!started && t_after >= t_start - 1e-9) {
      start = b;
      started = true;
    }
    while (started && next_check < out.size() && t_after >= t_start + checkpoints_s[next_check] - 1e-9) {
      Rollout& r = out[next_check++];
      measure(start, b, checkpoints_s[next_check - 1], r);
      r.max_tilt_deg = max_tilt;
      r.fell = fell;
      r.ok = link.err == 0;
      if (!r.ok) r.error = "the robot answered err";
      if (stop_if_violated != nullptr && violation(r, *stop_if_violated) > 0) {
        out.resize(next_check);
        return out;
      }
    }
  }
  return out;
}

double violation(const Rollout& r, const Options& o) {
  if (!r.ok) return 1e3;
  double v = r.fell ? 100.0 : 0.0;
  v += std::max(0.0, r.max_tilt_deg - o.max_tilt_deg);
  v += std::max(0.0, r.lateral_pct - o.max_lateral_pct);
  v += std::max(0.0, std::fabs(r.heading_deg) / r.walk_s - o.max_heading_deg_s);
  return v;
}

double violation(const std::vector<Rollout>& rs, const Options& o) {
  double v = 0;
  for (const Rollout& r : rs) v += violation(r, o);
  return v;
}

strider::GaitParams with(const strider::GaitParams& base, const Candidate& c) {
  strider::GaitParams p = base;
  p.step_length_mm = c.step_length_mm;
  p.step_height_mm = c.step_height_mm;
  p.cycle_s = c.cycle_s;
  return p;
}

void print_rollout(const char* name, const Candidate& c, const Rollout& r, const Options& o, bool comma) {
  std::printf("\"%s\":{\"walk_s\":%.2f,\"step_length_mm\":%.2f,\"step_height_mm\":%.2f,\"cycle_s\":%.3f,\"speed_mm_s\":%.2f,"
              "\"max_tilt_deg\":%.2f,\"lateral_pct\":%.2f,\"heading_deg\":%.2f,\"fell\":%s,\"feasible\":%s%s%s%s}%s",
              name, r.walk_s, double(c.step_length_mm), double(c.step_height_mm), double(c.cycle_s), r.speed_mm_s,
              r.max_tilt_deg, r.lateral_pct, r.heading_deg, r.fell ? "true" : "false",
              violation(r, o) == 0.0 ? "true" : "false", r.error.empty() ? "" : ",\"error\":\"",
              r.error.c_str(), r.error.empty() ? "" : "\"", comma ? "," : "");
}

int usage() {
  std::fprintf(stderr,
               "usage: gait_tune [--robot R] [--gait G] [--swarm N] [--iterations N] [--walk-s S] [--seed N]"
               " [--vx MM_S]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string robot = "sprawl8";
  int swarm_size = 8, iterations = 8;
  uint32_t seed = 1;
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage();
    const char* v = argv[++i];
    if (a == "--robot") robot = v;
    else if (a == "--swarm") swarm_size = std::atoi(v);
    else if (a == "--iterations") iterations = std::atoi(v);
    else if (a == "--walk-s") o.walk_s = std::atof(v);
    else if (a == "--seed") seed = uint32_t(std::atoi(v));
    else if (a == "--vx") o.walk = std::string("walk ") + v + "\n";
    else if (a == "--gait") o.gait = v;
    else return usage();
  }
  if (swarm_size < 1 || swarm_size > 20 || iterations < 1 || !(o.walk_s > 0)) return usage();
  const strider::RobotModel* model = strider::find_robot(robot.c_str());
  const strider::GaitParams* base = model != nullptr ? strider::gait_params_for(*model) : nullptr;
  if (base == nullptr) {
    std::fprintf(stderr, "gait_tune: unknown robot %s\n", robot.c_str());
    return 2;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  // Bounds around the defaults: half to 2.5 times the stride, half to twice
  // the step height, 0.4 to 1.5 times the cycle.
  strider::PsoParams<float, 3> p;
  p.lo[0] = 0.5f * base->step_length_mm;
  p.hi[0] = 2.5f * base->step_length_mm;
  p.lo[1] = 0.5f * base->step_height_mm;
  p.hi[1] = 2.0f * base->step_height_mm;
  p.lo[2] = 0.4f * base->cycle_s;
  p.hi[2] = 1.5f * base->cycle_s;
  p.swarm_size = uint8_t(swarm_size);
  p.max_iterations = uint16_t(iterations);
  p.seed = seed;
  p.cost_threshold = -1e9f;  // costs are negative speeds: the default 0 would stop at once
  int evaluations = 0;
  // Checked at half the window and at its end, with 30 % margin on drift and
  // turning (drift grows with time).
  Options tight = o;
  tight.max_lateral_pct *= 0.7;
  tight.max_heading_deg_s *= 0.7;
  const std::vector<double> checkpoints = {0.5 * o.walk_s, o.walk_s};
  const auto cost = [&](const strider::JointVector<float, 3>& x) {
    ++evaluations;
    const std::vector<Rollout> r = rollout(*model, with(*base, Candidate{x[0], x[1], x[2]}), o, checkpoints, &tight);
    const double v = violation(r, tight);
    return float(v > 0 ? 1000.0 + v : -r.back().speed_mm_s);
  };
  static strider::ParticleSwarm<float, 3, 20> pso;
  const strider::PsoResult<float, 3> best = pso.minimize(p, cost);
  const double tune_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double tune_cpu_s = double(std::clock() - c0) / CLOCKS_PER_SEC;
  const Candidate def{base->step_length_mm, base->step_height_mm, base->cycle_s};
  const Candidate tuned{best.position[0], best.position[1], best.position[2]};
  // Both gaits at the tuning checkpoints and over a walk twice as long as the
  // window, which the tuning never saw (one rollout each, the earlier
  // windows are the start of the same walk).
  const std::vector<double> windows = {0.5 * o.walk_s, o.walk_s, 2.0 * o.walk_s};
  const std::vector<Rollout> rd = rollout(*model, *base, o, windows);
  const std::vector<Rollout> rt = rollout(*model, with(*base, tuned), o, windows);
  std::printf("{\"robot\":\"%s\",\"gait\":\"%s\",\"swarm\":%d,\"iterations\":%d,\"evaluations\":%d,"
              "\"walk_s\":%.2f,\"checkpoints_s\":[%.2f,%.2f],\"check_walk_s\":%.2f,\"tune_wall_s\":%.2f,\"tune_cpu_s\":%.2f,"
              "\"tuned_cost\":%.3f,\"bounds\":[[%.2f,%.2f],[%.2f,%.2f],[%.3f,%.3f]],"
              "\"constraints\":{\"max_tilt_deg\":%.1f,\"max_lateral_pct\":%.1f,\"max_heading_deg_s\":%.1f},"
              "\"margin_pct\":30,",
              model->name, o.gait.empty() ? base->default_gait : o.gait.c_str(), swarm_size, iterations, evaluations,
              o.walk_s, checkpoints[0], checkpoints[1], windows.back(), tune_s, tune_cpu_s, double(best.cost),
              double(p.lo[0]), double(p.hi[0]), double(p.lo[1]), double(p.hi[1]), double(p.lo[2]), double(p.hi[2]),
              o.max_tilt_deg, o.max_lateral_pct, o.max_heading_deg_s);
  print_rollout("default", def, rd[1], o, true);
  print_rollout("tuned", tuned, rt[1], o, true);
  std::printf("\"windows\":[");
  for (size_t w = 0; w < windows.size(); ++w) {
    std::printf("{");
    print_rollout("default", def, rd[w], o, true);
    print_rollout("tuned", tuned, rt[w], o, false);
    std::printf("}%s", w + 1 < windows.size() ? "," : "");
  }
  std::printf("]}\n");
  bool ok = true;
  for (size_t w = 0; w < windows.size(); ++w) ok = ok && rd[w].ok && rt[w].ok;
  return ok ? 0 : 1;
}
