// strider-sim SCENARIO --out DIR [--firmware ELF] [--step S] [--quiet]
// Runs a scenario (docs/simulator.md) in the Bullet world and writes
// DIR/metrics.json, DIR/trace.csv and DIR/robot.log.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "sim_run.h"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: strider-sim SCENARIO --out DIR [--firmware ELF] [--step SECONDS] [--iterations N]\n"
               "                   [--solver mlcp|pgs] [--cfm CFM] [--friction MU] [--foot-pad MM]\n"
               "                   [--step-height MM] [--step-length MM] [--cycle S] [--swing SHAPE] [--duty D]\n"
               "                   [--quiet]\n"
               "  SCENARIO  scenario file (robot, duration, obstacle box, at T send TEXT)\n"
               "  --out     output folder: metrics.json, trace.csv, robot.log\n"
               "  --firmware  run the firmware ELF on the virtual Mega instead of the library\n"
               "  --step    physics step [s] (default 0.004)\n"
               "  --solver  constraint solver: mlcp (default, exact) or pgs (iterative)\n"
               "  --cfm     constraint force mixing of every solver row (default 1e-6; 0: none)\n"
               "  --foot-pad  feet as capsules across the leg, MM to each side (default 0: balls)\n"
               "  --step-height, --step-length, --cycle, --swing  the gait defaults to walk instead of\n"
               "            the model's (library mode): swing apex [mm], preferred stride [mm], cycle\n"
               "            at low speed [s], swing shape (rectangle semicircle ellipse cycloid parabola bezier)\n"
               "  --duty    fraction of the cycle each foot is on the ground, for every gait walked (library mode)\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenario_path, out_dir;
  strider_sim::RunOptions opt;
  bool quiet = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string* v) {
      if (i + 1 >= argc) return false;
      *v = argv[++i];
      return true;
    };
    std::string v;
    if (a == "--out") {
      if (!value(&out_dir)) return usage();
    } else if (a == "--firmware") {
      if (!value(&opt.firmware_elf)) return usage();
    } else if (a == "--step") {
      if (!value(&v)) return usage();
      opt.world.step_s = std::atof(v.c_str());
      if (!(opt.world.step_s > 0 && opt.world.step_s <= 0.01)) return usage();
    } else if (a == "--iterations") {
      if (!value(&v)) return usage();
      opt.world.solver_iterations = std::atoi(v.c_str());
    } else if (a == "--solver") {
      if (!value(&v) || (v != "pgs" && v != "mlcp")) return usage();
      opt.world.solver = v == "pgs" ? strider_sim::Solver::kPgs : strider_sim::Solver::kMlcp;
    } else if (a == "--residual") {
      if (!value(&v)) return usage();
      opt.world.solver_residual = std::atof(v.c_str());
    } else if (a == "--cfm") {
      if (!value(&v)) return usage();
      opt.world.solver_cfm = std::atof(v.c_str());
      if (!(opt.world.solver_cfm >= 0)) return usage();
    } else if (a == "--friction") {
      if (!value(&v)) return usage();
      opt.world.foot_friction = std::atof(v.c_str());
    } else if (a == "--foot-pad") {
      if (!value(&v)) return usage();
      opt.world.foot_pad_half_mm = std::atof(v.c_str());
      if (!(opt.world.foot_pad_half_mm >= 0 && opt.world.foot_pad_half_mm <= 50)) return usage();
    } else if (a == "--step-height" || a == "--step-length") {
      if (!value(&v)) return usage();
      const double mm = std::atof(v.c_str());
      if (!(mm > 0 && mm <= 500)) return usage();
      (a == "--step-height" ? opt.gait.step_height_mm : opt.gait.step_length_mm) = mm;
    } else if (a == "--cycle") {
      if (!value(&v)) return usage();
      opt.gait.cycle_s = std::atof(v.c_str());
      if (!(opt.gait.cycle_s >= 0.1 && opt.gait.cycle_s <= 10)) return usage();
    } else if (a == "--duty") {
      if (!value(&v)) return usage();
      opt.gait.duty = std::atof(v.c_str());
      if (!(opt.gait.duty > 0 && opt.gait.duty < 1)) return usage();
    } else if (a == "--swing") {
      if (!value(&opt.gait.swing) || opt.gait.swing.empty()) return usage();
    } else if (a == "--quiet") {
      quiet = true;
    } else if (a == "-h" || a == "--help") {
      usage();
      return 0;
    } else if (!a.empty() && a[0] != '-' && scenario_path.empty()) {
      scenario_path = a;
    } else {
      return usage();
    }
  }
  if (scenario_path.empty() || out_dir.empty()) return usage();
  strider_sim::Scenario sc;
  std::string error;
  if (!strider_sim::load_scenario(scenario_path, &sc, &error)) {
    std::fprintf(stderr, "strider-sim: %s: %s\n", scenario_path.c_str(), error.c_str());
    return 2;
  }
  const strider_sim::RunResult r = strider_sim::run_scenario(sc, opt);
  if (!r.ok) {
    std::fprintf(stderr, "strider-sim: %s\n", r.error.c_str());
    return 1;
  }
  if (!strider_sim::write_outputs(r, out_dir, &error)) {
    std::fprintf(stderr, "strider-sim: %s\n", error.c_str());
    return 1;
  }
  if (!quiet) {
    const strider_sim::Metrics& m = r.metrics;
    std::printf("%s %s: %.1f s simulated in %.2f s wall, %.2f s CPU (%.1fx real time), %ld solver fallbacks\n",
                m.robot.c_str(), m.mode.c_str(), m.sim_time_s, m.wall_time_s, m.cpu_time_s, m.real_time_factor,
                m.solver_fallbacks);
    std::printf("distance %.0f mm, top speed %.1f mm/s, heading %+.1f deg, drift %.1f mm (body frame %.1f mm), max tilt %.1f deg%s\n",
                m.distance_mm, m.speed_mm_s, m.heading_change_deg, m.lateral_drift_mm, m.body_drift_mm, m.max_tilt_deg,
                m.fell ? ", FELL" : "");
    if (m.has_obstacles)
      std::printf("closest body-obstacle distance %.0f mm, %d collisions\n", m.min_clearance_mm, m.collisions);
    std::printf("wrote %s/metrics.json, trace.csv, robot.log\n", out_dir.c_str());
  }
  return 0;
}
