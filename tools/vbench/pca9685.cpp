// PCA9685 register model (see pca9685.h).
#include "pca9685.h"

namespace strider_vmega {

Pca9685::Pca9685(uint8_t address7, double osc_hz) : address7_(address7), osc_hz_(osc_hz) {
  power_on_reset();
}

void Pca9685::power_on_reset() {
  regs_.fill(0);
  regs_[kMode1] = kSleep | kAllCall;  // 0x11: asleep, answers ALLCALL
  regs_[kMode2] = 0x04;               // OUTDRV totem pole
  regs_[0x02] = 0xE2;                 // SUBADR1..3, ALLCALLADR
  regs_[0x03] = 0xE4;
  regs_[0x04] = 0xE8;
  regs_[0x05] = 0xE0;
  for (int ch = 0; ch < kChannels; ++ch) regs_[size_t(kLed0OnL + 4 * ch + 3)] = kFullBit;
  regs_[kPreScale] = 0x1E;  // 200 Hz with the 25 MHz oscillator
  out_.fill(Output());
  pointer_ = 0;
  have_pointer_ = false;
  restart_flag_ = false;
  paused_ = false;
  pwm_written_ = false;
  woke_at_us_ = 0;
}

void Pca9685::set_powered(bool on) {
  if (on && !powered_) power_on_reset();
  powered_ = on;
}

uint8_t Pca9685::next_pointer(uint8_t r) {
  // Datasheet 7.3: past LED15_OFF_H (0x45) and past PRE_SCALE the pointer
  // rolls over to MODE1; ALL_LED_ON_L..PRE_SCALE is the other run.
  if (r == kLastLedReg || r >= kPreScale) return kMode1;
  return uint8_t(r + 1);
}

void Pca9685::begin_write() { have_pointer_ = false; }

void Pca9685::write_byte(uint8_t byte, uint64_t now_us) {
  if (!have_pointer_) {
    pointer_ = byte;
    have_pointer_ = true;
    return;
  }
  write_reg(pointer_, byte, now_us);
  if (regs_[kMode1] & kAutoIncrement) pointer_ = next_pointer(pointer_);
}

uint8_t Pca9685::read_byte() {
  const uint8_t v = reg(pointer_);
  if (regs_[kMode1] & kAutoIncrement) pointer_ = next_pointer(pointer_);
  return v;
}

uint8_t Pca9685::reg(uint8_t r) const {
  if (r > kLastLedReg && r < kPreScale) return 0;  // reserved and write-only ALL_LED
  return regs_[r];
}

void Pca9685::write_reg(uint8_t r, uint8_t v, uint64_t now_us) {
  if (r == kMode1) {
    write_mode1(v, now_us);
    return;
  }
  if (r == kPreScale) {
    // PRE_SCALE is write-protected while the oscillator runs; the hardware
    // forces a minimum of 3.
    if (sleeping()) regs_[r] = v < 3 ? 3 : v;
    return;
  }
  if (r >= kLed0OnL && r <= kLastLedReg) {
    regs_[r] = v;
    pwm_written_ = true;
    // OCH = 1: a channel's outputs change at the ACK of its fourth register.
    if ((regs_[kMode2] & kOch) && (r - kLed0OnL) % 4 == 3) latch();
    return;
  }
  if (r >= kAllLedOnL && r < kPreScale) {
    const int k = r - kAllLedOnL;
    for (int ch = 0; ch < kChannels; ++ch) regs_[size_t(kLed0OnL + 4 * ch + k)] = v;
    pwm_written_ = true;
    if ((regs_[kMode2] & kOch) && k == 3) latch();
    return;
  }
  if (r <= 0x05) regs_[r] = v;  // MODE2, sub-addresses, ALLCALLADR
  // Reserved registers and TestMode ignore writes.
}

void Pca9685::write_mode1(uint8_t v, uint64_t now_us) {
  const bool was_sleeping = sleeping();
  const bool sleep = (v & kSleep) != 0;
  if (!was_sleeping && sleep && any_output_active()) {
    // 7.3.1.1: sleeping with PWM running sets RESTART; the channels stay
    // stopped after waking until RESTART is written.
    restart_flag_ = true;
    paused_ = true;
  }
  if (was_sleeping && !sleep) woke_at_us_ = now_us;
  if ((v & kRestart) && restart_flag_ && !sleep) {
    if (now_us - woke_at_us_ < kOscillatorStartUs) ++early_restarts_;
    restart_flag_ = false;
    paused_ = false;
  }
  regs_[kMode1] = uint8_t((v & ~kRestart) | (restart_flag_ ? kRestart : 0));
}

void Pca9685::stop() {
  have_pointer_ = false;
  if (!pwm_written_) return;
  pwm_written_ = false;
  if (!(regs_[kMode2] & kOch)) latch();
  // Writing a PWM register and a STOP also clears RESTART (7.3.1.1).
  restart_flag_ = false;
  paused_ = false;
  regs_[kMode1] = uint8_t(regs_[kMode1] & ~kRestart);
}

void Pca9685::latch() {
  for (int ch = 0; ch < kChannels; ++ch) {
    const size_t b = size_t(kLed0OnL + 4 * ch);
    out_[size_t(ch)].on = uint16_t(regs_[b] | (regs_[b + 1] << 8));
    out_[size_t(ch)].off = uint16_t(regs_[b + 2] | (regs_[b + 3] << 8));
  }
}

bool Pca9685::any_output_active() const {
  for (int ch = 0; ch < kChannels; ++ch)
    if (pulse_us(ch) > 0) return true;
  return false;
}

double Pca9685::pulse_us(int ch) const {
  if (ch < 0 || ch >= kChannels || !powered_ || sleeping() || paused_) return 0.0;
  const Output& o = out_[size_t(ch)];
  if (o.off & 0x1000) return 0.0;  // full off wins over full on
  if (o.on & 0x1000) return period_us();
  const int on = o.on & 0x0FFF;
  const int off = o.off & 0x0FFF;
  if (on == off) return 0.0;
  const int ticks = (off - on) & 0x0FFF;
  return double(ticks) * tick_us();
}

}  // namespace strider_vmega
