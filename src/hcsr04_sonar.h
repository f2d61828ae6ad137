// The HC-SR04 driver: TRIG pulsed from the loop, ECHO timed by the INT4
// interrupt on both edges, so the loop never waits for an echo (pulseIn()
// would block it for up to 38 ms). The portable state machine that turns
// edges into samples, a missing echo included, is strider::SonarEcho.
#ifndef STRIDER_HCSR04_SONAR_H
#define STRIDER_HCSR04_SONAR_H

#include <stdint.h>

#include "control/hal_interfaces.h"

namespace hcsr04 {

void begin();
//! Starts one ping (a 10 us TRIG pulse) unless one is in flight.
void trigger(uint32_t now_us);
//! True once per ping with its sample (echo, too long, or missing).
bool poll(uint32_t now_us, strider::EchoSample* out);
bool busy();

}  // namespace hcsr04

#endif
