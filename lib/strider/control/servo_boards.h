//! ServoBoardReport: what a servo-board driver tells RobotApp about its
//! PCA9685 boards: which do not answer, which answer again, whether the bus
//! hangs, how many transfers failed. Board b is at I2C address
//! kPcaFirstAddress + b, driving the global channels 16 b .. 16 b + 15.
#ifndef STRIDER_CONTROL_SERVO_BOARDS_H
#define STRIDER_CONTROL_SERVO_BOARDS_H

#include <stdint.h>

#include "channel_map.h"

namespace strider {

//! Bit b of a board mask: board b.
constexpr uint8_t board_bit(uint8_t b) { return uint8_t(1u << b); }

//! The PCA9685 board that drives global channel ch.
constexpr uint8_t board_of_channel(uint8_t ch) { return uint8_t(ch / kPcaChannelsPerBoard); }

//! PCA9685 full-off bit of an OFF word (LEDn_OFF_H bit 4): the output sends no pulse.
constexpr uint16_t kPcaFullOff = 0x1000;

struct ServoBoardReport {
  uint8_t faulted = 0;   //!< bit b: board b does not answer (a missing board, no power, a loose wire)
  uint8_t restored = 0;  //!< bit b: board b answers again since the last report (set up anew if it had lost power)
  bool bus_stuck = false;  //!< a transfer timed out: the bus is held low (SDA or SCL)
  uint16_t errors = 0;   //!< transfers that failed since power-up (not acknowledged, timed out)
  //! What every channel drives now, restored boards' included: its OFF word
  //! (ON is 0), kPcaFullOff set for no pulse; `channels` entries.
  const uint16_t* outputs = nullptr;
  uint8_t channels = 0;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_BOARDS_H
