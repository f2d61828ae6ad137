// A ServoOutput that records every write.
#ifndef STRIDER_TEST_CONTROL_RECORDING_SERVO_H
#define STRIDER_TEST_CONTROL_RECORDING_SERVO_H

#include <stdint.h>

#include <vector>

namespace strider_test {

struct RecordingServo {
  struct Write {
    uint8_t channel;
    uint16_t ticks;
  };
  std::vector<Write> writes;
  uint8_t prescale = 0;
  std::vector<uint8_t> relaxed;
  int flushes = 0;
  void write_ticks(uint8_t channel, uint16_t ticks) { writes.push_back(Write{channel, ticks}); }
  void set_prescale(uint8_t p) { prescale = p; }
  void relax(uint8_t channel) { relaxed.push_back(channel); }
  void flush() { ++flushes; }
};

}  // namespace strider_test

#endif
