// The two text links: Serial (USB, port 0) and Serial1 (HC-05, port 1). A
// reply goes to the port its line came from, a notice to both. Lines end in
// CR LF (what the phone terminal apps expect).
//
// What does not fit the core's 64-byte transmit buffer waits in a ring and is
// handed over by poll() as the buffer drains. The Bluetooth ring has 248
// bytes: with the UART's 64 the longest reply (a status line with the servo
// boards' fields, about 276 bytes) waits there whole, taking 0.29 s at 9600
// baud; written blocking it would stall fourteen control ticks. The USB ring
// has 32 (RAM): at 115200 baud the longest line waits at most about 15 ms for
// the UART (it is sent when 64 bytes are free), within the 20 ms tick
// period. Only a ring that is full makes send_line()
// wait; that wait keeps the watchdog fed, since the UART always empties the
// buffer, and ticks missed by whole periods count as overruns. The main loop
// reads a port's bytes only while can_reply() says a reply would not wait
// (on USB: a reply of up to 64 bytes, all but status, help and cal show),
// so that a flood of lines cannot hold up the control tick on replies.
#ifndef STRIDER_SERIAL_LINK_H
#define STRIDER_SERIAL_LINK_H

// Library first: Arduino.h defines min, max, abs and constrain as macros.
#include "control/robot_app.h"

#include <Arduino.h>
#include <avr/wdt.h>

class SerialLink {
 public:
  void send_line(uint8_t port, const char* line) {
    if (port == 0 || port == strider::kAllPorts) usb_.put_line(Serial, line);
    if (port == 1 || port == strider::kAllPorts) bluetooth_.put_line(Serial1, line);
  }
  //! True when a reply to a line from `port` goes out without waiting: the
  //! longest (strider::kMaxReplyBytes) on Bluetooth; on USB, whose ring is
  //! smaller, one of up to 64 bytes (a longer one waits at most ~15 ms for
  //! the UART at 115200 baud, as the ring's size allows).
  bool can_reply(uint8_t port) {
    return port == 0 ? usb_.room(Serial) >= kUsbReplyRoom : bluetooth_.room(Serial1) >= kReplyRoom;
  }
  //! Moves waiting bytes into the UARTs' buffers; call every loop.
  void poll() {
    usb_.drain(Serial);
    bluetooth_.drain(Serial1);
  }

 private:
  // One ring's code for both sizes (a template would duplicate it in flash).
  class Ring {
   public:
    Ring(char* buf, uint8_t size) : buf_(buf), size_(size) {}
    void put_line(HardwareSerial& s, const char* line) {
      for (const char* p = line; *p != 0; ++p) put(s, *p);
      put(s, '\r');
      put(s, '\n');
    }
    //! Bytes that can be queued now without waiting.
    uint16_t room(HardwareSerial& s) const { return uint16_t(size_ - len_) + uint16_t(s.availableForWrite()); }
    void drain(HardwareSerial& s) {
      while (len_ > 0 && s.availableForWrite() > 0) {
        s.write(uint8_t(buf_[head_]));
        head_ = uint8_t(head_ + 1 == size_ ? 0 : head_ + 1);
        --len_;
      }
    }

   private:
    void put(HardwareSerial& s, char c) {
      drain(s);
      if (len_ == 0 && s.availableForWrite() > 0) {  // nothing queued: straight to the UART
        s.write(uint8_t(c));
        return;
      }
      while (len_ == size_) {  // full: the only place that waits, and it always
        wdt_reset();           // progresses (the UART sends a byte per ms at 9600 baud)
        drain(s);
      }
      const uint16_t at = uint16_t(head_) + len_;
      buf_[at >= size_ ? at - size_ : at] = c;
      ++len_;
    }
    char* buf_;
    uint8_t size_;
    uint8_t head_ = 0;
    uint8_t len_ = 0;
  };

  // The longest reply with its CR LF (without the NUL): what can_reply() asks of the Bluetooth ring.
  static constexpr uint16_t kReplyRoom = strider::kMaxReplyBytes + 1;
  static constexpr uint16_t kUsbReplyRoom = 64;
  char usb_buf_[32];         // 115200 baud: a long line waits <= ~15 ms for the UART
  char bluetooth_buf_[248];  // with the UART's 64: the longest reply (status) at 9600 baud
  static_assert(sizeof bluetooth_buf_ + SERIAL_TX_BUFFER_SIZE - 1 >= kReplyRoom, "the longest reply fits the Bluetooth queue");
  static_assert(sizeof usb_buf_ + SERIAL_TX_BUFFER_SIZE - 1 >= kUsbReplyRoom, "a short reply fits the USB queue");
  Ring usb_{usb_buf_, sizeof usb_buf_};
  Ring bluetooth_{bluetooth_buf_, sizeof bluetooth_buf_};
};

#endif
