//! TablePhases: the gait table as walked, in the engine's units: each leg's
//! lift-off phase, the swing's length, the duty and its inverses, the phase
//! a walk starts at, and the relabelling for the direction of travel.
#ifndef STRIDER_GAIT_TABLE_PHASES_H
#define STRIDER_GAIT_TABLE_PHASES_H

#include "gait_table.h"
#include "phase.h"

namespace strider {

template <typename S, uint8_t kLegs>
struct TablePhases {
  GaitTable base;  // as given; as walked: table()
  bool relabel;
  int8_t quarter;
  Phase16 offset[kLegs];
  uint32_t swing_len;
  S duty = scalar<S>(0.5), inv_swing = S(2), inv_stance = S(2);
  Phase16 start_phase;

  GaitTable table() const { return relabel ? gait_table::relabeled(base, quarter) : base; }

  void load(const GaitTable& t, uint8_t leg_count) {
    set_fractions(t, S());
    uint32_t latest_end = 0;
    for (uint8_t i = 0; i < leg_count; ++i) {
      offset[i] = table_phase(t.offset[i], S());
      const uint32_t end = uint32_t(offset[i]) + swing_len;
      if (end <= kPhaseOne && end > latest_end) latest_end = end;
    }
    // Start just before the first lift-off, or at the four-foot window
    // before it when the body must shift first.
    start_phase = t.shift_body && latest_end > 0 && latest_end < kPhaseOne ? Phase16(latest_end) : Phase16(0xFFFF);
  }

  //! The table's duty in the engine's units: float through double (the
  //! host), Fixed from the float's bits (integers only: the same values).
  void set_fractions(const GaitTable& t, float) {
    swing_len = phase_span(1.0 - double(t.duty));
    duty = scalar<S>(double(t.duty));
    inv_swing = scalar<S>(1.0 / (1.0 - double(t.duty)));
    inv_stance = scalar<S>(1.0 / double(t.duty));
  }
  void set_fractions(const GaitTable& t, Fixed) {
    swing_len = table_fraction::swing_span(t.duty);
    duty = Fixed::from_raw(int32_t(table_fraction::q16(t.duty)));
    inv_swing = table_fraction::inverse_of_rest(t.duty);
    inv_stance = table_fraction::inverse(t.duty);
  }
  static Phase16 table_phase(float offset, float) { return phase16(double(offset)); }
  static Phase16 table_phase(float offset, Fixed) { return Phase16(table_fraction::q16(offset) & 0xFFFFu); }
};

}  // namespace strider

#endif  // STRIDER_GAIT_TABLE_PHASES_H
