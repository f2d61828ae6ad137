//! LevelCalibration: the accelerometer's x and y offsets [mg], the mean of
//! kLevelCalSamples readings with the robot standing still on level ground
//! (`cal level`; docs/imu.md, "Level calibration").
#ifndef STRIDER_SENSING_LEVEL_CALIBRATION_H
#define STRIDER_SENSING_LEVEL_CALIBRATION_H

#include <stdint.h>

#include "../math/scalar.h"
#include "../math/vec3.h"
#include "imu_sample.h"

namespace strider {

constexpr uint8_t kLevelCalSamples = 50;       //!< readings averaged (1 s at the 50 Hz tick)
constexpr int16_t kLevelCalMaxMeanMg = 87;     //!< |mean| on x or y: sin(5 deg) g [mg]
constexpr int16_t kLevelCalMaxMg = 250;        //!< |reading| on x or y [mg]; 50 x 250 fits an int16 sum
constexpr double kLevelCalMaxUpErrG = 0.2;     //!< z within this of 1 g [g] (upright, not bouncing or falling)
constexpr double kLevelCalMaxRateRadS = 0.0524;  //!< |rate| about x or y [rad/s] (3 deg/s)

enum class LevelCalStatus : uint8_t {
  kIdle = 0,        //!< no run (none started, or the last one ended)
  kCollecting = 1,  //!< still and level so far, not enough readings yet
  kDone = 2,        //!< the offsets are the mean of kLevelCalSamples readings
  kMoving = 3,      //!< a reading turned: the run ended, nothing kept
  kNotLevel = 4,    //!< a reading or the mean is too far from level: the run ended
  kNoReading = 5    //!< the part did not answer (a failed read): the run ended
};

template <typename S>
class LevelCalibration {
 public:
  //! Starts a run; tag (0..3) is the caller's, kept in the count's byte.
  void start(uint8_t tag = 0) {
    n_ = uint8_t(1 | (tag << kTagShift));  // count 0: idle; the readings taken are count - 1
    sum_x_ = sum_y_ = 0;
  }
  bool running() const { return count() != 0; }
  uint8_t tag() const { return uint8_t(n_ >> kTagShift); }
  //! Ends a run (nothing kept).
  void stop() { n_ = uint8_t(n_ & ~kCountMask); }

  //! One reading and the gyro bias to take from it [rad/s]; kDone: *x_mg,
  //! *y_mg hold the offsets. Any status but kCollecting ends the run.
  LevelCalStatus add(const ImuSample<S>& s, const Vec3<S>& gyro_bias_rad_s, int8_t* x_mg, int8_t* y_mg) {
    if (count() == 0) return LevelCalStatus::kIdle;
    const S lim = scalar<S>(kLevelCalMaxRateRadS);
    const Vec3<S> w = s.gyro_rad_s - gyro_bias_rad_s;
    if (!(abs(w.x) < lim && abs(w.y) < lim)) return end(LevelCalStatus::kMoving);
    int16_t x = 0, y = 0;
    if (!to_mg(s.accel_m_s2.x, &x) || !to_mg(s.accel_m_s2.y, &y) ||
        !(abs(s.accel_m_s2.z - scalar<S>(kStandardGravity)) < scalar<S>(kLevelCalMaxUpErrG * kStandardGravity)))
      return end(LevelCalStatus::kNotLevel);
    sum_x_ = int16_t(sum_x_ + x);
    sum_y_ = int16_t(sum_y_ + y);
    if (count() < kLevelCalSamples) {
      ++n_;
      return LevelCalStatus::kCollecting;
    }
    const int16_t mx = mean(sum_x_), my = mean(sum_y_);
    if (mx > kLevelCalMaxMeanMg || mx < -kLevelCalMaxMeanMg || my > kLevelCalMaxMeanMg || my < -kLevelCalMaxMeanMg)
      return end(LevelCalStatus::kNotLevel);
    *x_mg = int8_t(mx);
    *y_mg = int8_t(my);
    return end(LevelCalStatus::kDone);
  }

 private:
  static constexpr uint8_t kTagShift = 6;
  static constexpr uint8_t kCountMask = (1u << kTagShift) - 1;
  static_assert(kLevelCalSamples < kCountMask, "the count fits below the tag");
  uint8_t count() const { return uint8_t(n_ & kCountMask); }
  LevelCalStatus end(LevelCalStatus s) {
    stop();
    return s;
  }
  //! a [m/s^2] -> *mg rounded; false beyond kLevelCalMaxMg (or NaN).
  static bool to_mg(S a, int16_t* mg) {
    constexpr S k = scalar<S>(1000.0 / kStandardGravity), lim = scalar<S>(double(kLevelCalMaxMg));
    const S v = a * k;
    if (!(abs(v) < lim)) return false;
    *mg = int16_t(round_to_int(v));
    return true;
  }
  static int32_t round_to_int(float v) { return v >= 0.0f ? int32_t(v + 0.5f) : -int32_t(-v + 0.5f); }
  static int32_t round_to_int(Fixed v) {
    const int32_t r = v.raw();
    return r >= 0 ? (r + 32768) >> 16 : -((-r + 32768) >> 16);
  }
  //! sum / kLevelCalSamples, rounded half away from zero.
  static int16_t mean(int16_t sum) {
    constexpr int16_t h = kLevelCalSamples / 2;
    return int16_t(sum >= 0 ? (sum + h) / kLevelCalSamples : -((-sum + h) / kLevelCalSamples));
  }

  int16_t sum_x_ = 0, sum_y_ = 0;  // [mg]
  uint8_t n_ = 0;                  // the count (bits 0-5) and the tag (6-7)
};

}  // namespace strider

#endif  // STRIDER_SENSING_LEVEL_CALIBRATION_H
