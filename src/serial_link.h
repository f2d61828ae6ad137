// The two text links: Serial (USB, port 0) and Serial1 (HC-05, port 1). A
// reply goes to the port its line came from, a notice to both. Lines end in
// CR LF (what the phone terminal apps expect).
#ifndef STRIDER_SERIAL_LINK_H
#define STRIDER_SERIAL_LINK_H

// Library first: Arduino.h defines min, max, abs and constrain as macros.
#include "control/robot_app.h"

#include <Arduino.h>

struct SerialLink {
  void send_line(uint8_t port, const char* line) {
    if (port == 0 || port == strider::kAllPorts) put(Serial, line);
    if (port == 1 || port == strider::kAllPorts) put(Serial1, line);
  }

 private:
  static void put(HardwareSerial& s, const char* line) {
    s.write(line);
    s.write("\r\n");
  }
};

#endif
