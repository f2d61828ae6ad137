//! Stored velocity limits: a built-in model's at its gait defaults, read from
//! the table generated on the host (velocity_limit_table.h) instead of the
//! IK search (velocity_search.h: 1.4-4 s and 2.5 KB of stack on the AVR).
#ifndef STRIDER_GAIT_STORED_VELOCITY_LIMITS_H
#define STRIDER_GAIT_STORED_VELOCITY_LIMITS_H

#include <string.h>

#include "gait_params.h"
#include "velocity_limit_encoding.h"
#include "velocity_limit_table.h"
#include "velocity_limits.h"

namespace strider {

//! The index of `model` in kAllRobots (same name and geometry fingerprint)
//! when `params` with `shape` are its defaults; kRobotCount otherwise. Not by
//! address: that would put every built-in model in the AVR's RAM.
inline uint8_t stored_limits_index(const RobotModel& model, const GaitParams& params, SwingShape shape) {
  namespace enc = velocity_limit_encoding;
  using T = detail::VelocityLimitTables<>;
  const uint8_t r = gait_params_index(model);
  if (r >= kRobotCount) return kRobotCount;
  GaitParams d;
  flash_copy(&d, &kGaitParams[r], sizeof d);
  uint16_t print[enc::kFingerprintWords];
  enc::geometry_fingerprint(model, print);
  for (uint8_t k = 0; k < enc::kFingerprintWords; ++k)
    if (flash_u16(T::kGeometry[r], k) != print[k]) return kRobotCount;
  // Positive defaults: equal values are equal bits (no float calls on AVR).
  const auto same_value = [](float a, float b) { return detail::float_bits(a) == detail::float_bits(b); };
  const bool same = shape == d.shape && same_value(params.step_height_mm, d.step_height_mm) &&
                    same_value(params.step_length_mm, d.step_length_mm) && same_value(params.cycle_s, d.cycle_s);
  return same ? r : kRobotCount;
}

namespace stored_limits_detail {
//! Robot r's strides: copied into RAM, or pointed at in flash.
inline void set_strides(StrideTable<true>& t, uint8_t r) {
  using T = detail::VelocityLimitTables<>;
  const uint8_t first = flash_u8(&T::kStrideRow[r]), legs = uint8_t(flash_u8(&T::kStrideRow[r + 1]) - first);
  for (uint8_t i = 0; i < kMaxLegs; ++i)
    for (uint8_t k = 0; k < kStrideDirections; ++k)
      t.stride_code[i][k] = i < legs ? flash_u16(&T::kStride[first + i][0], k) : uint16_t(0);
}
inline void set_strides(StrideTable<false>& t, uint8_t r) {
  // The model's legs only: a walker asks for no leg past its count.
  using T = detail::VelocityLimitTables<>;
  t.flash_codes = &T::kStride[flash_u8(&T::kStrideRow[r])][0];
}
}  // namespace stored_limits_detail

//! Fills `out` from the table, as compute_velocity_limits() would; false,
//! `out` untouched, when the table has no entry.
template <typename S, bool kSearch>
bool stored_velocity_limits(const RobotModel& model, const GaitParams& params, SwingShape shape,
                            VelocityLimits<S, kSearch>& out) {
  namespace enc = velocity_limit_encoding;
  const uint8_t r = stored_limits_index(model, params, shape);
  if (r >= kRobotCount) return false;
  using T = detail::VelocityLimitTables<>;
  out.set_gait(model, scalar<S>(params.step_length_mm), scalar<S>(params.cycle_s));
  stored_limits_detail::set_strides(out, r);
  S* const servo[3] = {&out.lift_ms, &out.swing_ms_per_mm, &out.stance_ms_per_mm};
  for (uint8_t j = 0; j < 3; ++j) {
    const uint32_t lo = flash_u16(T::kServo[r], uint16_t(2 * j)), hi = flash_u16(T::kServo[r], uint16_t(2 * j + 1));
    *servo[j] = enc::q16_of(lo | (hi << 16), S());
  }
  return true;
}

}  // namespace strider

#endif  // STRIDER_GAIT_STORED_VELOCITY_LIMITS_H
