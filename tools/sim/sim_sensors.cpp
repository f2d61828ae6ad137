// RobotSensors (see sim_sensors.h).
#include "sim_sensors.h"

namespace strider_sim {

RobotSensors::RobotSensors(const strider::RobotModel& model, const SensorOptions& options)
    : model_(model), options_(options), imu_(options.imu), battery_(options.battery.apply(battery_for(model))) {}

void RobotSensors::step(const World& world, double dt) {
  time_s_ += dt;
  const ImuReading& r = imu_.update(world.body_motion(options_.imu.position_body_mm), dt);
  double amps = 0;
  for (int i = 0; i < model_.leg_count; ++i)
    for (int j = 0; j < model_.dof(); ++j) {
      const strider::ServoPart part = model_.servo[j];
      amps += servo_supply_current_a(servo_model(part), servo_electrical(part), world.joint_torque_nm(i, j),
                                     world.joint_speed_rad_s(i, j), world.joint_on(i, j), battery_.config().servo_volts);
    }
  servo_current_a_ = amps;
  battery_.step(amps, dt);
  const double v[6] = {r.accel_m_s2.x, r.accel_m_s2.y, r.accel_m_s2.z, r.gyro_rad_s.x, r.gyro_rad_s.y, r.gyro_rad_s.z};
  for (int i = 0; i < 6; ++i) tick_sum_[i] += v[i];
  ++tick_samples_;
  if (time_s_ >= next_filter_s_ - 1e-9) {
    float m[6];
    for (int i = 0; i < 6; ++i) {
      m[i] = float(options_.filter_takes_mean ? tick_sum_[i] / tick_samples_ : v[i]);
      tick_sum_[i] = 0;
    }
    tick_samples_ = 0;
    filter_input_.accel_m_s2 = Vec{m[0], m[1], m[2]};
    filter_input_.gyro_rad_s = Vec{m[3], m[4], m[5]};
    filter_input_.temp_c = r.temp_c;
    const strider::Vec3<float> gyro(m[3], m[4], m[5]);
    if (options_.gyro_calibration && calibrated_s_ < 0 &&
        calibration_.add(gyro) == strider::GyroCalibrationStatus::kDone) {
      // Still: start again from the accelerometer's attitude, with the offset.
      filter_.reset();
      filter_.set_gyro_bias(calibration_.offset());
      calibrated_s_ = time_s_;
    }
    filter_.update(strider::Vec3<float>(m[0], m[1], m[2]), gyro, float(options_.filter_period_s));
    next_filter_s_ += options_.filter_period_s;
  }
}

SensorInputs RobotSensors::inputs() const {
  SensorInputs s;
  s.imu_fitted = options_.imu_fitted;
  s.imu = imu_.reading();
  s.battery_pin = battery_.config().adc_pin;
  s.battery_pin_v = battery_.pin_volts();
  return s;
}

double RobotSensors::roll_deg() const { return double(filter_.roll_rad()) * 180.0 / M_PI; }
double RobotSensors::pitch_deg() const { return double(filter_.pitch_rad()) * 180.0 / M_PI; }

}  // namespace strider_sim
