//! SonarEcho: the portable core of a non-blocking HC-SR04 driver: TRIG
//! pulsed, then triggered(); the pin-change interrupt calls edge(); poll()
//! hands out one EchoSample per ping, a missing echo included. No pulseIn(),
//! which would block the servo loop for up to 38 ms.
#ifndef STRIDER_CONTROL_SONAR_ECHO_H
#define STRIDER_CONTROL_SONAR_ECHO_H

#include <stdint.h>

#include "hal_interfaces.h"

namespace strider {

constexpr uint32_t kEchoStartDeadlineUs = 10000;  //!< no rising edge this long after TRIG -> missing [us]
constexpr uint32_t kEchoMaxWidthUs = 40000;       //!< longer pulses (sensor's ~38 ms "nothing") -> far [us]

class SonarEcho {
 public:
  //! TRIG was pulsed at now_us; any ping still in flight is dropped.
  void triggered(uint32_t now_us) {
    state_ = State::kWaitRise;
    trigger_us_ = now_us;
  }

  //! ECHO changed to level (true = high) at now_us. Interrupt-safe when the
  //! caller keeps poll() and edge() from interleaving (cli/sei around poll()).
  void edge(bool level, uint32_t now_us) {
    if (level && state_ == State::kWaitRise) {
      state_ = State::kWaitFall;
      rise_us_ = now_us;
    } else if (!level && state_ == State::kWaitFall) {
      const uint32_t width = elapsed(now_us, rise_us_);
      ready(EchoKind::kEcho, width > 0xFFFFu ? uint16_t(0xFFFF) : uint16_t(width));
    }
  }

  //! True once per ping when its sample is ready (echo measured, too long,
  //! or missing); *out is written only then.
  bool poll(uint32_t now_us, EchoSample* out) {
    // Signed: an edge stamped after the caller read now_us is no time at all.
    if (state_ == State::kWaitRise && since(now_us, trigger_us_) > int32_t(kEchoStartDeadlineUs)) {
      ready(EchoKind::kNoEdge, 0);
    } else if (state_ == State::kWaitFall && since(now_us, rise_us_) > int32_t(kEchoMaxWidthUs)) {
      ready(EchoKind::kEcho, 0xFFFF);  // echo line stuck high or nothing in range: far
    }
    if (state_ != State::kReady) return false;
    *out = sample_;
    state_ = State::kIdle;
    return true;
  }

  bool busy() const { return state_ == State::kWaitRise || state_ == State::kWaitFall; }  //!< ping in flight

 private:
  enum class State : uint8_t { kIdle, kWaitRise, kWaitFall, kReady };
  static int32_t since(uint32_t now, uint32_t then) { return int32_t(now - then); }

  void ready(EchoKind kind, uint16_t width_us) {
    sample_.kind = kind;
    sample_.width_us = width_us;
    sample_.at_us = trigger_us_;
    state_ = State::kReady;
  }

  EchoSample sample_{EchoKind::kNoEdge, 0, 0};
  uint32_t trigger_us_ = 0;
  uint32_t rise_us_ = 0;
  State state_ = State::kIdle;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_SONAR_ECHO_H
