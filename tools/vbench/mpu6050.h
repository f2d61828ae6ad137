// An MPU-6050 6-axis IMU (InvenSense) as seen from its I2C bus: the register
// file the Adafruit_MPU6050 library drives (register map rev 4.2, product
// specification rev 3.4), fed with physical values in SI units. Pure C++: the
// bus glue lives in vmega_twi.cpp.
//
// - WHO_AM_I (0x75) reads 0x68 whatever AD0 is (the address is 0x68 or 0x69);
// - power-on values: every register 0 except PWR_MGMT_1 = 0x40 (asleep);
//   PWR_MGMT_1.DEVICE_RESET puts them back and reads 0 at once;
//   SIGNAL_PATH_RESET is accepted and reads 0; USER_CTRL.SIG_COND_RESET
//   clears the data registers;
// - data registers 0x3B..0x48 (accel x y z, temperature, gyro x y z,
//   big-endian words): a sample of the inputs is taken at every sample
//   instant, at the gyro output rate (8 kHz with DLPF_CFG 0 or 7, 1 kHz
//   otherwise) / (1 + SMPLRT_DIV); a read transaction sees the last sample
//   before its START (the chip's shadow registers keep a burst coherent),
//   taken from the inputs as they are at the first START after the instant.
//   Asleep (SLEEP, or CYCLE), no sample is taken: the registers hold their
//   values (0 after a reset);
// - scales from AFS_SEL (ACCEL_CONFIG bits 4:3: 16384/8192/4096/2048 LSB/g)
//   and FS_SEL (GYRO_CONFIG bits 4:3: 131/65.5/32.8/16.4 LSB per deg/s),
//   rounded to the nearest word and saturated at -32768..32767 as the part
//   clips; temperature = word / 340 + 36.53 deg C;
// - INT_STATUS.DATA_RDY (0x3A bit 0) is set when a sample was taken since
//   it was last read, and cleared by reading it;
// - reads and writes auto-increment the register pointer (any register);
//   read-only registers ignore writes.
// Not modelled: the digital low-pass filter's smoothing (DLPF_CFG sets the
// rate only), self-test, the FIFO (FIFO_COUNT reads 0), interrupts on the
// INT pin, the auxiliary I2C master, motion detection, the 30 ms gyro
// start-up after waking.
#ifndef STRIDER_TOOLS_VBENCH_MPU6050_H
#define STRIDER_TOOLS_VBENCH_MPU6050_H

#include <array>
#include <cstdint>

namespace strider_vmega {

class Mpu6050 {
 public:
  static constexpr uint8_t kSmplrtDiv = 0x19;
  static constexpr uint8_t kConfig = 0x1A;
  static constexpr uint8_t kGyroConfig = 0x1B;
  static constexpr uint8_t kAccelConfig = 0x1C;
  static constexpr uint8_t kIntStatus = 0x3A;
  static constexpr uint8_t kAccelXoutH = 0x3B;
  static constexpr uint8_t kTempOutH = 0x41;
  static constexpr uint8_t kGyroXoutH = 0x43;
  static constexpr uint8_t kGyroZoutL = 0x48;
  static constexpr uint8_t kSignalPathReset = 0x68;
  static constexpr uint8_t kUserCtrl = 0x6A;
  static constexpr uint8_t kPwrMgmt1 = 0x6B;
  static constexpr uint8_t kFifoCountH = 0x72;
  static constexpr uint8_t kFifoRw = 0x74;
  static constexpr uint8_t kWhoAmI = 0x75;
  static constexpr uint8_t kDeviceId = 0x68;  // WHO_AM_I
  // PWR_MGMT_1 bits.
  static constexpr uint8_t kDeviceReset = 0x80;
  static constexpr uint8_t kSleep = 0x40;
  static constexpr uint8_t kCycle = 0x20;
  static constexpr uint8_t kDataRdy = 0x01;     // INT_STATUS
  static constexpr uint8_t kSigCondReset = 0x01;  // USER_CTRL
  static constexpr double kG = 9.80665;  // [m/s^2], as the Adafruit library converts

  explicit Mpu6050(uint8_t address7 = 0x68);

  //! Power-on register values (inputs kept).
  void power_on_reset();

  // Physical inputs, the chip's axes (its x and y arrows on the breakout, z
  // out of the top face).
  //! Specific force [m/s^2]: acceleration minus gravity (+9.81 on z lying flat).
  void set_accel_m_s2(double x, double y, double z);
  void set_gyro_rad_s(double x, double y, double z);  //!< [rad/s]
  void set_temp_c(double c);                         //!< die temperature [deg C]

  // Bus side, called by the I2C glue between START and STOP.
  //! SLA+W acknowledged: the next byte written is the register pointer.
  void begin_write();
  void write_byte(uint8_t byte, uint64_t now_us);
  //! SLA+R acknowledged at now_us: the data registers take the latest sample.
  void begin_read(uint64_t now_us);
  //! The byte a master read gets; advances the pointer.
  uint8_t read_byte();

  uint8_t address() const { return address7_; }
  void set_address(uint8_t address7) { address7_ = address7; }
  uint8_t pointer() const { return pointer_; }
  //! Register as a master would read it (without side effects).
  uint8_t reg(uint8_t r) const;
  bool sleeping() const { return (regs_[kPwrMgmt1] & (kSleep | kCycle)) != 0; }
  //! Data rate [Hz]: the gyro output rate / (1 + SMPLRT_DIV).
  double sample_rate_hz() const;
  int accel_range_g() const { return 2 << ((regs_[kAccelConfig] >> 3) & 3); }
  double accel_lsb_per_g() const { return 16384.0 / double(1 << ((regs_[kAccelConfig] >> 3) & 3)); }
  int gyro_range_dps() const { return 250 << ((regs_[kGyroConfig] >> 3) & 3); }
  double gyro_lsb_per_dps() const;
  //! The words a sample of the present inputs gives, in register order:
  //! accel x y z, temperature, gyro x y z.
  std::array<int16_t, 7> words() const;
  //! value * scale rounded to the nearest word, saturated.
  static int16_t to_word(double value_times_scale);
  //! Device resets (DEVICE_RESET) and samples taken so far.
  int device_resets() const { return device_resets_; }
  uint64_t samples() const { return samples_; }

 private:
  void write_reg(uint8_t r, uint8_t v);
  void take_sample();
  static bool read_only(uint8_t r);

  uint8_t address7_;
  std::array<uint8_t, 256> regs_{};
  uint8_t pointer_ = 0;
  bool have_pointer_ = false;
  double accel_[3] = {0, 0, kG};
  double gyro_[3] = {0, 0, 0};
  double temp_c_ = 25.0;
  uint64_t next_sample_us_ = 0;   // the next sample instant while awake
  bool data_ready_ = false;
  int device_resets_ = 0;
  uint64_t samples_ = 0;
};

}  // namespace strider_vmega

#endif  // STRIDER_TOOLS_VBENCH_MPU6050_H
