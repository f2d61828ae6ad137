// vbench's MPU-6050 register model (tools/vbench/mpu6050.h) on its own:
// power-on values, resets, pointer auto-increment, read-only registers, the
// sample clock from SMPLRT_DIV and CONFIG, DATA_RDY, sleep, scales,
// rounding and clipping; and the script directives that feed it and the ADC.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mpu6050.h"
#include "script.h"

using strider_vmega::Mpu6050;
using strider_vmega::ScriptEvent;

namespace {

constexpr double kG = 9.80665;

void write(Mpu6050& m, uint8_t reg, std::vector<uint8_t> bytes, uint64_t now_us = 0) {
  m.begin_write();
  m.write_byte(reg, now_us);
  for (uint8_t b : bytes) m.write_byte(b, now_us);
}

std::vector<uint8_t> read(Mpu6050& m, uint8_t reg, int n, uint64_t now_us) {
  m.begin_write();
  m.write_byte(reg, now_us);
  m.begin_read(now_us);  // repeated START, SLA+R
  std::vector<uint8_t> out;
  for (int i = 0; i < n; ++i) out.push_back(m.read_byte());
  return out;
}

int16_t word(const std::vector<uint8_t>& b, size_t i) { return int16_t(uint16_t(b[2 * i]) << 8 | b[2 * i + 1]); }

TEST(Mpu6050Model, PowerOnValuesAndDeviceReset) {
  Mpu6050 m;
  for (int r = 0; r < 0x80; ++r) {
    const uint8_t want = r == Mpu6050::kPwrMgmt1 ? 0x40 : r == Mpu6050::kWhoAmI ? 0x68 : 0;
    EXPECT_EQ(m.reg(uint8_t(r)), want) << std::hex << r;
  }
  EXPECT_TRUE(m.sleeping());
  Mpu6050 high(0x69);
  EXPECT_EQ(high.reg(Mpu6050::kWhoAmI), 0x68);  // WHO_AM_I ignores AD0
  write(m, Mpu6050::kSmplrtDiv, {7, 3, 0x18, 0x10});
  write(m, Mpu6050::kPwrMgmt1, {0x01});
  EXPECT_EQ(m.reg(Mpu6050::kSmplrtDiv), 7);
  EXPECT_EQ(m.gyro_range_dps(), 2000);
  EXPECT_EQ(m.accel_range_g(), 8);
  EXPECT_FALSE(m.sleeping());
  write(m, Mpu6050::kPwrMgmt1, {0x80});
  EXPECT_EQ(m.device_resets(), 1);
  EXPECT_EQ(m.reg(Mpu6050::kPwrMgmt1), 0x40);  // DEVICE_RESET reads 0 at once, asleep
  EXPECT_EQ(m.reg(Mpu6050::kSmplrtDiv), 0);
  EXPECT_EQ(m.gyro_range_dps(), 250);
  write(m, Mpu6050::kSignalPathReset, {0x07});
  EXPECT_EQ(m.reg(Mpu6050::kSignalPathReset), 0);
}

TEST(Mpu6050Model, BurstReadIsCoherentBigEndianAndAutoIncrements) {
  Mpu6050 m;
  write(m, Mpu6050::kPwrMgmt1, {0x00}, 1000);
  m.set_accel_m_s2(0.5 * kG, -kG, 2 * kG);  // 2 g clips at +-2 g
  m.set_gyro_rad_s(1.0, -1.0, 0.0);
  m.set_temp_c(36.53 + 1.0);
  const std::vector<uint8_t> b = read(m, Mpu6050::kAccelXoutH, 14, 2000);
  EXPECT_EQ(word(b, 0), 8192);
  EXPECT_EQ(word(b, 1), -16384);
  EXPECT_EQ(word(b, 2), 32767);
  EXPECT_EQ(word(b, 3), 340);
  EXPECT_EQ(word(b, 4), int16_t(std::lround(131 * 57.29577951308232)));
  EXPECT_EQ(word(b, 5), -int16_t(std::lround(131 * 57.29577951308232)));
  EXPECT_EQ(word(b, 6), 0);
  EXPECT_EQ(m.pointer(), Mpu6050::kGyroZoutL + 1);
  EXPECT_EQ(Mpu6050::to_word(-1e9), -32768);
  EXPECT_EQ(Mpu6050::to_word(std::nan("")), -32768);
  EXPECT_EQ(Mpu6050::to_word(-0.5), -1);  // rounds half away from zero
  // Writes to read-only registers are ignored; the pointer still moves on.
  write(m, Mpu6050::kAccelXoutH, {1, 2, 3});
  EXPECT_EQ(word(read(m, Mpu6050::kAccelXoutH, 2, 2000), 0), 8192);
  write(m, Mpu6050::kWhoAmI, {0});
  EXPECT_EQ(m.reg(Mpu6050::kWhoAmI), 0x68);
}

// Samples come at 8 kHz / (1 + SMPLRT_DIV) with DLPF_CFG 0 (1 kHz base
// otherwise); a read between two sample instants sees the older sample;
// DATA_RDY says whether a new one came and clears on read.
TEST(Mpu6050Model, SampleClockAndDataReady) {
  Mpu6050 m;
  write(m, Mpu6050::kSmplrtDiv, {9, 1}, 0);  // 1 kHz base (DLPF_CFG 1) / 10 = 100 Hz
  EXPECT_DOUBLE_EQ(m.sample_rate_hz(), 100.0);
  write(m, Mpu6050::kPwrMgmt1, {0x00}, 1000);  // awake at 1 ms: first sample at 11 ms
  m.set_accel_m_s2(kG, 0, 0);
  EXPECT_EQ(word(read(m, Mpu6050::kAccelXoutH, 2, 5000), 0), 0);  // no sample yet
  EXPECT_EQ(read(m, Mpu6050::kIntStatus, 1, 5000)[0], 0);
  EXPECT_EQ(word(read(m, Mpu6050::kAccelXoutH, 2, 11000), 0), 16384);
  m.set_accel_m_s2(-kG, 0, 0);
  EXPECT_EQ(word(read(m, Mpu6050::kAccelXoutH, 2, 20999), 0), 16384);  // before 21 ms: the old sample
  EXPECT_EQ(read(m, Mpu6050::kIntStatus, 1, 20999)[0], 1);
  EXPECT_EQ(read(m, Mpu6050::kIntStatus, 1, 20999)[0], 0);  // cleared by the read
  EXPECT_EQ(word(read(m, Mpu6050::kAccelXoutH, 2, 21000), 0), -16384);
  EXPECT_EQ(m.samples(), 2u);
  write(m, Mpu6050::kConfig, {0}, 22000);
  EXPECT_DOUBLE_EQ(m.sample_rate_hz(), 800.0);
  // Asleep, the registers hold; SIG_COND_RESET clears them.
  write(m, Mpu6050::kPwrMgmt1, {0x40}, 30000);
  m.set_accel_m_s2(0.5 * kG, 0, 0);
  EXPECT_EQ(word(read(m, Mpu6050::kAccelXoutH, 2, 90000), 0), -16384);
  write(m, Mpu6050::kUserCtrl, {0x01}, 90000);
  EXPECT_EQ(m.reg(Mpu6050::kUserCtrl), 0);
  EXPECT_EQ(word(read(m, Mpu6050::kAccelXoutH, 2, 90000), 0), 0);
}

TEST(Mpu6050Model, ScriptDirectives) {
  auto parse = [](const std::string& line, ScriptEvent* ev, std::string* err) {
    bool has = false;
    const bool ok = strider_vmega::parse_script_line(line, ev, &has, err);
    return ok && has;
  };
  ScriptEvent ev;
  std::string err;
  ASSERT_TRUE(parse("at 1.5 imu on", &ev, &err)) << err;
  EXPECT_EQ(ev.kind, ScriptEvent::Kind::kImu);
  EXPECT_EQ(ev.imu_action, ScriptEvent::ImuAction::kOn);
  EXPECT_EQ(ev.board_address, 0x68);
  EXPECT_EQ(ev.time_us, 1500000u);
  ASSERT_TRUE(parse("imu on 0x69", &ev, &err)) << err;
  EXPECT_EQ(ev.board_address, 0x69);
  ASSERT_TRUE(parse("imu off", &ev, &err)) << err;
  EXPECT_EQ(ev.imu_action, ScriptEvent::ImuAction::kOff);
  ASSERT_TRUE(parse("at 2 imu accel 0.5 -1 9.8", &ev, &err)) << err;
  EXPECT_EQ(ev.imu_action, ScriptEvent::ImuAction::kAccel);
  EXPECT_DOUBLE_EQ(ev.values[1], -1.0);
  ASSERT_TRUE(parse("imu gyro 0 0 1e-3", &ev, &err)) << err;
  EXPECT_DOUBLE_EQ(ev.values[2], 1e-3);
  ASSERT_TRUE(parse("imu tilt 10 -5", &ev, &err)) << err;
  EXPECT_EQ(ev.imu_action, ScriptEvent::ImuAction::kTilt);
  ASSERT_TRUE(parse("imu temp 40", &ev, &err)) << err;
  ASSERT_TRUE(parse("at 3 adc A7 4.2", &ev, &err)) << err;
  EXPECT_EQ(ev.kind, ScriptEvent::Kind::kAdc);
  EXPECT_EQ(ev.pin, 7);
  EXPECT_DOUBLE_EQ(ev.values[0], 4.2);
  ASSERT_TRUE(parse("adc 0 0", &ev, &err)) << err;
  for (const char* bad : {"imu", "imu on 0x40", "imu accel 1 2", "imu gyro a b c", "imu tilt 1", "imu temp",
                          "imu spin", "imu off now", "adc A8 1", "adc A1", "adc A1 -1", "adc B1 2"}) {
    EXPECT_FALSE(parse(bad, &ev, &err)) << bad;
  }
}

}  // namespace
