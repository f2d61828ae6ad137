// vbench's MPU-6050 and analog inputs against the real Adafruit_MPU6050
// library (2.2.8, Adafruit Unified Sensor 1.1.15, Adafruit BusIO 1.17.4) on
// the virtual Mega: the IMU probe (arduino_imu/imu_probe.cpp) calls begin()
// and getEvent() and prints what it read; the readings must be what vbench
// was fed, within the part's LSB, in every range. Without an IMU begin()
// fails cleanly. Strider's MPU-6050 conversion and attitude filter run on the
// Mega too. The vbench executable's --imu option and imu/adc directives last.
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "virtual_mega.h"

using strider_vmega::Mpu6050;
using strider_vmega::Options;
using strider_vmega::RunStatus;
using strider_vmega::VirtualMega;

namespace {

constexpr double kG = 9.80665;
constexpr double kDeg = M_PI / 180.0;

std::vector<double> numbers(const std::string& line, size_t skip_words = 1) {
  std::istringstream in(line);
  std::string w;
  for (size_t i = 0; i < skip_words; ++i) in >> w;
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  return v;
}

class ImuProbe : public ::testing::Test {
 protected:
  void boot(bool imu, uint8_t address = 0x68) {
    Options o;
    o.elf_path = STRIDER_IMU_PROBE_ELF;
    o.imu_address = imu ? address : 0;
    std::string err;
    ASSERT_TRUE(mega.load(o, &err)) << err;
    begin_line = next_line(3000000);
  }
  std::string next_line(uint64_t timeout_us) {
    const uint64_t end = mega.now_us() + timeout_us;
    while (mega.now_us() < end) {
      buffer += mega.take_output(0);
      const size_t nl = buffer.find('\n');
      if (nl != std::string::npos) {
        std::string line = buffer.substr(0, nl);
        buffer.erase(0, nl + 1);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return line;
      }
      if (mega.run_for_us(1000) != RunStatus::kOk) return "<stopped>";
    }
    return "<timeout>";
  }
  std::string command(const std::string& c, uint64_t timeout_us = 500000) {
    mega.send(0, c);
    return next_line(timeout_us);
  }
  // getEvent() after feeding a, w, t: the 7 values it returned.
  std::vector<double> read_event() {
    const std::string line = command("r");
    EXPECT_EQ(line.substr(0, 6), "event ") << line;
    return numbers(line);
  }

  VirtualMega mega;
  std::string buffer;
  std::string begin_line;
};

// The registers begin() leaves, and readings equal to the inputs within one
// LSB of the default ranges (+-2 g: 0.6 mm/s^2; +-500 deg/s: 0.27 mrad/s).
TEST_F(ImuProbe, BeginAndGetEventReadWhatWasFed) {
  boot(true);
  ASSERT_EQ(begin_line, "begin ok");
  const Mpu6050& imu = mega.imu();
  EXPECT_EQ(imu.device_resets(), 1);
  EXPECT_EQ(imu.reg(Mpu6050::kPwrMgmt1), 0x01);  // awake, PLL with the gyro x clock
  EXPECT_EQ(imu.reg(Mpu6050::kSmplrtDiv), 0);
  EXPECT_EQ(imu.reg(Mpu6050::kConfig), 0);       // 260 Hz bandwidth: 8 kHz gyro rate
  EXPECT_EQ(imu.gyro_range_dps(), 500);
  EXPECT_EQ(imu.accel_range_g(), 2);
  EXPECT_DOUBLE_EQ(imu.sample_rate_hz(), 8000.0);
  const double accel_lsb = kG / 16384, gyro_lsb = kDeg / 65.5, temp_lsb = 1 / 340.0;
  const double cases[][7] = {
      {0, 0, kG, 0, 0, 0, 25},
      {1.234, -5.678, 8.9, 0.5, -1.25, 2.0, 31.5},
      {-9.80665, 9.80665, -0.001, -8.7, 8.7, 0.0001, -10},
      {3 * kG, -3 * kG, 0, 20, -20, 0, 60},  // beyond both ranges: clipped
  };
  for (const auto& c : cases) {
    mega.set_imu_accel_m_s2(c[0], c[1], c[2]);
    mega.set_imu_gyro_rad_s(c[3], c[4], c[5]);
    mega.set_imu_temp_c(c[6]);
    const std::vector<double> v = read_event();
    ASSERT_EQ(v.size(), 7u);
    for (int i = 0; i < 3; ++i) {
      const double fed = std::max(-32768 * accel_lsb, std::min(32767 * accel_lsb, c[i]));
      EXPECT_NEAR(v[size_t(i)], fed, accel_lsb) << "accel " << i;
      const double fed_w = std::max(-32768 * gyro_lsb, std::min(32767 * gyro_lsb, c[3 + i]));
      EXPECT_NEAR(v[size_t(3 + i)], fed_w, gyro_lsb) << "gyro " << i;
    }
    EXPECT_NEAR(v[6], c[6], temp_lsb + 1e-4);
  }
}

// Every range the library sets scales the outputs.
TEST_F(ImuProbe, RangesScaleTheOutputs) {
  boot(true);
  ASSERT_EQ(begin_line, "begin ok");
  for (int n = 0; n < 4; ++n) {
    ASSERT_EQ(command("a" + std::to_string(n)), "ok accel " + std::to_string(n));
    ASSERT_EQ(command("g" + std::to_string(n)), "ok gyro " + std::to_string(n));
    EXPECT_EQ(mega.imu().accel_range_g(), 2 << n);
    EXPECT_EQ(mega.imu().gyro_range_dps(), 250 << n);
    const double g_full = (2 << n) * kG, w_full = (250 << n) * kDeg;
    const double lsb_per_dps[4] = {131, 65.5, 32.8, 16.4};
    const double accel_lsb = g_full / 32768, gyro_lsb = kDeg / lsb_per_dps[n];
    mega.set_imu_accel_m_s2(0.9 * g_full, -0.5 * g_full, 0.1234 * g_full);
    mega.set_imu_gyro_rad_s(-0.9 * w_full, 0.3 * w_full, 0.0);
    const std::vector<double> v = read_event();
    ASSERT_EQ(v.size(), 7u);
    EXPECT_NEAR(v[0], 0.9 * g_full, accel_lsb) << n;
    EXPECT_NEAR(v[1], -0.5 * g_full, accel_lsb) << n;
    EXPECT_NEAR(v[2], 0.1234 * g_full, accel_lsb) << n;
    EXPECT_NEAR(v[3], -0.9 * w_full, gyro_lsb) << n;
    EXPECT_NEAR(v[4], 0.3 * w_full, gyro_lsb) << n;
    EXPECT_NEAR(v[5], 0.0, gyro_lsb) << n;
  }
}

// The raw burst through Adafruit BusIO is the model's words, big-endian, and
// Strider's Fixed conversion of it agrees with the library's float one.
TEST_F(ImuProbe, BurstAndStriderConversionAgreeWithTheLibrary) {
  boot(true);
  ASSERT_EQ(begin_line, "begin ok");
  mega.set_imu_accel_m_s2(2.5, -7.25, 9.1);
  mega.set_imu_gyro_rad_s(1.5, -0.02, -3.3);
  mega.set_imu_temp_c(41.2);
  const std::vector<double> b = numbers(command("b"));
  ASSERT_EQ(b.size(), 14u);
  const std::array<int16_t, 7> w = mega.imu().words();
  for (size_t i = 0; i < 7; ++i) EXPECT_EQ(int16_t(uint16_t(b[2 * i]) << 8 | uint16_t(b[2 * i + 1])), w[i]) << i;
  const std::vector<double> q = numbers(next_line(200000));
  ASSERT_EQ(q.size(), 7u);
  const std::vector<double> v = read_event();
  ASSERT_EQ(v.size(), 7u);
  for (size_t i = 0; i < 6; ++i) EXPECT_NEAR(q[i] / 65536.0, v[i], 2.5e-5) << i;
  EXPECT_NEAR(q[6] / 65536.0, v[6], 1e-4);
}

// No MPU-6050: begin() gives up after its five tries and the program goes on.
TEST_F(ImuProbe, BeginFailsCleanlyWithoutAnImu) {
  boot(false);
  EXPECT_EQ(begin_line, "begin failed");
  EXPECT_FALSE(mega.imu_present());
  int to_imu = 0, acked = 0;
  for (const auto& t : mega.i2c_log())
    if (t.address7 == 0x68) {
      ++to_imu;
      acked += t.acked;
    }
  EXPECT_EQ(to_imu, 5);  // begin()'s tries
  EXPECT_EQ(acked, 0);
  EXPECT_EQ(command("v").substr(0, 4), "adc ");
}

// At 0x69 (AD0 high) begin(0x68) finds nothing either.
TEST_F(ImuProbe, AnImuAt0x69DoesNotAnswerAt0x68) {
  boot(true, 0x69);
  EXPECT_EQ(begin_line, "begin failed");
}

// Disconnected and connected again, the part starts from its power-on
// state: asleep, every data register 0.
TEST_F(ImuProbe, ReconnectedImuIsAsleep) {
  boot(true);
  ASSERT_EQ(begin_line, "begin ok");
  mega.set_imu_accel_m_s2(1, 2, 3);
  EXPECT_NEAR(read_event()[0], 1.0, 1e-3);
  mega.set_imu_present(false);
  mega.set_imu_present(true);
  EXPECT_TRUE(mega.imu().sleeping());
  const std::vector<double> v = read_event();
  ASSERT_EQ(v.size(), 7u);
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(v[i], 0.0) << i;
}

// analogRead() on A0..A7 gives floor(V x 1024 / 5 V), at most 1023.
TEST_F(ImuProbe, AnalogPinsReadTheirVoltages) {
  boot(false);
  const double volts[8] = {0.0, 2.47, 5.0, 7.0, 0.0049, 0.0048828125, 3.3, 4.9951};
  for (int pin = 0; pin < 8; ++pin) mega.set_adc_volts(pin, volts[pin]);
  const std::vector<double> v = numbers(command("v"));
  ASSERT_EQ(v.size(), 8u);
  for (int pin = 0; pin < 8; ++pin) {
    const int want = std::min(1023, int(std::floor(volts[pin] * 1024 / 5.0)));
    EXPECT_EQ(int(v[size_t(pin)]), want) << "A" << pin;
    EXPECT_EQ(mega.adc_code(pin), want);
  }
  mega.set_adc_volts(0, 1.0);
  EXPECT_EQ(int(numbers(command("v"))[0]), 204);
}

// Strider's attitude filter on the Mega, float and Fixed, fed by the library
// at 50 Hz for 2 s: a static tilt read back within 0.02 deg; the time of one
// update printed (docs/imu.md).
TEST_F(ImuProbe, AttitudeFilterOnTheMega) {
  boot(true);
  ASSERT_EQ(begin_line, "begin ok");
  const double roll = 20 * kDeg, pitch = -10 * kDeg;
  mega.set_imu_accel_m_s2(-kG * std::sin(pitch), kG * std::sin(roll) * std::cos(pitch),
                          kG * std::cos(roll) * std::cos(pitch));
  mega.set_imu_gyro_rad_s(0, 0, 0);
  const std::string line = command("f", 5000000);
  const std::vector<double> v = numbers(line);
  ASSERT_EQ(v.size(), 6u) << line;
  EXPECT_NEAR(v[0], 20.0, 0.02);
  EXPECT_NEAR(v[1], -10.0, 0.02);
  EXPECT_NEAR(v[2], 20.0, 0.02);
  EXPECT_NEAR(v[3], -10.0, 0.02);
  std::cout << "[measured] AttitudeFilter::update on the ATmega2560: float " << v[4] << " us, Fixed " << v[5]
            << " us (16 MHz, Timer0's interrupt included)\n";
  EXPECT_LT(v[4], 2000);
  EXPECT_LT(v[5], 2000);
}

std::string run_vbench(const std::string& args, const std::string& script_text) {
  const char* dir = std::getenv("TMPDIR");
  const std::string script = std::string(dir ? dir : "/tmp") + "/strider_vbench_imu_" + std::to_string(getpid()) + ".vb";
  {
    std::ofstream s(script);
    s << script_text;
  }
  const std::string cmd = std::string(STRIDER_VBENCH_EXE) + " --elf " + STRIDER_IMU_PROBE_ELF + " --script " + script +
                          " " + args;
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  if (p == nullptr) return out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  EXPECT_EQ(pclose(p), 0);
  std::remove(script.c_str());
  return out;
}

// vbench --imu with the script directives: a tilt, then rates, then the
// part unplugged; the ADC directive on A3.
TEST(VbenchImuExe, OptionAndDirectives) {
  const std::string out = run_vbench("--imu --duration 1.6",
                                     "at 0.8 imu tilt 30 0\nat 0.8 imu temp 30\nat 0.9 send0 r\n"
                                     "at 1.0 imu accel 1 2 3\nat 1.0 imu gyro 0.1 -0.2 0.3\nat 1.1 send0 r\n"
                                     "at 1.2 adc A3 2.5\nat 1.3 send0 v\n");
  EXPECT_NE(out.find("uart0: begin ok"), std::string::npos) << out;
  const size_t e1 = out.find("uart0: event ");
  ASSERT_NE(e1, std::string::npos) << out;
  const std::vector<double> a = numbers(out.substr(e1 + 7, out.find('\n', e1) - e1 - 7));
  ASSERT_EQ(a.size(), 7u);
  EXPECT_NEAR(a[0], 0.0, 1e-3);
  EXPECT_NEAR(a[1], kG * 0.5, 1e-3);
  EXPECT_NEAR(a[2], kG * std::cos(30 * kDeg), 1e-3);
  EXPECT_NEAR(a[6], 30.0, 3e-3);
  const size_t e2 = out.find("uart0: event ", e1 + 1);
  ASSERT_NE(e2, std::string::npos) << out;
  const std::vector<double> b = numbers(out.substr(e2 + 7, out.find('\n', e2) - e2 - 7));
  ASSERT_EQ(b.size(), 7u);
  EXPECT_NEAR(b[0], 1.0, 1e-3);
  EXPECT_NEAR(b[4], -0.2, 3e-4);
  EXPECT_NE(out.find("uart0: adc 0 0 0 512 0 0 0 0"), std::string::npos) << out;
  // Without --imu nothing answers at 0x68.
  EXPECT_NE(run_vbench("--duration 0.5", "").find("uart0: begin failed"), std::string::npos);
}

}  // namespace
