//! A model's figures that a firmware keeps as compile-time constants:
//! avoidance's clearing distance and the default gait's name.
#ifndef STRIDER_CONTROL_MODEL_CONSTANTS_H
#define STRIDER_CONTROL_MODEL_CONSTANTS_H

#include <stdint.h>

#include "../gait/gait_params.h"
#include "../gait/gait_table.h"
#include "../robots/robot_model.h"

namespace strider {

//! Avoidance's clearing distance: the widest standing foot's distance from
//! the body's centre line plus kAvoidClearMarginMm [mm].
constexpr float kAvoidClearMarginMm = 40.0f;
constexpr uint16_t avoid_clear_mm(const RobotModel& m) {
  float w = 0.0f;
  for (uint8_t i = 0; i < m.leg_count && i < kMaxLegs; ++i) {
    const float y = m.legs[i].stand_mm.y;
    if (y > w) w = y;
    if (-y > w) w = -y;
  }
  w += kAvoidClearMarginMm;
  return w < 60000.0f ? uint16_t(w + 0.5f) : uint16_t(60000);
}

//! A gait's name as a value (kGaitNameBytes with its zero): RobotApp's
//! kStoredGait, a firmware's constant in flash.
struct GaitName {
  char text[kGaitNameBytes];
};
//! The default gait of built-in model r (kGaitParams order).
constexpr GaitName default_gait_name(uint8_t r) {
  GaitName n{};
  for (uint8_t i = 0; i < kGaitNameBytes; ++i) n.text[i] = kGaitParams[r].default_gait[i];
  return n;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_MODEL_CONSTANTS_H
