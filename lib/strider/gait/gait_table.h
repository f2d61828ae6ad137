//! GaitTable: a gait as data. Each leg lifts off once per cycle at its phase
//! offset and stays in the air for (1 - duty) of the cycle: with the cycle
//! phase in [0, 1), leg i swings while psi_i = frac(phase - offset_i) < 1 - duty.
//! Legs are numbered as the models number them (docs/robots.md).
#ifndef STRIDER_GAIT_GAIT_TABLE_H
#define STRIDER_GAIT_GAIT_TABLE_H

#include <stdint.h>

#include "../robots/robot_model.h"

namespace strider {

//! Longest gait name, its terminating zero included.
constexpr uint8_t kGaitNameBytes = 7;

struct GaitTable {
  //! CLI name, e.g. "walk". An array, not a pointer: a table kept in flash
  //! (gait_library.h) keeps its name there too.
  char name[kGaitNameBytes];
  uint8_t leg_count;         //!< 4 or 6
  float duty;                //!< fraction of the cycle each foot is on the ground, (0, 1)
  float offset[kMaxLegs];    //!< lift-off phase of each leg, [0, 1); unused slots 0
  //! Statically stable gait: the engine shifts the body so that the CoM stays
  //! inside the support polygon (needs swings_separated()).
  bool shift_body;
  //! The leg sequence is meant relative to the direction of travel (seed 000
  //! section 3.3): for sideways or backward walking the engine relabels legs.
  bool relabel_by_direction;
};

namespace gait_table {

//! True when leg `leg` is in the air at cycle phase `phase` in [0, 1): its
//! own phase frac(phase - offset) below 1 - duty.
constexpr bool in_swing(const GaitTable& t, uint8_t leg, float phase) {
  return (phase - t.offset[leg] < 0.0f ? phase - t.offset[leg] + 1.0f : phase - t.offset[leg]) < 1.0f - t.duty;
}

//! Offsets in [0, 1), duty in (0, 1), a known leg count, unused slots zero.
constexpr bool valid(const GaitTable& t) {
  if (!(t.leg_count == 4 || t.leg_count == 6)) return false;
  if (!(t.duty > 0.0f && t.duty < 1.0f)) return false;
  for (uint8_t i = 0; i < kMaxLegs; ++i) {
    if (i < t.leg_count && !(t.offset[i] >= 0.0f && t.offset[i] < 1.0f)) return false;
    if (i >= t.leg_count && t.offset[i] != 0.0f) return false;
  }
  return true;
}

//! Samples the cycle at `samples` points: at every sample at least
//! `min_support` feet are on the ground.
constexpr bool keeps_support(const GaitTable& t, uint8_t min_support, uint16_t samples = 960) {
  for (uint16_t k = 0; k < samples; ++k) {
    const float phase = (float(k) + 0.5f) / float(samples);
    uint8_t down = 0;
    for (uint8_t i = 0; i < t.leg_count; ++i)
      if (!in_swing(t, i, phase)) ++down;
    if (down < min_support) return false;
  }
  return true;
}

//! True when legs with different offsets are never in the air together and
//! every two consecutive swings are separated by a moment with every foot
//! down: what shift_body needs.
constexpr bool swings_separated(const GaitTable& t, uint16_t samples = 960) {
  bool seen_all_down = false;
  for (uint16_t k = 0; k < samples; ++k) {
    const float phase = (float(k) + 0.5f) / float(samples);
    bool any = false;
    float first = -1.0f;
    for (uint8_t i = 0; i < t.leg_count; ++i) {
      if (!in_swing(t, i, phase)) continue;
      if (any && t.offset[i] != first) return false;
      any = true;
      first = t.offset[i];
    }
    if (!any) seen_all_down = true;
  }
  return seen_all_down;
}

//! The table with the leg roles turned by `quarter_turns` x 90 deg
//! counter-clockwise, for walking that far left of forward (4 legs only):
//! leg i takes the offset of leg (i - quarter_turns) mod 4 (seed 000
//! section 3.3's direction change, docs/gaits.md).
constexpr GaitTable relabeled(const GaitTable& t, int8_t quarter_turns) {
  if (t.leg_count != 4) return t;
  GaitTable r = t;
  const uint8_t k = uint8_t(((quarter_turns % 4) + 4) % 4);
  for (uint8_t i = 0; i < 4; ++i) r.offset[i] = t.offset[(i + 4 - k) % 4];
  return r;
}

}  // namespace gait_table
}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_TABLE_H
