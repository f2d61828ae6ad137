//! RobotApp's links (Link: `void send_line(uint8_t port, const char* line)`):
//! the boot notices, and LinkPorts, one CommandParser per port, each reply
//! back to its line's port. The reply buffer is a member, not on the stack:
//! a command may reconfigure the walker, the deepest call chain (docs/reliability.md).
#ifndef STRIDER_CONTROL_LINK_PORTS_H
#define STRIDER_CONTROL_LINK_PORTS_H

#include <stdint.h>

#include "../sensing/level_calibration.h"
#include "command_parser.h"
#include "hal_interfaces.h"
#include "line_check.h"
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

//! Which record the settings came from: ` slot=1 seq=7` or ` version=1`,
//! and ` other=corrupt` when the other slot holds neither record nor erased bytes.
inline void describe_record(ReplyWriter& w, const SettingsRecord& r) {
  if (r.version == kSettingsSingleRecordVersion) {
    w.field(FlashText{text::kVersion}, r.version);
  } else {
    w.field(FlashText{text::kSlot}, r.slot).field(FlashText{text::kSeq}, r.seq);
  }
  if (r.other != SettingsStatus::kOk && r.other != SettingsStatus::kEmpty)
    w.field_text(FlashText{text::kOther}, to_flash(r.other));
}

//! The boot notices: model and boards (or `error`, in flash), how the settings loaded.
template <typename Link>
STRIDER_NOINLINE void send_boot_notices(const char* error, const char* name, uint8_t joints, uint8_t boards,
                                        const SettingsRecord& record, Link& link) {
  ReplyLine line;
  ReplyWriter& w = line.w;
  char* const buf = line.buf;
  if (error != nullptr) {
    w.text(FlashText{error});
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

//! Ctl: a Controller; Cal: the LevelCalibration whose tag keeps the port of its reply.
template <typename Ctl, typename Cal>
class LinkPorts {
 public:
  LinkPorts() : last_byte_ms_(), reply_buf_() {}

  template <typename Link>
  void on_byte(uint8_t port, uint8_t b, uint32_t now_us, Ctl& ctl, Cal& cal, Link& link) {
    if (port >= kLinkPorts) return;
    const uint32_t now_ms = now_us / 1000u;
    last_byte_ms_[port] = now_ms;
    Command c;
    const ParseResult r = parsers_[port].feed(b, &c);
    reply(port, r, c, now_ms, ctl, cal, link);
  }

  //! Bytes lost before the next one: its line gets `err 10`; after
  //! kLineIdleMs of silence they ended the line: `err 8`, as idle.
  template <typename Link>
  void on_bytes_lost(uint8_t port, uint32_t now_us, Ctl& ctl, Cal& cal, Link& link) {
    if (port >= kLinkPorts) return;
    const uint32_t now_ms = now_us / 1000u;
    if (elapsed(now_ms, last_byte_ms_[port]) < kLineIdleMs) {
      parsers_[port].lost();
      return;
    }
    Command c;
    reply(port, parsers_[port].idle_timeout(&c), c, now_ms, ctl, cal, link);
  }

  //! Every tick: the partial lines idle for kLineIdleMs are dropped.
  template <typename Link>
  void time_out(uint32_t now_ms, Ctl& ctl, Cal& cal, Link& link) {
    for (uint8_t p = 0; p < kLinkPorts; ++p) {
      if (elapsed(now_ms, last_byte_ms_[p]) < kLineIdleMs) continue;
      Command c;
      reply(p, parsers_[p].idle_timeout(&c), c, now_ms, ctl, cal, link);
    }
  }

  //! The deferred reply to `cal level`, to the port in its tag.
  template <typename Link>
  void level_cal_reply(LevelCalStatus st, int8_t x, int8_t y, uint8_t tag, Ctl& ctl, Link& link) {
    const bool checked = (tag & kChecked) != 0;
    ReplyWriter w(reply_buf_, uint16_t(sizeof reply_buf_ - (checked ? kLineCheckBytes : 0)));
    ctl.level_cal_done(st, x, y, w);
    if (checked) append_line_check(reply_buf_, w.length());
    link.send_line(uint8_t(tag & ~kChecked), reply_buf_);
  }

 private:
  static constexpr uint8_t kChecked = 2;  // a `cal level` tag: the port (bit 0), a checked reply (bit 1)
  static_assert(kLinkPorts <= 2, "cal level keeps the port in one bit");

  template <typename Link>
  void reply(uint8_t port, ParseResult r, const Command& c, uint32_t now_ms, Ctl& ctl, Cal& cal, Link& link) {
    if (r == ParseResult::kNothing) return;
    if (c.source == CommandSource::kBareByte) {  // an RC byte: no reply, so none is written
      char none;
      ReplyWriter nowhere(&none, 1);
      ctl.on_parsed(r, c, now_ms, nowhere);
      return;
    }
    reply_line(port, r, c, now_ms, ctl, cal, link);
  }
  template <typename Link>
  STRIDER_NOINLINE void reply_line(uint8_t port, ParseResult r, const Command& c, uint32_t now_ms, Ctl& ctl, Cal& cal,
                                   Link& link) {
    const bool checked = c.source == CommandSource::kCheckedLine;
    ReplyWriter w(reply_buf_, uint16_t(sizeof reply_buf_ - (checked ? kLineCheckBytes : 0)));
    if (!ctl.on_parsed(r, c, now_ms, w)) return;
    if (w.length() == 0) {  // `cal level` measuring: the reply follows (level_cal_reply())
      cal.start(uint8_t(port | (checked ? kChecked : 0)));
      return;
    }
    if (checked) append_line_check(reply_buf_, w.length());
    link.send_line(port, reply_buf_);
  }

  CommandParser parsers_[kLinkPorts];
  uint32_t last_byte_ms_[kLinkPorts];
  char reply_buf_[kMaxReplyBytes];
};

}  // namespace strider

#endif  // STRIDER_CONTROL_LINK_PORTS_H
