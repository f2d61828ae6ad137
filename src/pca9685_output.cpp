#include "pca9685_output.h"

#include "pca9685_bus.h"

bool Pca9685Output::begin(uint8_t boards) {
  boards_ = boards;
  for (uint8_t i = 0; i < channels_; ++i) off_[i] = kFullOff;
  dirty_ = 0;
  return pca9685_bus::begin(boards);
}

void Pca9685Output::set_prescale(uint8_t prescale) { pca9685_bus::set_prescale(boards_, prescale); }

void Pca9685Output::flush() {
  bytes_ = 0;
  uint8_t burst[4 * pca9685_bus::kMaxBurstChannels];
  uint8_t ch = 0;
  while (dirty_ != 0 && ch < channels_) {
    if (!(dirty_ & (uint32_t(1) << ch))) { ++ch; continue; }
    // A run of changed channels on one board, at most kMaxBurstChannels long.
    const uint8_t board = uint8_t(ch / strider::kPcaChannelsPerBoard);
    const uint8_t first = ch;
    uint8_t n = 0;
    while (ch < channels_ && (dirty_ & (uint32_t(1) << ch)) && ch / strider::kPcaChannelsPerBoard == board &&
           n < pca9685_bus::kMaxBurstChannels) {
      const uint16_t off = off_[ch];
      burst[4 * n + 0] = 0;  // ON at tick 0
      burst[4 * n + 1] = 0;
      burst[4 * n + 2] = uint8_t(off & 0xFF);
      burst[4 * n + 3] = uint8_t(off >> 8);
      dirty_ &= ~(uint32_t(1) << ch);
      ++n;
      ++ch;
    }
    if (board >= boards_) continue;
    if (!pca9685_bus::write_channels(board, uint8_t(first % strider::kPcaChannelsPerBoard), burst, n)) ++errors_;
    bytes_ = uint16_t(bytes_ + 2 + 4 * n - 2);  // address + register + data from the first OFF_L
  }
}
