// The sensing layer instantiated for the ATmega2560 (avr-g++ 5.4, gnu++14):
// every template compiled, not only declared. Built twice: with
// STRIDER_SENSING_FIXED_ONLY, Fixed alone, whose ELF must link no soft-float
// routine (a fixed-point firmware computes in integers only); without it,
// float too.
#include <stdint.h>

#include "sensing/attitude_filter.h"
#include "sensing/gyro_calibration.h"
#include "sensing/level_calibration.h"
#include "sensing/mpu6050_sample.h"

namespace {

volatile uint8_t g_bytes[strider::kMpu6050BurstBytes];
volatile int32_t g_sink;

template <typename S>
int32_t run(strider::AttitudeFilter<S>& f, strider::GyroCalibration<S>& cal) {
  uint8_t burst[strider::kMpu6050BurstBytes];
  for (uint8_t i = 0; i < strider::kMpu6050BurstBytes; ++i) burst[i] = g_bytes[i];
  const strider::ImuSample<S> s =
      strider::mpu6050_sample<S>(burst, strider::Mpu6050AccelRange(g_bytes[0] & 3), strider::Mpu6050GyroRange(g_bytes[1] & 3));
  if (cal.add(s.gyro_rad_s) == strider::GyroCalibrationStatus::kDone) f.set_gyro_bias(cal.offset());
  static strider::LevelCalibration<S> level;
  int8_t x = 0, y = 0;
  if (!level.running()) level.start();
  if (level.add(s, f.gyro_bias_rad_s(), &x, &y) == strider::LevelCalStatus::kDone) g_sink = x + y;
  const strider::AttitudeStatus st = f.update(s, strider::scalar<S>(0.02));
  const S sum = f.roll_rad() + f.pitch_rad() + f.tilt_rad() + f.gyro_bias_rad_s().x + s.temp_c;
  return int32_t(st) + (sum < S() ? 1 : 0) + (f.has_attitude() ? 2 : 0);
}

}  // namespace

int main() {
  strider::AttitudeFilter<strider::Fixed> fixed;
  strider::GyroCalibration<strider::Fixed> fixed_cal;
  int32_t acc = 0;
#ifndef STRIDER_SENSING_FIXED_ONLY
  strider::AttitudeFilter<float> flt;
  strider::GyroCalibration<float> flt_cal;
#endif
  for (;;) {
    acc += run(fixed, fixed_cal);
#ifndef STRIDER_SENSING_FIXED_ONLY
    acc += run(flt, flt_cal);
#endif
    g_sink = acc;
  }
}
