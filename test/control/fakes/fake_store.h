// In-memory EEPROM with write counting and injectable write failures.
#ifndef STRIDER_TEST_CONTROL_FAKE_STORE_H
#define STRIDER_TEST_CONTROL_FAKE_STORE_H

#include <stdint.h>

#include "control/hal_interfaces.h"

namespace strider_test {

struct FakeStore : strider::ArrayByteStore<4096> {
  FakeStore() { erase(); }
  int writes = 0;
  int fail_at_write = -1;    // the n-th write (0-based) fails, -1 = never
  bool stuck_bits = false;   // writes "succeed" but bit 0 stays set (worn cell)
  bool write(uint16_t addr, uint8_t v) {
    const int n = writes++;
    if (n == fail_at_write) return false;
    return ArrayByteStore<4096>::write(addr, stuck_bits ? uint8_t(v | 1u) : v);
  }
};

}  // namespace strider_test

#endif
