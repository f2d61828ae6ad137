//! GaitChoice: the RC pad's speed-dependent gait, per model. Animals walk
//! slowly and trot fast, and switch at different speeds going up and coming
//! down (hysteresis), so that a speed near the switch does not flip between
//! gaits. A model listed here has a slow gait whose top body speed is below
//! the pad's 100 % (control/robot_mode.h's RcLimits) and a fast gait that
//! makes it; pressing a pad button at a forward (or backward) speed or a
//! turn rate over `up` switches slow -> fast, one under `down` on both
//! switches back. Sideways speed does not count: sprawl8 trotting sideways
//! at 155 mm/s drifts 13 % forward and turns 6 deg (sprawl8_strafe), its
//! crawl strafes straight (at its top speed, ~37 mm/s), so the pad's
//! sideways buttons walk the slow gait. A model not listed,
//! or a gait that is neither of its pair (one the user chose with `gait`),
//! keeps its gait.
//!
//! Thresholds are body speeds (after speed_correction.h), measured in the
//! simulator, firmware mode (steady speeds): sprawl8's crawl makes ~33 mm/s
//! and ~29 deg/s at its limits, and its feet slip more the faster it goes
//! (0.49 of its gait speed at 15 mm/s, 0.40 at 27 mm/s), so its one speed
//! correction holds to ~25 mm/s: the pad changes up above 25 mm/s or
//! 25 deg/s (the slider's 20 % and 50 %) and back below 18 mm/s and
//! 18 deg/s (10 %, 30 %).
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

//! In flash on the AVR: read through gait_choice_for().
constexpr GaitChoice kGaitChoices[kGaitChoiceCount] STRIDER_PROGMEM = {
    {"sprawl8", "crawl", "trot", 250, 180, 250, 180},
};

namespace detail {
inline int32_t abs32(int32_t v) { return v < 0 ? -v : v; }
}  // namespace detail

//! The gait the pad walks body speed (vx, vy [0.1 mm/s], wz [0.1 deg/s]) in
//! for `robot` now walking `gait`: true and its name in `to`
//! (kGaitNameBytes) when that is another gait; false: keep the gait. A
//! standstill (all zero) keeps the gait.
inline bool gait_choice_for(const char* robot, const char* gait, int32_t vx, int32_t vy, int32_t wz, char* to) {
  const int32_t linear = detail::abs32(vx);
  const int32_t turn = detail::abs32(wz);
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
