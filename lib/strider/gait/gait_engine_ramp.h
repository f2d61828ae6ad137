//! GaitEngine's set-up and ramps: configuration, gait tables, planning a
//! command and ramping to it (in stride per cycle, see replan()), placing
//! the feet that land during the ramp, starting to walk, changing gaits,
//! stand-up / sit-down and the body offsets' rate limit (kept apart from the
//! class declaration in gait_engine.h; include gait_engine.h).
#ifndef STRIDER_GAIT_GAIT_ENGINE_RAMP_H
#define STRIDER_GAIT_GAIT_ENGINE_RAMP_H

#include "gait_engine.h"

namespace strider {

//! Takes the configuration and a gait; the robot stands (or sits).
template <typename S>
void GaitEngine<S>::configure(const GaitConfig<S>& config, const GaitTable& gait, bool sitting) {
  if (&config != &cfg_) cfg_ = config;
  base_ = gait;
  relabel_ = false;  // table() is the gait as given until the robot walks
  quarter_ = 0;
  load_table(gait);
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
    foot_[i] = cfg_.home[i];
    contact_[i] = true;
    pending_[i] = false;
  }
  state_ = sitting ? GaitState::kSitting : GaitState::kStanding;
  progress_ = sitting ? S(0) : S(1);
  vx_ = vy_ = wz_ = S(0);
  hz_ = cfg_.limits.min_hz;
  to_ = VelocityPlan<S>{S(0), S(0), S(0), hz_, false};
  from_s_ = to_s_ = now_s_ = land_s_ = Stride{S(0), S(0), S(0), hz_};
  land_fresh_ = false;
  ramp_ = S(1);
  shift_.reset();
  pose_ = goal_pose_ = BodyOffsets<S>::zero();
  pose_at_goal_ = true;
  odo_x_ = odo_y_ = odo_yaw_ = S(0);
  odo_c_ = S(1);
  odo_s_ = S(0);
  support_dirty_ = true;
  margin_fresh_ = false;
  step_cache_.dt = S(0);
  invalidate_touchdown();
  vel_fresh_ = false;
  odo_dx_ = odo_dy_ = odo_wx_ = odo_wy_ = S(0);
  // beyond_edge(): kEdgeShare of the shortest stride (2 edge_mm), 1 % less
  // for rounding, squared in working units.
  constexpr S share = scalar<S>(kEdgeShare * 2.0 * 0.99);
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
    const S r = units::to_unit(cfg_.edge_mm[i] * share, cfg_.unit_shift);
    edge_r2_[i] = r * r;
  }
}

template <typename S>
void GaitEngine<S>::step_transition(S dt) {
  const S d = dt / cfg_.transition_s;
  if (state_ == GaitState::kStandingUp) {
    progress_ = min_of(progress_ + d, S(1));
    if (progress_ >= S(1)) state_ = GaitState::kStanding;
  } else {
    progress_ = max_of(progress_ - d, S(0));
    if (progress_ <= S(0)) state_ = GaitState::kSitting;
  }
}

template <typename S>
void GaitEngine<S>::step_pose(S dt) {
  // At its goal (the usual case): nothing to move, no products.
  if (pose_at_goal_) return;
  // Every offset moves by at most its rate; when all were at the goal
  // already (none moved), the pose is there.
  const S dp = cfg_.pose_speed_mm_s * dt, da = cfg_.pose_rate_rad_s * dt;
  // The six offsets in their order (x, y, z, roll, pitch, yaw) at their
  // byte offsets in BodyOffsets (six scalars, no padding), one call site:
  // the lengths at dp, the angles at da.
  unsigned char* v = reinterpret_cast<unsigned char*>(&pose_);
  const unsigned char* goal = reinterpret_cast<const unsigned char*>(&goal_pose_);
  bool there = true;
  for (uint8_t k = 0; k < 6; ++k, v += sizeof(S), goal += sizeof(S))
    there &= move_toward(*reinterpret_cast<S*>(v), *reinterpret_cast<const S*>(goal), k < 3 ? dp : da);
  pose_at_goal_ = there;
}

template <typename S>
void GaitEngine<S>::set_gait(const GaitTable& gait) {
  const S old_duty = duty_;
  base_ = gait;
  load_table(relabel_ ? gait_table::relabeled(gait, quarter_) : gait);
  // Keep each stance's travel (stride per cycle x duty): with a longer
  // duty the body slows at once, with a shorter one the step rate drops;
  // either way nothing moves faster, then the ramp goes to the new plan.
  const S r = old_duty / duty_;
  now_s_.x = now_s_.x * r;
  now_s_.y = now_s_.y * r;
  now_s_.yaw = now_s_.yaw * r;
  if (r > S(1)) now_s_.hz = now_s_.hz / r;
  vel_fresh_ = false;
  land_fresh_ = false;
  step_command(S(0));
  replan();
}

template <typename S>
void GaitEngine<S>::load_table(const GaitTable& t) {
  set_fractions(t, S());
  invalidate_touchdown();
  uint32_t latest_end = 0;
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
    offset_[i] = table_phase(t.offset[i], S());
    const uint32_t end = uint32_t(offset_[i]) + swing_len_;
    if (end <= kPhaseOne && end > latest_end) latest_end = end;
  }
  // Start just before the first lift-off, or at the four-foot window
  // before it when the body must shift first.
  start_phase_ =
      t.shift_body && latest_end > 0 && latest_end < kPhaseOne ? Phase16(latest_end) : Phase16(0xFFFF);
}

//! The table's duty in the engine's units: float through double (the host),
//! Fixed from the float's bits (integers only: the same values, test/gait).
template <typename S>
void GaitEngine<S>::set_fractions(const GaitTable& t, float) {
  swing_len_ = phase_span(1.0 - double(t.duty));
  duty_ = scalar<S>(double(t.duty));
  inv_swing_ = scalar<S>(1.0 / (1.0 - double(t.duty)));
  inv_stance_ = scalar<S>(1.0 / double(t.duty));
}
template <typename S>
void GaitEngine<S>::set_fractions(const GaitTable& t, Fixed) {
  swing_len_ = table_fraction::swing_span(t.duty);
  duty_ = Fixed::from_raw(int32_t(table_fraction::q16(t.duty)));
  inv_swing_ = table_fraction::inverse_of_rest(t.duty);
  inv_stance_ = table_fraction::inverse(t.duty);
}
template <typename S>
Phase16 GaitEngine<S>::table_phase(float offset, float) {
  return phase16(double(offset));
}
template <typename S>
Phase16 GaitEngine<S>::table_phase(float offset, Fixed) {
  return Phase16(table_fraction::q16(offset) & 0xFFFFu);
}

//! Plans the command and starts the ramp to it. The ramp runs in phase,
//! linearly in the stride per cycle and the rate: at least one cycle, and
//! no faster than the acceleration limits at the faster of the two rates.
template <typename S>
void GaitEngine<S>::replan() {
  to_ = cfg_.limits.plan(cfg_.home, cmd_vx_, cmd_vy_, cmd_wz_, duty_, budget(), base_.shift_body);
  const S inv = S(1) / to_.step_hz;
  to_s_ = Stride{to_.vx_mm_s * inv, to_.vy_mm_s * inv, to_.wz_rad_s * inv, to_.step_hz};
  from_s_ = now_s_;
  const S dv = max_of(abs(to_.vx_mm_s - vx_), abs(to_.vy_mm_s - vy_));
  const S dw = abs(to_.wz_rad_s - wz_);
  const S time = max_of(dv / cfg_.accel_mm_s2, dw / cfg_.yaw_accel_rad_s2);
  const S cycles = max_of(time * max_of(to_s_.hz, from_s_.hz), S(1));
  ramp_cycles_ = cycles;
  ramp_per_cycle_ = S(1) / cycles;
  ramp_ = S(0);
  land_fresh_ = false;
}

template <typename S>
void GaitEngine<S>::start_walking() {
  const bool relabel = base_.relabel_by_direction && (to_.vx_mm_s != S(0) || to_.vy_mm_s != S(0));
  int8_t quarter = 0;
  if (relabel) {
    // The quadrant of the direction of travel (seed 000 section 3.3).
    const S ax = abs(to_.vx_mm_s), ay = abs(to_.vy_mm_s);
    quarter = ax >= ay ? (to_.vx_mm_s >= S(0) ? 0 : 2) : (to_.vy_mm_s > S(0) ? 1 : 3);
  }
  // configure(), set_gait() and the last start loaded the table that
  // relabel_ and quarter_ name: the same one again (the usual start) keeps
  // its phases and fractions (the duty's conversions cost ~5,000 cycles in
  // Fixed, in the tick that also starts the ramp and the first swings).
  if (relabel != relabel_ || quarter != quarter_) {
    relabel_ = relabel;
    quarter_ = quarter;
    load_table(relabel ? gait_table::relabeled(base_, quarter) : base_);
  } else {
    invalidate_touchdown();
  }
  clock_.reset(start_phase_);
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
    pending_[i] = false;
    // Each foot starts as if it had been down since its last touch-down
    // in the table (negative for a foot the table has in the air: its
    // first stance runs to its offset), so none looks overdue.
    stance_elapsed_[i] = int32_t(kPhaseOne - swing_len_) - int32_t(Phase16(offset_[i] - start_phase_));
  }
  in_window_ = false;
  window_group_ = kNoGroup;
  state_ = GaitState::kWalking;
}

//! Moves the ramp on by this tick's phase; the velocity is stride x rate.
template <typename S>
void GaitEngine<S>::step_command(S dt) {
  if (ramp_ < S(1)) {
    ramp_ = min_of(ramp_ + dt * hz_ * ramp_per_cycle_, S(1));
    if (ramp_ >= S(1)) {
      now_s_ = to_s_;
    } else {
      ramp_stride(now_s_, ramp_);
    }
    vel_fresh_ = false;
    land_fresh_ = false;
  }
  if (vel_fresh_) return;  // a steady command: the products of the last tick hold
  // Products into locals first, then the stores: written member by member,
  // avr-gcc 5.4 -Os clobbered the address register between two of them.
  const S hz = now_s_.hz;
  // A zero part (a straight or forward walk's) needs no product: the
  // rate is positive, so the product would be that zero, its sign included.
  const S vx = now_s_.x * hz;
  const S vy = now_s_.y == S(0) ? now_s_.y : now_s_.y * hz;
  const S wz = now_s_.yaw == S(0) ? now_s_.yaw : now_s_.yaw * hz;
  hz_ = hz;
  vx_ = vx;
  vy_ = vy;
  wz_ = wz;
  step_cache_.dt = S(0);  // the body step is made again
  vel_fresh_ = true;
}

template <typename S>
void GaitEngine<S>::ramp_stride(Stride& out, S t) const {
  // The four parts in their order (x, y, yaw, hz) at their byte offsets in
  // Stride (four scalars, no padding): one mix() inlined, one loop.
  const unsigned char* a = reinterpret_cast<const unsigned char*>(&from_s_);
  const unsigned char* b = reinterpret_cast<const unsigned char*>(&to_s_);
  unsigned char* o = reinterpret_cast<unsigned char*>(&out);
  for (uint8_t k = 0; k < 4; ++k, a += sizeof(S), b += sizeof(S), o += sizeof(S))
    *reinterpret_cast<S*>(o) = mix(*reinterpret_cast<const S*>(a), *reinterpret_cast<const S*>(b), t);
}

template <typename S>
inline void GaitEngine<S>::touchdown_xy(uint8_t i, S& x, S& y) {
  if (!td_fresh_) refresh_touchdown();
  // Sums in place (scalar.h's add_inline: the same bits as operator+).
  if (td_sin_ == S(0) && td_cos_ == S(1)) {
    x = add_inline(cfg_.home[i].x, td_dx_);
    y = add_inline(cfg_.home[i].y, td_dy_);
  } else {
    touchdown_turned(i, x, y);
  }
}

//! touchdown_xy()'s terms: where a foot lands is centred on home for the
//! travel of its coming stance (duty cycles, stride-per-cycle units),
//! stance.h's touchdown_point; its leg-independent terms are computed once
//! per change of the landing stride (every tick of a ramp), out of line.
template <typename S>
void GaitEngine<S>::refresh_touchdown() {
  if (land_s_.yaw == S(0)) {
    // Not turning: touchdown_point() is home + the stride x duty / 2.
    constexpr S half = scalar<S>(0.5);
    const S k = duty_ * half;
    td_dx_ = land_s_.x * k;
    td_dy_ = land_s_.y * k;
    td_cos_ = S(1);
    td_sin_ = S(0);
  } else {
    // touchdown_point()'s offset and rotation for every home (stance.h).
    touchdown_frame(land_s_.x, land_s_.y, land_s_.yaw, duty_, td_dx_, td_dy_, td_cos_, td_sin_);
  }
  td_fresh_ = true;
}

template <typename S>
void GaitEngine<S>::touchdown_turned(uint8_t i, S& x, S& y) const {
  const Vec3<S>& h = cfg_.home[i];
  x = td_cos_ * h.x - td_sin_ * h.y + td_dx_;
  y = td_sin_ * h.x + td_cos_ * h.y + td_dy_;
}

//! The mean stride per cycle over the next stance (duty cycles) along the
//! ramp: a foot landing now is placed for it.
template <typename S>
void GaitEngine<S>::update_landing() {
  // The ramp over and land_s_ already now_s_: nothing changes.
  if (land_fresh_) return;
  // The old stride's three parts, not the whole Stride (a byte loop).
  const S was_x = land_s_.x, was_y = land_s_.y, was_yaw = land_s_.yaw;
  if (ramp_ >= S(1)) {
    land_s_ = now_s_;
  } else {
    const S left = S(1) - ramp_;              // ramp still to go
    // Products, not divisions, on every tick of a ramp: the ramp's length
    // and 1 / duty are at hand.
    const S finish = left * ramp_cycles_;  // its length [cycles]
    // lag = (integral over the stance of (1 - ramp)) / stance
    constexpr S half = scalar<S>(0.5);
    const S lag = finish >= duty_ ? left - ramp_per_cycle_ * duty_ * half : left * finish * half * inv_stance_;
    ramp_stride(land_s_, S(1) - lag);
  }
  if (!(land_s_.x == was_x && land_s_.y == was_y && land_s_.yaw == was_yaw)) invalidate_touchdown();
  land_fresh_ = ramp_ >= S(1);
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_ENGINE_RAMP_H
