//! GyroCalibration: a gyro's zero-rate offset [rad/s], the mean of `count`
//! readings in a row that stay within `spread` of each other on every axis.
#ifndef STRIDER_SENSING_GYRO_CALIBRATION_H
#define STRIDER_SENSING_GYRO_CALIBRATION_H

#include <stdint.h>

#include "../math/scalar.h"
#include "../math/vec3.h"

namespace strider {

enum class GyroCalibrationStatus : uint8_t {
  kCollecting = 0,  //!< still readings so far, not enough yet
  kDone = 1,        //!< offset() holds the mean of `count` still readings
  kRestarted = 2    //!< the reading moved beyond the spread: the run starts again from it
};

template <typename S>
class GyroCalibration {
 public:
  //! count >= 1 readings (50: 1 s at 50 Hz); spread: max - min per axis [rad/s].
  explicit GyroCalibration(uint8_t count = 50, S spread_rad_s = scalar<S>(0.035))
      : count_(count == 0 ? 1 : count), spread_(spread_rad_s) {
    restart();
  }

  void restart() {
    n_ = 0;
    done_ = false;
    sum_ = lo_ = hi_ = offset_ = Vec3<S>();
  }

  //! One reading [rad/s]; after kDone, further readings change nothing.
  GyroCalibrationStatus add(const Vec3<S>& gyro_rad_s) {
    if (done_) return GyroCalibrationStatus::kDone;
    if (!finite(gyro_rad_s)) {
      restart();
      return GyroCalibrationStatus::kRestarted;
    }
    GyroCalibrationStatus status = GyroCalibrationStatus::kCollecting;
    if (n_ > 0 && (!widen(lo_.x, hi_.x, gyro_rad_s.x) || !widen(lo_.y, hi_.y, gyro_rad_s.y) ||
                   !widen(lo_.z, hi_.z, gyro_rad_s.z))) {
      n_ = 0;
      status = GyroCalibrationStatus::kRestarted;
    }
    if (n_ == 0) {
      sum_ = Vec3<S>();
      lo_ = hi_ = gyro_rad_s;
    }
    sum_ += gyro_rad_s;
    if (++n_ < count_) return status;
    offset_ = sum_ * (scalar<S>(1.0) / S(int(count_)));
    done_ = true;
    return GyroCalibrationStatus::kDone;
  }

  bool done() const { return done_; }
  //! The offset [rad/s]; zero until done().
  const Vec3<S>& offset() const { return offset_; }
  //! Still readings collected in the current run.
  uint8_t collected() const { return n_; }

 private:
  // Grows [lo, hi] to take v; false (unchanged) when that would exceed the spread.
  bool widen(S& lo, S& hi, S v) const {
    const S new_lo = v < lo ? v : lo, new_hi = hi < v ? v : hi;
    if (spread_ < new_hi - new_lo) return false;
    lo = new_lo;
    hi = new_hi;
    return true;
  }
  static bool finite(const Vec3<float>& v) {
    return detail::is_finite(v.x) && detail::is_finite(v.y) && detail::is_finite(v.z);
  }
  static bool finite(const Vec3<Fixed>&) { return true; }

  uint8_t count_;
  S spread_;
  uint8_t n_;
  bool done_;
  Vec3<S> sum_, lo_, hi_, offset_;
};

}  // namespace strider

#endif  // STRIDER_SENSING_GYRO_CALIBRATION_H
