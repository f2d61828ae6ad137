// The MPU-6050 on the servo boards' I2C bus (0x68, optional): probed at
// start-up, then one burst of its accelerometer, temperature and gyro
// registers a tick (docs/imu.md).
#ifndef STRIDER_MPU6050_IMU_H
#define STRIDER_MPU6050_IMU_H

#include <stdint.h>

#include "sensing/mpu6050_sample.h"

namespace mpu6050_imu {

// The ranges begin() sets: +-4 g, +-500 deg/s (a walking robot's shakes and
// turns with room to spare, at 8192 LSB/g and 65.5 LSB/(deg/s)).
constexpr strider::Mpu6050AccelRange kAccelRange = strider::Mpu6050AccelRange::k4g;
constexpr strider::Mpu6050GyroRange kGyroRange = strider::Mpu6050GyroRange::k500Dps;

// True when a part answers WHO_AM_I at 0x68; then it is woken (PLL clock),
// its ranges set and its low-pass at 5 Hz (a servo frame's jerk lands at the
// same point of every tick: one reading a tick would alias it, docs/imu.md).
bool begin();
// The 14-byte burst from ACCEL_XOUT_H; false when the transfer failed.
bool read(uint8_t* burst);

}  // namespace mpu6050_imu

#endif
