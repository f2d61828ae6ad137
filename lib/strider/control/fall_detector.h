//! FallDetector: whether the robot has tipped over, from the attitude
//! filter's tilt: past kFallTiltDeg for kFallHoldTicks ticks is a fall,
//! under kUprightTiltDeg for kUprightHoldTicks ticks clears it.
#ifndef STRIDER_CONTROL_FALL_DETECTOR_H
#define STRIDER_CONTROL_FALL_DETECTOR_H

#include <stdint.h>

#include "../math/scalar.h"

namespace strider {

constexpr double kFallTiltDeg = 50.0;      //!< past this the robot is down [deg]
constexpr uint8_t kFallHoldTicks = 10;     //!< ... for this many ticks (0.2 s at 50 Hz)
constexpr double kUprightTiltDeg = 20.0;   //!< under this it stands again [deg]
constexpr uint8_t kUprightHoldTicks = 50;  //!< ... for this many ticks (1 s)

template <typename S>
class FallDetector {
 public:
  //! One tick's tilt [rad]; true when fallen() changed.
  bool update(S tilt_rad) {
    constexpr S kFall = scalar<S>(kFallTiltDeg * 0.017453292519943295);
    constexpr S kUpright = scalar<S>(kUprightTiltDeg * 0.017453292519943295);
    const bool past = fallen_ ? tilt_rad < kUpright : kFall < tilt_rad;
    if (!past) {
      count_ = 0;
      return false;
    }
    if (++count_ < (fallen_ ? kUprightHoldTicks : kFallHoldTicks)) return false;
    fallen_ = !fallen_;
    count_ = 0;
    return true;
  }
  bool fallen() const { return fallen_; }

 private:
  bool fallen_ = false;
  uint8_t count_ = 0;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_FALL_DETECTOR_H
