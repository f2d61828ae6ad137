// A PCA9685 16-channel PWM controller as seen from its I2C bus: the register
// file, MODE1 sleep/restart/auto-increment, PRE_SCALE (written only while
// asleep), the ALL_LED registers, full-on/full-off bits and the decoded pulse
// width of each channel. Pure C++: the bus glue lives in virtual_mega.cpp.
// Register behaviour follows the NXP PCA9685 datasheet (rev. 4), section 7.
#ifndef STRIDER_TOOLS_VBENCH_PCA9685_H
#define STRIDER_TOOLS_VBENCH_PCA9685_H

#include <array>
#include <cstddef>
#include <cstdint>

namespace strider_vmega {

using std::size_t;

class Pca9685 {
 public:
  static constexpr int kChannels = 16;
  static constexpr uint8_t kMode1 = 0x00;
  static constexpr uint8_t kMode2 = 0x01;
  static constexpr uint8_t kLed0OnL = 0x06;
  static constexpr uint8_t kLastLedReg = 0x45;
  static constexpr uint8_t kAllLedOnL = 0xFA;
  static constexpr uint8_t kPreScale = 0xFE;
  static constexpr uint8_t kTestMode = 0xFF;
  // MODE1 bits.
  static constexpr uint8_t kRestart = 0x80;
  static constexpr uint8_t kExtClk = 0x40;
  static constexpr uint8_t kAutoIncrement = 0x20;
  static constexpr uint8_t kSleep = 0x10;
  static constexpr uint8_t kAllCall = 0x01;
  // MODE2 bit: outputs change on ACK (1) or on STOP (0).
  static constexpr uint8_t kOch = 0x08;
  // Bit 4 of LEDn_ON_H / LEDn_OFF_H.
  static constexpr uint8_t kFullBit = 0x10;
  //! The oscillator must run this long after SLEEP is cleared before RESTART [us].
  static constexpr uint64_t kOscillatorStartUs = 500;

  //! address7: 7-bit bus address; osc_hz: this board's oscillator [Hz].
  explicit Pca9685(uint8_t address7 = 0x40, double osc_hz = 25e6);

  //! Power-on (or software-reset) register values.
  void power_on_reset();
  //! Supply on or off: an unpowered board drives no output and does not
  //! answer on the bus; powered again, it starts from its power-on values.
  void set_powered(bool on);
  bool powered() const { return powered_; }

  // Bus side, called by the I2C glue between START and STOP.
  //! SLA+W acknowledged: the next byte written is the control register pointer.
  void begin_write();
  //! A byte written by the master (pointer first, then data) at now_us.
  void write_byte(uint8_t byte, uint64_t now_us);
  //! The byte a master read gets; advances the pointer when AI is set.
  uint8_t read_byte();
  //! STOP (or repeated START): outputs latch here when MODE2.OCH = 0.
  void stop();

  uint8_t address() const { return address7_; }
  double osc_hz() const { return osc_hz_; }
  void set_osc_hz(double hz) { osc_hz_ = hz; }
  //! Register as a master would read it.
  uint8_t reg(uint8_t r) const;
  uint8_t pointer() const { return pointer_; }
  bool sleeping() const { return (regs_[kMode1] & kSleep) != 0; }
  //! PWM stopped by sleep until RESTART (or a channel write) wakes it.
  bool paused() const { return paused_; }
  uint8_t prescale() const { return regs_[kPreScale]; }
  //! One PWM count [us] with this board's oscillator and prescale.
  double tick_us() const { return 1e6 * (double(prescale()) + 1.0) / osc_hz_; }
  double period_us() const { return 4096.0 * tick_us(); }
  double pwm_hz() const { return 1e6 / period_us(); }
  //! Latched output registers of a channel (12-bit counts plus full bits).
  uint16_t on_word(int ch) const { return out_[size_t(ch)].on; }
  uint16_t off_word(int ch) const { return out_[size_t(ch)].off; }
  //! High time of a channel's output [us]; 0 when off, full-off, asleep or
  //! unpowered, one period when full-on.
  double pulse_us(int ch) const;
  //! Times RESTART was written sooner than kOscillatorStartUs after waking.
  int early_restarts() const { return early_restarts_; }

 private:
  struct Output {
    uint16_t on = 0;
    uint16_t off = 0x1000;  // full off at power-on
  };
  void write_reg(uint8_t r, uint8_t v, uint64_t now_us);
  void write_mode1(uint8_t v, uint64_t now_us);
  void latch();
  bool any_output_active() const;
  static uint8_t next_pointer(uint8_t r);

  uint8_t address7_;
  double osc_hz_;
  std::array<uint8_t, 256> regs_{};
  std::array<Output, kChannels> out_{};
  uint8_t pointer_ = 0;
  bool have_pointer_ = false;
  bool restart_flag_ = false;
  bool paused_ = false;
  bool pwm_written_ = false;  // a PWM register changed since the last STOP
  uint64_t woke_at_us_ = 0;
  int early_restarts_ = 0;
  bool powered_ = true;
};

}  // namespace strider_vmega

#endif  // STRIDER_TOOLS_VBENCH_PCA9685_H
