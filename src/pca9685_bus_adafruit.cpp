// The PlatformIO build's PCA9685 backend: the Adafruit PWM Servo Driver
// library resets each board and sets the prescale. The library has no
// multi-channel write, so the frame bursts (auto-increment, several channels
// per transfer, which the library's begin() enables) go over the same Wire
// bus directly.
#if defined(STRIDER_PCA9685_ADAFRUIT) && STRIDER_PCA9685_ADAFRUIT

#include "control/channel_map.h"  // before Arduino.h (its min/max macros)

#include <Adafruit_PWMServoDriver.h>
#include <Arduino.h>
#include <Wire.h>

#include "board_pins.h"
#include "pca9685_bus.h"

namespace pca9685_bus {
namespace {

// The library's own oscillator figure is never used for timing: Strider
// computes ticks from the board's calibrated oscillator (pca9685_timing.h).
constexpr float kLibraryOscHz = 25000000.0f;

Adafruit_PWMServoDriver g_boards[strider::kMaxPcaBoards] = {
    Adafruit_PWMServoDriver(strider::kPcaFirstAddress, Wire),
    Adafruit_PWMServoDriver(strider::kPcaFirstAddress + 1, Wire)};

}  // namespace

bool begin(uint8_t boards) {
  bool ok = true;
  for (uint8_t b = 0; b < boards && b < strider::kMaxPcaBoards; ++b) {
    ok = g_boards[b].begin() && ok;
    g_boards[b].setOscillatorFrequency(uint32_t(kLibraryOscHz));
    g_boards[b].setOutputMode(true);  // totem pole
    for (uint8_t ch = 0; ch < 16; ++ch) g_boards[b].setPin(ch, 0);  // full off
  }
  Wire.setClock(pins::kI2cClockHz);
  return ok;
}

void set_prescale(uint8_t boards, uint8_t prescale) {
  // setPWMFreq() rounds osc / (4096 f) - 1: the frequency below gives back
  // exactly `prescale` with the library's nominal oscillator.
  const float hz = kLibraryOscHz / (4096.0f * (float(prescale) + 1.0f));
  for (uint8_t b = 0; b < boards && b < strider::kMaxPcaBoards; ++b) g_boards[b].setPWMFreq(hz);
}

}  // namespace pca9685_bus

#endif
