//! GaitEngine's balance while walking: the body shift (body_shift.h; walk and
//! crawl) and the stability margin (stability.h); include gait_engine.h.
#ifndef STRIDER_GAIT_GAIT_ENGINE_BALANCE_H
#define STRIDER_GAIT_GAIT_ENGINE_BALANCE_H

#include "gait_engine.h"

namespace strider {

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::step_shift(S dt) {
  if (!phases_.base.shift_body) {  // relabelling keeps it
    // Back to no shift (after a gait change); once there, nothing to move.
    if (shift_.x_mm() != S(0) || shift_.y_mm() != S(0)) shift_.step_toward(S(0), S(0), cfg_.shift_speed_mm_s * dt);
    return;
  }
  const S max_step = cfg_.shift_speed_mm_s * dt;
  const uint8_t n = cfg_.leg_count;
  const Vec3<S>& pose_t = posture_.pose.translation_mm;
  S ref_x = cfg_.com_x_mm + pose_t.x, ref_y = cfg_.com_y_mm + pose_t.y;
  bool any_swing = false;
  for (uint8_t i = 0; i < n; ++i)
    if (!contact_[i]) any_swing = true;
  if (support_dirty_) build_support();
  // The support now while feet swing; in a window, that of the next swing
  // for the CoM where it will be at lift-off, blended in below.
  const SupportPolygon<S, kLegs>* poly = &support_;
  S t = S(0);
  ShiftWindow<S, kLegs>& w = window_;
  constexpr uint8_t kNoGroup = ShiftWindow<S, kLegs>::kNoGroup;
  if (any_swing) {
    w.open = false;
  } else {
    const Phase16 now = clock_.now();
    if (!w.open) {
      w.open = true;
      shift_.begin_window();
      w.start = now;
      w.group = kNoGroup;
    }
    // The group that lifts next: the nearest offset among feet still to step.
    uint8_t lead = kNoGroup;
    Phase16 ahead = 0;
    for (uint8_t i = 0; i < n; ++i) {
      if (done(i)) continue;
      const Phase16 d = pending_[i] ? Phase16(0) : Phase16(phases_.offset[i] - now);
      if (lead == kNoGroup || d < ahead) {
        lead = i;
        ahead = d;
      }
    }
    if (lead != w.group) {
      w.group = lead;
      if (lead != kNoGroup) {
        bool stays[kLegs];
        for (uint8_t i = 0; i < n; ++i) stays[i] = contact_[i] && phases_.offset[i] != phases_.offset[lead];
        w.next_support.build(foot_, stays, n, cfg_.foot_radius_mm, cfg_.unit_shift);
        const Phase16 len = Phase16(Phase16(now + ahead) - w.start);
        w.inv = len == 0 ? S(0) : S(1) / phase_to<S>(len);
      }
    }
    poly = nullptr;
    if (lead != kNoGroup) {
      poly = &w.next_support;
      const S cycles = phase_to<S>(ahead);  // until it lifts
      ref_x = ref_x + ramp_.now.x * cycles;
      ref_y = ref_y + ramp_.now.y * cycles;
    }
    t = w.inv == S(0) ? S(1) : phase_to<S>(Phase16(now - w.start)) * w.inv;
  }
  S cx = S(0), cy = S(0);
  if (poly != nullptr) {  // the shift that moves the reference into the region with the target margin
    S px = ref_x, py = ref_y;
    poly->constrain(foot_, px, py, cfg_.margin_mm, cfg_.shift_x_only);
    cx = px - ref_x;
    cy = py - ref_y;
  }
  S tx = cx, ty = cy;
  if (!any_swing) shift_.window_target(t, cx, cy, tx, ty);
  // Never beyond the reach kept for it (a gait switch mid-stride may ask more).
  const S b = cfg_.shift_budget_mm;
  shift_.step_toward(clamp(tx, -b, b), clamp(ty, -b, b), max_step);
}

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::update_margin() const {
  margin_fresh_ = true;
  const BodyPose<S> bp = body_pose();
  S cx = bp.translation_mm.x + cfg_.com_x_mm, cy = bp.translation_mm.y + cfg_.com_y_mm;
  const bool tilted = bp.roll_rad != S(0) || bp.pitch_rad != S(0) || bp.yaw_rad != S(0);
  if (tilted && (cfg_.com_x_mm != S(0) || cfg_.com_y_mm != S(0))) {
    const Vec3<S> com = rotation_rpy(bp.roll_rad, bp.pitch_rad, bp.yaw_rad, bp.order) *
                        Vec3<S>(cfg_.com_x_mm, cfg_.com_y_mm, S(0));
    cx = bp.translation_mm.x + com.x;
    cy = bp.translation_mm.y + com.y;
  }
  margin_ = support().margin(foot_, cx, cy);
}

//! The support polygon of the feet down now, built when first needed after a
//! lift-off or touch-down (gaits without body shift: only for margin_mm()).
template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::build_support() const {
  support_.build(foot_, contact_, cfg_.leg_count, cfg_.foot_radius_mm, cfg_.unit_shift);
  support_dirty_ = false;
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_ENGINE_BALANCE_H
