// FirmwareDriver: the real firmware ELF on the virtual Mega (tools/vbench):
// scenario bytes go into its UART1 (HC-05) at the baud it programmed, its
// PCA9685 boards' pulse widths drive the joint motors, the HC-SR04's echo
// comes from the world's ray cast, the MPU-6050 (when fitted) reads the IMU
// model and the battery divider's pin the battery model.
#include "driver.h"

#ifdef STRIDER_SIM_HAVE_VMEGA

#include <deque>

#include "virtual_mega.h"

namespace strider_sim {

namespace {

constexpr int kBluetoothUart = 1;
constexpr uint64_t kRangeUpdateUs = 5000;  // the ray cast follows the body every 5 ms
// Nothing within 3 m: the HC-SR04 still answers, with its ~38 ms "no
// obstacle" pulse (a missing pulse would mean an unplugged sensor).
constexpr double kNothingMm = 38000.0 * 0.343 / 2.0;

class FirmwareDriver : public Driver {
 public:
  FirmwareDriver(RangeFn range) : range_(std::move(range)) {}

  bool load(const std::string& elf, double osc_hz, std::string* error) {
    strider_vmega::Options o;
    o.elf_path = elf;
    o.pca_osc_hz = osc_hz;
    return mega_.load(o, error);
  }

  const char* mode() const override { return "firmware"; }
  bool begin(std::string* /*error*/) override { return true; }

  void send(const std::string& bytes, uint64_t at_us) override { tx_.push_back({at_us, bytes}); }

  void advance_to(uint64_t now_us) override {
    while (!tx_.empty() && tx_.front().at_us <= now_us) {
      run(tx_.front().at_us);
      mega_.send(kBluetoothUart, tx_.front().bytes);
      tx_.pop_front();
    }
    run(now_us);
    for (int ch = 0; ch < kMaxChannels; ++ch) {
      const double w = ch < 16 * mega_.board_count() ? mega_.pulse_us(ch) : 0.0;
      pulses_[ch].on = w > 0;
      pulses_[ch].pulse_us = w;
    }
  }

  const ChannelPulse* pulses() const override { return pulses_; }

  double imu_bandwidth_hz() const override {
    if (!mega_.imu_present()) return 0;
    return ImuModel::dlpf_bandwidth_hz(mega_.imu().reg(strider_vmega::Mpu6050::kConfig) & 7);
  }

  void set_sensors(const SensorInputs& s) override {
    Driver::set_sensors(s);
    if (s.imu_fitted != mega_.imu_present()) mega_.set_imu_present(s.imu_fitted);
    if (s.imu_fitted) {
      mega_.set_imu_accel_m_s2(s.imu.accel_m_s2.x, s.imu.accel_m_s2.y, s.imu.accel_m_s2.z);
      mega_.set_imu_gyro_rad_s(s.imu.gyro_rad_s.x, s.imu.gyro_rad_s.y, s.imu.gyro_rad_s.z);
      mega_.set_imu_temp_c(s.imu.temp_c);
    }
    mega_.set_adc_volts(s.battery_pin, s.battery_pin_v);
  }

  std::vector<std::string> take_lines() override {
    partial_ += mega_.take_output(kBluetoothUart);
    std::vector<std::string> out;
    size_t start = 0;
    for (size_t i = 0; i < partial_.size(); ++i) {
      if (partial_[i] != '\n') continue;
      std::string line = partial_.substr(start, i - start);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      out.push_back(line);
      start = i + 1;
    }
    partial_.erase(0, start);
    return out;
  }

 private:
  struct Tx {
    uint64_t at_us;
    std::string bytes;
  };

  void run(uint64_t t_us) {
    if (t_us >= next_range_us_) {
      const double d = range_ ? range_() : -1.0;
      mega_.set_range_mm(d < 0 ? kNothingMm : d);
      next_range_us_ = t_us + kRangeUpdateUs;
    }
    if (t_us > mega_.now_us()) mega_.run_until_us(t_us);
  }

  strider_vmega::VirtualMega mega_;
  RangeFn range_;
  std::deque<Tx> tx_;
  std::string partial_;
  uint64_t next_range_us_ = 0;
  ChannelPulse pulses_[kMaxChannels];
};

}  // namespace

std::unique_ptr<Driver> make_firmware_driver(const std::string& elf_path, const strider::RobotModel& /*model*/,
                                             double osc_hz, RangeFn range, std::string* error) {
  std::unique_ptr<FirmwareDriver> d(new FirmwareDriver(std::move(range)));
  if (!d->load(elf_path, osc_hz, error)) return nullptr;
  return std::unique_ptr<Driver>(d.release());
}

}  // namespace strider_sim

#else

namespace strider_sim {

std::unique_ptr<Driver> make_firmware_driver(const std::string& /*elf_path*/, const strider::RobotModel& /*model*/,
                                             double /*osc_hz*/, RangeFn /*range*/, std::string* error) {
  *error = "firmware mode needs the virtual Mega (tools/vbench, simavr); this build has none";
  return nullptr;
}

}  // namespace strider_sim

#endif
