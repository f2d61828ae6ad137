//! RxOverflowWatch: where bytes may be missing from a receive ring that drops
//! what arrives while it is full, as the Arduino core's serial ports do
//! (HardwareSerial's receive interrupt discards the byte and sets no flag).
//!
//! Asked before each byte is read, with how many bytes wait, it says whether
//! bytes may be missing right before that byte. Only reads empty the ring,
//! so a byte dropped since the previous read leaves the ring full at the
//! next one, and the dropped bytes belong after its last byte: a full ring
//! at a read marks the stream position after its contents. No loss goes
//! unseen; a ring that filled exactly without losing anything is reported
//! too (the safe side). Positions count modulo 2^16: the ring holds fewer.
#ifndef STRIDER_CONTROL_RX_OVERFLOW_H
#define STRIDER_CONTROL_RX_OVERFLOW_H

#include <stdint.h>

namespace strider {

class RxOverflowWatch {
 public:
  //! Before reading one byte: `waiting` bytes are in the ring, which holds
  //! at most `capacity`. True when bytes may have been lost just before the
  //! byte about to be read (the caller then tells the parser,
  //! CommandParser::lost()).
  bool gap_before_next(uint16_t waiting, uint16_t capacity) {
    if (waiting >= capacity) {
      const uint16_t at = uint16_t(read_ + waiting);  // the byte after the ring's last one
      if (!pending_) first_ = at;
      pending_ = true;
      last_ = at;
    }
    const bool gap = pending_ && int16_t(uint16_t(read_ - first_)) >= 0;
    if (gap && read_ == last_) pending_ = false;
    ++read_;
    return gap;
  }

 private:
  uint16_t read_ = 0;   // bytes read so far
  uint16_t first_ = 0;  // the first and last position that may follow a gap
  uint16_t last_ = 0;
  bool pending_ = false;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_RX_OVERFLOW_H
