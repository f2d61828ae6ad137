// Pca9685Output: the firmware's ServoOutput (lib/strider/control/
// hal_interfaces.h). Writes go to a shadow of every channel; flush() sends
// only the channels that changed since the last frame, consecutive ones in
// one auto-increment burst (up to 8 per transfer), so a frame of 18 servos
// costs a few transfers instead of 18 (and the PRESCALE register is never
// re-read: the timing is cached in lib/strider/control/pca9685_timing.h).
#ifndef STRIDER_PCA9685_OUTPUT_H
#define STRIDER_PCA9685_OUTPUT_H

#include <stdint.h>

#include "control/channel_map.h"

class Pca9685Output {
 public:
  static constexpr uint8_t kMaxChannels = strider::kMaxPcaBoards * strider::kPcaChannelsPerBoard;
  static constexpr uint16_t kFullOff = 0x1000;  // LEDn_OFF_H bit 4

  //! The shadow is the caller's: `channels` entries (at most kMaxChannels),
  //! 16 per board its model uses, so that a one-board robot keeps no shadow
  //! of a second board. Writes to other channels are ignored.
  Pca9685Output(uint16_t* shadow, uint8_t channels)
      : off_(shadow), channels_(channels <= kMaxChannels ? channels : kMaxChannels) {}

  //! Starts the bus and the boards; false when a board did not answer.
  bool begin(uint8_t boards);

  void write_ticks(uint8_t channel, uint16_t off_ticks) { set(channel, uint16_t(off_ticks & 0x0FFF)); }
  void relax(uint8_t channel) { set(channel, kFullOff); }
  void set_prescale(uint8_t prescale);
  //! Sends the changed channels.
  void flush();

  uint16_t bytes_last_frame() const { return bytes_; }  //!< I2C payload bytes of the last flush
  uint16_t bus_errors() const { return errors_; }       //!< transfers not acknowledged

 private:
  void set(uint8_t channel, uint16_t off) {
    if (channel >= channels_ || off_[channel] == off) return;
    off_[channel] = off;
    dirty_ |= uint32_t(1) << channel;
  }

  uint16_t* off_;
  uint8_t channels_;
  uint32_t dirty_ = 0;
  uint16_t bytes_ = 0;
  uint16_t errors_ = 0;
  uint8_t boards_ = 0;
};

#endif
