#include "hcsr04_sonar.h"

#include "control/sonar_echo.h"  // before Arduino.h (its min/max macros)

#include <Arduino.h>
#include <util/atomic.h>

#include "board_pins.h"

namespace hcsr04 {
namespace {

strider::SonarEcho g_echo;

void on_echo_edge() { g_echo.edge(digitalRead(pins::kSonarEcho) == HIGH, micros()); }

}  // namespace

void begin() {
  pinMode(pins::kSonarTrig, OUTPUT);
  digitalWrite(pins::kSonarTrig, LOW);
  pinMode(pins::kSonarEcho, INPUT);
  attachInterrupt(digitalPinToInterrupt(pins::kSonarEcho), on_echo_edge, CHANGE);
}

bool busy() {
  bool b;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { b = g_echo.busy(); }
  return b;
}

void trigger(uint32_t now_us) {
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { g_echo.triggered(now_us); }
  digitalWrite(pins::kSonarTrig, HIGH);
  delayMicroseconds(10);  // datasheet: >= 10 us
  digitalWrite(pins::kSonarTrig, LOW);
}

bool poll(uint32_t now_us, strider::EchoSample* out) {
  bool ready;
  ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { ready = g_echo.poll(now_us, out); }
  return ready;
}

}  // namespace hcsr04
