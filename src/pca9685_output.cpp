#include "pca9685_output.h"

#include "pca9685_bus.h"

namespace {
constexpr uint8_t kPerBoard = strider::kPcaChannelsPerBoard;
}  // namespace

void Pca9685Output::begin(uint8_t boards, uint8_t warm_prescale) {
  boards_ = boards <= strider::kMaxPcaBoards ? boards : strider::kMaxPcaBoards;
  for (uint8_t i = 0; i < channels_; ++i) off_[i] = kFullOff;
  dirty_ = 0;
  held_ = 0;
  pca9685_bus::begin();
  for (uint8_t b = 0; b < boards_; ++b) {
    uint8_t mode1 = 0, prescale = 0;
    if (warm_prescale != 0 && pca9685_bus::read_mode(b, &mode1, &prescale) &&
        mode1 == pca9685_bus::kMode1Running && prescale == warm_prescale && read_back(b)) {
      running_[b] = prescale;  // it kept running through the reset: as it is
      for (uint8_t i = uint8_t(b * kPerBoard); i < channels_ && i < (b + 1) * kPerBoard; ++i)
        if (!(off_[i] & kFullOff)) ++held_;
      continue;
    }
    if (!pca9685_bus::init_board(b)) fail(b);
  }
}

void Pca9685Output::set_prescale(uint8_t prescale) {
  prescale_ = prescale;
  for (uint8_t b = 0; b < boards_; ++b) {
    if ((faulted_ & strider::board_bit(b)) || running_[b] == prescale) continue;
    if (pca9685_bus::set_prescale(b, prescale)) running_[b] = prescale;
    else fail(b);
  }
}

void Pca9685Output::flush() {
  bytes_ = 0;
  uint8_t burst[4 * pca9685_bus::kMaxBurstChannels];
  uint8_t ch = 0;
  while (dirty_ != 0 && ch < channels_) {
    if (!(dirty_ & (uint32_t(1) << ch))) { ++ch; continue; }
    // A run of changed channels on one board, at most kMaxBurstChannels long.
    const uint8_t board = uint8_t(ch / kPerBoard);
    const uint8_t first = ch;
    uint8_t n = 0;
    while (ch < channels_ && (dirty_ & (uint32_t(1) << ch)) && ch / kPerBoard == board &&
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
    // A faulted board gets nothing: take_back() brings it up to date.
    if (board >= boards_ || (faulted_ & strider::board_bit(board))) continue;
    if (!pca9685_bus::write_channels(board, uint8_t(first % kPerBoard), burst, n)) fail(board);
    bytes_ = uint16_t(bytes_ + 2 + 4 * n - 2);  // address + register + data from the first OFF_L
  }
}

void Pca9685Output::fail(uint8_t b) {
  if (errors_ != 0xFFFF) ++errors_;
  faulted_ |= strider::board_bit(b);
  // A time-out: the bus itself is held, no board can be reached.
  if (pca9685_bus::timed_out()) {
    bus_stuck_ = true;
    faulted_ = all_boards();
  }
}

void Pca9685Output::service(uint32_t now_ms) {
  if (int32_t(now_ms - next_check_ms_) >= 0) {
    next_check_ms_ = now_ms + kCheckMs;
    check();
  }
  if (faulted_ != 0 && int32_t(now_ms - next_probe_ms_) >= 0) {
    next_probe_ms_ = now_ms + kProbeMs;
    probe();
  }
}

void Pca9685Output::check() {
  for (uint8_t b = 0; b < boards_; ++b) {
    if (faulted_ & strider::board_bit(b)) continue;
    uint8_t mode1 = 0, prescale = 0;
    if (pca9685_bus::read_mode(b, &mode1, &prescale) && mode1 == pca9685_bus::kMode1Running &&
        prescale == running_[b])
      continue;
    fail(b);  // silent, or reset behind the firmware's back (asleep: its outputs are off)
    if (bus_stuck_) return;
  }
}

void Pca9685Output::probe() {
  for (uint8_t b = 0; b < boards_; ++b) {
    if (!(faulted_ & strider::board_bit(b))) continue;
    const bool there = pca9685_bus::probe(b);  // not counted: a missing board is probed for ever
    if (pca9685_bus::timed_out()) return;     // still held: no other board either
    bus_stuck_ = false;
    if (!there) continue;
    if (take_back(b)) {
      faulted_ &= uint8_t(~strider::board_bit(b));
      restored_ |= strider::board_bit(b);
    } else {
      fail(b);
    }
  }
}

bool Pca9685Output::take_back(uint8_t b) {
  uint8_t mode1 = 0, prescale = 0;
  if (!pca9685_bus::read_mode(b, &mode1, &prescale)) return false;
  // Kept its registers (its bus wires came loose, the supply stayed): it
  // drives what it drove; RobotApp moves its legs on from there.
  if (mode1 == pca9685_bus::kMode1Running && prescale == prescale_ && running_[b] == prescale_) return read_back(b);
  // Lost them (power-on state): asleep with every output off, then the
  // prescale and awake; its legs get their first pulses from RobotApp's
  // soft start.
  running_[b] = 0;
  if (!pca9685_bus::init_board(b)) return false;
  for (uint8_t i = uint8_t(b * kPerBoard); i < channels_ && i < (b + 1) * kPerBoard; ++i) {
    off_[i] = kFullOff;
    dirty_ &= ~(uint32_t(1) << i);
  }
  if (prescale_ == 0) return true;  // set_prescale() has not run yet: it will
  if (!pca9685_bus::set_prescale(b, prescale_)) return false;
  running_[b] = prescale_;
  return true;
}

bool Pca9685Output::read_back(uint8_t b) {
  uint16_t words[kPerBoard];
  if (!pca9685_bus::read_outputs(b, words)) return false;
  for (uint8_t k = 0; k < kPerBoard; ++k) {
    const uint8_t i = uint8_t(b * kPerBoard + k);
    if (i >= channels_) break;
    off_[i] = words[k];
    dirty_ &= ~(uint32_t(1) << i);
  }
  return true;
}

strider::ServoBoardReport Pca9685Output::report() {
  strider::ServoBoardReport r;
  r.faulted = faulted_;
  r.restored = restored_;
  r.bus_stuck = bus_stuck_;
  r.errors = errors_;
  r.outputs = off_;
  r.channels = channels_;
  restored_ = 0;
  return r;
}
