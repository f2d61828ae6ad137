// run_scenario: one scenario in one world with one driver, stepped in
// lock-step (the controller runs up to each physics step's time, then the
// world steps with the pulses it produced), and the metrics of the run.
#pragma once

#include <string>
#include <vector>

#include "driver.h"
#include "scenario.h"
#include "sim_sensors.h"
#include "world.h"

namespace strider_sim {

struct RunOptions {
  std::string firmware_elf;     // empty: library mode
  WorldConfig world;
  GaitOverrides gait;           // library mode only (driver.h)
  double trace_period_s = 0.02; // one trace row per control tick
  // The IMU and the battery (sim_sensors.h); the scenario's `imu on` fits
  // the IMU too.
  SensorOptions sensors;
};

struct TraceRow {
  double t_s = 0;
  BodyState body;               // yaw unwrapped
  std::vector<double> q_deg;    // joint k = leg * dof + j, seed convention
  std::vector<double> target_deg;
  std::vector<Vec> feet_mm;
  std::vector<bool> contact;
  Vec com_mm;                   // whole robot's centre of mass, world [mm]
  double sonar_mm = -1;
  double clearance_mm = -1;     // body box to the nearest obstacle; -1 without obstacles
  double odo_x_mm = 0, odo_y_mm = 0, odo_yaw_deg = 0;
  ImuReading imu;                       // what the IMU reads now (noise and offsets included)
  ImuReading imu_tick;                  // what the filter took: its mean over the last tick (trace.csv's imu_*)
  double imu_roll_deg = 0, imu_pitch_deg = 0;  // the attitude filter on it
  double battery_v = 0, battery_a = 0;  // pack terminals, pack current
  double servo_work_j = 0;      // since the start (World::servo_work_j)
};

struct Metrics {
  std::string robot, mode;
  std::string solver;             // "mlcp" (PGS when it gives up on a step) or "pgs"
  double distance_mm = 0;         // start -> end, horizontal
  double path_mm = 0;             // along the trace
  double speed_mm_s = 0;          // best 2 s window: displacement / 2 s
  double mean_speed_mm_s = 0;     // distance / duration
  double heading_change_deg = 0;  // unwrapped, anticlockwise positive
  double yaw_rate_deg_s = 0;      // best 2 s window of |heading change| / 2 s
  double turn_360_s = -1;         // first turn past 1 deg -> 360 deg; -1: never
  double lateral_drift_mm = 0;    // off the main axis of the motion (body frame at the start)
  double body_drift_mm = 0;       // the same in the body frame at each instant (crabbing; body_track.h)
  double max_tilt_deg = 0;
  bool fell = false;
  bool has_obstacles = false;
  double min_clearance_mm = 0;        // body box
  double min_robot_clearance_mm = 0;  // any part
  int collisions = 0;
  double ready_s = 0;               // metrics start: stood up and settled after the power-up, or the first motion command
  double sim_time_s = 0, wall_time_s = 0, cpu_time_s = 0;
  double real_time_factor = 0;      // simulated / CPU time of this process (one core)
  double real_time_factor_wall = 0; // simulated / wall-clock time
  long physics_steps = 0;           // Bullet steps simulated
  long solver_fallbacks = 0;        // steps the MLCP solver handed to PGS
  bool has_odometry = false;
  double odometry_mm = 0;          // the gait engine's dead reckoning (library mode)
  double odometry_error_pct = 0;   // (odometry - distance along it) / odometry * 100 (seed 003 eq 16)
  double final_x_mm = 0, final_y_mm = 0, final_yaw_deg = 0;
  int replies_ok = 0, replies_err = 0;
  bool imu_fitted = false;
  double imu_max_error_deg = 0;     // attitude filter against the body, roll or pitch, from ready_s and the gyro calibration
  double imu_calibrated_s = -1;     // the gyro's offset measured (sim_sensors.h); -1: never
  Vec imu_gyro_bias_dps, imu_accel_bias_mg;  // the IMU's offsets (drawn or given)
  double battery_start_v = 0, battery_min_v = 0, battery_end_v = 0;  // under load
  double battery_max_a = 0, battery_used_mah = 0;
  double mass_kg = 0;               // the model's
  double servo_work_j = 0;          // the servos' mechanical work over the window [J]
  double cost_of_transport = -1;    // servo_work_j / (mass g distance); -1: under 10 mm walked
  bool has_gait = false;            // library mode: the gait walked at the end
  GaitInfo gait;
};

struct LogLine {
  double t_s;
  std::string text;
};

struct RunResult {
  bool ok = false;
  std::string error;
  Metrics metrics;
  int legs = 0, dof = 0;
  std::vector<TraceRow> trace;
  std::vector<LogLine> log;  // every line the robot sent
  std::vector<ObstacleBox> obstacles;
  std::string scene_json;    // what a renderer needs: body, hips, obstacles
};

RunResult run_scenario(const Scenario& scenario, const RunOptions& options);

// The metrics that come from r.trace (distance, speeds, heading, drifts; from
// r.metrics.ready_s on), into r.metrics; run_scenario() ends with it.
void compute_metrics(const Scenario& scenario, RunResult& r);

// DIR/metrics.json, DIR/trace.csv, DIR/robot.log, DIR/scene.json (creates DIR).
bool write_outputs(const RunResult& r, const std::string& dir, std::string* error);
std::string metrics_json(const Metrics& m);

}  // namespace strider_sim
