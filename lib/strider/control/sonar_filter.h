//! SonarFilter: HC-SR04 echo widths -> a filtered obstacle distance (343 m/s,
//! out and back): the median of the last kSonarWindow samples, 2-300 cm
//! (nearer: 20 mm, longer: far); kSonarFailAfter missing echoes in a row
//! report kFailed, no sample for kSonarStaleUs kStale.
#ifndef STRIDER_CONTROL_SONAR_FILTER_H
#define STRIDER_CONTROL_SONAR_FILTER_H

#include <stdint.h>

#include "hal_interfaces.h"

namespace strider {

constexpr uint16_t kSonarMinMm = 20;           //!< nearest valid distance [mm]
constexpr uint16_t kSonarMaxMm = 3000;         //!< farthest valid distance [mm]
constexpr uint16_t kSonarFarMm = 0xFFFF;       //!< distance reported when nothing is in range
constexpr uint8_t kSonarWindow = 5;            //!< median window [samples]
constexpr uint8_t kSonarFailAfter = 5;         //!< missing echoes in a row -> failed
constexpr uint32_t kSonarPingPeriodUs = 60000; //!< HC-SR04 datasheet: >= 60 ms between pings
constexpr uint32_t kSonarStaleUs = 500000;     //!< no sample this long -> stale [us]

enum class SonarStatus : uint8_t {
  kNoData = 0,  //!< not enough samples yet
  kOk = 1,      //!< distance_mm valid (kSonarFarMm = nothing within 300 cm)
  kFailed = 2,  //!< missing echoes in a row: sensor unplugged or broken
  kStale = 3    //!< no sample for kSonarStaleUs
};

struct SonarReading {
  SonarStatus status;
  uint16_t distance_mm;  //!< median distance [mm]; kSonarFarMm when clear
};

//! Echo width [us] -> distance [mm], rounded; no range check.
constexpr uint32_t echo_to_mm(uint16_t width_us) { return (uint32_t(width_us) * uint32_t(343) + uint32_t(1000)) / uint32_t(2000); }

class SonarFilter {
 public:
  //! True when the next ping is due, at most once per kSonarPingPeriodUs.
  bool ping_due(uint32_t now_us) {
    if (pinged_ && elapsed(now_us, last_ping_us_) < kSonarPingPeriodUs) return false;
    pinged_ = true;
    last_ping_us_ = now_us;
    return true;
  }

  //! Adds one sample from the driver, taken at now_us.
  void add(const EchoSample& s, uint32_t now_us) {
    last_sample_us_ = now_us;
    have_sample_ = true;
    if (s.kind == EchoKind::kNoEdge) {
      if (missing_ < 255) ++missing_;
      return;
    }
    missing_ = 0;
    const uint32_t mm = echo_to_mm(s.width_us);
    uint16_t d = mm > kSonarMaxMm ? kSonarFarMm : (mm < kSonarMinMm ? kSonarMinMm : uint16_t(mm));
    window_[next_] = d;
    next_ = uint8_t((next_ + 1) % kSonarWindow);
    if (count_ < kSonarWindow) ++count_;
  }

  //! The filtered reading at now_us.
  SonarReading reading(uint32_t now_us) const {
    SonarReading r{SonarStatus::kNoData, kSonarFarMm};
    if (!have_sample_ || elapsed(now_us, last_sample_us_) > kSonarStaleUs) {
      r.status = have_sample_ ? SonarStatus::kStale : SonarStatus::kNoData;
      return r;
    }
    if (missing_ >= kSonarFailAfter) { r.status = SonarStatus::kFailed; return r; }
    if (count_ < kSonarWindow / 2 + 1) return r;
    r.status = SonarStatus::kOk;
    r.distance_mm = median();
    return r;
  }

 private:
  uint16_t median() const {
    uint16_t v[kSonarWindow];
    for (uint8_t i = 0; i < count_; ++i) v[i] = window_[i];
    for (uint8_t i = 1; i < count_; ++i) {  // insertion sort of <= 5 values
      const uint16_t x = v[i];
      uint8_t j = i;
      while (j > 0 && v[j - 1] > x) { v[j] = v[j - 1]; --j; }
      v[j] = x;
    }
    return v[count_ / 2];
  }

  uint16_t window_[kSonarWindow] = {};
  uint8_t count_ = 0;
  uint8_t next_ = 0;
  uint8_t missing_ = 0;
  bool have_sample_ = false;
  bool pinged_ = false;
  uint32_t last_sample_us_ = 0;
  uint32_t last_ping_us_ = 0;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_SONAR_FILTER_H
