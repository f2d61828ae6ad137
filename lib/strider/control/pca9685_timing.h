//! Pca9685Timing: PWM prescale and pulse-width -> 12-bit tick conversion for
//! the PCA9685, from the board's calibrated oscillator frequency (23-27 MHz,
//! not the nominal 25: docs/calibration.md, "The PCA9685 oscillator").
//! Computed once in configure(); pulse_ticks() is integer-only.
#ifndef STRIDER_CONTROL_PCA9685_TIMING_H
#define STRIDER_CONTROL_PCA9685_TIMING_H

#include <stdint.h>

namespace strider {

constexpr uint32_t kPca9685NominalOscHz = 25000000ul;  //!< datasheet nominal [Hz]
constexpr uint32_t kPca9685MinOscHz = 20000000ul;      //!< accepted calibration range [Hz]
constexpr uint32_t kPca9685MaxOscHz = 30000000ul;      //!< accepted calibration range [Hz]
constexpr uint16_t kPca9685MaxTick = 4095;             //!< last 12-bit counter value
constexpr uint8_t kPca9685MinPrescale = 3;             //!< datasheet minimum
constexpr uint8_t kPca9685MaxPrescale = 255;           //!< register width

enum class PwmTimingStatus : uint8_t {
  kOk = 0,
  kClamped = 1,     //!< the frequency needed a prescale outside 3..255: clamped
  kBadOscillator = 2  //!< oscillator outside 20-30 MHz: configuration rejected
};

//! The datasheet prescale, round(osc / (4096 f)) - 1, clamped to 3..255.
//! Integer rounding: (osc + 2048 f) / (4096 f); no overflow for f <= 1 MHz.
inline uint8_t pca9685_prescale(uint32_t osc_hz, uint16_t pwm_hz, PwmTimingStatus* status = nullptr) {
  const uint32_t denom = 4096ul * (pwm_hz == 0 ? 1ul : uint32_t(pwm_hz));
  const uint32_t rounded = (osc_hz + denom / 2) / denom;
  int32_t p = int32_t(rounded) - 1;
  PwmTimingStatus s = PwmTimingStatus::kOk;
  if (p < kPca9685MinPrescale) { p = kPca9685MinPrescale; s = PwmTimingStatus::kClamped; }
  if (p > kPca9685MaxPrescale) { p = kPca9685MaxPrescale; s = PwmTimingStatus::kClamped; }
  if (pwm_hz == 0) s = PwmTimingStatus::kClamped;
  if (status) *status = s;
  return uint8_t(p);
}

class Pca9685Timing {
 public:
  Pca9685Timing() { configure(kPca9685NominalOscHz, 50); }

  //! On kBadOscillator the previous configuration is kept.
  PwmTimingStatus configure(uint32_t osc_hz, uint16_t pwm_hz) {
    if (osc_hz < kPca9685MinOscHz || osc_hz > kPca9685MaxOscHz) return PwmTimingStatus::kBadOscillator;
    PwmTimingStatus status = PwmTimingStatus::kOk;
    prescale_ = pca9685_prescale(osc_hz, pwm_hz, &status);
    // Period in 1/64 us: (p + 1) * 4096 * 64e6 / osc. (p + 1) * 262144 <= 6.8e7,
    // then times 1e6 / osc as long division in three base-100 steps, so every
    // intermediate stays below 2^32 (x < osc <= 3e7, x * 100 < 3e9).
    uint32_t x = (uint32_t(prescale_) + uint32_t(1)) * uint32_t(262144);
    uint32_t period = x / osc_hz;
    x %= osc_hz;
    for (uint8_t step = 0; step < 3; ++step) {
      x *= uint32_t(100);
      period = period * uint32_t(100) + x / osc_hz;
      x %= osc_hz;
    }
    if (uint32_t(2) * x >= osc_hz) ++period;  // round to nearest
    period_x64_ = period;
    return status;
  }

  uint8_t prescale() const { return prescale_; }      //!< value for the PRESCALE register
  //! Actual PWM period [1/64 us] after prescale rounding (<= 3.4e6).
  uint32_t period_x64() const { return period_x64_; }

  //! Pulse width [us] -> on-time ticks, rounded to nearest, at most 4095.
  //! ticks = width * 4096 * 64 / period_x64: one 32-bit division for widths
  //! below 16000 us (width * 262144 + period / 2 < 2^32), else two exact steps.
  uint16_t pulse_ticks(uint16_t width_us) const {
    uint32_t ticks;
    if (width_us < 16000u) {
      ticks = (uint32_t(width_us) * uint32_t(262144) + period_x64_ / 2) / period_x64_;
    } else {
      const uint32_t num = uint32_t(width_us) * uint32_t(4096);
      const uint32_t r = (num % period_x64_) * uint32_t(64);
      ticks = (num / period_x64_) * uint32_t(64) + r / period_x64_;
      if (uint32_t(2) * (r % period_x64_) >= period_x64_) ++ticks;
    }
    return ticks > kPca9685MaxTick ? kPca9685MaxTick : uint16_t(ticks);
  }

  //! Pulse width [us] -> the on-time ticks rounded up (at least width_us
  //! long) or down (at most width_us), at most 4095: a joint limit's bound
  //! rounded toward the inside of the range (servo_map.h, limit_ticks()).
  uint16_t pulse_ticks_toward(uint16_t width_us, bool up) const {
    const uint32_t num = uint32_t(width_us) * uint32_t(4096);  // < 2^28
    const uint32_t r = (num % period_x64_) * uint32_t(64);     // < 2^28
    uint32_t ticks = (num / period_x64_) * uint32_t(64) + r / period_x64_;
    if (up && r % period_x64_ != 0) ++ticks;
    return ticks > kPca9685MaxTick ? kPca9685MaxTick : uint16_t(ticks);
  }

 private:
  uint32_t period_x64_ = 1280000ul;
  uint8_t prescale_ = 121;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_PCA9685_TIMING_H
