//! Calibration: live per-joint trims and oscillator edited over Bluetooth,
//! with save and abort. The saved values are the caller's (the settings in
//! force): start() and abort() take them, so no second copy stays in RAM.
#ifndef STRIDER_CONTROL_CALIBRATION_H
#define STRIDER_CONTROL_CALIBRATION_H

#include <stdint.h>

#include "settings_store.h"

namespace strider {

enum class CalStatus : uint8_t {
  kOk = 0,
  kNotActive = 1,   //!< `cal start` first
  kOutOfRange = 2,  //!< joint index or value outside the settings ranges
  kStoreFailed = 3  //!< the save did not reach the store (live values kept)
};

class Calibration {
 public:
  explicit Calibration(const Settings& saved) : live_(saved) {}

  void start(const Settings& saved) {
    active_ = true;
    live_ = saved;
  }
  bool active() const { return active_; }

  CalStatus set_trim(uint8_t joint, int16_t decideg) {
    if (!active_) return CalStatus::kNotActive;
    if (joint >= kMaxServoJoints || decideg > kMaxTrimDecideg || decideg < -kMaxTrimDecideg) return CalStatus::kOutOfRange;
    live_.trim_decideg[joint] = decideg;
    return CalStatus::kOk;
  }

  CalStatus set_oscillator(uint32_t osc_hz) {
    if (!active_) return CalStatus::kNotActive;
    if (osc_hz < kPca9685MinOscHz || osc_hz > kPca9685MaxOscHz) return CalStatus::kOutOfRange;
    live_.pca_osc_hz = osc_hz;
    return CalStatus::kOk;
  }

  CalStatus set_pwm(uint16_t pwm_hz) {
    if (!active_) return CalStatus::kNotActive;
    if (pwm_hz < 40 || pwm_hz > 400) return CalStatus::kOutOfRange;
    live_.pwm_hz = pwm_hz;
    return CalStatus::kOk;
  }

  //! Saves the live values with `others` after *record; live() is then what
  //! was saved. On a store failure calibration stays active.
  template <typename Store>
  CalStatus save(Store& store, const Settings& others, SettingsRecord* record) {
    if (!active_) return CalStatus::kNotActive;
    Settings s = others;
    s.pca_osc_hz = live_.pca_osc_hz;
    s.pwm_hz = live_.pwm_hz;
    for (uint8_t i = 0; i < kMaxServoJoints; ++i) s.trim_decideg[i] = live_.trim_decideg[i];
    if (save_settings(store, s, record) != SettingsStatus::kOk) return CalStatus::kStoreFailed;
    live_ = s;
    active_ = false;
    return CalStatus::kOk;
  }

  void abort(const Settings& saved) {
    live_ = saved;
    active_ = false;
  }

  const Settings& live() const { return live_; }  //!< values to drive the servos with

 private:
  Settings live_;
  bool active_ = false;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_CALIBRATION_H
