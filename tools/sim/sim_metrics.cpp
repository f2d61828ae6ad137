// The metrics of a run (metrics.json) and the files strider-sim writes: metrics.json,
// trace.csv, scene.json and robot.log.
#include "sim_run.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "body_track.h"

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
