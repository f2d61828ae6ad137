// strider-sim SCENARIO --out DIR [--firmware ELF] [--step S] [--quiet]
// Runs a scenario (docs/simulator.md) in the Bullet world and writes
// DIR/metrics.json, DIR/trace.csv and DIR/robot.log.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "sim_run.h"

namespace {

// "X,Y,Z" -> v; false on anything else.
bool parse_vec(const std::string& text, strider_sim::Vec* v) {
  double x, y, z;
  char tail;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &x, &y, &z, &tail) != 3) return false;
  *v = strider_sim::Vec{x, y, z};
  return true;
}

int usage() {
  std::fprintf(stderr,
               "usage: strider-sim SCENARIO --out DIR [--firmware ELF] [--step SECONDS] [--iterations N]\n"
               "                   [--solver mlcp|pgs] [--cfm CFM] [--friction MU] [--foot-pad MM]\n"
               "                   [--step-height MM] [--step-length MM] [--cycle S] [--swing SHAPE] [--duty D]\n"
               "                   [--imu] [--imu-ideal] [--imu-seed N] [--imu-gyro-bias X,Y,Z] [--imu-accel-bias X,Y,Z]\n"
               "                   [--imu-bandwidth HZ] [--imu-single-sample]\n"
               "                   [--battery-cells N] [--battery-mah C] [--battery-ohm R] [--battery-soc S]\n"
               "                   [--battery-divider K] [--battery-pin P] [--quiet]\n"
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
               "  --duty    fraction of the cycle each foot is on the ground, for every gait walked (library mode)\n"

               "  --imu     an MPU-6050 is fitted (as the scenario's `imu on`): in firmware mode vbench's\n"
               "            answers at 0x68, fed by the IMU model every physics step\n"
               "  --imu-ideal  no noise and no offsets; --imu-seed: the noise and the drawn offsets\n"
               "  --imu-gyro-bias, --imu-accel-bias  the offsets [deg/s], [mg] instead of drawn ones\n"
               "            (default: drawn within the data sheet's +-20 deg/s, +-50/50/80 mg)\n"
               "  --battery-cells, -mah, -ohm, -soc  the LiPo pack (default 2 cells, 2200 mAh, 0.06 ohm,\n"
               "            full; dog12: 3 cells, 5000 mAh, 0.04 ohm); --battery-divider, --battery-pin:\n"
               "            pack volts per pin volt (3) on A0..A7 (0)\n"
               "  --imu-bandwidth HZ  the IMU's low-pass (default 260, no filter; firmware mode: the\n"
               "            firmware's DLPF setting)\n"
               "  --imu-single-sample  the trace's attitude filter takes one reading a tick, not the\n"
               "            tick's mean\n");
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
    } else if (a == "--imu") {
      opt.sensors.imu_fitted = true;
    } else if (a == "--imu-ideal") {
      const strider_sim::Vec at = opt.sensors.imu.position_body_mm;
      opt.sensors.imu = strider_sim::ImuConfig::ideal();
      opt.sensors.imu.position_body_mm = at;
    } else if (a == "--imu-bandwidth") {
      if (!value(&v)) return usage();
      opt.sensors.imu.bandwidth_hz = std::atof(v.c_str());
      if (!(opt.sensors.imu.bandwidth_hz >= 1 && opt.sensors.imu.bandwidth_hz <= 1000)) return usage();
    } else if (a == "--imu-single-sample") {
      opt.sensors.filter_takes_mean = false;
    } else if (a == "--imu-seed") {
      if (!value(&v)) return usage();
      opt.sensors.imu.seed = uint32_t(std::strtoul(v.c_str(), nullptr, 0));
    } else if (a == "--imu-gyro-bias" || a == "--imu-accel-bias") {
      if (!value(&v)) return usage();
      strider_sim::ImuConfig& c = opt.sensors.imu;
      if (!parse_vec(v, a == "--imu-gyro-bias" ? &c.gyro_bias_dps : &c.accel_bias_mg)) return usage();
      if (c.random_bias) {  // the other offset, not given, is 0
        c.random_bias = false;
        (a == "--imu-gyro-bias" ? c.accel_bias_mg : c.gyro_bias_dps) = strider_sim::Vec{};
      }
    } else if (a == "--battery-cells" || a == "--battery-pin") {
      if (!value(&v)) return usage();
      const int n = std::atoi(v.c_str());
      if (a == "--battery-cells" ? !(n >= 1 && n <= 12) : !(n >= 0 && n <= 7)) return usage();
      (a == "--battery-cells" ? opt.sensors.battery.cells : opt.sensors.battery.adc_pin) = n;
    } else if (a == "--battery-mah" || a == "--battery-ohm" || a == "--battery-soc" || a == "--battery-divider") {
      if (!value(&v)) return usage();
      const double x = std::atof(v.c_str());
      strider_sim::BatteryOverrides& b = opt.sensors.battery;
      if (a == "--battery-mah" && x > 0) b.capacity_mah = x;
      else if (a == "--battery-ohm" && x >= 0) b.internal_ohm = x;
      else if (a == "--battery-soc" && x >= 0 && x <= 1) b.soc = x;
      else if (a == "--battery-divider" && x >= 1) b.divider = x;
      else return usage();
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
    std::printf("%s %s: %.1f s simulated in %.2f s wall clock (%.1fx real time), %.2f s CPU (%.1fx per CPU second)\n",
                m.robot.c_str(), m.mode.c_str(), m.sim_time_s, m.wall_time_s, m.real_time_factor_wall, m.cpu_time_s,
                m.real_time_factor);
    if (opt.world.solver == strider_sim::Solver::kMlcp)
      std::printf("physics: %ld of %ld steps solved by PGS because the exact (MLCP) solver gave up on them\n",
                  m.solver_fallbacks, m.physics_steps);
    std::printf("displacement %.0f mm (start to end), path %.0f mm (along the way), top speed %.1f mm/s, "
                "heading %+.1f deg, drift %.1f mm (body frame %.1f mm), max tilt %.1f deg%s\n",
                m.distance_mm, m.path_mm, m.speed_mm_s, m.heading_change_deg, m.lateral_drift_mm, m.body_drift_mm,
                m.max_tilt_deg, m.fell ? ", FELL" : "");
    if (m.has_odometry)
      std::printf("gait odometry %.0f mm, the body %.1f %% short of it\n", m.odometry_mm, m.odometry_error_pct);
    if (m.has_obstacles)
      std::printf("closest body-obstacle distance %.0f mm, %d collisions\n", m.min_clearance_mm, m.collisions);
    std::printf("battery %.2f V -> %.2f V (min %.2f V, max %.1f A, %.1f mAh)%s\n", m.battery_start_v, m.battery_end_v,
                m.battery_min_v, m.battery_max_a, m.battery_used_mah,
                m.imu_fitted ? "; MPU-6050 fitted" : "");
    std::printf("wrote %s/metrics.json, trace.csv, robot.log\n", out_dir.c_str());
  }
  return 0;
}
