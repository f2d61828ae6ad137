#include "sim_run.h"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include "gait/gait_params.h"
#include "body_track.h"
#include "driver.h"
#include "host_robot.h"
#include "robots/all_robots.h"

namespace strider_sim {

namespace {

constexpr double kWindowS = 2.0;     // speed and yaw-rate window [s]
constexpr double kFallTiltDeg = 45;  // beyond this the robot has fallen over

double hdist(const Vec& a, const Vec& b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

void compute_metrics(const Scenario& sc, RunResult& r) {
  Metrics& m = r.metrics;
  // The window starts when every servo is on: a robot sagging on limp
  // servos during the power-up is not walking yet.
  std::vector<TraceRow> tr;
  for (const TraceRow& row : r.trace)
    if (row.t_s >= m.ready_s - 1e-9) tr.push_back(row);
  if (tr.empty()) return;
  const TraceRow& a = tr.front();
  const TraceRow& b = tr.back();
  m.distance_mm = hdist(a.body.pos_mm, b.body.pos_mm);
  for (size_t k = 1; k < tr.size(); ++k) m.path_mm += hdist(tr[k - 1].body.pos_mm, tr[k].body.pos_mm);
  m.heading_change_deg = b.body.yaw_deg - a.body.yaw_deg;
  m.final_x_mm = b.body.pos_mm.x;
  m.final_y_mm = b.body.pos_mm.y;
  m.final_yaw_deg = b.body.yaw_deg;
  m.mean_speed_mm_s = m.distance_mm / std::max(1e-9, b.t_s - a.t_s);
  // Best windows: displacement (not path: the body sways within a cycle).
  size_t k0 = 0;
  for (size_t k = 0; k < tr.size(); ++k) {
    while (tr[k].t_s - tr[k0].t_s > kWindowS + 1e-9) ++k0;
    const double span = tr[k].t_s - tr[k0].t_s;
    if (span < kWindowS - 1e-9) continue;
    m.speed_mm_s = std::max(m.speed_mm_s, hdist(tr[k].body.pos_mm, tr[k0].body.pos_mm) / span);
    m.yaw_rate_deg_s = std::max(m.yaw_rate_deg_s, std::fabs(tr[k].body.yaw_deg - tr[k0].body.yaw_deg) / span);
  }
  double t_start = -1;
  for (const TraceRow& row : tr) {
    const double turned = std::fabs(row.body.yaw_deg - a.body.yaw_deg);
    if (t_start < 0 && turned > 1.0) t_start = row.t_s;
    if (turned >= 360.0) {
      m.turn_360_s = row.t_s - t_start;
      break;
    }
  }
  // Drift: the displacement in the starting body frame; the larger of its
  // forward and sideways parts is the motion, the other the drift.
  const double yaw0 = a.body.yaw_deg * M_PI / 180.0;
  const double dx = b.body.pos_mm.x - a.body.pos_mm.x, dy = b.body.pos_mm.y - a.body.pos_mm.y;
  const double fwd = std::cos(yaw0) * dx + std::sin(yaw0) * dy;
  const double side = -std::sin(yaw0) * dx + std::cos(yaw0) * dy;
  m.lateral_drift_mm = std::fabs(fwd) >= std::fabs(side) ? std::fabs(side) : std::fabs(fwd);
  // The same in the body frame, turning with the heading: a slow turn does not add to it.
  BodyTrack track;
  for (const TraceRow& row : tr) track.add(row.t_s, row.body);
  m.body_drift_mm = track.drift_mm();
  m.has_obstacles = !sc.obstacles.empty();
  if (m.has_odometry) {
    // The engine's odometry frame is the body at power-up (the first row):
    // the distance reached counts only along the way the gait went, so a
    // robot sliding backward has an error above 100 %.
    const double y0 = r.trace.front().body.yaw_deg * M_PI / 180.0;
    const double ox = b.odo_x_mm - a.odo_x_mm, oy = b.odo_y_mm - a.odo_y_mm;
    const double wx = std::cos(y0) * ox - std::sin(y0) * oy, wy = std::sin(y0) * ox + std::cos(y0) * oy;
    m.odometry_mm = std::hypot(ox, oy);
    const double along = m.odometry_mm > 1e-6 ? (dx * wx + dy * wy) / m.odometry_mm : 0.0;
    m.odometry_error_pct = m.odometry_mm > 1e-6 ? (m.odometry_mm - along) / m.odometry_mm * 100.0 : 0.0;
  }
  m.fell = m.fell || m.max_tilt_deg > kFallTiltDeg;
  m.servo_work_j = b.servo_work_j - a.servo_work_j;
  m.cost_of_transport = m.distance_mm >= 10.0 ? m.servo_work_j / (m.mass_kg * 9.81 * m.distance_mm * 1e-3) : -1.0;
}

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

namespace {

std::string num(double v, int digits = 3) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string json_string(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      o += buf;
      continue;
    }
    o += c;
  }
  return o + "\"";
}

}  // namespace

std::string metrics_json(const Metrics& m) {
  std::ostringstream o;
  o << "{\n";
  o << "  \"robot\": " << json_string(m.robot) << ",\n";
  o << "  \"mode\": " << json_string(m.mode) << ",\n";
  o << "  \"distance_mm\": " << num(m.distance_mm) << ",\n";
  o << "  \"path_mm\": " << num(m.path_mm) << ",\n";
  o << "  \"speed_mm_s\": " << num(m.speed_mm_s) << ",\n";
  o << "  \"mean_speed_mm_s\": " << num(m.mean_speed_mm_s) << ",\n";
  o << "  \"heading_change_deg\": " << num(m.heading_change_deg) << ",\n";
  o << "  \"yaw_rate_deg_s\": " << num(m.yaw_rate_deg_s) << ",\n";
  o << "  \"turn_360_s\": " << (m.turn_360_s < 0 ? std::string("null") : num(m.turn_360_s)) << ",\n";
  o << "  \"lateral_drift_mm\": " << num(m.lateral_drift_mm) << ",\n";
  o << "  \"body_drift_mm\": " << num(m.body_drift_mm) << ",\n";
  o << "  \"max_tilt_deg\": " << num(m.max_tilt_deg) << ",\n";
  o << "  \"fell\": " << (m.fell ? "true" : "false") << ",\n";
  o << "  \"min_clearance_mm\": " << (m.has_obstacles ? num(m.min_clearance_mm) : "null") << ",\n";
  o << "  \"min_robot_clearance_mm\": " << (m.has_obstacles ? num(m.min_robot_clearance_mm) : "null") << ",\n";
  o << "  \"collisions\": " << m.collisions << ",\n";
  o << "  \"odometry_mm\": " << (m.has_odometry ? num(m.odometry_mm) : "null") << ",\n";
  o << "  \"odometry_error_pct\": " << (m.has_odometry ? num(m.odometry_error_pct) : "null") << ",\n";
  o << "  \"final_x_mm\": " << num(m.final_x_mm) << ",\n";
  o << "  \"final_y_mm\": " << num(m.final_y_mm) << ",\n";
  o << "  \"final_yaw_deg\": " << num(m.final_yaw_deg) << ",\n";
  o << "  \"replies_ok\": " << m.replies_ok << ",\n";
  o << "  \"replies_err\": " << m.replies_err << ",\n";
  o << "  \"imu_fitted\": " << (m.imu_fitted ? "true" : "false") << ",\n";
  o << "  \"imu_max_error_deg\": " << num(m.imu_max_error_deg) << ",\n";
  o << "  \"imu_calibrated_s\": " << (m.imu_calibrated_s < 0 ? std::string("null") : num(m.imu_calibrated_s)) << ",\n";
  o << "  \"imu_gyro_bias_dps\": [" << num(m.imu_gyro_bias_dps.x) << ", " << num(m.imu_gyro_bias_dps.y) << ", "
    << num(m.imu_gyro_bias_dps.z) << "],\n";
  o << "  \"imu_accel_bias_mg\": [" << num(m.imu_accel_bias_mg.x, 1) << ", " << num(m.imu_accel_bias_mg.y, 1) << ", "
    << num(m.imu_accel_bias_mg.z, 1) << "],\n";
  o << "  \"battery_start_v\": " << num(m.battery_start_v) << ",\n";
  o << "  \"battery_min_v\": " << num(m.battery_min_v) << ",\n";
  o << "  \"battery_end_v\": " << num(m.battery_end_v) << ",\n";
  o << "  \"battery_max_a\": " << num(m.battery_max_a) << ",\n";
  o << "  \"battery_used_mah\": " << num(m.battery_used_mah, 2) << ",\n";
 o << "  \"ready_s\": " << num(m.ready_s) << ",\n";
  o << "  \"sim_time_s\": " << num(m.sim_time_s) << ",\n";
  o << "  \"wall_time_s\": " << num(m.wall_time_s) << ",\n";
  o << "  \"cpu_time_s\": " << num(m.cpu_time_s) << ",\n";
  o << "  \"real_time_factor\": " << num(m.real_time_factor, 1) << ",\n";
  o << "  \"real_time_factor_wall\": " << num(m.real_time_factor_wall, 1) << ",\n";
  o << "  \"physics_steps\": " << m.physics_steps << ",\n";
  o << "  \"solver\": " << json_string(m.solver) << ",\n";
  o << "  \"solver_fallbacks\": " << m.solver_fallbacks << ",\n";
  o << "  \"mass_kg\": " << num(m.mass_kg, 3) << ",\n";
  o << "  \"servo_work_j\": " << num(m.servo_work_j, 4) << ",\n";
  o << "  \"cost_of_transport\": " << (m.cost_of_transport < 0 ? std::string("null") : num(m.cost_of_transport, 4)) << ",\n";
  if (m.has_gait) {
    const GaitInfo& g = m.gait;
    o << "  \"gait\": {\"name\": " << json_string(g.gait) << ", \"duty\": " << num(g.duty, 4)
      << ", \"step_height_mm\": " << num(g.step_height_mm, 2) << ", \"step_length_mm\": " << num(g.step_length_mm, 2)
      << ", \"cycle_s\": " << num(g.cycle_s, 3) << ", \"swing\": " << json_string(g.swing)
      << ", \"body_height_mm\": " << num(g.body_height_mm, 2) << ",\n           \"table\": {\"legs\": " << g.leg_count
      << ", \"offsets\": [";
    for (size_t i = 0; i < g.offsets.size(); ++i) o << (i ? ", " : "") << num(g.offsets[i], 6);
    o << "], \"shift_body\": " << (g.shift_body ? "true" : "false")
      << ", \"relabel_by_direction\": " << (g.relabel_by_direction ? "true" : "false") << "},\n"
      << "           \"defaults\": {\"default_gait\": " << json_string(g.default_gait)
      << ", \"stance_depth_mm\": " << num(g.stance_depth_mm, 2) << ", \"foot_radius_mm\": " << num(g.foot_radius_mm, 2)
      << ", \"com_x_mm\": " << num(g.com_x_mm, 2) << ", \"com_y_mm\": " << num(g.com_y_mm, 2)
      << ", \"margin_mm\": " << num(g.margin_mm, 2) << ", \"shift_budget_mm\": " << num(g.shift_budget_mm, 2)
      << ", \"sit_drop_mm\": " << num(g.sit_drop_mm, 2) << ", \"transition_s\": " << num(g.transition_s, 3) << "}";
    if (g.has_bounds) {
      const auto range = [&](const char* key, const double* r) {
        o << ", \"" << key << "\": [" << num(r[0], 2) << ", " << num(r[1], 2) << "]";
      };
      o << ",\n           \"bounds\": {\"swings\": [";
      for (size_t i = 0; i < g.swings.size(); ++i) o << (i ? ", " : "") << json_string(g.swings[i]);
      o << "]";
      range("step_height_mm", g.step_height_range);
      range("step_length_mm", g.step_length_range);
      range("cycle_s", g.cycle_range);
      range("duty", g.duty_range);
      o << ", \"swing_lift_ms\": " << num(g.swing_lift_ms, 3);
      o << "}";
    }
    o << "}\n";
  } else {
    o << "  \"gait\": null\n";
  }
  o << "}\n";
  return o.str();
}

bool write_outputs(const RunResult& r, const std::string& dir, std::string* error) {
  std::string path;
  for (size_t i = 0; i <= dir.size(); ++i)
    if (i == dir.size() || dir[i] == '/') {
      path = dir.substr(0, i);
      if (!path.empty()) mkdir(path.c_str(), 0777);
    }
  struct stat st;
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    *error = "cannot create " + dir;
    return false;
  }
  {
    std::ofstream f(dir + "/metrics.json");
    f << metrics_json(r.metrics);
    if (!f) return *error = "cannot write metrics.json", false;
  }
  {
    std::ofstream f(dir + "/trace.csv");
    f << "t,x_mm,y_mm,z_mm,roll_deg,pitch_deg,yaw_deg,vx_mm_s,vy_mm_s";
    for (int i = 0; i < r.legs; ++i)
      for (int j = 0; j < r.dof; ++j) f << ",q_" << i << "_" << j;
    for (int i = 0; i < r.legs; ++i)
      for (int j = 0; j < r.dof; ++j) f << ",target_" << i << "_" << j;
    for (int i = 0; i < r.legs; ++i) f << ",foot_" << i << "_x,foot_" << i << "_y,foot_" << i << "_z,contact_" << i;
    f << ",com_x_mm,com_y_mm,com_z_mm,sonar_mm,clearance_mm,odo_x_mm,odo_y_mm,odo_yaw_deg";
    f << ",imu_ax_m_s2,imu_ay_m_s2,imu_az_m_s2,imu_gx_rad_s,imu_gy_rad_s,imu_gz_rad_s,imu_roll_deg,imu_pitch_deg";
    f << ",battery_v,battery_a\n";
    for (const TraceRow& row : r.trace) {
      f << num(row.t_s) << ',' << num(row.body.pos_mm.x, 2) << ',' << num(row.body.pos_mm.y, 2) << ','
        << num(row.body.pos_mm.z, 2) << ',' << num(row.body.roll_deg, 2) << ',' << num(row.body.pitch_deg, 2) << ','
        << num(row.body.yaw_deg, 2) << ',' << num(row.body.vel_mm_s.x, 1) << ',' << num(row.body.vel_mm_s.y, 1);
      for (double q : row.q_deg) f << ',' << num(q, 2);
      for (double q : row.target_deg) f << ',' << num(q, 2);
      for (size_t i = 0; i < row.feet_mm.size(); ++i)
        f << ',' << num(row.feet_mm[i].x, 1) << ',' << num(row.feet_mm[i].y, 1) << ',' << num(row.feet_mm[i].z, 1) << ','
          << (row.contact[i] ? 1 : 0);
      f << ',' << num(row.com_mm.x, 2) << ',' << num(row.com_mm.y, 2) << ',' << num(row.com_mm.z, 2);
      f << ',' << num(row.sonar_mm, 1) << ',' << num(row.clearance_mm, 1) << ',' << num(row.odo_x_mm, 2) << ','
        << num(row.odo_y_mm, 2) << ',' << num(row.odo_yaw_deg, 2);
      const ImuReading& u = row.imu_tick;
      f << ',' << num(u.accel_m_s2.x, 4) << ',' << num(u.accel_m_s2.y, 4) << ',' << num(u.accel_m_s2.z, 4) << ','
        << num(u.gyro_rad_s.x, 5) << ',' << num(u.gyro_rad_s.y, 5) << ',' << num(u.gyro_rad_s.z, 5) << ','
        << num(row.imu_roll_deg, 3) << ',' << num(row.imu_pitch_deg, 3) << ',' << num(row.battery_v, 3) << ','
        << num(row.battery_a, 3) << '\n';
    }
    if (!f) return *error = "cannot write trace.csv", false;
  }
  {
    std::ofstream f(dir + "/scene.json");
    f << r.scene_json;
  }
  {
    std::ofstream f(dir + "/robot.log");
    for (const LogLine& l : r.log) f << num(l.t_s) << ' ' << l.text << '\n';
  }
  return true;
}

}  // namespace strider_sim
