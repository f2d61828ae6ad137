// The PCA9685 register model on its own, against the datasheet's rules.
#include "pca9685.h"

#include <gtest/gtest.h>

#include <initializer_list>

using strider_vmega::Pca9685;

namespace {

// One bus transaction: START, SLA+W, pointer, data..., STOP.
void write(Pca9685& p, std::initializer_list<uint8_t> bytes, uint64_t t_us = 0) {
  p.begin_write();
  for (uint8_t b : bytes) p.write_byte(b, t_us);
  p.stop();
}

// The usual bring-up at 50 Hz: sleep, prescale, wake, auto-increment + restart.
void bring_up(Pca9685& p, uint8_t prescale = 121) {
  write(p, {0x00, 0x10}, 0);
  write(p, {0xFE, prescale}, 10);
  write(p, {0x00, 0x20}, 20);
  write(p, {0x00, 0xA0}, 1000);
}

TEST(Pca9685, PowerOnValues) {
  Pca9685 p;
  EXPECT_EQ(p.reg(0x00), 0x11);
  EXPECT_EQ(p.reg(0x01), 0x04);
  EXPECT_EQ(p.reg(0x05), 0xE0);
  EXPECT_EQ(p.reg(0xFE), 0x1E);
  EXPECT_EQ(p.reg(0x09), 0x10);  // LED0_OFF_H: full off
  EXPECT_TRUE(p.sleeping());
  for (int ch = 0; ch < 16; ++ch) EXPECT_EQ(p.pulse_us(ch), 0.0);
}

TEST(Pca9685, PulseWidthFromTicksPrescaleAndOscillator) {
  Pca9685 p(0x40, 25e6);
  bring_up(p, 121);  // round(25e6 / (4096 * 50)) - 1
  write(p, {0x06 + 4 * 3, 0, 0, 0x33, 0x01});  // ch3: ON 0, OFF 307
  EXPECT_NEAR(p.pwm_hz(), 25e6 / (4096.0 * 122), 1e-9);
  EXPECT_NEAR(p.pulse_us(3), 307 * 122 / 25.0, 1e-9);
  // The same registers on a board whose oscillator runs at 26 MHz.
  p.set_osc_hz(26e6);
  EXPECT_NEAR(p.pulse_us(3), 307 * 122 / 26.0, 1e-9);
  // ON > OFF wraps around the 4096-count period.
  write(p, {0x06 + 4 * 4, 0x00, 0x0F, 0x64, 0x00});  // ON 3840, OFF 100
  EXPECT_NEAR(p.pulse_us(4), (4096 - 3840 + 100) * p.tick_us(), 1e-9);
}

TEST(Pca9685, PrescaleIgnoredWhileAwake) {
  Pca9685 p;
  bring_up(p, 121);
  write(p, {0xFE, 50});
  EXPECT_EQ(p.prescale(), 121);
  write(p, {0x00, 0x30});  // sleep (AI kept)
  write(p, {0xFE, 50});
  EXPECT_EQ(p.prescale(), 50);
  write(p, {0xFE, 1});  // the hardware forces at least 3
  EXPECT_EQ(p.prescale(), 3);
}

TEST(Pca9685, FullOnFullOffAndEqualOnOff) {
  Pca9685 p;
  bring_up(p);
  write(p, {0x06, 0x00, 0x10, 0x00, 0x00});  // ch0 full on
  EXPECT_NEAR(p.pulse_us(0), p.period_us(), 1e-9);
  write(p, {0x06, 0x00, 0x10, 0x00, 0x10});  // full off wins
  EXPECT_EQ(p.pulse_us(0), 0.0);
  write(p, {0x06, 0x20, 0x00, 0x20, 0x00});  // ON == OFF
  EXPECT_EQ(p.pulse_us(0), 0.0);
}

TEST(Pca9685, AutoIncrementWrapsAfterLed15ToMode1) {
  Pca9685 p;
  bring_up(p);
  // Start at LED15_OFF_L, write OFF_L, OFF_H, then MODE1 (wrapped), MODE2.
  write(p, {0x44, 0x2C, 0x01, 0x20, 0x0C});
  EXPECT_EQ(p.reg(0x44), 0x2C);
  EXPECT_EQ(p.reg(0x45), 0x01);
  EXPECT_EQ(p.reg(0x00), 0x20);
  EXPECT_EQ(p.reg(0x01), 0x0C);
}

TEST(Pca9685, WithoutAutoIncrementThePointerStays) {
  Pca9685 p;
  write(p, {0x00, 0x00});  // awake, AI off
  write(p, {0x06, 0x11, 0x22});
  EXPECT_EQ(p.reg(0x06), 0x22);
  EXPECT_EQ(p.reg(0x07), 0x00);
}

TEST(Pca9685, AllLedRegistersWriteEveryChannelAndReadZero) {
  Pca9685 p;
  bring_up(p);
  write(p, {0xFA, 0x00, 0x00, 0x90, 0x01});  // all: ON 0, OFF 400
  for (int ch = 0; ch < 16; ++ch) EXPECT_NEAR(p.pulse_us(ch), 400 * p.tick_us(), 1e-9) << ch;
  EXPECT_EQ(p.reg(0xFC), 0x00);
  EXPECT_EQ(p.reg(0xFE), 121);
  // AI from ALL_LED_OFF_H goes to PRE_SCALE, then MODE1.
  write(p, {0xFD, 0x00, 0x05, 0x30});
  EXPECT_EQ(p.prescale(), 121);  // awake: ignored
  EXPECT_EQ(p.reg(0x00) & 0x7F, 0x30);  // asleep with PWM running: RESTART set too
}

TEST(Pca9685, ReadsAutoIncrement) {
  Pca9685 p;
  bring_up(p);
  write(p, {0x06, 0x01, 0x02, 0x03, 0x04});
  p.begin_write();
  p.write_byte(0x06, 0);
  EXPECT_EQ(p.read_byte(), 0x01);
  EXPECT_EQ(p.read_byte(), 0x02);
  EXPECT_EQ(p.read_byte(), 0x03);
  p.stop();
}

TEST(Pca9685, SleepWithActiveOutputsNeedsRestart) {
  Pca9685 p;
  bring_up(p);
  write(p, {0x06, 0, 0, 0x33, 0x01});
  const double w = p.pulse_us(0);
  ASSERT_GT(w, 0.0);
  write(p, {0x00, 0x30}, 2000);  // sleep
  EXPECT_EQ(p.pulse_us(0), 0.0);
  EXPECT_EQ(p.reg(0x00) & 0x80, 0x80);  // RESTART reads 1
  write(p, {0x00, 0x20}, 3000);          // wake: still stopped
  EXPECT_EQ(p.pulse_us(0), 0.0);
  EXPECT_TRUE(p.paused());
  write(p, {0x00, 0xA0}, 3600);  // RESTART after 500 us
  EXPECT_EQ(p.pulse_us(0), w);
  EXPECT_EQ(p.reg(0x00) & 0x80, 0);
  EXPECT_EQ(p.early_restarts(), 0);
}

TEST(Pca9685, RestartTooSoonAfterWakeIsCounted) {
  Pca9685 p;
  bring_up(p);
  write(p, {0x06, 0, 0, 0x33, 0x01});
  write(p, {0x00, 0x30}, 2000);
  write(p, {0x00, 0xA0}, 2100);  // wake and restart at once
  EXPECT_EQ(p.early_restarts(), 1);
}

TEST(Pca9685, OutputsChangeOnStopNotBefore) {
  Pca9685 p;
  bring_up(p);
  p.begin_write();
  for (uint8_t b : {uint8_t(0x06), uint8_t(0), uint8_t(0), uint8_t(0x33), uint8_t(0x01)}) p.write_byte(b, 0);
  EXPECT_EQ(p.pulse_us(0), 0.0);
  p.stop();
  EXPECT_GT(p.pulse_us(0), 0.0);
}

}  // namespace
