// The MPU-6050 through Adafruit BusIO's Adafruit_I2CDevice, as the servo
// boards are (pca9685_bus.cpp). Adafruit_MPU6050's own reads (getEvent())
// give float values only, which would link soft-float into the fixed-point
// firmware; the registers it writes in begin() are written here (data sheet
// RM-MPU-6000A, the same register map as Adafruit_MPU6050.h) and the burst is
// converted in integers by lib/strider/sensing/mpu6050_sample.h.
#include "mpu6050_imu.h"  // before Arduino.h (its min/max macros)

#include <Adafruit_I2CDevice.h>
#include <Arduino.h>
#include <Wire.h>

namespace mpu6050_imu {
namespace {

constexpr uint8_t kAddress = 0x68;      // AD0 low
constexpr uint8_t kSmplrtDiv = 0x19;
constexpr uint8_t kConfig = 0x1A;       // DLPF_CFG
constexpr uint8_t kGyroConfig = 0x1B;   // FS_SEL << 3
constexpr uint8_t kAccelConfig = 0x1C;  // AFS_SEL << 3
constexpr uint8_t kAccelXoutH = 0x3B;
constexpr uint8_t kPwrMgmt1 = 0x6B;
constexpr uint8_t kWhoAmI = 0x75;
constexpr uint8_t kWhoAmIValue = 0x68;
constexpr uint8_t kClockPllX = 0x01;    // PWR_MGMT_1: awake, PLL with the X gyro
constexpr uint8_t kDlpf5Hz = 0x06;

Adafruit_I2CDevice g_imu(kAddress, &Wire);

bool write_reg(uint8_t reg, uint8_t value) {
  const uint8_t b[2] = {reg, value};
  return g_imu.write(b, 2);
}

}  // namespace

bool begin() {
  uint8_t reg = kWhoAmI, id = 0;
  if (!g_imu.write_then_read(&reg, 1, &id, 1) || id != kWhoAmIValue) return false;
  return write_reg(kPwrMgmt1, kClockPllX) && write_reg(kSmplrtDiv, 9) &&  // 1 kHz / 10: 100 Hz
         write_reg(kConfig, kDlpf5Hz) && write_reg(kGyroConfig, uint8_t(uint8_t(kGyroRange) << 3)) &&
         write_reg(kAccelConfig, uint8_t(uint8_t(kAccelRange) << 3));
}

bool read(uint8_t* burst) {
  const uint8_t reg = kAccelXoutH;
  return g_imu.write_then_read(&reg, 1, burst, strider::kMpu6050BurstBytes);
}

}  // namespace mpu6050_imu
