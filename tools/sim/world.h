// World: one robot model as a Bullet btMultiBody on a ground plane with box
// obstacles, its joints driven by servo models from PCA9685 pulse widths.
//
// Units inside Bullet are SI (m, kg, s); everything this class hands out is
// in millimetres and degrees like the rest of Strider. World frame: x, y on
// the ground, z up; the robot starts at the origin facing +x.
// See docs/simulator.md for the masses, friction and servo figures.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "leg_geometry.h"
#include "robots/robot_model.h"
#include "servo_model.h"

namespace strider_sim {

// An axis-aligned box resting on the ground, centre at (x, y) [mm].
struct ObstacleBox {
  double x_mm = 0, y_mm = 0;
  double sx_mm = 0, sy_mm = 0, sz_mm = 0;  // full sizes [mm]
};

// The constraint solver. PGS (Bullet's default, iterative): with a body ten
// to twenty times heavier than a leg and four feet down, 40 iterations leave
// a residual that sags loaded knees by 1.5-5 deg and lets stance feet creep
// backward (mammal8's walk went backward on it; docs/simulator.md). MLCP
// (default): the same contact and motor problem solved exactly each step
// (Dantzig; Bullet falls back to PGS for a step it cannot solve), and no
// slower than 40 PGS iterations for any model here.
enum class Solver { kPgs, kMlcp };

struct WorldConfig {
  // 4 ms and 40 iterations: within ~3 % of a 1 ms / 50 iteration reference on
  // every scenario (docs/simulator.md), and hexapod18 runs 24x real time; at
  // 2 ms / 25 the solver's cost per simulated second is twice as high.
  double step_s = 0.004;           // physics step [s]
  int solver_iterations = 40;
  Solver solver = Solver::kMlcp;
  double solver_residual = 0;      // early exit of the solver's iterations (0: run them all)
  // Constraint force mixing added to every row's diagonal (Bullet's
  // m_globalCfm, s/kg; the diagonal grows by cfm / step). Four feet on the
  // ground and eight stiff motors make the exact solver's matrix singular or
  // nearly so: without it Dantzig gave up on 10-60 % of mammal8's steps and
  // Bullet solved them with PGS (`solver_fallbacks`). 1e-6 is a compliance of
  // 1 / (cfm x step), 2.5e8 N/m at 4 ms: regularisation, not a soft contact.
  double solver_cfm = 1e-6;
  double foot_friction = 0.8;      // rubber foot caps on a laminate (Formica) board
  // 0: each foot is a ball of the model's foot radius. > 0: a capsule of that
  // radius across the leg (along its last joint's axis), this far from the
  // foot point to each side [mm]: a rubber tube over the shank's end, for
  // trying wider feet (docs/simulator.md, mammal8 item 9).
  double foot_pad_half_mm = 0;
  double body_friction = 0.4;      // aluminium or plastic on the same board
  double osc_hz = 25e6;            // the simulated PCA9685 boards' oscillator [Hz]
  double link_density_g_mm = 0.1;  // leg brackets and links [g per mm of link]
  // Joint angles to start from (joint k = leg * dof + j, seed convention
  // [rad]); empty: the model's standing pose.
  std::vector<double> initial_joints_rad;
};

struct BodyState {
  Vec pos_mm;                 // body centre, world frame [mm]
  double roll_deg = 0, pitch_deg = 0, yaw_deg = 0;  // ZYX Euler angles [deg]
  double tilt_deg = 0;        // angle of body z from world z [deg]
  Vec vel_mm_s;               // velocity of the body part's COM (Bullet's base) [mm/s]
};

// How a point fixed to the body moves: what an IMU there senses
// (imu_model.h turns it into readings).
struct BodyMotion {
  Vec vel_mm_s;          // velocity of the point, world frame [mm/s]
  Vec omega_body_rad_s;  // the body's angular velocity, body frame [rad/s]
  double rot[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // body -> world rotation: rot * v_body = v_world
  Vec gravity_m_s2;      // the world's gravity, world frame [m/s^2]
};

class World {
 public:
  World(const strider::RobotModel& model, const WorldConfig& cfg, const std::vector<ObstacleBox>& obstacles);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  const strider::RobotModel& model() const { return model_; }
  const WorldConfig& config() const { return cfg_; }
  double time_s() const { return double(steps_) * cfg_.step_s; }
  int joint_count() const { return joints_; }

  // The pulses every global channel sends from now on (kMaxChannels).
  void set_pulses(const ChannelPulse* pulses);
  // One physics step of config().step_s.
  void step();

  // Roll, pitch and tilt against gravity (on a ramp: not against the ground);
  // position and yaw in the world frame, whose x, y are the ground's.
  BodyState body() const;
  // Joint j of leg `leg`, seed convention [rad]; and the servo's target.
  double joint_rad(int leg, int j) const;
  double joint_target_rad(int leg, int j) const;
  // The foot point (tip of the last link), world frame [mm].
  Vec foot_mm(int leg) const;
  // True when the foot touches the ground this step.
  bool foot_contact(int leg) const;
  // HC-SR04: the nearest hit of its beam [mm], or a negative value when
  // nothing is within 3 m. Origin and aim in sensor_pose().
  double sonar_mm() const;
  // Sensor origin in the body frame [mm] (centre of the body's front face,
  // 5 mm ahead of it); the beam points along body +x.
  Vec sonar_origin_body_mm() const;
  // Closest distance [mm] between the body box (or every robot part) and any
  // obstacle; a large value without obstacles. Negative: penetration.
  double body_clearance_mm() const;
  double robot_clearance_mm() const;
  // Robot parts touching an obstacle this step.
  int obstacle_contacts() const;
  // The body box touches the ground this step.
  bool body_on_ground() const;
  // Every servo receives pulses (the firmware's soft start is over).
  bool all_servos_on() const;
  // Centre of mass of the whole robot, world frame [mm].
  Vec com_mm() const;
  // The motion of a point fixed in the body, given in the body frame from
  // the body centre [mm] (world_motion.cpp).
  BodyMotion body_motion(const Vec& point_body_mm) const;
  // A joint's servo in the last step: the torque its motor applied along the
  // joint axis [N m] (what it holds and moves), the joint's speed [rad/s],
  // and whether it receives pulses.
  double joint_torque_nm(int leg, int j) const;
  double joint_speed_rad_s(int leg, int j) const;
  bool joint_on(int leg, int j) const;
  // The ground slopes slope_deg, rising toward uphill_deg (world frame, 0:
  // +x): gravity is tilted instead of the plane, so the world frame stays the
  // ground's and everything on it (start pose, obstacles) is as on the flat
  // (world_events.cpp).
  void set_ramp(double slope_deg, double uphill_deg);
  // An impulse [N s], world frame, at the centre of the body's top face,
  // given over the next step.
  void shove(const Vec& impulse_ns);
  // Sets the robot back on its feet where its body is, heading kept, body
  // parallel to the ground, legs in the starting (sitting) pose, at rest.
  void upright();

  // Steps the exact (MLCP) solver could not solve, so Bullet solved them
  // with PGS instead (always 0 with Solver::kPgs).
  long solver_fallbacks() const;
  // Mechanical work of the servos since the start [J]: the sum over steps
  // and joints of |motor torque x joint speed| x step (a hobby servo does
  // not recover the work a load does on it, so negative work counts too).
  double servo_work_j() const { return servo_work_j_; }

 private:
  struct Impl;
  const strider::RobotModel& model_;
  WorldConfig cfg_;
  int joints_ = 0;
  long steps_ = 0;
  double servo_work_j_ = 0;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strider_sim
