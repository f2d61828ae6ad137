//! A servo stage's warm start: taking over the pulses that the boards'
//! outputs already drive (after an MCU reset the boards kept running
//! through, or a board that answers again) instead of switching them off.
#ifndef STRIDER_CONTROL_SERVO_WARM_START_H
#define STRIDER_CONTROL_SERVO_WARM_START_H

#include <stdint.h>

#include "servo_boards.h"
#include "servo_tick_map.h"

namespace strider {

//! For each joint of `map` on a board in board_mask (words[ch]: channel
//! ch's OFF word): one whose output holds a pulse within its limits goes on
//! from it (ticks[k]), any other is switched off (ticks[k] = off). Only with
//! the limits known (`fast`). Returns the joints that hold a pulse.
template <typename Map, typename Output>
uint8_t adopt_held_outputs(const Map& map, bool fast, uint8_t count, uint16_t* ticks, uint16_t off, Output& out,
                           const uint16_t* words, uint8_t channels, uint8_t board_mask) {
  uint8_t held = 0;
  for (uint8_t k = 0; k < count; ++k) {
    const uint8_t ch = map.channel(k);
    if (!(board_mask & board_bit(board_of_channel(ch)))) continue;
    const uint16_t w = ch < channels ? words[ch] : kPcaFullOff;
    bool inside = false;
    if (fast && w < kPcaFullOff) {
      const auto j = map.joint(k);
      inside = w >= j.lo_ticks && w <= j.hi_ticks;
    }
    if (inside) {
      ticks[k] = w;
      ++held;
    } else {
      ticks[k] = off;
      out.relax(ch);
    }
  }
  return held;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_WARM_START_H
