// A RangeSensor that replays a script of echo widths / missing echoes.
#ifndef STRIDER_TEST_CONTROL_SCRIPTED_SONAR_H
#define STRIDER_TEST_CONTROL_SCRIPTED_SONAR_H

#include <stdint.h>

#include <vector>

#include "control/hal_interfaces.h"

namespace strider_test {

struct ScriptedSonar {
  // Width [us] per ping; 0 = missing echo (no edge).
  std::vector<uint16_t> script;
  size_t next = 0;
  bool pending = false;
  uint32_t triggered_us = 0;

  void trigger(uint32_t now_us) { pending = true; triggered_us = now_us; }
  bool poll(strider::EchoSample* out) {
    if (!pending) return false;
    pending = false;
    const uint16_t w = next < script.size() ? script[next] : script.empty() ? 0 : script.back();
    ++next;
    out->kind = w == 0 ? strider::EchoKind::kNoEdge : strider::EchoKind::kEcho;
    out->width_us = w;
    out->at_us = triggered_us;
    return true;
  }
  // Width [us] whose echo_to_mm is mm.
  static uint16_t width_for_mm(uint32_t mm) { return uint16_t((mm * 2000u) / 343u); }
};

}  // namespace strider_test

#endif
