//! Deadman: stop and stand when no valid command arrived for a configurable
//! time while the robot is moving (a dropped Bluetooth link must not leave it
//! walking). Time is a parameter [ms]; wrap-safe by subtraction.
#ifndef STRIDER_CONTROL_DEADMAN_H
#define STRIDER_CONTROL_DEADMAN_H

#include <stdint.h>

#include "hal_interfaces.h"

namespace strider {

class Deadman {
 public:
  explicit Deadman(uint16_t timeout_ms = 1000) : last_ms_(0), timeout_ms_(timeout_ms) {}

  void set_timeout(uint16_t timeout_ms) { timeout_ms_ = timeout_ms; }  //!< 0 = off

  //! A valid command arrived at now_ms (RC buttons repeat while held).
  void feed(uint32_t now_ms) { last_ms_ = now_ms; armed_ = true; }

  //! True once when moving and the last command is older than the timeout;
  //! not moving restarts the wait.
  bool expired(uint32_t now_ms, bool moving) {
    if (!moving || timeout_ms_ == 0) { last_ms_ = now_ms; armed_ = true; return false; }
    if (!armed_) return false;
    if (elapsed(now_ms, last_ms_) < timeout_ms_) return false;
    armed_ = false;  // report once; feed() re-arms
    return true;
  }

 private:
  uint32_t last_ms_;  // zero, by the constructors
  uint16_t timeout_ms_;
  bool armed_ = true;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_DEADMAN_H
