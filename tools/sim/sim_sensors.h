// RobotSensors: the robot's IMU and battery in the simulator, stepped with
// the world (imu_model.h, battery_model.h), what the drivers hand the robot
// (SensorInputs: vbench's MPU-6050 and ADC in firmware mode), and the
// attitude filter a firmware runs on the IMU (lib/strider/sensing), for the
// trace: roll and pitch as the robot would see them. The filter takes the
// mean of the readings over each tick, as a firmware that reads the part's
// FIFO (or several samples a tick) does: one sample a tick aliases the jerk
// the servos give the body at every tick into a false rate (docs/imu.md).
#pragma once

#include "battery_model.h"
#include "driver.h"
#include "imu_model.h"
#include "robots/robot_model.h"
#include "sensing/attitude_filter.h"
#include "sensing/gyro_calibration.h"
#include "world.h"

namespace strider_sim {

// Changes to the model's pack (battery_for()); unset fields keep its value.
struct BatteryOverrides {
  int cells = 0;
  double capacity_mah = 0;
  double internal_ohm = -1;
  double soc = -1;
  double divider = 0;
  int adc_pin = -1;
  // top, with these values where top has none (the scenario's pack under
  // the command line's options).
  BatteryOverrides under(BatteryOverrides top) const {
    if (top.cells <= 0) top.cells = cells;
    if (top.capacity_mah <= 0) top.capacity_mah = capacity_mah;
    if (top.internal_ohm < 0) top.internal_ohm = internal_ohm;
    if (top.soc < 0) top.soc = soc;
    if (top.divider <= 0) top.divider = divider;
    if (top.adc_pin < 0) top.adc_pin = adc_pin;
    return top;
  }
  BatteryConfig apply(BatteryConfig c) const {
    if (cells > 0) c.cells = cells;
    if (capacity_mah > 0) c.capacity_mah = capacity_mah;
    if (internal_ohm >= 0) c.internal_ohm = internal_ohm;
    if (soc >= 0) c.soc = soc;
    if (divider > 0) c.divider = divider;
    if (adc_pin >= 0) c.adc_pin = adc_pin;
    return c;
  }
};

struct SensorOptions {
  bool imu_fitted = false;        // firmware mode: vbench's MPU-6050 at 0x68 answers
  ImuConfig imu;
  BatteryOverrides battery;
  double filter_period_s = 0.02;  // the firmware's tick
  // The filter takes the mean of the readings over each tick (true), or only
  // the one at the tick, as a firmware reading the part once a tick does.
  bool filter_takes_mean = true;
  // The filter's bias starts from the gyro's mean over the first still
  // second (strider::GyroCalibration at the tick: 50 readings within 2 deg/s
  // of each other), as a firmware calibrates at power-up, and the filter
  // starts again from the accelerometer then; false: from 0, the filter's
  // own bias estimate only.
  bool gyro_calibration = true;
};

class RobotSensors {
 public:
  RobotSensors(const strider::RobotModel& model, const SensorOptions& options);
  // After each physics step of dt [s].
  void step(const World& world, double dt);
  // The part's low-pass bandwidth from now on [Hz] (the firmware's DLPF_CFG).
  void set_imu_bandwidth_hz(double hz) { imu_.set_bandwidth_hz(hz); }
  SensorInputs inputs() const;

  const ImuModel& imu() const { return imu_; }
  // What the filter took at its last update: the mean reading over the tick.
  const ImuReading& filter_input() const { return filter_input_; }
  const BatteryModel& battery() const { return battery_; }
  double servo_current_a() const { return servo_current_a_; }  // at the BEC's output [A]
  // When the gyro's offset was measured [s]; negative: not (yet).
  double calibrated_s() const { return calibrated_s_; }
  // The attitude filter's estimate [deg] (0 until its first update).
  double roll_deg() const;
  double pitch_deg() const;
  const SensorOptions& options() const { return options_; }

 private:
  const strider::RobotModel& model_;
  SensorOptions options_;
  ImuModel imu_;
  BatteryModel battery_;
  strider::AttitudeFilter<float> filter_;
  double time_s_ = 0, next_filter_s_ = 0;
  double tick_sum_[6] = {0, 0, 0, 0, 0, 0};  // readings since the last filter update
  int tick_samples_ = 0;
  strider::GyroCalibration<float> calibration_;
  ImuReading filter_input_;
  double servo_current_a_ = 0;
  double calibrated_s_ = -1;
};

}  // namespace strider_sim
