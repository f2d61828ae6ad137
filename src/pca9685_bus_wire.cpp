// OFFLINE SUBSTITUTE for the Adafruit PWM Servo Driver library: the offline
// CMake build cannot install the Adafruit library, so this small Wire driver
// does the same register work (datasheet PCA9685 rev. 4, sections 7.3.1 and
// 7.3.5) behind the same pca9685_bus interface. The PlatformIO build that
// users flash uses pca9685_bus_adafruit.cpp instead.
#if !defined(STRIDER_PCA9685_ADAFRUIT) || !STRIDER_PCA9685_ADAFRUIT

#include "control/channel_map.h"  // before Arduino.h (its min/max macros)

#include <Arduino.h>
#include <Wire.h>

#include "board_pins.h"
#include "pca9685_bus.h"

namespace pca9685_bus {
namespace {

bool write_reg(uint8_t board, uint8_t reg, uint8_t value) { return write(board, reg, &value, 1); }

// MODE1 as begin() sets it: register auto-increment, answers the all-call address.
constexpr uint8_t kMode1Awake = kMode1AutoIncrement | kMode1AllCall;

}  // namespace

bool begin(uint8_t boards) {
  Wire.begin();
  Wire.setClock(pins::kI2cClockHz);
  bool ok = true;
  static const uint8_t kAllOff[4] = {0x00, 0x00, 0x00, 0x10};  // ALL_LED_OFF_H bit 4: full off
  for (uint8_t b = 0; b < boards; ++b) {
    ok = write_reg(b, kMode1, kMode1Awake | kMode1Sleep) && ok;
    ok = write_reg(b, kMode2, kMode2OutDrv) && ok;
    ok = write(b, 0xFA, kAllOff, 4) && ok;  // ALL_LED_ON_L..ALL_LED_OFF_H
  }
  return ok;
}

void set_prescale(uint8_t boards, uint8_t prescale) {
  // MODE1 is known (begin() wrote it), so no register is read back: writes only.
  for (uint8_t b = 0; b < boards; ++b) {
    write_reg(b, kMode1, kMode1Awake | kMode1Sleep);  // PRE_SCALE is writable only asleep
    write_reg(b, kPrescale, prescale);
    write_reg(b, kMode1, kMode1Awake);
    delayMicroseconds(500);  // oscillator start-up (datasheet: 500 us)
    write_reg(b, kMode1, kMode1Awake | kMode1Restart);
  }
}

}  // namespace pca9685_bus

#endif
