//! GaitEngine's feet in the air: lift-off, the swing toward the touch-down
//! point, and its steering when the landing stride changes (include gait_engine.h).
#ifndef STRIDER_GAIT_GAIT_ENGINE_SWING_H
#define STRIDER_GAIT_GAIT_ENGINE_SWING_H

#include "gait_engine.h"

namespace strider {

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::lift_foot(uint8_t i, bool crossed) {
  swing_.lift[i] = foot_[i];
  contact_[i] = false;
  pending_[i] = false;
  swing_.len[i] = phases_.swing_len;
  swing_.inv_swing[i] = phases_.inv_swing;
  swing_.shape[i] = cfg_.shape;
  swing_.elapsed[i] = crossed ? uint32_t(Phase16(clock_.now() - phases_.offset[i])) : 0u;
  Vec3<S>& t = swing_.target[i];
  touchdown_xy(i, t.x, t.y);
  t.z = cfg_.home[i].z;
  swing_.settled[i] = true;
  // Only the semicircle's apex depends on the step's length (a square root).
  const Vec3<S>& l = swing_.lift[i];
  swing_.apex[i] = cfg_.shape == SwingShape::kSemicircle
                       ? swing_apex_mm(cfg_.shape, hypot(t.x - l.x, t.y - l.y), cfg_.step_height_mm)
                       : cfg_.step_height_mm;
}

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::step_swing(S dt) {
  const uint8_t n = cfg_.leg_count;
  const S max_step = cfg_.target_speed_mm_s * dt;
  // Feet of one swing group (a tripod's three) share their swing point.
  SwingPoint<S> sp{S(0), S(0)};
  uint32_t sp_elapsed = 0;
  S sp_inv = S(0), sp_apex = S(0), sp_lift = S(0);
  SwingShape sp_shape = SwingShape::kRectangle;
  bool sp_known = false, lift_known = false;  // lift_known: sp_lift = sp_apex * sp.w
  SwingFeet<S, kLegs>& w = swing_;
  for (uint8_t i = 0; i < n; ++i) {
    if (contact_[i]) continue;
    if (!w.settled[i]) settle_target(i, max_step);
    if (!sp_known || w.elapsed[i] != sp_elapsed || w.inv_swing[i] != sp_inv || w.shape[i] != sp_shape) {
      sp_elapsed = w.elapsed[i];
      sp_inv = w.inv_swing[i];
      sp_shape = w.shape[i];
      sp = swing_point(sp_shape, phase_to<S>(sp_elapsed) * sp_inv);
      sp_known = true;
      lift_known = false;
    }
    if (!lift_known || w.apex[i] != sp_apex) {
      sp_apex = w.apex[i];
      sp_lift = sp_apex * sp.w;
      lift_known = true;
    }
    // A foot that lifted from the ground line: no product for its zero dz.
    const S dz = sub_inline(cfg_.home[i].z, w.lift[i].z);
    foot_[i].x = add_inline(w.lift[i].x, sub_inline(w.target[i].x, w.lift[i].x) * sp.u);
    foot_[i].y = add_inline(w.lift[i].y, sub_inline(w.target[i].y, w.lift[i].y) * sp.u);
    foot_[i].z = add_inline(dz == S(0) ? w.lift[i].z : add_inline(w.lift[i].z, dz * sp.u), sp_lift);
  }
}

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::settle_target(uint8_t i, S max_step) {
  S wx, wy;
  touchdown_xy(i, wx, wy);
  swing_.settle(i, wx, wy, max_step);
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_ENGINE_SWING_H
