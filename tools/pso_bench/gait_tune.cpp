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
// Score: forward speed [mm/s] along the heading (the body-frame velocity
// integrated, tools/sim/body_track.h) over the tuning window of a `walk 500`
// (the gait engine caps the speed at what the candidate allows). A candidate
// is feasible when the robot does not fall, tilts at most 10 degrees, crabs
// (drifts sideways in its own frame, strider-sim's body_drift_mm) at most
// 10 % of the distance and turns at most 1 deg/s on average, each checked at
// half the window and at its end. The drift from the starting direction is
// reported, not constrained: with any heading drift it grows without bound
// on a long walk, whatever the gait. Drift and turning are tuned with a 30 %
// margin; an infeasible candidate costs 1000 + its violation. One particle
// starts at the model's gait, so the result is never worse than it on this
// cost. Bounds: step length up to the longest forward stride the legs reach
// (the gait engine's own stride limit at the lowest step height of the box),
// height half to twice the default, cycle 0.4 to 1.5 times the default.
//
// usage: gait_tune [--robot R] [--gait G] [--swarm N] [--iterations N]
//                  [--walk-s S] [--seed N] [--vx MM_S]
// (defaults: sprawl8, its default gait, swarm 12, 12 iterations, S 30 s)
// Output: one JSON object on stdout: "default" and "tuned" over the tuning
// window (S, default 30 s), and "windows": both over S, over a validation
// walk twice as long (2 S) and over its second half alone (S to 2 S, which
// the tuning never saw).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "control/robot_app.h"
#include "kinematics/pso.h"
#include "robots/all_robots.h"
#include "body_track.h"
#include "host_robot.h"
#include "world.h"

namespace {

using strider_sim::ChannelPulse;
using strider_sim::kMaxChannels;
using strider_sim::World;
using strider_sim::WorldConfig;

struct Replies {
  int err = 0;
  void send_line(uint8_t, const char* line) { err += std::strncmp(line, "err", 3) == 0; }
};

struct Candidate {
  float step_length_mm, step_height_mm, cycle_s;
};

// A window of a rollout, [from_s, to_s] seconds of walking after the
// settling time, and what was measured over it.
struct Rollout {
  double from_s = 0, to_s = 0;
  bool ok = false;
  std::string error;
  double speed_mm_s = 0;            // forward along the heading (body frame at each instant)
  double start_dir_speed_mm_s = 0;  // forward along the heading at the window's start
  double body_drift_pct = 0;        // sideways in the body frame, % of the forward distance (crabbing)
  double lateral_pct = 0;           // sideways from the starting direction, % of the distance along it
  double heading_deg = 0;           // unwrapped change
  double max_tilt_deg = 0;
  bool fell = false;
  double walk_s() const { return to_s - from_s; }
  double turn_deg_s() const { return std::fabs(heading_deg) / walk_s(); }
};

struct Options {
  double walk_at_s = 3.0;  // soft start and stand-up are over by then (sprawl8: 2.3 s)
  double settle_s = 1.5;   // acceleration, not measured
  double walk_s = 30.0;    // tuning window
  double sample_s = 0.02;  // body samples (strider-sim's trace period)
  double max_tilt_deg = 10.0;
  double max_body_drift_pct = 10.0;
  double max_heading_deg_s = 1.0;  // turning while asked to walk straight [deg/s]
  std::string walk = "walk 500\n";  // the command walked
  std::string gait;                  // gait to switch to ("" = the model's default)
};

// A window being measured: the body at its start, and what it did since.
struct Window {
  explicit Window(Rollout* r) : out(r) {}
  Rollout* out;
  bool open = false, done = false;
  strider_sim::BodyState start{}, last{};
  strider_sim::BodyTrack track;

  // The body at every physics step, t_s seconds of walking (negative:
  // accelerating): tilt and fall. A window from the start of the walk
  // includes the acceleration's.
  void observe(const strider_sim::BodyState& b, double t_s, bool fell) {
    if (done || (t_s < out->from_s - 1e-9 && out->from_s > 0)) return;
    out->max_tilt_deg = std::max(out->max_tilt_deg, b.tilt_deg);
    out->fell = out->fell || fell;
  }

  // A body sample (every sample_s): the track.
  void sample(const strider_sim::BodyState& b, double t_s) {
    if (done || t_s < out->from_s - 1e-9) return;
    if (!open) {
      open = true;
      start = b;
    }
    last = b;
    track.add(t_s, b);
    if (t_s >= out->to_s - 1e-9) finish();
  }

  void finish() {
    done = true;
    Rollout& r = *out;
    const double yaw = start.yaw_deg * M_PI / 180.0;
    const double dx = last.pos_mm.x - start.pos_mm.x, dy = last.pos_mm.y - start.pos_mm.y;
    const double fwd = dx * std::cos(yaw) + dy * std::sin(yaw);
    const double lat = -dx * std::sin(yaw) + dy * std::cos(yaw);
    const double forward = track.forward_mm(), left = track.left_mm();
    r.speed_mm_s = forward / r.walk_s();
    r.start_dir_speed_mm_s = fwd / r.walk_s();
    r.body_drift_pct = std::fabs(forward) > 1e-6 ? 100.0 * std::fabs(left) / std::fabs(forward) : 0.0;
    r.lateral_pct = std::fabs(fwd) > 1e-6 ? 100.0 * std::fabs(lat) / std::fabs(fwd) : 0.0;
    r.heading_deg = track.turned_deg();
  }
};

double violation(const Rollout& r, const Options& o);

// One rollout, measured over each of `windows` (from_s and to_s set; sorted
// by to_s); the rollout ends at the last window's end, or when a window
// ends that violates `stop_if_violated` (when given: the tuning need not walk
// an infeasible candidate to the end), and returns the windows finished.
std::vector<Rollout> rollout(const strider::RobotModel& model, const strider::GaitParams& params, const Options& o,
                             std::vector<Rollout> out, const Options* stop_if_violated = nullptr) {
  auto fail = [&](const char* why) {
    for (Rollout& r : out) r.error = why;
    return out;
  };
  WorldConfig wc;
  wc.initial_joints_rad = strider_sim::sitting_joints(model);
  World world(model, wc, {});
  strider_sim::HostParts parts;
  strider_sim::HostApp app(model, parts.boards, parts.store);
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
  const Send sends[] = {{0.4, gait_line.c_str()}, {0.5, "$deadman off*cb77\n"}, {0.6, "avoid off\n"},
                        {o.walk_at_s, o.walk.c_str()}};
  size_t next_send = 0;
  const double dt = wc.step_s;
  const double t_start = o.walk_at_s + o.settle_s;
  const long sample_every = std::max(1L, std::lround(o.sample_s / dt));
  const long steps = std::lround((t_start + out.back().to_s) / dt);
  std::vector<Window> windows;
  for (Rollout& r : out) windows.push_back(Window{&r});
  size_t finished = 0;
  uint64_t next_tick_us = strider::kTickPeriodUs;
  ChannelPulse pulses[kMaxChannels];
  bool fell = false;
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
    parts.boards.pulses(wc.osc_hz, pulses);
    world.set_pulses(pulses);
    world.step();
    const double t_walk = double(k + 1) * dt - t_start;  // seconds of walking measured
    if (t_walk < -o.settle_s - 1e-9) continue;            // before the walk command
    fell = fell || world.body_on_ground();
    const strider_sim::BodyState b = world.body();
    for (Window& w : windows) w.observe(b, t_walk, fell);
    if ((k + 1) % sample_every != 0 && k + 1 != steps) continue;
    for (Window& w : windows) w.sample(b, t_walk);
    while (finished < out.size() && windows[finished].done) {
      Rollout& r = out[finished++];
      r.ok = link.err == 0;
      if (!r.ok) r.error = "the robot answered err";
      if (stop_if_violated != nullptr && violation(r, *stop_if_violated) > 0) {
        out.resize(finished);
        return out;
      }
    }
  }
  return out;
}

std::vector<Rollout> windows_of(const std::vector<std::pair<double, double>>& spans) {
  std::vector<Rollout> w(spans.size());
  for (size_t i = 0; i < spans.size(); ++i) {
    w[i].from_s = spans[i].first;
    w[i].to_s = spans[i].second;
  }
  return w;
}

double violation(const Rollout& r, const Options& o) {
  if (!r.ok) return 1e3;
  double v = r.fell ? 100.0 : 0.0;
  v += std::max(0.0, r.max_tilt_deg - o.max_tilt_deg);
  v += std::max(0.0, r.body_drift_pct - o.max_body_drift_pct);
  v += std::max(0.0, r.turn_deg_s() - o.max_heading_deg_s);
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

// The longest forward stride the gait engine lets every leg make with
// `params` (its velocity limits: the legs' reach, kStrideShare of it) [mm];
// 0 when the walker refuses them.
double forward_stride_mm(const strider::RobotModel& model, const strider::GaitParams& params) {
  static strider::WalkerMotion<float> motion;  // large: not on the stack
  if (!motion.configure(model, params)) return 0.0;
  const strider::GaitConfig<float>& c = motion.walker().engine().config();
  double shortest = 1e9;
  for (uint8_t i = 0; i < model.leg_count; ++i) shortest = std::min(shortest, double(c.limits.stride_mm(i, 0)));
  return shortest;
}

void print_rollout(const char* name, const Candidate& c, const Rollout& r, const Options& o, bool comma) {
  std::printf("\"%s\":{\"from_s\":%.2f,\"to_s\":%.2f,\"walk_s\":%.2f,\"step_length_mm\":%.2f,\"step_height_mm\":%.2f,"
              "\"cycle_s\":%.3f,\"speed_mm_s\":%.2f,\"start_dir_speed_mm_s\":%.2f,\"max_tilt_deg\":%.2f,"
              "\"body_drift_pct\":%.2f,\"lateral_pct\":%.2f,\"heading_deg\":%.2f,\"turn_deg_s\":%.3f,"
              "\"fell\":%s,\"feasible\":%s%s%s%s}%s",
              name, r.from_s, r.to_s, r.walk_s(), double(c.step_length_mm), double(c.step_height_mm), double(c.cycle_s),
              r.speed_mm_s, r.start_dir_speed_mm_s, r.max_tilt_deg, r.body_drift_pct, r.lateral_pct, r.heading_deg,
              r.turn_deg_s(), r.fell ? "true" : "false", violation(r, o) == 0.0 ? "true" : "false",
              r.error.empty() ? "" : ",\"error\":\"", r.error.c_str(), r.error.empty() ? "" : "\"", comma ? "," : "");
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
  int swarm_size = 12, iterations = 12;
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
  // Bounds: half the default step height to twice it, 0.4 to 1.5 times the
  // cycle; step length from half the default to the longest forward stride
  // the legs reach at the lowest step height (a higher swing reaches less; a
  // longer preferred step than the reach would be walked as the reach).
  strider::PsoParams<float, 3> p;
  p.lo[1] = 0.5f * base->step_height_mm;
  p.hi[1] = 2.0f * base->step_height_mm;
  p.lo[2] = 0.4f * base->cycle_s;
  p.hi[2] = 1.5f * base->cycle_s;
  strider::GaitParams low = *base;
  low.step_height_mm = p.lo[1];
  const double reach_mm = forward_stride_mm(*model, low);
  p.lo[0] = 0.5f * base->step_length_mm;
  p.hi[0] = std::max(float(reach_mm), base->step_length_mm);
  p.swarm_size = uint8_t(swarm_size);
  p.max_iterations = uint16_t(iterations);
  p.seed = seed;
  p.cost_threshold = -1e9f;  // costs are negative speeds: the default 0 would stop at once
  const strider::JointVector<float, 3> start{{base->step_length_mm, base->step_height_mm, base->cycle_s}};
  p.start = &start;  // particle 0: the model's gait
  int evaluations = 0;
  // Checked at half the window and at its end, with 30 % margin on drift and
  // turning.
  Options tight = o;
  tight.max_body_drift_pct *= 0.7;
  tight.max_heading_deg_s *= 0.7;
  const std::vector<Rollout> checks = windows_of({{0.0, 0.5 * o.walk_s}, {0.0, o.walk_s}});
  double default_cost = 0;
  const auto cost = [&](const strider::JointVector<float, 3>& x) {
    const std::vector<Rollout> r = rollout(*model, with(*base, Candidate{x[0], x[1], x[2]}), o, checks, &tight);
    const double v = violation(r, tight);
    const float c = float(v > 0 ? 1000.0 + v : -r.back().speed_mm_s);
    if (evaluations++ == 0) default_cost = c;
    return c;
  };
  static strider::ParticleSwarm<float, 3, 20> pso;
  const strider::PsoResult<float, 3> best = pso.minimize(p, cost);
  const double tune_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double tune_cpu_s = double(std::clock() - c0) / CLOCKS_PER_SEC;
  const Candidate def{base->step_length_mm, base->step_height_mm, base->cycle_s};
  const Candidate tuned{best.position[0], best.position[1], best.position[2]};
  // Both gaits over the tuning window, a validation walk twice as long, and
  // its second half alone, which the tuning never saw (one rollout each).
  const std::vector<Rollout> report = windows_of({{0.0, o.walk_s}, {0.0, 2.0 * o.walk_s}, {o.walk_s, 2.0 * o.walk_s}});
  const std::vector<Rollout> rd = rollout(*model, *base, o, report);
  const std::vector<Rollout> rt = rollout(*model, with(*base, tuned), o, report);
  std::printf("{\"robot\":\"%s\",\"gait\":\"%s\",\"swarm\":%d,\"iterations\":%d,\"evaluations\":%d,"
              "\"walk_s\":%.2f,\"checkpoints_s\":[%.2f,%.2f],\"check_walk_s\":%.2f,\"tune_wall_s\":%.2f,"
              "\"tune_cpu_s\":%.2f,\"tuned_cost\":%.3f,\"default_cost\":%.3f,\"start_particle\":\"default\","
              "\"reach_stride_mm\":%.2f,\"bounds\":[[%.2f,%.2f],[%.2f,%.2f],[%.3f,%.3f]],"
              "\"constraints\":{\"max_tilt_deg\":%.1f,\"max_body_drift_pct\":%.1f,\"max_heading_deg_s\":%.1f},"
              "\"margin_pct\":30,",
              model->name, o.gait.empty() ? base->default_gait : o.gait.c_str(), swarm_size, iterations, evaluations,
              o.walk_s, checks[0].to_s, checks[1].to_s, report[1].to_s, tune_s, tune_cpu_s, double(best.cost),
              default_cost, reach_mm, double(p.lo[0]), double(p.hi[0]), double(p.lo[1]), double(p.hi[1]),
              double(p.lo[2]), double(p.hi[2]), o.max_tilt_deg, o.max_body_drift_pct, o.max_heading_deg_s);
  print_rollout("default", def, rd[0], o, true);
  print_rollout("tuned", tuned, rt[0], o, true);
  std::printf("\"windows\":[");
  for (size_t w = 0; w < report.size(); ++w) {
    std::printf("{");
    print_rollout("default", def, rd[w], o, true);
    print_rollout("tuned", tuned, rt[w], o, false);
    std::printf("}%s", w + 1 < report.size() ? "," : "");
  }
  std::printf("]}\n");
  // The swarm's best is never worse than its start particle, the default.
  bool ok = rd.size() == report.size() && rt.size() == report.size() && double(best.cost) <= default_cost;
  for (size_t w = 0; ok && w < report.size(); ++w) ok = rd[w].ok && rt[w].ok;
  return ok ? 0 : 1;
}
