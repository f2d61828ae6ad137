// Driver: what runs the robot's control code in lock-step with the world.
// Two implementations produce the same thing, a pulse width per global
// PCA9685 channel: LibraryDriver (lib/strider's RobotApp compiled natively)
// and FirmwareDriver (the firmware ELF on a simulated ATmega2560).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "imu_model.h"
#include "robots/robot_model.h"
#include "servo_model.h"

namespace strider_sim {

// The HC-SR04's view of the world: distance to the nearest echo [mm], or a
// negative value when nothing is within range. Called when the robot pings.
using RangeFn = std::function<double()>;

// What the robot's own sensors read, set before each advance_to(): the
// MPU-6050 (when fitted) and the battery divider's output on an analog pin.
struct SensorInputs {
  bool imu_fitted = false;   // an MPU-6050 at 0x68 (firmware mode: vbench's, fed every physics step)
  ImuReading imu;            // body frame = the chip's, mounted flat with its x arrow forward
  int battery_pin = 0;       // A0..A7
  double battery_pin_v = 0;  // [V]
};

// What the robot walks with now (library mode): the gait, its parameters
// and the body height, for metrics.json.
struct GaitInfo {
  std::string gait, swing;
  double duty = 0, step_height_mm = 0, step_length_mm = 0, cycle_s = 0;
  double body_height_mm = 0;  // the standing height with the `height` offset
  // The rest of the gait table (gait_library.h) and of the model's gait
  // defaults (gait_params.h), for writing a tuned row in their formats.
  int leg_count = 0;
  std::vector<double> offsets;
  bool shift_body = false, relabel_by_direction = false;
  std::string default_gait;
  double stance_depth_mm = 0, foot_radius_mm = 0, com_x_mm = 0, com_y_mm = 0, margin_mm = 0, shift_budget_mm = 0;
  double sit_drop_mm = 0, transition_s = 0;
  // What the robot accepts of each live parameter for this gait (`set`,
  // gait_tuner.h): [lo, hi] in the parameter's unit, the swings allowed.
  bool has_bounds = false;
  double step_height_range[2] = {0, 0}, step_length_range[2] = {0, 0}, cycle_range[2] = {0, 0};
  double duty_range[2] = {0, 0};
  double swing_lift_ms = 0;  // the servos' lift alone: a cycle c takes duties up to 1 - lift / c
  std::vector<std::string> swings;
};

class Driver {
 public:
  virtual ~Driver() = default;
  virtual const char* mode() const = 0;  // "library" or "firmware"
  // Power-up at simulated time 0. False (and *error) when the robot cannot run.
  virtual bool begin(std::string* error) = 0;
  // Queues bytes on the Bluetooth link, arriving from at_us on at the link's
  // baud rate (9600 by default: 1.04 ms per byte).
  virtual void send(const std::string& bytes, uint64_t at_us) = 0;
  // Runs the robot's controller up to simulated time now_us.
  virtual void advance_to(uint64_t now_us) = 0;
  // The sensors' readings from now on (a driver ignores what its robot has no use for).
  virtual void set_sensors(const SensorInputs& s) { sensors_ = s; }
  const SensorInputs& sensors() const { return sensors_; }
  // The bandwidth the robot set its IMU's low-pass filter to [Hz]; 0: not
  // known (library mode, or no IMU), the IMU model keeps its own.
  virtual double imu_bandwidth_hz() const { return 0; }
  // What every channel sends now (kMaxChannels entries).
  virtual const ChannelPulse* pulses() const = 0;
  // Lines the robot sent on either port since the last call (without endings).
  virtual std::vector<std::string> take_lines() = 0;
  // The gait engine's own odometry (dead reckoning from the commanded feet):
  // only the library driver can see it. x, y [mm], yaw [rad].
  virtual bool odometry(double* x_mm, double* y_mm, double* yaw_rad) const {
    (void)x_mm, (void)y_mm, (void)yaw_rad;
    return false;
  }
  // The gait parameters in use (library mode only).
  virtual bool gait_info(GaitInfo* info) const {
    (void)info;
    return false;
  }

 protected:
  SensorInputs sensors_;  // library mode: for the robot's code once it reads an IMU and a battery
};

// Gait defaults to walk instead of the model's (gait_params.h), for trying a
// gait's step and cycle without a rebuild; 0 (or an empty swing): the
// model's value. Library mode only: a firmware has its defaults built in.
struct GaitOverrides {
  double step_height_mm = 0;  // swing apex above the ground [mm]
  double step_length_mm = 0;  // preferred stride [mm]
  double cycle_s = 0;         // cycle time at low speed [s]
  std::string swing;          // swing shape: rectangle, semicircle, ellipse, cycloid, parabola, bezier
  // Fraction of the cycle each foot is on the ground, for whichever gait
  // the robot walks (its default, then every `gait NAME`): the gait table's
  // duty with the same leg offsets. A gait it would leave without support
  // (or without the four-foot windows its body shift needs) keeps its own,
  // and the robot's log says so.
  double duty = 0;
  bool any() const {
    return step_height_mm > 0 || step_length_mm > 0 || cycle_s > 0 || !swing.empty() || duty > 0;
  }
};


// The library: strider::RobotApp<float> with an in-memory EEPROM (erased,
// so the robot boots on default settings) and a PCA9685 with oscillator osc_hz.
// With `gait` overrides, the walker is configured again with them before the
// robot stands up (begin() fails when the walker refuses them).
std::unique_ptr<Driver> make_library_driver(const strider::RobotModel& model, double osc_hz, RangeFn range,
                                            const GaitOverrides& gait = GaitOverrides());

// The firmware ELF on the virtual Mega; nullptr and *error when this build
// has no virtual Mega or the ELF does not load.
std::unique_ptr<Driver> make_firmware_driver(const std::string& elf_path, const strider::RobotModel& model,
                                             double osc_hz, RangeFn range, std::string* error);

}  // namespace strider_sim
