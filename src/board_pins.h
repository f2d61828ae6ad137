// The Mega 2560 pin map (docs/wiring.md has the wiring and the reasons).
#ifndef STRIDER_BOARD_PINS_H
#define STRIDER_BOARD_PINS_H

#include <stdint.h>

namespace pins {

// I2C to the PCA9685 boards: SDA = D20, SCL = D21 (the Mega's TWI pins).
constexpr uint32_t kI2cClockHz = 400000;  // PCA9685 fast mode
// HC-05 on Serial1: TX1 = D18 -> HC-05 RXD (through a 1k/2k divider), RX1 = D19 <- HC-05 TXD.
constexpr uint32_t kUsbBaud = 115200;     // Serial (USB): same protocol as the HC-05 link
// HC-SR04: TRIG output; ECHO on D2 = INT4 (an external interrupt times the pulse).
constexpr uint8_t kSonarTrig = 3;   // PE5
constexpr uint8_t kSonarEcho = 2;   // PE4, INT4
constexpr uint8_t kHeartbeatLed = 13;  // PB7, the board's LED
// Battery: pack + -- 20 kOhm -- A0 -- 10 kOhm -- GND (docs/wiring.md): the
// pin reads a third of the pack, up to 15 V against the 5 V reference. With
// nothing wired the pin reads near 0 V and the firmware reports no battery.
constexpr uint8_t kBatteryAdcChannel = 0;    // A0
constexpr uint16_t kBatteryDividerX100 = 300;  // pack volts per pin volt, x100
constexpr uint16_t kAdcReferenceMv = 5000;     // AVCC

}  // namespace pins

#endif
