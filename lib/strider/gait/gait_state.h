//! GaitState: what the gait engine is doing, and its name.
#ifndef STRIDER_GAIT_GAIT_STATE_H
#define STRIDER_GAIT_GAIT_STATE_H

#include <stdint.h>

#include "../math/flash_table.h"

namespace strider {

enum class GaitState : uint8_t {
  kSitting = 0,     //!< body lowered, all feet down
  kStandingUp = 1,  //!< rising to the standing height
  kStanding = 2,    //!< all feet home, not stepping
  kWalking = 3,     //!< stepping
  kStopping = 4,    //!< command at zero, finishing the last steps
  kSittingDown = 5  //!< lowering the body
};

//! The states' names in GaitState's order, each ended by a NUL (in flash on
//! the AVR): what to_string() and the firmware's replies read.
constexpr char kGaitStateNames[] STRIDER_PROGMEM = "sitting\0standing_up\0standing\0walking\0stopping\0sitting_down";
constexpr uint8_t kGaitStateCount = 6;

//! The state's name: a pointer into kGaitStateNames (on the AVR an address
//! in flash); "standing" for a value out of range.
inline const char* to_string(GaitState s) {
  const char* p = kGaitStateNames;
  for (uint8_t i = uint8_t(s) < kGaitStateCount ? uint8_t(s) : uint8_t(GaitState::kStanding); i > 0; --i)
    while (flash_u8(p++) != 0) {}
  return p;
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_STATE_H
