#include "sim_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "gait/gait_params.h"
#include "driver.h"
#include "host_robot.h"
#include "robots/all_robots.h"

namespace strider_sim {

RunResult run_scenario(const Scenario& sc, const RunOptions& opt) {
  RunResult r;
  const strider::RobotModel* model = strider::find_robot(sc.robot.c_str());
  if (model == nullptr) {
    r.error = "unknown robot " + sc.robot;
    return r;
  }
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  WorldConfig wc = opt.world;
  if (wc.initial_joints_rad.empty()) wc.initial_joints_rad = sitting_joints(*model);
  if (wc.foot_pad_half_mm == 0) wc.foot_pad_half_mm = sc.foot_pad_half_mm;
  World world(*model, wc, sc.obstacles);
  if (sc.ramp_deg != 0) world.set_ramp(sc.ramp_deg, sc.ramp_uphill_deg);
  RangeFn range = [&world]() { return world.sonar_mm(); };
  std::unique_ptr<Driver> driver;
  if (opt.firmware_elf.empty()) {
    driver = make_library_driver(*model, wc.osc_hz, range, opt.gait);
  } else if (opt.gait.any()) {
    r.error = "gait parameter options need library mode: a firmware has its gait defaults built in";
    return r;
  } else {
    driver = make_firmware_driver(opt.firmware_elf, *model, wc.osc_hz, range, &r.error);
    if (!driver) return r;
  }
  if (!driver->begin(&r.error)) return r;
  SensorOptions so = opt.sensors;
  so.imu_fitted = so.imu_fitted || sc.imu;
  so.battery = sc.battery.under(opt.sensors.battery);
  RobotSensors sensors(*model, so);
  sensors.step(world, 0);  // at rest: the readings before the first step

  Metrics& m = r.metrics;
  m.robot = model->name;
  m.mode = driver->mode();
  m.solver = opt.world.solver == Solver::kMlcp ? "mlcp" : "pgs";
  m.mass_kg = double(model->body.mass_kg);
  r.legs = model->leg_count;
  r.dof = model->dof();
  const double dt = wc.step_s;
  const long steps = std::lround(sc.duration_s / dt);
  const long trace_every = std::max(1L, std::lround(opt.trace_period_s / dt));
  size_t next_send = 0, next_event = 0;
  double yaw_unwrapped = 0, last_yaw = 0;
  bool first_row = true;
  bool touching_obstacle = false;
  bool ready = false;
  // Power-up: soft start, then the stand-up transition and half a second to settle.
  const strider::GaitParams* gp = strider::gait_params_for(*model);
  const double settle_s = (gp != nullptr ? double(gp->transition_s) : 1.0) + 0.5;
  double all_on_s = -1;
  m.min_clearance_mm = m.min_robot_clearance_mm = 1e9;
  double ox = 0, oy = 0, oyaw = 0;
  m.imu_fitted = so.imu_fitted;
  m.imu_gyro_bias_dps = sensors.imu().gyro_bias_dps();
  m.imu_accel_bias_mg = sensors.imu().accel_bias_mg();
  m.battery_start_v = m.battery_min_v = sensors.battery().volts();

  auto record = [&](double t_s) {
    TraceRow row;
    row.t_s = t_s;
    row.body = world.body();
    if (first_row) {
      yaw_unwrapped = row.body.yaw_deg;
      first_row = false;
    } else {
      double d = row.body.yaw_deg - last_yaw;
      while (d > 180) d -= 360;
      while (d < -180) d += 360;
      yaw_unwrapped += d;
    }
    last_yaw = row.body.yaw_deg;
    row.body.yaw_deg = yaw_unwrapped;
    // Velocity of the body centre over the last trace period (what a camera
    // measures; Bullet's base velocity is its COM's, mid-step).
    row.body.vel_mm_s = Vec{};
    if (!r.trace.empty()) {
      const TraceRow& prev = r.trace.back();
      const double span = t_s - prev.t_s;
      if (span > 0)
        row.body.vel_mm_s = Vec{(row.body.pos_mm.x - prev.body.pos_mm.x) / span,
                                (row.body.pos_mm.y - prev.body.pos_mm.y) / span,
                                (row.body.pos_mm.z - prev.body.pos_mm.z) / span};
    }
    for (int i = 0; i < r.legs; ++i) {
      for (int j = 0; j < r.dof; ++j) {
        row.q_deg.push_back(world.joint_rad(i, j) * 180.0 / M_PI);
        row.target_deg.push_back(world.joint_target_rad(i, j) * 180.0 / M_PI);
      }
      row.feet_mm.push_back(world.foot_mm(i));
      row.contact.push_back(world.foot_contact(i));
    }
    row.com_mm = world.com_mm();
    row.sonar_mm = world.sonar_mm();
    if (!sc.obstacles.empty()) {
      row.clearance_mm = world.body_clearance_mm();
      m.min_clearance_mm = std::min(m.min_clearance_mm, row.clearance_mm);
      m.min_robot_clearance_mm = std::min(m.min_robot_clearance_mm, world.robot_clearance_mm());
    }
    row.imu = sensors.imu().reading();
    row.imu_tick = sensors.filter_input();
    row.imu_roll_deg = sensors.roll_deg();
    row.imu_pitch_deg = sensors.pitch_deg();
    row.battery_v = sensors.battery().volts();
    row.battery_a = sensors.battery().current_a();
    if (ready && (!so.gyro_calibration || sensors.calibrated_s() >= 0)) {
      double d = std::fabs(row.imu_roll_deg - row.body.roll_deg);
      d = std::min(d, 360.0 - d);
      m.imu_max_error_deg = std::max({m.imu_max_error_deg, d, std::fabs(row.imu_pitch_deg - row.body.pitch_deg)});
    }
    if (driver->odometry(&ox, &oy, &oyaw)) {
      m.has_odometry = true;
      row.odo_x_mm = ox;
      row.odo_y_mm = oy;
      row.odo_yaw_deg = oyaw * 180.0 / M_PI;
    }
    row.servo_work_j = world.servo_work_j();
    r.trace.push_back(std::move(row));
  };
  double motion_s = -1;  // the robot was first told to move (ok move, or an RC motion byte)
  auto take_lines = [&](double t_s) {
    for (std::string& s : driver->take_lines()) {
      if (motion_s < 0 && s.rfind("ok move", 0) == 0) motion_s = t_s;
      if (s.rfind("ok", 0) == 0) ++m.replies_ok;
      if (s.rfind("err", 0) == 0) ++m.replies_err;
      r.log.push_back(LogLine{t_s, std::move(s)});
    }
  };

  take_lines(0);
  record(0);
  for (long k = 0; k < steps; ++k) {
    const double t = double(k) * dt;
    const uint64_t t_us = uint64_t(std::llround(t * 1e6));
    while (next_send < sc.sends.size() && sc.sends[next_send].at_s <= t + 1e-12) {
      const std::string& b = sc.sends[next_send].bytes;
      if (motion_s < 0 && !b.empty() && std::string("FBLRGIHJ").find(b[0]) != std::string::npos) motion_s = t;
      driver->send(b, uint64_t(std::llround(sc.sends[next_send].at_s * 1e6)));
      ++next_send;
    }
    for (; next_event < sc.events.size() && sc.events[next_event].at_s <= t + 1e-12; ++next_event) {
      const TimedEvent& e = sc.events[next_event];
      if (e.kind == TimedEvent::kShove) world.shove(e.impulse_ns);
      else if (e.kind == TimedEvent::kRamp) world.set_ramp(e.ramp_deg, e.ramp_uphill_deg);
      else world.upright();
    }
    driver->set_sensors(sensors.inputs());
    driver->advance_to(t_us);
    take_lines(t);
    world.set_pulses(driver->pulses());
    world.step();
    if (const double hz = driver->imu_bandwidth_hz()) sensors.set_imu_bandwidth_hz(hz);
    sensors.step(world, dt);
    m.battery_min_v = std::min(m.battery_min_v, sensors.battery().volts());
    m.battery_max_a = std::max(m.battery_max_a, sensors.battery().current_a());
    if (all_on_s < 0 && world.all_servos_on()) all_on_s = double(k + 1) * dt;
    const bool moving = motion_s >= 0 && all_on_s >= 0;
    if (!ready && ((all_on_s >= 0 && double(k + 1) * dt >= all_on_s + settle_s) || moving)) {
      ready = true;
      m.ready_s = double(k + 1) * dt;
    }
    if (ready) {
      m.max_tilt_deg = std::max(m.max_tilt_deg, world.body().tilt_deg);
      if (world.body_on_ground()) m.fell = true;
    }
    const bool touching = world.obstacle_contacts() > 0;
    if (touching && !touching_obstacle) ++m.collisions;
    touching_obstacle = touching;
    if ((k + 1) % trace_every == 0) record(double(k + 1) * dt);
  }
  m.sim_time_s = double(steps) * dt;
  m.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  m.cpu_time_s = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  m.real_time_factor = m.sim_time_s / std::max(1e-9, m.cpu_time_s);
  m.real_time_factor_wall = m.sim_time_s / std::max(1e-9, m.wall_time_s);
  m.physics_steps = long(steps);
  m.solver_fallbacks = world.solver_fallbacks();
  m.imu_calibrated_s = sensors.calibrated_s();
  m.battery_end_v = sensors.battery().volts();
  m.battery_used_mah = sensors.battery().used_mah();
  m.has_gait = driver->gait_info(&m.gait);
  compute_metrics(sc, r);
  r.obstacles = sc.obstacles;
  {
    std::ostringstream o;
    o << "{\"robot\": \"" << model->name << "\", \"legs\": " << int(model->leg_count) << ", \"dof\": " << int(model->dof())
      << ", \"body_mm\": [" << model->body.length_mm << ", " << model->body.width_mm << ", " << model->body.height_mm
      << "], \"hips_mm\": [";
    for (int i = 0; i < model->leg_count; ++i)
      o << (i ? ", " : "") << "[" << model->legs[i].mount_mm.x << ", " << model->legs[i].mount_mm.y << ", "
        << model->legs[i].mount_mm.z << "]";
    o << "], \"sonar_mm\": [" << world.sonar_origin_body_mm().x << ", 0, 0], \"obstacles_mm\": [";
    for (size_t k = 0; k < sc.obstacles.size(); ++k) {
      const ObstacleBox& b = sc.obstacles[k];
      o << (k ? ", " : "") << "[" << b.x_mm << ", " << b.y_mm << ", " << b.sx_mm << ", " << b.sy_mm << ", " << b.sz_mm << "]";
    }
    o << "]}\n";
    r.scene_json = o.str();
  }
  r.ok = true;
  return r;
}

}  // namespace strider_sim
