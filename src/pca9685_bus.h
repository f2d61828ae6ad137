// The three things the firmware asks of the PCA9685 boards. Two backends
// implement them with the same behaviour:
//   pca9685_bus_adafruit.cpp  the Adafruit PWM Servo Driver library (the
//                             PlatformIO build, STRIDER_PCA9685_ADAFRUIT=1)
//   pca9685_bus_wire.cpp      a small Wire driver of our own that stands in
//                             for the Adafruit library where it cannot be
//                             installed (the offline CMake build)
#ifndef STRIDER_PCA9685_BUS_H
#define STRIDER_PCA9685_BUS_H

#include <stdint.h>

namespace pca9685_bus {

constexpr uint8_t kMode1 = 0x00;
constexpr uint8_t kMode2 = 0x01;
constexpr uint8_t kLed0OnL = 0x06;    // LEDn_ON_L = 0x06 + 4 n
constexpr uint8_t kPrescale = 0xFE;
constexpr uint8_t kMode1Restart = 0x80;
constexpr uint8_t kMode1AutoIncrement = 0x20;
constexpr uint8_t kMode1Sleep = 0x10;
constexpr uint8_t kMode1AllCall = 0x01;
constexpr uint8_t kMode2OutDrv = 0x04;  // totem-pole outputs (servo signal lines)
constexpr uint8_t kMaxBurstChannels = 7;  // Wire's 32-byte buffer: register + 7 x 4 bytes

//! Starts the bus (400 kHz) and puts `boards` boards (0x40, 0x41, ...) in
//! auto-increment mode with every output off. False if a board does not answer.
bool begin(uint8_t boards);

//! Sets the PWM prescale of every board (sleep, write, wake, restart).
void set_prescale(uint8_t boards, uint8_t prescale);

//! Writes n bytes from register reg on, in one auto-increment transfer.
//! False when the board did not acknowledge.
bool write(uint8_t board, uint8_t reg, const uint8_t* data, uint8_t n);

}  // namespace pca9685_bus

#endif
