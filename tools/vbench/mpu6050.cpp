// MPU-6050 register model (see mpu6050.h).
#include "mpu6050.h"

#include <cmath>

namespace strider_vmega {

namespace {
constexpr double kRadToDeg = 57.29577951308232;
}  // namespace

Mpu6050::Mpu6050(uint8_t address7) : address7_(address7) { power_on_reset(); }

void Mpu6050::power_on_reset() {
  regs_.fill(0);
  regs_[kPwrMgmt1] = kSleep;
  regs_[kWhoAmI] = kDeviceId;
  pointer_ = 0;
  have_pointer_ = false;
  next_sample_us_ = 0;
  data_ready_ = false;
}

void Mpu6050::set_accel_m_s2(double x, double y, double z) {
  accel_[0] = x;
  accel_[1] = y;
  accel_[2] = z;
}

void Mpu6050::set_gyro_rad_s(double x, double y, double z) {
  gyro_[0] = x;
  gyro_[1] = y;
  gyro_[2] = z;
}

void Mpu6050::set_temp_c(double c) { temp_c_ = c; }

double Mpu6050::gyro_lsb_per_dps() const {
  static const double kLsb[4] = {131.0, 65.5, 32.8, 16.4};
  return kLsb[(regs_[kGyroConfig] >> 3) & 3];
}

double Mpu6050::sample_rate_hz() const {
  const uint8_t dlpf = regs_[kConfig] & 7;
  const double gyro_rate = dlpf == 0 || dlpf == 7 ? 8000.0 : 1000.0;
  return gyro_rate / (1.0 + double(regs_[kSmplrtDiv]));
}

int16_t Mpu6050::to_word(double v) {
  if (!(v > -32768.0)) return -32768;  // NaN too
  if (v >= 32767.0) return 32767;
  return int16_t(std::lround(v));
}

std::array<int16_t, 7> Mpu6050::words() const {
  const double a = accel_lsb_per_g() / kG, g = gyro_lsb_per_dps() * kRadToDeg;
  return {to_word(accel_[0] * a), to_word(accel_[1] * a), to_word(accel_[2] * a), to_word((temp_c_ - 36.53) * 340.0),
          to_word(gyro_[0] * g),  to_word(gyro_[1] * g),  to_word(gyro_[2] * g)};
}

bool Mpu6050::read_only(uint8_t r) {
  return (r >= kIntStatus && r <= kGyroZoutL) || r == kFifoCountH || r == kFifoCountH + 1 || r == kWhoAmI;
}

void Mpu6050::begin_write() { have_pointer_ = false; }

void Mpu6050::write_byte(uint8_t byte, uint64_t now_us) {
  if (!have_pointer_) {
    pointer_ = byte;
    have_pointer_ = true;
    return;
  }
  const bool was_asleep = sleeping();
  write_reg(pointer_, byte);
  if (was_asleep && !sleeping()) {  // waking: samples from one period on
    next_sample_us_ = now_us + uint64_t(std::llround(1e6 / sample_rate_hz()));
  }
  ++pointer_;
}

void Mpu6050::write_reg(uint8_t r, uint8_t v) {
  if (read_only(r)) return;
  switch (r) {
    case kPwrMgmt1:
      if (v & kDeviceReset) {
        ++device_resets_;
        power_on_reset();  // the bit reads 0 again once the reset is done
        return;
      }
      break;
    case kSignalPathReset:
      return;  // resets the analog and digital paths; write-only
    case kUserCtrl:
      if (v & kSigCondReset)
        for (uint8_t a = kAccelXoutH; a <= kGyroZoutL; ++a) regs_[a] = 0;
      v &= uint8_t(~0x07);  // FIFO_RESET, I2C_MST_RESET, SIG_COND_RESET clear themselves
      break;
    default:
      break;
  }
  regs_[r] = v;
}

void Mpu6050::begin_read(uint64_t now_us) {
  have_pointer_ = false;
  if (sleeping() || now_us < next_sample_us_) return;
  const uint64_t period = uint64_t(std::llround(1e6 / sample_rate_hz()));
  take_sample();
  next_sample_us_ += ((now_us - next_sample_us_) / period + 1) * period;
}

void Mpu6050::take_sample() {
  const std::array<int16_t, 7> w = words();
  for (size_t i = 0; i < w.size(); ++i) {
    regs_[kAccelXoutH + 2 * i] = uint8_t(uint16_t(w[i]) >> 8);
    regs_[kAccelXoutH + 2 * i + 1] = uint8_t(uint16_t(w[i]) & 0xFF);
  }
  data_ready_ = true;
  ++samples_;
}

uint8_t Mpu6050::reg(uint8_t r) const {
  if (r == kIntStatus) return data_ready_ ? kDataRdy : 0;
  return regs_[r];
}

uint8_t Mpu6050::read_byte() {
  const uint8_t v = reg(pointer_);
  if (pointer_ == kIntStatus) data_ready_ = false;
  ++pointer_;
  return v;
}

}  // namespace strider_vmega
