//! ServoBoardWatch: which servo boards answer, from the driver's reports
//! (servo_boards.h): a silent board or a hung bus is reported once, one
//! that answers again too, its legs soft-started; the servos cannot walk
//! meanwhile (docs/reliability.md, "Servo boards").
#ifndef STRIDER_CONTROL_SERVO_BOARD_WATCH_H
#define STRIDER_CONTROL_SERVO_BOARD_WATCH_H

#include <stdint.h>

#include "reply_texts.h"
#include "link_ports.h"
#include "servo_boards.h"

namespace strider {

struct ServoBoardWatch {
  //! Report r at now_ms: its notices, a board back adopted and soft-started.
  //! True while the servos cannot walk.
  template <typename Stage, typename Output, typename Link>
  bool report(const ServoBoardReport& r, uint32_t now_ms, Stage& stage, Output& out, Link& link) {
    notify(r, link);
    if (r.restored != 0 && r.outputs != nullptr) {
      stage.adopt_outputs(out, r.outputs, r.channels, r.restored);
      if (stage.all_on() || stage.starting()) {
        stage.restart_soft_start(now_ms);
        restoring = true;
      }
    }
    return keep(r);
  }
  //! True once the legs of a board that came back are all on again.
  bool restored(bool starting) {
    if (!restoring || starting) return false;
    restoring = false;
    return true;
  }
  //! The notices of report r against the last one kept.
  template <typename Link>
  void notify(const ServoBoardReport& r, Link& link) const {
    const uint8_t lost = uint8_t((r.faulted | r.restored) & ~faulted);
    const uint8_t back = uint8_t((faulted | r.restored) & ~r.faulted);
    for (uint8_t b = 0; b < kMaxPcaBoards; ++b)
      if (lost & board_bit(b)) send_board_notice(FlashText{text::kInfoFaultPca}, b, FlashText{text::kNothing}, link);
    if (r.bus_stuck && !bus_stuck) send_notice(FlashText{text::kInfoFaultI2c}, link);
    for (uint8_t b = 0; b < kMaxPcaBoards; ++b)
      if (back & board_bit(b)) send_board_notice(FlashText{text::kInfoPca}, b, FlashText{text::kRestored}, link);
  }
  //! Keeps report r; true while the servos cannot walk.
  bool keep(const ServoBoardReport& r) {
    faulted = r.faulted;
    bus_stuck = r.bus_stuck;
    i2c_errors = r.errors;
    return faulted != 0 || restoring;
  }
  //! ` pca9685=ok` or the silent boards' addresses, ` i2c_errors=`.
  void write_status(ReplyWriter& w) const {
    w.ch(' ').text(FlashText{text::kPca9685}).ch('=');
    if (faulted == 0) w.text(FlashText{text::kOk});
    for (uint8_t b = 0, n = 0; b < kMaxPcaBoards; ++b)
      if (faulted & board_bit(b)) write_board(n++ != 0 ? w.ch(',') : w, b);
    w.field(FlashText{text::kI2cErrors}, i2c_errors);
  }

  uint8_t faulted = 0;      //!< boards not answering
  bool bus_stuck = false;
  bool restoring = false;   //!< a board came back: its legs are being switched on again
  uint16_t i2c_errors = 0;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_BOARD_WATCH_H
