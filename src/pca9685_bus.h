// What the firmware asks of the PCA9685 boards, through Adafruit's
// libraries (pca9685_bus.cpp): the PWM Servo Driver library's register map
// and Adafruit_BusIO's I2C device, the object that library makes all its
// transfers through. Board b is the one at 0x40 + b. Every call returns
// within a few milliseconds whatever the bus does: a transfer that does not
// complete times out (timed_out()).
#ifndef STRIDER_PCA9685_BUS_H
#define STRIDER_PCA9685_BUS_H

#include <stdint.h>

namespace pca9685_bus {

//! Channels per auto-increment burst: a burst starts at its first channel's
//! OFF_L (every ON word stays 0 from begin() on), so register + 8 x 4 - 2
//! bytes fill 31 of the 32 bytes Adafruit_I2CDevice (and Wire) send in one
//! transfer on the AVR.
constexpr uint8_t kMaxBurstChannels = 8;

//! MODE1 while the firmware drives a board: awake, register auto-increment,
//! answering the all-call address (its power-on default).
constexpr uint8_t kMode1Running = 0x21;

//! OFF word of an output that sends no pulse (LEDn_OFF_H bit 4).
constexpr uint16_t kFullOff = 0x1000;

//! Starts the bus: 400 kHz, and Wire's time-out on (a held bus cannot hang
//! the firmware). Before any other call.
void begin();

//! Puts board b to sleep in auto-increment mode with every output off
//! (ON 0, full-off). False if it did not acknowledge.
bool init_board(uint8_t board);

//! Sets board b's PWM prescale (asleep, write, wake, restart; about 1 ms).
//! False if it did not acknowledge.
bool set_prescale(uint8_t board, uint8_t prescale);

//! Whether board b acknowledges its address.
bool probe(uint8_t board);

//! Board b's MODE1 (0 unless MODE2 is the firmware's) and PRE_SCALE, in
//! one transfer. False if it did not answer.
bool read_mode(uint8_t board, uint8_t* mode1, uint8_t* prescale);

//! The OFF word of each of board b's 16 outputs (off[16]): kFullOff for one
//! that sends no pulse or whose ON word is not 0 (not a frame of this
//! firmware's). False if it did not answer.
bool read_outputs(uint8_t board, uint16_t* off);

//! Writes `count` consecutive channels (at most kMaxBurstChannels) from
//! channel `first` (0-15) of a board on, in one auto-increment transfer.
//! `words` holds 4 bytes per channel, ON_L, ON_H, OFF_L, OFF_H, with every
//! ON word 0 (the first channel's ON is not sent: init_board() zeroed it).
//! False when the board did not acknowledge.
bool write_channels(uint8_t board, uint8_t first, const uint8_t* words, uint8_t count);

//! Whether a transfer timed out (the bus held low) since the last call.
bool timed_out();

}  // namespace pca9685_bus

#endif
