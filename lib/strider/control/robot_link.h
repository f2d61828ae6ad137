//! RobotApp's link: its ports, and the notices it sends to all of them
//! (boot, servo boards, battery, fall), each a line of its own.
//! Link: `void send_line(uint8_t port, const char* line)`, line without its
//! ending; port kAllPorts means every port.
#ifndef STRIDER_CONTROL_ROBOT_LINK_H
#define STRIDER_CONTROL_ROBOT_LINK_H

#include <stdint.h>

#include "reply_texts.h"
#include "servo_boards.h"
#include "settings_store.h"

namespace strider {

constexpr uint8_t kLinkPorts = 2;          //!< 0 = USB serial, 1 = Bluetooth (HC-05)
constexpr uint8_t kAllPorts = 0xFF;        //!< send_line(): every port
constexpr uint16_t kLineIdleMs = 300;      //!< a partial line older than this is dropped [ms]

template <typename Link>
STRIDER_NOINLINE void send_notice(FlashText text, Link& link) {
  ReplyLine line;
  line.w.text(text);
  link.send_line(kAllPorts, line.buf);
}

//! Board b's I2C address, `0x41`.
inline ReplyWriter& write_board(ReplyWriter& w, uint8_t b) {
  const uint8_t a = uint8_t(kPcaFirstAddress + b);
  const char lo = char(a & 15u);
  return w.ch('0').ch('x').ch(char('0' + (a >> 4))).ch(char(lo < 10 ? '0' + lo : 'a' + lo - 10));
}
//! `<head>0x41<tail>` for board b.
template <typename Link>
STRIDER_NOINLINE void send_board_notice(FlashText head, uint8_t b, FlashText tail, Link& link) {
  ReplyLine line;
  write_board(line.w.text(head), b).text(tail);
  link.send_line(kAllPorts, line.buf);
}

//! Which record the settings came from: ` slot=1 seq=7`, or ` version=1`
//! (the single record before the slots); ` other=corrupt` (old_version,
//! invalid) when the other slot holds neither a record nor erased bytes.
inline void describe_record(ReplyWriter& w, const SettingsRecord& r) {
  if (r.version == kSettingsSingleRecordVersion) {
    w.field(FlashText{text::kVersion}, r.version);
  } else {
    w.field(FlashText{text::kSlot}, r.slot).field(FlashText{text::kSeq}, r.seq);
  }
  if (r.other != SettingsStatus::kOk && r.other != SettingsStatus::kEmpty)
    w.field_text(FlashText{text::kOther}, to_flash(r.other));
}

//! The boot notices: model and boards (or err 30: the model does not fit),
//! how the settings loaded.
template <typename Link>
STRIDER_NOINLINE void send_boot_notices(bool ok, const char* name, uint8_t joints, uint8_t boards,
                                        const SettingsRecord& record, Link& link) {
  ReplyLine line;
  ReplyWriter& w = line.w;
  char* const buf = line.buf;
  if (!ok) {
    w.text(FlashText{text::kErrModel});
    link.send_line(kAllPorts, buf);
    return;
  }
  w.text(FlashText{text::kInfoStrider}).text(name).text(FlashText{text::kReady});
  w.field(FlashText{text::kJoints}, joints).field(FlashText{text::kBoards}, boards);
  link.send_line(kAllPorts, buf);
  ReplyWriter e(buf, sizeof line.buf);
  e.text(FlashText{text::kInfoEeprom}).text(to_flash(record.load_status));
  if (record.load_status != SettingsStatus::kOk) {
    e.text(FlashText{text::kDefaults});
  } else {
    describe_record(e, record);
  }
  link.send_line(kAllPorts, buf);
}

}  // namespace strider

#endif  // STRIDER_CONTROL_ROBOT_LINK_H
