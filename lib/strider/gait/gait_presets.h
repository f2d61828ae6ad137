//! Gait presets: a model's named operating points, each a library gait walked
//! with its own live parameters (gait_tuning.h; docs/gaits.md, "Presets").
#ifndef STRIDER_GAIT_GAIT_PRESETS_H
#define STRIDER_GAIT_GAIT_PRESETS_H

#include <stdint.h>
#include <string.h>

#include "../math/flash_table.h"
#include "../robots/model_entries.h"
#include "gait_params.h"
#include "gait_tuning.h"

namespace strider {

struct GaitPreset {
  char robot[kRobotNameBytes];  //!< the model it is for
  char name[kGaitNameBytes];    //!< what `gait NAME` takes
  char gait[kGaitNameBytes];    //!< the library gait it walks
  // Applied step height first (a lower lift lets the servos step faster:
  // the cycle and duty are checked against it), then the cycle, the share
  // down and the stride; 0: the gait's own.
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
//! "Presets"; why these values: docs/simulator.md, "mammal8 at seed 003's
//! point". trot50: mammal8's fast trot, a trot with four-foot windows and
//! low steps that stays level at 50 mm/s (docs/simulator.md, "mammal8's
//! fast trot").
constexpr GaitPreset kGaitPresets[] STRIDER_PROGMEM = {
    {"mammal8", "walk10", "walk", 0, 0, 1000, 300, 0, false},
    {"mammal8", "trot10", "trot", 238, 85, 1000, 1000, 13, true},
    {"mammal8", "pace10", "pace", 323, 70, 1000, 300, 13, true},
    {"mammal8", "trot50", "trot", 90, 80, 0, 500, 0, false},
};
constexpr uint8_t kGaitPresetCount = sizeof kGaitPresets / sizeof kGaitPresets[0];

//! kGaitPresets as a table of robots/model_entries.h.
struct GaitPresetTable {
  using Entry = GaitPreset;
  static constexpr const GaitPreset (&all())[kGaitPresetCount] { return kGaitPresets; }
};
//! The presets a build keeps (robots/model_entries.h): a firmware's own
//! model's only, in flash.
template <uint8_t kModel>
using GaitPresetsOf = ModelTable<GaitPresetTable, kModel>;

//! The i-th preset the build keeps into *out (copied out of flash on the
//! AVR); false past the last.
template <uint8_t kModel = kEveryModel>
bool gait_preset_at(uint8_t i, GaitPreset* out) {
  if (i >= GaitPresetsOf<kModel>::kCount) return false;
  flash_copy(out, &GaitPresetsOf<kModel>::kTable.at[i], sizeof *out);
  return true;
}

//! The preset `name` of the model called `robot` into *out (copied out of
//! flash on the AVR); false when it has none of that name.
template <uint8_t kModel = kEveryModel>
bool find_gait_preset(const char* robot, const char* name, GaitPreset* out) {
  for (uint8_t i = 0; gait_preset_at<kModel>(i, out); ++i)
    if (strcmp(out->name, name) == 0 && strcmp(out->robot, robot) == 0) return true;
  return false;
}

//! The preset's parameters through `tune(TuneParam, value)` (a sink's or a
//! tuner's); false when one is refused (the rest are not tried).
template <typename Tune>
bool apply_gait_preset(const GaitPreset& p, Tune tune) {
  return (p.step_height_cmm == 0 || tune(TuneParam::kStepHeight, p.step_height_cmm)) &&
         (p.cycle_cs == 0 || tune(TuneParam::kCycle, p.cycle_cs)) &&
         (p.duty_pct == 0 || tune(TuneParam::kDuty, p.duty_pct)) &&
         (p.step_length_cmm == 0 || tune(TuneParam::kStepLength, p.step_length_cmm));
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_PRESETS_H
