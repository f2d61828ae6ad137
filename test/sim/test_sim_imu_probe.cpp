// strider-sim's firmware mode feeding vbench's MPU-6050 and ADC: the IMU
// probe (test/vbench/arduino_imu: the real Adafruit_MPU6050 library and
// Strider's attitude filter on the virtual Mega) is the robot's firmware; it
// answers over the Bluetooth port what it reads while sprawl8's body lies in
// the world (its servos get no pulses: the probe drives none).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "sim_run.h"

namespace {

std::vector<double> numbers(const std::string& line) {
  std::istringstream in(line);
  std::string w;
  in >> w;
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  return v;
}

const strider_sim::TraceRow& row_at(const strider_sim::RunResult& r, double t) {
  for (const strider_sim::TraceRow& row : r.trace)
    if (row.t_s >= t - 1e-9) return row;
  return r.trace.back();
}

TEST(SimImuProbe, FirmwareReadsTheImuAndBatteryModels) {
  strider_sim::Scenario sc;
  std::string err;
  ASSERT_TRUE(strider_sim::parse_scenario("robot sprawl8\nduration 6.5\nimu on\nat 2 send v\nat 2.2 send r\n"
                                          "at 3 send f\n",
                                          &sc, &err))
      << err;
  strider_sim::RunOptions o;
  o.firmware_elf = STRIDER_IMU_PROBE_ELF;
  o.sensors.imu = strider_sim::ImuConfig::ideal();
  o.trace_period_s = 0.004;  // a row per physics step: the one vbench had at the read is among them
  const strider_sim::RunResult r = strider_sim::run_scenario(sc, o);
  ASSERT_TRUE(r.ok) << r.error;
  std::string adc, event, filter;
  double event_t = 0, filter_t = 0;
  for (const strider_sim::LogLine& l : r.log) {
    if (l.text.rfind("adc ", 0) == 0) adc = l.text;
    if (l.text.rfind("event ", 0) == 0) event = l.text, event_t = l.t_s;
    if (l.text.rfind("filter ", 0) == 0) filter = l.text, filter_t = l.t_s;
  }
  // A0: the pack through the 3:1 divider (no servo on: logic current only).
  const std::vector<double> a = numbers(adc);
  ASSERT_EQ(a.size(), 8u) << adc;
  const double pin_v = row_at(r, 2.0).battery_v / 3.0;
  EXPECT_NEAR(a[0], std::floor(pin_v * 1024 / 5.0), 1.0) << adc;
  // getEvent(): the IMU model's reading at one of the ticks before the
  // reply's last byte (60 characters at 9600 baud), within the part's LSB.
  const std::vector<double> e = numbers(event);
  ASSERT_EQ(e.size(), 7u) << event;
  double best = 1e9;
  for (const strider_sim::TraceRow& row : r.trace) {
    if (row.t_s < event_t - 0.15 || row.t_s > event_t) continue;
    const strider_sim::ImuReading& m = row.imu;
    best = std::min(best, std::max({std::fabs(e[0] - m.accel_m_s2.x), std::fabs(e[1] - m.accel_m_s2.y),
                                    std::fabs(e[2] - m.accel_m_s2.z), std::fabs(e[3] - m.gyro_rad_s.x) * 10}));
  }
  EXPECT_LT(best, 0.002) << event;
  // The filter on the Mega against the body's own roll and pitch.
  const std::vector<double> f = numbers(filter);
  ASSERT_EQ(f.size(), 6u) << filter;
  const strider_sim::TraceRow& b = row_at(r, filter_t);
  EXPECT_NEAR(f[0], b.body.roll_deg, 0.3) << filter;
  EXPECT_NEAR(f[1], b.body.pitch_deg, 0.3) << filter;
  EXPECT_NEAR(f[2], b.body.roll_deg, 0.3) << filter;
  EXPECT_NEAR(f[3], b.body.pitch_deg, 0.3) << filter;
}

}  // namespace
