//! The control tick: its period, the time it advances the gait by, and
//! TickLoad, how long the ticks take (`status`: overruns, tick_max_us and
//! the deepest stack).
#ifndef STRIDER_CONTROL_CONTROL_TICK_H
#define STRIDER_CONTROL_CONTROL_TICK_H

#include <stdint.h>

#include "../math/fixed.h"
#include "reply_texts.h"

namespace strider {

constexpr uint32_t kTickPeriodUs = 20000;  //!< control tick, 50 Hz [us]

//! Microseconds (<= 1e6) -> seconds, without a division.
inline void to_seconds(uint32_t us, float* s) { *s = float(us) * 1e-6f; }
inline void to_seconds(uint32_t us, Fixed* s) { *s = Fixed::from_raw(int32_t((us * 4295ul) >> 16)); }  // 2^16 / 1e6 = 4295 / 2^16 (+1e-5)

//! The time a tick advances the gait by [s]: period_us when the caller
//! schedules the ticks, else the time since the last tick (*last_us, now
//! now_us); at most five ticks, so that a stalled loop does not make the gait leap.
template <typename S>
S tick_seconds(uint32_t now_us, uint32_t* last_us, uint32_t period_us) {
  uint32_t dt_us = period_us != 0 ? period_us : now_us - *last_us;
  *last_us = now_us;
  if (dt_us > 5 * kTickPeriodUs) dt_us = 5 * kTickPeriodUs;
  S dt_s;
  to_seconds(dt_us, &dt_s);
  return dt_s;
}

struct TickLoad {
  //! How long a tick took [us] (the caller measures); longer than a period
  //! counts as an overrun.
  void record(uint32_t took_us) {
    if (took_us > max_us) max_us = took_us;
    if (took_us > kTickPeriodUs && overruns < 0xFFFF) ++overruns;
  }
  //! Ticks the caller had to skip (it fell behind by whole periods).
  void record_missed(uint16_t n) {
    const uint32_t sum = uint32_t(overruns) + n;
    overruns = sum > 0xFFFFu ? uint16_t(0xFFFF) : uint16_t(sum);
  }
  void write_status(ReplyWriter& w) const {
    w.format(FlashText{text::kOverrunsFmt}, overruns, int32_t(max_us));
    if (stack_probe != nullptr) w.field(FlashText{text::kStackPeak}, stack_probe());
  }

  uint32_t max_us = 0;
  uint16_t overruns = 0;
  //! A board-specific probe: the deepest stack use since power-up [bytes]
  //! (the firmware paints the free RAM at start-up and counts what was
  //! overwritten; the scan runs only when status is asked).
  uint16_t (*stack_probe)() = nullptr;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_CONTROL_TICK_H
