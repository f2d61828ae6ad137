//! Gait presets: a model's named operating points, each a library gait walked
//! with its own live parameters (gait_tuning.h; docs/gaits.md, "Presets").
#ifndef STRIDER_GAIT_GAIT_PRESETS_H
#define STRIDER_GAIT_GAIT_PRESETS_H

#include <stdint.h>
#include <string.h>

#include "../math/flash_table.h"
#include "gait_params.h"
#include "gait_tuning.h"

namespace strider {

struct GaitPreset {
  char robot[kRobotNameBytes];  //!< the model it is for
  char name[kGaitNameBytes];    //!< what `gait NAME` takes
  char gait[kGaitNameBytes];    //!< the library gait it walks
  // Applied in this order (the cycle before the share down); 0: the gait's own.
  uint16_t cycle_cs;
  uint8_t duty_pct;
  uint16_t step_length_cmm;
  uint16_t step_height_cmm;
  //! Stance feet moved in steps of this length [0.1 mm], 0: every tick;
  //! and only while all feet are down (stance_ratchet.h).
  uint8_t stance_step_dmm;
  bool on_all_feet;
};

//! mammal8 at seed 003's own operating point (table 5): docs/gaits.md,
//! "Presets"; why these values: docs/simulator.md, "mammal8 at seed 003's point".
constexpr GaitPreset kGaitPresets[] STRIDER_PROGMEM = {
    {"mammal8", "walk10", "walk", 0, 0, 1000, 300, 0, false},
    {"mammal8", "trot10", "trot", 238, 85, 1000, 1000, 13, true},
    {"mammal8", "pace10", "pace", 323, 70, 1000, 300, 13, true},
};
constexpr uint8_t kGaitPresetCount = sizeof kGaitPresets / sizeof kGaitPresets[0];

//! The preset `name` of the model called `robot` into *out (copied out of
//! flash on the AVR); false when it has none of that name.
inline bool find_gait_preset(const char* robot, const char* name, GaitPreset* out) {
  for (uint8_t i = 0; i < kGaitPresetCount; ++i) {
    flash_copy(out, &kGaitPresets[i], sizeof *out);
    if (strcmp(out->name, name) == 0 && strcmp(out->robot, robot) == 0) return true;
  }
  return false;
}

//! The preset's parameters through `tune(TuneParam, value)` (a sink's or a
//! tuner's); false when one is refused (the rest are not tried).
template <typename Tune>
bool apply_gait_preset(const GaitPreset& p, Tune tune) {
  return (p.cycle_cs == 0 || tune(TuneParam::kCycle, p.cycle_cs)) &&
         (p.duty_pct == 0 || tune(TuneParam::kDuty, p.duty_pct)) &&
         (p.step_length_cmm == 0 || tune(TuneParam::kStepLength, p.step_length_cmm)) &&
         (p.step_height_cmm == 0 || tune(TuneParam::kStepHeight, p.step_height_cmm));
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_PRESETS_H
