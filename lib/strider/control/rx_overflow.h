//! RxOverflowWatch: where bytes may be missing from a receive ring that
//! drops what arrives while it is full, flagging nothing (the Arduino core's
//! serial ports). Only reads empty the ring, so a dropped byte leaves the
//! ring full at the next read, the gap after its contents. A ring that
//! filled exactly without loss is reported too (the safe side).
#ifndef STRIDER_CONTROL_RX_OVERFLOW_H
#define STRIDER_CONTROL_RX_OVERFLOW_H

#include <stdint.h>

namespace strider {

class RxOverflowWatch {
 public:
  //! Before reading one byte, `waiting` in a ring of `capacity`: true when
  //! bytes may have been lost just before it (CommandParser::lost()).
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
