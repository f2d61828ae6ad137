// The PCA9685 boards through Adafruit's libraries: the registers and bits of
// the Adafruit PWM Servo Driver library (Adafruit_PWMServoDriver.h) written
// through Adafruit_BusIO's Adafruit_I2CDevice, the object that library makes
// every one of its own transfers through.
//
// Why not Adafruit_PWMServoDriver's methods (measured on the virtual Mega
// with the library's 3.0.2 release):
// - begin() software-resets a board and sets 1 kHz (setPWMFreq(1000)). After
//   an MCU reset the boards are still powered and still hold the last frame:
//   every servo then gets 66-81 us pulses at 1 kHz until its channel is
//   written again (a twitch at every reset).
// - setPWMFreq(float) computes the prescale in float, which links about 1 KB
//   of soft-float into a fixed-point firmware, and blocks 5 ms per board.
//   Strider computes the prescale and every pulse from the board's calibrated
//   oscillator in integers (lib/strider/control/pca9685_timing.h).
// - begin() allocates its Adafruit_I2CDevice with new, and every other method
//   needs that device, so none of them can be used without begin().
// - It has no multi-channel write: 18 channels one setPWM() at a time cost
//   18 transfers (about 2.9 ms of bus at 400 kHz); the frame's bursts of up
//   to 7 channels (auto-increment) cost 1.8 ms.
// So the firmware keeps one Adafruit_I2CDevice per board and writes the
// registers the library's begin()/setPWMFreq() write, in an order that never
// lets a board run at another frequency.
//
// Faults: Wire's time-out is on (kTimeoutUs), so a bus held low (a slave
// holding SDA, a short) fails a transfer within milliseconds instead of
// hanging the loop until the watchdog resets the board (and again after the
// reset); Wire then resets the TWI. A board that does not answer fails its
// transfers at once (no ACK). Pca9685Output decides what follows.
#include "control/channel_map.h"  // before Arduino.h (its min/max macros)

#include <Adafruit_I2CDevice.h>
#include <Adafruit_PWMServoDriver.h>
#include <Arduino.h>
#include <Wire.h>

#include "board_pins.h"
#include "pca9685_bus.h"

namespace pca9685_bus {
namespace {

static_assert(strider::kPcaFirstAddress == PCA9685_I2C_ADDRESS, "the first board at the library's default address");
static_assert(1 + 4 * kMaxBurstChannels - 2 <= 32, "a burst fits Adafruit_I2CDevice's 32-byte transfer on the AVR");
static_assert(kMode1Running == (MODE1_AI | MODE1_ALLCAL), "MODE1 while running: auto-increment, all-call");

// A transfer's longest wait for the bus [us]: the longest transfer (32
// bytes, 0.72 ms at 400 kHz) with room for clock stretching; three of them
// are still within a tick of the 20 ms period.
constexpr uint32_t kTimeoutUs = 2000;

Adafruit_I2CDevice g_boards[strider::kMaxPcaBoards] = {
    Adafruit_I2CDevice(PCA9685_I2C_ADDRESS, &Wire),
    Adafruit_I2CDevice(PCA9685_I2C_ADDRESS + 1, &Wire)};

bool g_timed_out = false;

// Whether the transfer that just returned `ok` failed by a time-out.
bool note(bool ok) {
  if (!ok && Wire.getWireTimeoutFlag()) {
    Wire.clearWireTimeoutFlag();
    g_timed_out = true;
  }
  return ok;
}

bool write_register(uint8_t board, uint8_t reg, uint8_t value) {
  return note(g_boards[board].write(&value, 1, true, &reg, 1));
}

bool read_registers(uint8_t board, uint8_t reg, uint8_t* to, uint8_t n) {
  return note(g_boards[board].write_then_read(&reg, 1, to, n));
}

}  // namespace

void begin() {
  for (uint8_t b = 0; b < strider::kMaxPcaBoards; ++b) g_boards[b].begin(false);  // Wire.begin(), no transfer
  Wire.setClock(pins::kI2cClockHz);        // after Wire.begin(), which sets 100 kHz
  Wire.setWireTimeout(kTimeoutUs, true);  // true: Wire resets the TWI after a time-out
}

bool init_board(uint8_t b) {
  if (b >= strider::kMaxPcaBoards) return false;
  // Asleep first: a board that kept running through an MCU reset stops its
  // pulses here rather than emitting the old frame at another frequency.
  if (!write_register(b, PCA9685_MODE1, kMode1Running | MODE1_SLEEP)) return false;
  if (!write_register(b, PCA9685_MODE2, MODE2_OUTDRV)) return false;  // totem-pole outputs for servo lines
  static const uint8_t kAllFullOff[4] = {0x00, 0x00, 0x00, 0x10};  // ALL_LED_OFF_H bit 4
  const uint8_t reg = PCA9685_ALLLED_ON_L;
  return note(g_boards[b].write(kAllFullOff, sizeof kAllFullOff, true, &reg, 1));
}

bool set_prescale(uint8_t b, uint8_t prescale) {
  if (b >= strider::kMaxPcaBoards) return false;
  // MODE1 is known (init_board() wrote it): writes only, nothing read back.
  if (!write_register(b, PCA9685_MODE1, kMode1Running | MODE1_SLEEP) ||  // PRE_SCALE is writable only asleep
      !write_register(b, PCA9685_PRESCALE, prescale) || !write_register(b, PCA9685_MODE1, kMode1Running))
    return false;
  delayMicroseconds(500);  // oscillator start-up (datasheet 7.3.1.1: 500 us)
  return write_register(b, PCA9685_MODE1, kMode1Running | MODE1_RESTART);
}

bool probe(uint8_t b) { return b < strider::kMaxPcaBoards && note(g_boards[b].detected()); }

// One transfer from PRE_SCALE on: auto-increment rolls over from it to MODE1
// and MODE2 (datasheet 7.3, table 4's remark). A board without
// auto-increment (its power-on state) sends PRE_SCALE three times, which
// no MODE2 this firmware sets matches: such a board is not running.
bool read_mode(uint8_t b, uint8_t* mode1, uint8_t* prescale) {
  uint8_t r[3];
  if (b >= strider::kMaxPcaBoards || !read_registers(b, PCA9685_PRESCALE, r, sizeof r)) return false;
  *prescale = r[0];
  *mode1 = r[2] == MODE2_OUTDRV ? r[1] : uint8_t(0);
  return true;
}

bool read_outputs(uint8_t b, uint16_t* off) {
  if (b >= strider::kMaxPcaBoards) return false;
  // Eight channels per transfer (32 bytes, Wire's buffer), from LED0_ON_L.
  uint8_t words[4 * kMaxBurstChannels];
  for (uint8_t first = 0; first < strider::kPcaChannelsPerBoard; first += kMaxBurstChannels) {
    if (!read_registers(b, uint8_t(PCA9685_LED0_ON_L + 4 * first), words, sizeof words)) return false;
    for (uint8_t i = 0; i < kMaxBurstChannels; ++i) {
      const uint8_t* w = words + 4 * i;
      const uint16_t on = uint16_t(w[0] | (w[1] << 8));
      const uint16_t v = uint16_t(w[2] | (w[3] << 8));
      off[first + i] = on == 0 && !(v & kFullOff) ? uint16_t(v & 0x0FFF) : kFullOff;
    }
  }
  return true;
}

// From the first channel's OFF_L on: its ON word is 0 since init_board() (as
// every channel's, and the burst writes 0 to the ones it crosses), and the
// two bytes saved per transfer keep 18 channels within 1.8 ms of a 400 kHz
// bus and 8 within one transfer.
bool write_channels(uint8_t board, uint8_t first, const uint8_t* words, uint8_t count) {
  if (board >= strider::kMaxPcaBoards || count == 0 || count > kMaxBurstChannels) return false;
  const uint8_t reg = uint8_t(PCA9685_LED0_OFF_L + 4 * first);
  return note(g_boards[board].write(words + 2, size_t(4) * count - 2, true, &reg, 1));
}

bool timed_out() {
  const bool t = g_timed_out;
  g_timed_out = false;
  return t;
}

}  // namespace pca9685_bus
