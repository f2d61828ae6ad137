// The three things the firmware asks of the PCA9685 boards, through
// Adafruit's libraries (pca9685_bus.cpp): the PWM Servo Driver library's
// register map and Adafruit_BusIO's I2C device, the object that library
// makes all its transfers through.
#ifndef STRIDER_PCA9685_BUS_H
#define STRIDER_PCA9685_BUS_H

#include <stdint.h>

namespace pca9685_bus {

//! Channels per auto-increment burst: a burst starts at its first channel's
//! OFF_L (every ON word stays 0 from begin() on), so register + 8 x 4 - 2
//! bytes fill 31 of the 32 bytes Adafruit_I2CDevice (and Wire) send in one
//! transfer on the AVR.
constexpr uint8_t kMaxBurstChannels = 8;

//! Starts the bus (400 kHz) and puts `boards` boards (0x40, 0x41, ...) to
//! sleep in auto-increment mode with every output off. False if a board does
//! not answer.
bool begin(uint8_t boards);

//! Sets the PWM prescale of every board (asleep, write, wake, restart).
void set_prescale(uint8_t boards, uint8_t prescale);

//! Writes `count` consecutive channels (at most kMaxBurstChannels) from
//! channel `first` (0-15) of a board on, in one auto-increment transfer.
//! `words` holds 4 bytes per channel, ON_L, ON_H, OFF_L, OFF_H, with every
//! ON word 0 (the first channel's ON is not sent: begin() zeroed it). False
//! when the board did not acknowledge.
bool write_channels(uint8_t board, uint8_t first, const uint8_t* words, uint8_t count);

}  // namespace pca9685_bus

#endif
