// A clock the test advances by hand.
#ifndef STRIDER_TEST_CONTROL_MANUAL_CLOCK_H
#define STRIDER_TEST_CONTROL_MANUAL_CLOCK_H

#include <stdint.h>

namespace strider_test {

struct ManualClock {
  uint32_t us = 0;
  uint32_t now_us() const { return us; }
  uint32_t now_ms() const { return us / 1000u; }
  void advance_ms(uint32_t ms) { us += ms * 1000u; }
};

}  // namespace strider_test

#endif
