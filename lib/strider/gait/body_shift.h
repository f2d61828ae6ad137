//! BodyShift: how a statically stable gait (walk, crawl) moves the body over
//! its feet so that the CoM stays inside the support polygon with a margin
//! (seed 003 section 3): a horizontal offset [mm] added to the body's pose
//! (docs/gaits.md, "Static stability").
#ifndef STRIDER_GAIT_BODY_SHIFT_H
#define STRIDER_GAIT_BODY_SHIFT_H

#include "../math/flash_table.h"
#include "gait_table.h"
#include "phase.h"
#include "stability.h"

namespace strider {

//! Moves v toward goal by at most max_step either way (a rate limit); true
//! when v was at the goal already. Not inlined: written once for every value.
template <typename S>
STRIDER_NOINLINE bool move_toward(S& v, S goal, S max_step) {
  const bool there = v == goal;
  v += clamp(goal - v, -max_step, max_step);
  return there;
}

template <typename S>
class BodyShift {
 public:
  BodyShift() : x_(), y_(), from_x_(), from_y_() {}
  S x_mm() const { return x_; }
  S y_mm() const { return y_; }

  void reset() { x_ = y_ = from_x_ = from_y_ = S(0); }

  //! Marks the start of a four-foot window: the blend starts from here.
  void begin_window() {
    from_x_ = x_;
    from_y_ = y_;
  }

  //! The window's blend at progress t in [0, 1] toward (to_x, to_y).
  void window_target(S t, S to_x, S to_y, S& tx, S& ty) const {
    const S k = smoothstep(t);
    tx = from_x_ + (to_x - from_x_) * k;
    ty = from_y_ + (to_y - from_y_) * k;
  }

  //! Moves toward (tx, ty) by at most max_step_mm per axis (not inlined: it
  //! would change the registers step_walk() keeps across step_shift()).
  STRIDER_NOINLINE void step_toward(S tx, S ty, S max_step_mm) {
    move_toward(x_, tx, max_step_mm);
    move_toward(y_, ty, max_step_mm);
  }

  //! 3 t^2 - 2 t^3 on [0, 1]: zero slope at both ends.
  static S smoothstep(S t) {
    t = clamp(t, S(0), S(1));
    return t * t * (S(3) - S(2) * t);
  }

 private:
  S x_, y_;  // zero, by the constructors
  S from_x_, from_y_;
};

//! The four-foot window: open while every foot is down and the body shifts
//! for the next swing group (led by leg `group`) to stand on `next_support`.
template <typename S, uint8_t kLegs>
struct ShiftWindow {
  static constexpr uint8_t kNoGroup = 0xFF;
  bool open;
  uint8_t group = kNoGroup;
  Phase16 start;
  S inv;  // 1 / its length [cycles]; 0: no length
  SupportPolygon<S, kLegs> next_support;
};

}  // namespace strider

#endif  // STRIDER_GAIT_BODY_SHIFT_H
