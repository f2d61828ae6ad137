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

Adafruit_I2CDevice g_boards[strider::kMaxPcaBoards] = {
    Adafruit_I2CDevice(PCA9685_I2C_ADDRESS, &Wire),
    Adafruit_I2CDevice(PCA9685_I2C_ADDRESS + 1, &Wire)};

// MODE1 while the firmware runs: register auto-increment, answers the
// all-call address (the power-on default), oscillator on.
constexpr uint8_t kMode1Awake = MODE1_AI | MODE1_ALLCAL;

bool write_register(uint8_t board, uint8_t reg, uint8_t value) {
  return g_boards[board].write(&value, 1, true, &reg, 1);
}

}  // namespace

bool begin(uint8_t boards) {
  if (boards > strider::kMaxPcaBoards) boards = strider::kMaxPcaBoards;
  bool ok = true;
  for (uint8_t b = 0; b < boards; ++b) {
    ok = g_boards[b].begin() && ok;  // Wire.begin(), then is the board there?
    // Asleep first: a board that kept running through an MCU reset stops its
    // pulses here rather than emitting the old frame at another frequency.
    ok = write_register(b, PCA9685_MODE1, kMode1Awake | MODE1_SLEEP) && ok;
    ok = write_register(b, PCA9685_MODE2, MODE2_OUTDRV) && ok;  // totem-pole outputs for servo lines
    static const uint8_t kAllFullOff[4] = {0x00, 0x00, 0x00, 0x10};  // ALL_LED_OFF_H bit 4
    const uint8_t reg = PCA9685_ALLLED_ON_L;
    ok = g_boards[b].write(kAllFullOff, sizeof kAllFullOff, true, &reg, 1) && ok;
  }
  g_boards[0].setSpeed(pins::kI2cClockHz);  // one bus: Wire.setClock()
  return ok;
}

void set_prescale(uint8_t boards, uint8_t prescale) {
  if (boards > strider::kMaxPcaBoards) boards = strider::kMaxPcaBoards;
  // MODE1 is known (begin() wrote it): writes only, nothing read back.
  for (uint8_t b = 0; b < boards; ++b) {
    write_register(b, PCA9685_MODE1, kMode1Awake | MODE1_SLEEP);  // PRE_SCALE is writable only asleep
    write_register(b, PCA9685_PRESCALE, prescale);
    write_register(b, PCA9685_MODE1, kMode1Awake);
    delayMicroseconds(500);  // oscillator start-up (datasheet 7.3.1.1: 500 us)
    write_register(b, PCA9685_MODE1, kMode1Awake | MODE1_RESTART);
  }
}

// From the first channel's OFF_L on: its ON word is 0 since begin() (as
// every channel's, and the burst writes 0 to the ones it crosses), and the
// two bytes saved per transfer keep 18 channels within 1.8 ms of a 400 kHz
// bus and 8 within one transfer.
bool write_channels(uint8_t board, uint8_t first, const uint8_t* words, uint8_t count) {
  if (board >= strider::kMaxPcaBoards || count == 0 || count > kMaxBurstChannels) return false;
  const uint8_t reg = uint8_t(PCA9685_LED0_OFF_L + 4 * first);
  return g_boards[board].write(words + 2, size_t(4) * count - 2, true, &reg, 1);
}

}  // namespace pca9685_bus
