//! GaitTuning: the gait parameters a user changes live over the link
//! (`set step_height|step_length|cycle|duty|swing V`, docs/protocol.md), in
//! the protocol's integer units (no soft float in the firmware), and the
//! rules that bound them (a step and swing path no higher than the model's
//! own: the stored strides were searched with them).
#ifndef STRIDER_GAIT_GAIT_TUNING_H
#define STRIDER_GAIT_GAIT_TUNING_H

#include <stdint.h>

#include "../math/flash_table.h"
#include "gait_table.h"
#include "phase.h"
#include "swing_trajectory.h"

namespace strider {

//! The parameters `set` takes, in the order of kTuneParamNames.
enum class TuneParam : uint8_t { kStepHeight = 0, kStepLength = 1, kCycle = 2, kDuty = 3, kSwing = 4 };
constexpr uint8_t kTuneParamCount = 5;
constexpr char kTuneParamNames[] STRIDER_PROGMEM = "step_height\0step_length\0cycle\0duty\0swing";

//! One gait's live parameters. Two decimals, as the protocol takes them.
struct GaitTuning {
  uint16_t step_height_cmm;  //!< swing apex [0.01 mm]
  uint16_t step_length_cmm;  //!< preferred stride [0.01 mm]
  uint16_t cycle_cs;         //!< cycle at low speed [0.01 s]
  uint8_t duty_pct;          //!< share of the cycle a foot is down [0.01]
  uint8_t shape;             //!< SwingShape
  int16_t height_dmm;        //!< body height [0.1 mm]; 0: the model's standing height
};

//! The range of one parameter [its unit / 100]; for kSwing, lo is a mask of
//! the shapes allowed (bit = SwingShape) and hi is unused.
struct TuneRange {
  int32_t lo;
  int32_t hi;
};

constexpr int32_t kMinStepHeightCmm = 100;   //!< 1 mm: a foot that lifts at all
constexpr int32_t kMinStepLengthCmm = 500;   //!< 5 mm
constexpr int32_t kMinCycleCs = 20;          //!< 0.2 s
constexpr int32_t kMaxCycleCs = 500;         //!< 5 s
constexpr int32_t kMaxDutyPct = 95;          //!< a swing of at least a twentieth of the cycle

//! Phases this close [2^-16 of a cycle] are the same moment: the tables'
//! fractions (sixths, thirds) rounded to 2^-16 differ by a unit or two.
constexpr uint32_t kPhaseSlack = 2;

//! A gait table's lift-off phases [2^-16 of a cycle], converted from its
//! floats once (integer operations on their bits).
struct LiftPhases {
  uint16_t at[kMaxLegs];
  uint8_t count;
  explicit LiftPhases(const GaitTable& t) : at(), count(t.leg_count) {
    for (uint8_t i = 0; i < count; ++i) at[i] = uint16_t(table_fraction::q16(t.offset[i]) & 0xFFFFu);
  }
};

//! The fewest feet on the ground over a cycle of a gait lifting at `p`
//! with a swing of `swing` [2^-16 of a cycle], counted just after each
//! lift-off (a foot that lands as another lifts counts as down).
inline uint8_t fewest_feet_down(const LiftPhases& p, uint32_t swing) {
  uint8_t fewest = p.count;
  for (uint8_t j = 0; j < p.count; ++j) {
    uint8_t up = 0;
    for (uint8_t i = 0; i < p.count; ++i)
      if (i == j || uint32_t(uint16_t(p.at[j] - p.at[i])) + kPhaseSlack < swing) ++up;
    if (uint8_t(p.count - up) < fewest) fewest = uint8_t(p.count - up);
  }
  return fewest;
}
inline uint8_t fewest_feet_down(const GaitTable& t, uint32_t swing) { return fewest_feet_down(LiftPhases(t), swing); }

//! gait_table::swings_separated() (what a body-shifting gait needs) for
//! lift-off phases p and a swing of `swing`.
inline bool swings_apart(const LiftPhases& p, uint32_t swing) {
  for (uint8_t j = 0; j < p.count; ++j)
    for (uint8_t i = 0; i < p.count; ++i) {
      const uint32_t d = uint16_t(p.at[j] - p.at[i]);
      if (d > kPhaseSlack && d < 65536u - kPhaseSlack && (d <= swing + kPhaseSlack || d + swing + kPhaseSlack >= 65536u))
        return false;
    }
  return true;
}

namespace gait_tuning_detail {
inline bool duty_allowed(const GaitTable& t, const LiftPhases& p, uint8_t own_down, uint8_t duty_pct) {
  if (duty_pct == 0 || duty_pct > kMaxDutyPct) return false;
  const uint32_t swing = (uint32_t(100 - duty_pct) * 65536u + 50u) / 100u;  // round((1 - duty) 2^16)
  if (fewest_feet_down(p, swing) < own_down) return false;
  return !t.shift_body || swings_apart(p, swing);
}
}  // namespace gait_tuning_detail

//! Whether gait t may be walked with duty_pct: as many feet down as at its
//! own duty, and its swings apart if it shifts the body.
inline bool duty_allowed(const GaitTable& t, uint8_t duty_pct) {
  const LiftPhases p(t);
  return gait_tuning_detail::duty_allowed(t, p, fewest_feet_down(p, table_fraction::swing_span(t.duty)), duty_pct);
}

//! The duties gait t may be walked with [0.01], the least allowed one to
//! kMaxDutyPct (one interval: more feet down only adds support).
inline TuneRange duty_range(const GaitTable& t) {
  const LiftPhases p(t);
  const uint8_t own = fewest_feet_down(p, table_fraction::swing_span(t.duty));
  int32_t lo = kMaxDutyPct;
  for (uint8_t d = kMaxDutyPct; d > 0 && gait_tuning_detail::duty_allowed(t, p, own, d); --d) lo = d;
  return TuneRange{lo, kMaxDutyPct};
}

//! t's duty in hundredths, rounded up (a sixth is 0.84: as many feet down as
//! the table's own) but for the table's float rounding.
inline uint8_t duty_pct_of(const GaitTable& t) {
  return uint8_t((table_fraction::q16(t.duty) * 100u + 65536u - 100u) >> 16);
}

//! The swing shapes whose path never rises above shape `own`'s at the same
//! progress and step height (bit = SwingShape; a semicircle at its highest
//! under the others, at its lowest as their bound; test/gait checks it).
constexpr uint8_t kSwingsWithin[kSwingShapeCount] STRIDER_PROGMEM = {0x1F, 0x02, 0x1E, 0x18, 0x10, 0x20};
inline uint8_t swings_within(SwingShape own) { return flash_u8(&kSwingsWithin[uint8_t(own)]); }

//! The ranges of the parameters for one model and gait.
struct TuneBounds {
  TuneRange step_height;
  TuneRange step_length;
  TuneRange cycle;
  TuneRange duty;
  uint8_t shapes;  //!< swings_within() of the model's own shape
};

//! The range of parameter p under bounds b (for kSwing: lo = the shapes' mask).
inline TuneRange range_of(const TuneBounds& b, TuneParam p) {
  switch (p) {
    case TuneParam::kStepHeight: return b.step_height;
    case TuneParam::kStepLength: return b.step_length;
    case TuneParam::kCycle: return b.cycle;
    case TuneParam::kDuty: return b.duty;
    case TuneParam::kSwing: break;
  }
  return TuneRange{b.shapes, 0};
}

//! Whether v (the parameter's unit / 100; kSwing: a SwingShape) is in
//! parameter p's range r.
inline bool in_tune_range(const TuneRange& r, TuneParam p, int32_t v) {
  if (p == TuneParam::kSwing) return v >= 0 && v < kSwingShapeCount && (r.lo >> v) & 1;
  return v >= r.lo && v <= r.hi;
}
//! Whether v is allowed for parameter p under bounds b.
inline bool tune_value_allowed(const TuneBounds& b, TuneParam p, int32_t v) { return in_tune_range(range_of(b, p), p, v); }

//! Every parameter of `t` allowed (a record read back from EEPROM).
inline bool tuning_allowed(const TuneBounds& b, const GaitTuning& t) {
  return tune_value_allowed(b, TuneParam::kStepHeight, t.step_height_cmm) &&
         tune_value_allowed(b, TuneParam::kStepLength, t.step_length_cmm) &&
         tune_value_allowed(b, TuneParam::kCycle, t.cycle_cs) && tune_value_allowed(b, TuneParam::kDuty, t.duty_pct) &&
         tune_value_allowed(b, TuneParam::kSwing, t.shape);
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_TUNING_H
