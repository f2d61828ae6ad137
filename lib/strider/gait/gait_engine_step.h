//! GaitEngine's walking tick, body shift and margin (kept apart from the
//! class declaration in gait_engine.h so that each file reads on its own;
//! include gait_engine.h, not this file).
#ifndef STRIDER_GAIT_GAIT_ENGINE_STEP_H
#define STRIDER_GAIT_GAIT_ENGINE_STEP_H

#include "gait_engine.h"

namespace strider {

template <typename S>
void GaitEngine<S>::step_walk(S dt) {
  // A steady command (the ramp over, the products known) and its landing
  // stride known: step_command() and update_landing() have nothing to do.
  if (ramp_ < S(1) || !vel_fresh_) step_command(dt);
  if (!land_fresh_) update_landing();
  StepCache& sc = step_cache_;
  if (!(sc.dt == dt)) sc = StepCache{dt, BodyStep<S>::make(vx_, vy_, wz_, dt)};
  // Field by field: avr-gcc copies the whole struct with a byte loop.
  BodyStep<S> step{sc.step.dx_mm, sc.step.dy_mm, sc.step.dyaw, sc.step.cos_yaw, sc.step.sin_yaw};
  // A foot on the ground at the edge of its reach that this step would take
  // farther out holds the body for this tick (it lifts as soon as it can).
  held_ = false;
  bool edge[kWalkerLegs];  // legs 0 to leg_count - 1, all set here
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) edge[i] = contact_[i] && at_edge(i);
  for (uint8_t i = 0; i < cfg_.leg_count && !held_; ++i) {
    if (!edge[i]) continue;
    held_ = step_takes_out(i, step);
  }
  if (held_) step = BodyStep<S>::none();
  // Odometry: the step in the world frame; heading kept as cos/sin,
  // renormalised by one Newton step (no trig per tick).
  // While the body does not turn, the world step repeats: kept, not recomputed.
  if (!(step.dyaw == S(0) && step.dx_mm == odo_dx_ && step.dy_mm == odo_dy_)) {
    odo_dx_ = step.dx_mm;
    odo_dy_ = step.dy_mm;
    odo_wx_ = odo_c_ * step.dx_mm - odo_s_ * step.dy_mm;
    odo_wy_ = odo_s_ * step.dx_mm + odo_c_ * step.dy_mm;
  }
  // Sums in place (scalar.h's add_inline: the same bits as operator+).
  odo_x_ = add_inline(odo_x_, odo_wx_);
  odo_y_ = add_inline(odo_y_, odo_wy_);
  odo_yaw_ = add_inline(odo_yaw_, step.dyaw);
  if (step.dyaw != S(0)) {
    odo_dx_ = odo_dy_ = S(0);  // the heading changes: recompute next tick
    const S c = odo_c_ * step.cos_yaw - odo_s_ * step.sin_yaw;
    const S s = odo_s_ * step.cos_yaw + odo_c_ * step.sin_yaw;
    constexpr S half = scalar<S>(0.5);
    const S k = (S(3) - (c * c + s * s)) * half;
    odo_c_ = c * k;
    odo_s_ = s * k;
  }

  const uint8_t n = cfg_.leg_count;
  bool changed = step_ground(step, dt);
  if (step_lift(edge)) changed = true;
  step_swing(dt);
  if (cfg_.stance_depth_mm != S(0)) {
    for (uint8_t i = 0; i < n; ++i) {
      if (!contact_[i]) continue;
      const uint32_t down = stance_elapsed_[i] > 0 ? uint32_t(stance_elapsed_[i]) : 0u;
      foot_[i].z = cfg_.home[i].z - stance_sink_mm(cfg_.stance_depth_mm, phase_to<S>(down) * inv_stance_);
    }
  }
  if (changed) support_dirty_ = true;
  // A gait without body shift and no shift left (a trot, a tripod): nothing to move, no call.
  if (base_.shift_body || shift_.x_mm() != S(0) || shift_.y_mm() != S(0)) step_shift(dt);

  if (state_ == GaitState::kWalking && !wants_to_walk()) state_ = GaitState::kStopping;
  if (state_ == GaitState::kStopping && wants_to_walk()) state_ = GaitState::kWalking;
  if (state_ == GaitState::kStopping && at_rest()) {
    bool still = shift_.x_mm() == S(0) && shift_.y_mm() == S(0);
    for (uint8_t i = 0; i < n && still; ++i) still = contact_[i] && near_home(i);
    if (still) state_ = GaitState::kStanding;
  }
}

template <typename S>
bool GaitEngine<S>::step_ground(const BodyStep<S>& step, S dt) {
  clock_.advance(dt, hz_);
  const uint32_t delta = Phase16(clock_.now() - clock_.before());
  const uint8_t n = cfg_.leg_count;
  bool changed = false;
  // Not turning (walking straight): move_ground_point()'s differences, in
  // place and without its call.
  const bool straight = step.sin_yaw == S(0) && step.cos_yaw == S(1);
  Vec3<S>* foot = foot_;
  int32_t* elapsed = stance_elapsed_;
  // One pass: a foot landing this tick stays where it lands (the feet on
  // the ground move on their own, so the order of the legs does not matter).
  for (uint8_t i = 0; i < n; ++i, ++foot, ++elapsed) {
    if (!contact_[i]) {
      swing_elapsed_[i] += delta;
      if (swing_elapsed_[i] < leg_swing_len_[i]) continue;
      foot->x = target_[i].x;
      foot->y = target_[i].y;
      foot->z = cfg_.home[i].z;
      contact_[i] = true;
      *elapsed = int32_t(swing_elapsed_[i] - leg_swing_len_[i]);
      changed = true;
      continue;
    }
    // Feet on the ground stay on the ground: they move by the inverse step.
    if (straight) {
      foot->x = sub_inline(foot->x, step.dx_mm);
      foot->y = sub_inline(foot->y, step.dy_mm);
    } else {
      // Field by field (leg_ik::copy_point): avr-gcc copies a whole Vec3 with a byte loop.
      leg_ik::copy_point(step.move_ground_point(*foot), *foot);
    }
    const int32_t e = *elapsed + int32_t(delta);
    *elapsed = e < int32_t(kPhaseOne) ? e : int32_t(kPhaseOne);
  }
  return changed;
}

template <typename S>
bool GaitEngine<S>::step_lift(const bool* edge) {
  const uint8_t n = cfg_.leg_count;
  bool changed = false;
  // Lift-offs when the clock passes a foot's offset.
  for (uint8_t i = 0; i < n; ++i) {
    if (!contact_[i]) continue;
    const bool crossed = clock_.crossed(offset_[i]);
    // Lift at the offset; or, after a gait change that made a foot miss its
    // offset, as soon as its stance is a sixteenth of a cycle overdue; or
    // when the foot reaches the edge of its stride (a command change).
    if (crossed || stance_elapsed_[i] >= int32_t(kPhaseOne - swing_len_ + kPhaseOne / 16) || (edge[i] && at_edge(i)))
      pending_[i] = true;
    if (!pending_[i]) continue;
    if (done(i)) {
      pending_[i] = false;  // home already: this foot stays down
      continue;
    }
    if (!may_lift(i)) continue;  // deferred until enough feet are down
    lift_foot(i, crossed);
    changed = true;
  }
  return changed;
}

template <typename S>
void GaitEngine<S>::lift_foot(uint8_t i, bool crossed) {
  lift_[i] = foot_[i];
  contact_[i] = false;
  pending_[i] = false;
  leg_swing_len_[i] = swing_len_;
  leg_inv_swing_[i] = inv_swing_;
  leg_shape_[i] = cfg_.shape;
  swing_elapsed_[i] = crossed ? uint32_t(Phase16(clock_.now() - offset_[i])) : 0u;
  Vec3<S>& t = target_[i];
  touchdown_xy(i, t.x, t.y);
  t.z = cfg_.home[i].z;
  settled_[i] = true;
  // Only the semicircle's apex depends on the step's length (a square root).
  apex_[i] = cfg_.shape == SwingShape::kSemicircle
                 ? swing_apex_mm(cfg_.shape, hypot(t.x - lift_[i].x, t.y - lift_[i].y), cfg_.step_height_mm)
                 : cfg_.step_height_mm;
}

template <typename S>
void GaitEngine<S>::step_swing(S dt) {
  const uint8_t n = cfg_.leg_count;
  // Feet in the air follow the swing shape toward a touch-down point that
  // moves at most max_step per tick (command and gait changes).
  const S max_step = cfg_.target_speed_mm_s * dt;
  // Feet of one swing group (a tripod's three) share their swing phase:
  // the swing point of the last foot is reused when the phase is the same.
  SwingPoint<S> sp{S(0), S(0)};
  uint32_t sp_elapsed = 0;
  S sp_inv = S(0), sp_apex = S(0), sp_lift = S(0);
  SwingShape sp_shape = SwingShape::kRectangle;
  bool sp_known = false, lift_known = false;  // lift_known: sp_lift = sp_apex * sp.w
  for (uint8_t i = 0; i < n; ++i) {
    if (contact_[i]) continue;
    if (!settled_[i]) settle_target(i, max_step);
    if (!sp_known || swing_elapsed_[i] != sp_elapsed || leg_inv_swing_[i] != sp_inv || leg_shape_[i] != sp_shape) {
      sp_elapsed = swing_elapsed_[i];
      sp_inv = leg_inv_swing_[i];
      sp_shape = leg_shape_[i];
      sp = swing_point(sp_shape, phase_to<S>(sp_elapsed) * sp_inv);
      sp_known = true;
      lift_known = false;
    }
    if (!lift_known || apex_[i] != sp_apex) {
      sp_apex = apex_[i];
      sp_lift = sp_apex * sp.w;
      lift_known = true;
    }
    // A foot that lifted from the ground line (no stance depth) keeps its
    // height but for the lift: no product for the zero difference (without
    // the stance depth built in, every foot lifts from there).
    const S dz = sub_inline(cfg_.home[i].z, lift_[i].z);
    foot_[i].x = add_inline(lift_[i].x, sub_inline(target_[i].x, lift_[i].x) * sp.u);
    foot_[i].y = add_inline(lift_[i].y, sub_inline(target_[i].y, lift_[i].y) * sp.u);
    foot_[i].z = add_inline(dz == S(0) ? lift_[i].z : add_inline(lift_[i].z, dz * sp.u), sp_lift);
  }
}

template <typename S>
bool GaitEngine<S>::step_takes_out(uint8_t i, const BodyStep<S>& step) const {
  const Vec3<S> next = step.move_ground_point(foot_[i]);
  const S before = abs(foot_[i].x - cfg_.home[i].x) + abs(foot_[i].y - cfg_.home[i].y);
  const S after = abs(next.x - cfg_.home[i].x) + abs(next.y - cfg_.home[i].y);
  return after > before;
}

template <typename S>
void GaitEngine<S>::settle_target(uint8_t i, S max_step) {
  // Every tick of a ramp, for every foot in the air: x and y into place,
  // sums in place (scalar.h: the same bits as the operators).
  S wx, wy;
  touchdown_xy(i, wx, wy);
  Vec3<S>& t = target_[i];
  const S lo = neg_inline(max_step);
  t.x = add_inline(t.x, clamp(sub_inline(wx, t.x), lo, max_step));
  t.y = add_inline(t.y, clamp(sub_inline(wy, t.y), lo, max_step));
  settled_[i] = t.x == wx && t.y == wy;
}

template <typename S>
void GaitEngine<S>::step_shift(S dt) {
  if (!base_.shift_body) {  // relabelling keeps it
    // Back to no shift (after a gait change); once there, nothing to move.
    if (shift_.x_mm() != S(0) || shift_.y_mm() != S(0)) shift_.step_toward(S(0), S(0), cfg_.shift_speed_mm_s * dt);
    return;
  }
  const S max_step = cfg_.shift_speed_mm_s * dt;
  const uint8_t n = cfg_.leg_count;
  S ref_x = cfg_.com_x_mm + pose_.translation_mm.x, ref_y = cfg_.com_y_mm + pose_.translation_mm.y;
  bool any_swing = false;
  for (uint8_t i = 0; i < n; ++i)
    if (!contact_[i]) any_swing = true;
  if (support_dirty_) build_support();
  // One correction call: the support now while feet swing; in a window, the
  // support of the next swing (if a foot is still to step) for the CoM
  // where it will be at lift-off, blended in below.
  const SupportPolygon<S>* poly = &support_;
  S t = S(0);
  if (any_swing) {
    in_window_ = false;
  } else {
    const Phase16 now = clock_.now();
    if (!in_window_) {
      in_window_ = true;
      shift_.begin_window();
      window_start_ = now;
      window_group_ = kNoGroup;
    }
    // The group that lifts next: the nearest offset among feet still to step.
    uint8_t lead = kNoGroup;
    Phase16 ahead = 0;
    for (uint8_t i = 0; i < n; ++i) {
      if (done(i)) continue;
      const Phase16 d = pending_[i] ? Phase16(0) : Phase16(offset_[i] - now);
      if (lead == kNoGroup || d < ahead) {
        lead = i;
        ahead = d;
      }
    }
    if (lead != window_group_) {
      window_group_ = lead;
      if (lead != kNoGroup) {
        bool stays[kWalkerLegs];
        for (uint8_t i = 0; i < n; ++i) stays[i] = contact_[i] && offset_[i] != offset_[lead];
        next_support_.build(foot_, stays, n, cfg_.foot_radius_mm, cfg_.unit_shift);
        const Phase16 len = Phase16(Phase16(now + ahead) - window_start_);
        window_inv_ = len == 0 ? S(0) : S(1) / phase_to<S>(len);
      }
    }
    poly = nullptr;
    if (lead != kNoGroup) {
      poly = &next_support_;
      const S cycles = phase_to<S>(ahead);  // until it lifts
      ref_x = ref_x + now_s_.x * cycles;
      ref_y = ref_y + now_s_.y * cycles;
    }
    t = window_inv_ == S(0) ? S(1) : phase_to<S>(Phase16(now - window_start_)) * window_inv_;
  }
  S cx = S(0), cy = S(0);
  if (poly != nullptr) BodyShift<S>::correction(*poly, foot_, ref_x, ref_y, cfg_.margin_mm, cfg_.shift_x_only, cx, cy);
  S tx = cx, ty = cy;
  if (!any_swing) shift_.window_target(t, cx, cy, tx, ty);
  // Never beyond the reach kept for it (the walk and crawl stay within it,
  // test/gait; a switch from another gait mid-stride may ask for more).
  const S b = cfg_.shift_budget_mm;
  shift_.step_toward(clamp(tx, -b, b), clamp(ty, -b, b), max_step);
}

template <typename S>
void GaitEngine<S>::update_margin() const {
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

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_ENGINE_STEP_H
