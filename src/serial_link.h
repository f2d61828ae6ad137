// The two text links: Serial (USB, port 0) and Serial1 (HC-05, port 1). A
// reply goes to the port its line came from, a notice to both. Lines end in
// CR LF (what the phone terminal apps expect).
//
// Nothing here waits for the UART: what does not fit the core's 64-byte
// transmit buffer waits in a 192-byte ring per port and is handed over by
// poll() as the buffer drains (a 230-byte status line takes 0.24 s at 9600
// baud: written blocking, it would stall twelve control ticks). Only a ring
// that is full makes send_line() wait (a client sending lines faster than
// their replies can go out); that wait keeps the watchdog fed, since the UART
// always empties the buffer, and the missed ticks count as overruns.
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
  //! Moves waiting bytes into the UARTs' buffers; call every loop.
  void poll() {
    usb_.drain(Serial);
    bluetooth_.drain(Serial1);
  }

 private:
  class Ring {
   public:
    void put_line(HardwareSerial& s, const char* line) {
      for (const char* p = line; *p != 0; ++p) put(s, *p);
      put(s, '\r');
      put(s, '\n');
    }
    void drain(HardwareSerial& s) {
      while (len_ > 0 && s.availableForWrite() > 0) {
        s.write(uint8_t(buf_[head_]));
        head_ = uint8_t((head_ + 1) % kSize);
        --len_;
      }
    }

   private:
    static constexpr uint8_t kSize = 192;  // with the UART's 64: the longest reply (status)
    void put(HardwareSerial& s, char c) {
      drain(s);
      if (len_ == 0 && s.availableForWrite() > 0) {  // nothing queued: straight to the UART
        s.write(uint8_t(c));
        return;
      }
      while (len_ == kSize) {  // full: the only place that waits, and it always
        wdt_reset();           // progresses (the UART sends a byte per ms at 9600 baud)
        drain(s);
      }
      buf_[(head_ + len_) % kSize] = c;
      ++len_;
    }
    char buf_[kSize];
    uint8_t head_ = 0;
    uint8_t len_ = 0;
  };

  Ring usb_;
  Ring bluetooth_;
};

#endif
