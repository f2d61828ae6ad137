#include "hcsr04_sonar.h"

#include "control/sonar_echo.h"  // before Arduino.h (its min/max macros)

#include <Arduino.h>
#include <avr/interrupt.h>
#include <util/atomic.h>
#include <util/delay.h>

#include "board_pins.h"

namespace hcsr04 {
namespace {

strider::SonarEcho g_echo;

static_assert(pins::kSonarEcho == 2, "ECHO on D2 = PE4 = INT4 (the ISR below)");

}  // namespace

// ECHO edges: INT4 set up by hand rather than with attachInterrupt(), whose
// core file brings all eight external-interrupt handlers and their table
// (about 0.9 KB of flash and 16 bytes of RAM) for the one used here.
ISR(INT4_vect) { g_echo.edge((PINE & _BV(PE4)) != 0, micros()); }

// TRIG and ECHO through their port's registers: pinMode() and digitalRead()
// with their pin tables are not linked for two fixed pins.
static_assert(pins::kSonarTrig == 3, "TRIG on D3 = PE5 (the port bits below)");

void begin() {
  PORTE &= uint8_t(~_BV(PE5));  // TRIG low, an output
  DDRE |= _BV(PE5);
  DDRE &= uint8_t(~_BV(PE4));   // ECHO an input without pull-up
  PORTE &= uint8_t(~_BV(PE4));
  // What attachInterrupt(digitalPinToInterrupt(2), ..., CHANGE) does on the
  // Mega: INT4 on any logical change (ISC41:40 = 01), then enabled.
  EICRB = uint8_t((EICRB & ~(_BV(ISC40) | _BV(ISC41))) | _BV(ISC40));
  EIMSK |= _BV(INT4);
}

bool busy() {
  bool b;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { b = g_echo.busy(); }
  return b;
}

void trigger(uint32_t now_us) {
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { g_echo.triggered(now_us); }
  PORTE |= _BV(PE5);
  // The HC-SR04 needs >= 10 us. _delay_us() is a cycle-exact busy loop at
  // any optimisation; delayMicroseconds(10), inlined under PlatformIO's
  // -flto, gave 8.9 us and the sensor never answered. 12 us keeps a margin.
  _delay_us(12);
  PORTE &= uint8_t(~_BV(PE5));
}

bool poll(uint32_t now_us, strider::EchoSample* out) {
  bool ready;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { ready = g_echo.poll(now_us, out); }
  return ready;
}

}  // namespace hcsr04
