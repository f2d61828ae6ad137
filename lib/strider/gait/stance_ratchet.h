//! StanceRatchet: when the stance feet move under the body. Off by default:
//! every tick, as walked. Two settings, for slow gaits on hobby servos
//! (docs/gaits.md, "Presets"; docs/simulator.md, "mammal8 at seed 003's point"):
//!
//! - Steps: the feet move in steps of a set length, all at once. A hobby
//!   servo ignores a pulse change smaller than its dead band (5 us on the
//!   MG996R, ~0.45 deg), so at a few mm/s each stance joint moves in jumps
//!   of its own, each at its own moment; with two feet down (a trot, a
//!   pace) the foot whose joint jumps fights the one that holds still, and
//!   one slides: mammal8's trot at seed 003's 4.2 mm/s made a third of its
//!   distance. In steps longer than a dead band's worth at the feet every
//!   stance joint jumps at the same tick, and the body goes with them.
//! - On all feet: the body moves only while every foot is down, and stands
//!   still on the feet it keeps down while others swing: a trot's diagonal
//!   then holds the CoM where it stood at mid-stance, on the diagonal,
//!   instead of past it, and a pace's stance side does not push against
//!   swing feet that the body tips onto. The feet catch up with what was
//!   walked meanwhile a step a tick once the last foot is down.
//!
//! Odometry keeps the walked steps; the feet lag them by what is held,
//! which a stop (all feet down) and a turn take at once.
#ifndef STRIDER_GAIT_STANCE_RATCHET_H
#define STRIDER_GAIT_STANCE_RATCHET_H

#include "../math/scalar.h"
#include "stance.h"

namespace strider {

template <typename S>
class StanceRatchet {
 public:
  //! Steps of at least `step_mm` (along x or y) [mm], 0: every tick; on all
  //! feet: only while every foot is down (the engine's `now`).
  void set(S step_mm, bool on_all_feet) {
    step_mm_ = step_mm > S(0) ? step_mm : S(0);
    on_all_feet_ = on_all_feet && step_mm_ > S(0);
  }
  bool on_all_feet() const { return on_all_feet_; }

  //! What of this tick's body step the stance feet take, in place: `step`
  //! as walked in, as taken out (its rotation kept). `now`: the feet may
  //! move this tick (false: on all feet, a foot is up); `flush`: a stop may
  //! take what is held (false: a foot at its edge holds the body). Off or
  //! turning: all that is held with this tick's step. Sums and comparisons
  //! on what is held, in place: on the AVR each Fixed value copied or
  //! computed costs flash (~620 bytes in all).
  STRIDER_NOINLINE void take(BodyStep<S>& step, bool flush, bool now) {
    // Off and nothing held (every gait but a preset's): the step as walked.
    if (step_mm_ == S(0) && held_x_ == S(0) && held_y_ == S(0)) return;
    const bool walked = step.dx_mm != S(0) || step.dy_mm != S(0);
    held_x_ = held_x_ + step.dx_mm;
    held_y_ = held_y_ + step.dy_mm;
    S limit = max_of(abs(held_x_), abs(held_y_));  // all of it
    if (step_mm_ != S(0) && step.sin_yaw == S(0) && step.cos_yaw == S(1)) {
      // A full step while walking, the rest when stopped; more than 1.5
      // steps (on all feet, catching up) a step a tick.
      if (!now || (walked ? limit < step_mm_ : !flush)) {
        limit = S(0);
      } else if (step_mm_ + step_mm_ + step_mm_ < limit + limit) {
        limit = step_mm_;
      }
    }
    step.dx_mm = take_axis(held_x_, limit);
    step.dy_mm = take_axis(held_y_, limit);
  }

 private:
  //! Up to `limit` of what is held along one axis, taken from it.
  STRIDER_NOINLINE static S take_axis(S& held, S limit) {
    const S taken = clamp(held, -limit, limit);
    held = held - taken;
    return taken;
  }

  S step_mm_ = S(0);
  S held_x_ = S(0);  //!< walked and not yet taken by the stance feet [mm]
  S held_y_ = S(0);
  bool on_all_feet_ = false;
};

}  // namespace strider

#endif  // STRIDER_GAIT_STANCE_RATCHET_H
