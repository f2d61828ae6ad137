//! IkStatus: the result code of every inverse-kinematics solver.
#ifndef STRIDER_KINEMATICS_IK_STATUS_H
#define STRIDER_KINEMATICS_IK_STATUS_H

#include <stdint.h>

namespace strider {

//! Ordered by severity: a solver reports the worst that applied.
enum class IkStatus : uint8_t {
  kOk = 0,          //!< target reached within the tolerance
  kClamped = 1,     //!< target out of reach: solved for the nearest reachable point
  kJointLimit = 2,  //!< a joint was clamped to its limit; the point reached is reported
  kUnreachable = 3  //!< too far from the workspace to clamp: outputs left untouched
};

inline const char* to_string(IkStatus s) {
  switch (s) {
    case IkStatus::kOk: return "ok";
    case IkStatus::kClamped: return "clamped";
    case IkStatus::kJointLimit: return "joint_limit";
    case IkStatus::kUnreachable: return "unreachable";
  }
  return "unknown";
}

//! The worse of two statuses.
inline IkStatus worst(IkStatus a, IkStatus b) { return uint8_t(a) >= uint8_t(b) ? a : b; }

}  // namespace strider

#endif  // STRIDER_KINEMATICS_IK_STATUS_H
