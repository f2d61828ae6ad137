// ImuModel: an MPU-6050 fixed to the robot's body (docs/imu.md).
//
// What it reads, from the body's motion each physics step (World::
// body_motion): the specific force at its position, a - g (the point's
// acceleration, a finite difference of its velocity over the step, minus
// gravity, so +9.81 m/s^2 along up at rest), and the body's angular rate,
// both in the body frame, which is the chip's frame when it is mounted flat
// with its x arrow forward. Then the part's errors, each axis on its own:
// - white noise: the data sheet's spectral density over the bandwidth of its
//   low-pass filter, sigma = density x sqrt(bandwidth): 0.005 deg/s/rtHz and
//   400 ug/rtHz (product specification rev 3.4, tables 6.1 and 6.2) over the
//   260 Hz the Adafruit library selects: 0.081 deg/s and 6.4 mg rms;
// - a constant offset: by default drawn (seeded) uniformly within the data
//   sheet's initial tolerances, +-20 deg/s zero-rate output and +-50 mg (x,
//   y), +-80 mg (z) accelerometer offset: a part as it comes, uncalibrated;
//   or given;
// - its low-pass filter (first order at the given bandwidth) on the motion.
// Not modelled: quantisation and clipping (vbench's MPU-6050 does both at
// the ranges the firmware sets), temperature drift, cross-axis sensitivity,
// scale errors.
#pragma once

#include <cstdint>
#include <random>

#include "world.h"

namespace strider_sim {

struct ImuConfig {
  Vec position_body_mm;              // where it sits: body frame, from the body centre [mm]
  double gyro_noise_dps_rthz = 0.005;  // rate noise spectral density [deg/s/rtHz]
  double accel_noise_ug_rthz = 400;    // accelerometer noise spectral density [ug/rtHz]
  // The part's digital low-pass filter (CONFIG.DLPF_CFG): its bandwidth
  // [Hz] smooths the signal (first order, at the physics step) and sets the
  // noise's spread. 250 Hz and up is DLPF_CFG 0 (what Adafruit's begin()
  // selects, 260 Hz in its names): no filter; in firmware mode the
  // firmware's own setting replaces it (set_bandwidth_hz).
  double bandwidth_hz = 260;
  bool random_bias = true;             // draw the offsets within the tolerances below
  double gyro_bias_max_dps = 20;       // zero-rate output tolerance, each axis [deg/s]
  Vec accel_bias_max_mg{50, 50, 80};   // accelerometer offset tolerance, each axis [mg]
  Vec gyro_bias_dps;                   // the offsets when not drawn [deg/s]
  Vec accel_bias_mg;                   // [mg]
  double temp_c = 25;                  // die temperature [deg C]
  uint32_t seed = 1;                   // noise and drawn offsets
  // No noise and no offset: the ideal readings.
  static ImuConfig ideal() {
    ImuConfig c;
    c.gyro_noise_dps_rthz = c.accel_noise_ug_rthz = 0;
    c.random_bias = false;
    return c;
  }
};

struct ImuReading {
  Vec accel_m_s2;  // specific force, body frame [m/s^2]
  Vec gyro_rad_s;  // angular rate, body frame [rad/s]
  double temp_c = 25;
};

class ImuModel {
 public:
  explicit ImuModel(const ImuConfig& config = ImuConfig());

  // The reading after a physics step of dt [s] that ended in motion m (the
  // first call sees no acceleration: the body's velocity before is unknown).
  const ImuReading& update(const BodyMotion& m, double dt);
  const ImuReading& reading() const { return reading_; }
  // The same without the part's errors.
  const ImuReading& ideal() const { return ideal_; }
  const ImuConfig& config() const { return config_; }
  void set_bandwidth_hz(double hz) { config_.bandwidth_hz = hz; }
  // DLPF_CFG 0..7 -> the gyro's bandwidth [Hz] (register map rev 4.2, 4.3).
  static double dlpf_bandwidth_hz(int dlpf_cfg);
  // The offsets in use (drawn or given).
  const Vec& gyro_bias_dps() const { return gyro_bias_dps_; }
  const Vec& accel_bias_mg() const { return accel_bias_mg_; }

 private:
  ImuConfig config_;
  std::mt19937 rng_;
  Vec gyro_bias_dps_, accel_bias_mg_;
  bool have_velocity_ = false;
  bool have_filtered_ = false;
  Vec lp_accel_, lp_gyro_;  // the low-pass filter's state
  Vec last_vel_mm_s_;
  ImuReading reading_, ideal_;
};

}  // namespace strider_sim
