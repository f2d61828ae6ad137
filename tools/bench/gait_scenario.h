// The walk the gait benchmark times (bench_gait.h), in portable code so
// that the host can replay it: the model's default gait, forward at half
// its top speed from standing, 50 Hz ticks. walk_record() condenses the
// walker's state into int32 values (Fixed: raw Q16.16; float: the value
// x 65536, rounded) that the firmware prints and test/avr compares with the
// host's (Fixed bit-exact, float within rounding).
#ifndef STRIDER_TOOLS_BENCH_GAIT_SCENARIO_H
#define STRIDER_TOOLS_BENCH_GAIT_SCENARIO_H

#include <stdint.h>

#include "gait/gait_library.h"
#include "gait/walker.h"

namespace strider_bench {

//! Ticks of one timed walk (quick mode: an eighth).
constexpr uint16_t kGaitTicks = 250;
//! Values in a walk record: every joint of six 3-DOF legs, odometry x, y.
constexpr uint8_t kWalkRecordMax = 20;

//! The model's default gait into *out (out of flash on the AVR); false if none.
inline bool scenario_gait(const strider::RobotModel& m, strider::GaitTable* out) {
  strider::GaitParams p;
  return strider::gait_params_of(m, &p) && strider::load_gait(m, p.default_gait, out);
}

//! Configures w for model m (its default gait and parameters); false if none.
template <typename S>
bool scenario_configure(strider::Walker<S>& w, const strider::RobotModel& m) {
  strider::GaitParams p;
  strider::GaitTable g;
  return strider::gait_params_of(m, &p) && scenario_gait(m, &g) && w.configure(m, g, p, p.shape);
}

//! Half the top forward speed of the configured gait [mm/s].
template <typename S>
S scenario_speed(const strider::Walker<S>& w) {
  const strider::GaitEngine<S>& e = w.engine();
  return e.config().limits.max_speed_mm_s(e.config().home, S(1), S(0), strider::scalar<S>(double(e.table().duty))) *
         strider::scalar<S>(0.5);
}

//! Back to standing with the configuration built before, then the command.
template <typename S>
void scenario_restart(strider::Walker<S>& w, const strider::RobotModel& m, S vx) {
  strider::GaitTable g;
  if (scenario_gait(m, &g)) w.configure(m, g, w.engine().config());
  w.engine().set_command(vx, S(0), S(0));
}

inline int32_t record_value(strider::Fixed v) { return v.raw(); }
inline int32_t record_value(float v) {
  const float s = v * 65536.0f;
  return s >= 0.0f ? int32_t(s + 0.5f) : -int32_t(-s + 0.5f);
}

//! The walker's joints (legs x dof) and odometry x, y into out; the count.
template <typename S>
uint8_t walk_record(const strider::Walker<S>& w, int32_t* out) {
  uint8_t n = 0;
  for (uint8_t i = 0; i < w.leg_count(); ++i)
    for (uint8_t j = 0; j < w.dof(); ++j) out[n++] = record_value(w.leg(i).q[j]);
  out[n++] = record_value(w.engine().odometry_x());
  out[n++] = record_value(w.engine().odometry_y());
  return n;
}

}  // namespace strider_bench

#endif  // STRIDER_TOOLS_BENCH_GAIT_SCENARIO_H
