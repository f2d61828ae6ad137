// The frame bursts, the same for both backends: one Wire transfer from
// register reg on (the boards are in auto-increment mode).
#include "control/channel_map.h"  // before Arduino.h (its min/max macros)

#include <Wire.h>

#include "pca9685_bus.h"

namespace pca9685_bus {

bool write(uint8_t board, uint8_t reg, const uint8_t* data, uint8_t n) {
  Wire.beginTransmission(uint8_t(strider::kPcaFirstAddress + board));
  Wire.write(reg);
  Wire.write(data, n);
  return Wire.endTransmission() == 0;
}

}  // namespace pca9685_bus
