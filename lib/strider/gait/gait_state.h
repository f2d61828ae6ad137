//! GaitState: what the gait engine is doing (sitting, standing up,
//! standing, walking, stopping, sitting down), and its name.
#ifndef STRIDER_GAIT_GAIT_STATE_H
#define STRIDER_GAIT_GAIT_STATE_H

#include <stdint.h>

namespace strider {

enum class GaitState : uint8_t {
  kSitting = 0,     //!< body lowered, all feet down
  kStandingUp = 1,  //!< rising to the standing height
  kStanding = 2,    //!< all feet home, not stepping
  kWalking = 3,     //!< stepping
  kStopping = 4,    //!< command at zero, finishing the last steps
  kSittingDown = 5  //!< lowering the body
};

inline const char* to_string(GaitState s) {
  switch (s) {
    case GaitState::kSitting: return "sitting";
    case GaitState::kStandingUp: return "standing_up";
    case GaitState::kStanding: return "standing";
    case GaitState::kWalking: return "walking";
    case GaitState::kStopping: return "stopping";
    case GaitState::kSittingDown: return "sitting_down";
  }
  return "standing";
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_STATE_H
