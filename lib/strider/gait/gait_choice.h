//! GaitChoice: the RC pad's speed-dependent gait, per model, with hysteresis
//! (docs/protocol.md, "The pad picks sprawl8's gait by speed"). Thresholds are
//! body speeds (after speed_correction.h): sprawl8's crawl correction holds to ~25 mm/s.
#ifndef STRIDER_GAIT_GAIT_CHOICE_H
#define STRIDER_GAIT_GAIT_CHOICE_H

#include <stdint.h>
#include <string.h>

#include "../math/flash_table.h"
#include "gait_table.h"

namespace strider {

struct GaitChoice {
  char robot[10];                //!< model name (as kGaitParams)
  char slow[kGaitNameBytes];     //!< the gait at low speed (the model's default)
  char fast[kGaitNameBytes];     //!< the gait above `up`
  uint16_t up_linear;            //!< slow -> fast above this forward speed [0.1 mm/s]
  uint16_t down_linear;          //!< fast -> slow below this one (and down_turn) [0.1 mm/s]
  uint16_t up_turn;              //!< slow -> fast above this turn rate [0.1 deg/s]
  uint16_t down_turn;            //!< fast -> slow below this one (and down_linear) [0.1 deg/s]
};

constexpr uint8_t kGaitChoiceCount = 1;

constexpr GaitChoice kGaitChoices[kGaitChoiceCount] STRIDER_PROGMEM = {
    {"sprawl8", "crawl", "trot", 250, 180, 250, 180},
};

//! The gait the pad walks body speed (vx, vy [0.1 mm/s], wz [0.1 deg/s]) in
//! for `robot` now walking `gait`: true and its name in `to` (kGaitNameBytes)
//! when that is another gait; false (a standstill too): keep the gait.
inline bool gait_choice_for(const char* robot, const char* gait, int32_t vx, int32_t vy, int32_t wz, char* to) {
  const int32_t linear = vx < 0 ? -vx : vx;
  const int32_t turn = wz < 0 ? -wz : wz;
  if (linear == 0 && turn == 0 && vy == 0) return false;
  for (uint8_t i = 0; i < kGaitChoiceCount; ++i) {
    GaitChoice c;
    flash_copy(&c, &kGaitChoices[i], sizeof c);
    if (strcmp(c.robot, robot) != 0) continue;
    if (strcmp(gait, c.slow) == 0 && (linear > c.up_linear || turn > c.up_turn)) {
      memcpy(to, c.fast, kGaitNameBytes);
      return true;
    }
    if (strcmp(gait, c.fast) == 0 && linear < c.down_linear && turn < c.down_turn) {
      memcpy(to, c.slow, kGaitNameBytes);
      return true;
    }
    return false;
  }
  return false;
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_CHOICE_H
