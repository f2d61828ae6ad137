//! GaitEngine's set-up, gait changes and walking tick: the phase clock, the
//! feet on the ground and when they lift and land (include gait_engine.h).
#ifndef STRIDER_GAIT_GAIT_ENGINE_WALK_H
#define STRIDER_GAIT_GAIT_ENGINE_WALK_H

#include "gait_engine.h"

namespace strider {

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::configure(const GaitConfig<S, kLegs, kSearch>& config, const GaitTable& gait, bool sitting) {
  if (&config != &cfg_) {
    cfg_ = config;
  } else if (home_draw_mm_ != S(0)) {  // a restart: from the standing homes
    ramp_.cmd_vx = ramp_.cmd_vy = ramp_.cmd_wz = steer_wz_ = S(0);
    draw_homes_for_turn();
  }
  home_draw_mm_ = S(0);
  phases_.base = gait;
  phases_.relabel = false;  // table() is the gait as given until the robot walks
  phases_.quarter = 0;
  load_table(gait);
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
    foot_[i] = cfg_.home[i];
    contact_[i] = true;
    pending_[i] = false;
  }
  state_ = sitting ? GaitState::kSitting : GaitState::kStanding;
  posture_.reset(sitting);
  ramp_.reset(cfg_.limits.min_hz);
  shift_.reset();
  odo_.reset();
  support_dirty_ = true;
  margin_fresh_ = false;
  edge_.configure(cfg_);
}

//! Share of its distance from the body's middle (along x) by which a planar
//! leg's foot stands nearer the middle while the robot turns in place (less
//! as the command goes forward too). Planar feet cannot step sideways: the
//! body turns by sliding them, and the front and rear feet resist that with
//! their x distance as the lever against the side's stride at its y distance
//! (docs/gaits.md, "Turning on planar legs": mammal8 turns 2 % of the gait's
//! rate with its feet under the hips, 31-38 % drawn in by this share).
constexpr double kPlanarTurnDraw = 0.3;

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::draw_homes_for_turn() {
  // The turn's part of the feet's stride speed against the forward part.
  const S turn = abs(ramp_.cmd_wz - steer_wz_) * abs(cfg_.home[0].y);
  const S along = abs(ramp_.cmd_vx) + turn;
  const S share = along == S(0) ? S(0) : turn / along;
  const S draw = share * scalar<S>(kPlanarTurnDraw) * (abs(cfg_.home[0].x) + home_draw_mm_);
  const S d = draw - home_draw_mm_;
  // A change under a millimetre is not worth moving the feet's homes (float
  // and fixed point would move them on different commands); back to none is.
  if (d == S(0) || (abs(d) < S(1) && !(draw == S(0)))) return;
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
    if (cfg_.home[i].x > S(0)) cfg_.home[i].x = cfg_.home[i].x - d;
    if (cfg_.home[i].x < S(0)) cfg_.home[i].x = cfg_.home[i].x + d;
  }
  home_draw_mm_ = draw;
  invalidate_touchdown();
}

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::set_gait(const GaitTable& gait) {
  const S old_duty = phases_.duty;
  phases_.base = gait;
  load_table(phases_.relabel ? gait_table::relabeled(gait, phases_.quarter) : gait);
  ramp_.keep_travel(old_duty, phases_.duty);
  ramp_.step(S(0));
  replan();
}

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::start_walking() {
  const VelocityPlan<S>& to = ramp_.plan;
  const bool relabel = phases_.base.relabel_by_direction && (to.vx_mm_s != S(0) || to.vy_mm_s != S(0));
  int8_t quarter = 0;
  if (relabel) {
    // The quadrant of the direction of travel (seed 000 section 3.3).
    const S ax = abs(to.vx_mm_s), ay = abs(to.vy_mm_s);
    quarter = ax >= ay ? (to.vx_mm_s >= S(0) ? 0 : 2) : (to.vy_mm_s > S(0) ? 1 : 3);
  }
  // The table loaded already (the usual start) keeps its phases and
  // fractions (~5,000 cycles in Fixed, in the tick that starts the ramp).
  if (relabel != phases_.relabel || quarter != phases_.quarter) {
    phases_.relabel = relabel;
    phases_.quarter = quarter;
    load_table(phases_.table());
  } else {
    invalidate_touchdown();
  }
  clock_.reset(phases_.start_phase);
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
    pending_[i] = false;
    // As if down since its last touch-down in the table (negative for a
    // foot the table has in the air), so none looks overdue.
    stance_elapsed_[i] =
        int32_t(kPhaseOne - phases_.swing_len) - int32_t(Phase16(phases_.offset[i] - phases_.start_phase));
  }
  window_.open = false;
  window_.group = ShiftWindow<S, kLegs>::kNoGroup;
  state_ = GaitState::kWalking;
}

template <typename S, uint8_t kLegs, bool kSearch>
void GaitEngine<S, kLegs, kSearch>::step_walk(S dt) {
  // A steady command and its landing stride known: nothing to ramp or place.
  if (ramp_.t < S(1) || !ramp_.vel_fresh) ramp_.step(dt);
  if (!ramp_.land_fresh && ramp_.update_landing(phases_.duty, phases_.inv_stance)) invalidate_touchdown();
  typename SpeedRamp<S>::StepCache& sc = ramp_.step_cache;
  if (!(sc.dt == dt)) sc = typename SpeedRamp<S>::StepCache{dt, BodyStep<S>::make(ramp_.vx, ramp_.vy, ramp_.wz, dt)};
  // Field by field: avr-gcc copies the whole struct with a byte loop.
  BodyStep<S> step{sc.step.dx_mm, sc.step.dy_mm, sc.step.dyaw, sc.step.cos_yaw, sc.step.sin_yaw};
  // A foot on the ground at the edge of its reach that this step would take
  // farther out holds the body for this tick.
  held_ = false;
  bool edge[kLegs];  // legs 0 to leg_count - 1, all set here
  for (uint8_t i = 0; i < cfg_.leg_count; ++i) edge[i] = contact_[i] && at_edge(i);
  for (uint8_t i = 0; i < cfg_.leg_count && !held_; ++i) {
    if (!edge[i]) continue;
    held_ = ReachEdge<S, kLegs>::takes_out(foot_[i], cfg_.home[i], step);
  }
  if (held_) step = BodyStep<S>::none();
  odo_.add(step);

  const uint8_t n = cfg_.leg_count;
  ratchet_.take(step, !held_, stance_moves_now());  // what of it the stance feet take now
  bool changed = step_ground(step, dt);
  if (step_lift(edge)) changed = true;
  step_swing(dt);
  if (cfg_.stance_depth_mm != S(0)) {
    for (uint8_t i = 0; i < n; ++i) {
      if (!contact_[i]) continue;
      const uint32_t down = stance_elapsed_[i] > 0 ? uint32_t(stance_elapsed_[i]) : 0u;
      foot_[i].z = cfg_.home[i].z - stance_sink_mm(cfg_.stance_depth_mm, phase_to<S>(down) * phases_.inv_stance);
    }
  }
  if (changed) support_dirty_ = true;
  // A gait without body shift and no shift left (a trot, a tripod): nothing to move, no call.
  if (phases_.base.shift_body || shift_.x_mm() != S(0) || shift_.y_mm() != S(0)) step_shift(dt);

  if (state_ == GaitState::kWalking && !wants_to_walk()) state_ = GaitState::kStopping;
  if (state_ == GaitState::kStopping && wants_to_walk()) state_ = GaitState::kWalking;
  if (state_ == GaitState::kStopping && at_rest()) {
    bool still = shift_.x_mm() == S(0) && shift_.y_mm() == S(0);
    for (uint8_t i = 0; i < n && still; ++i) still = contact_[i] && near_home(i);
    if (still) state_ = GaitState::kStanding;
  }
}

template <typename S, uint8_t kLegs, bool kSearch>
bool GaitEngine<S, kLegs, kSearch>::stance_moves_now() const {
  // Duty d leaves two four-foot windows of d - 1/2 each, in which the feet
  // catch up with a cycle's walk; under a duty of 0.65 they are short.
  constexpr S kMinDuty = scalar<S>(0.65);
  if (!ratchet_.on_all_feet() || phases_.duty < kMinDuty) return true;
  for (uint8_t i = 0; i < cfg_.leg_count; ++i)
    if (!contact_[i]) return false;
  return true;
}

template <typename S, uint8_t kLegs, bool kSearch>
bool GaitEngine<S, kLegs, kSearch>::step_ground(const BodyStep<S>& step, S dt) {
  clock_.advance(dt, ramp_.hz);
  const uint32_t delta = Phase16(clock_.now() - clock_.before());
  const uint8_t n = cfg_.leg_count;
  bool changed = false;
  // Walking straight: move_ground_point()'s differences in place, no call.
  const bool straight = step.sin_yaw == S(0) && step.cos_yaw == S(1);
  Vec3<S>* foot = foot_;
  int32_t* elapsed = stance_elapsed_;
  // One pass: a foot landing this tick stays where it lands.
  for (uint8_t i = 0; i < n; ++i, ++foot, ++elapsed) {
    if (!contact_[i]) {
      swing_.elapsed[i] += delta;
      if (swing_.elapsed[i] < swing_.len[i]) continue;
      foot->x = swing_.target[i].x;
      foot->y = swing_.target[i].y;
      foot->z = cfg_.home[i].z;
      contact_[i] = true;
      *elapsed = int32_t(swing_.elapsed[i] - swing_.len[i]);
      changed = true;
      continue;
    }
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

template <typename S, uint8_t kLegs, bool kSearch>
bool GaitEngine<S, kLegs, kSearch>::step_lift(const bool* edge) {
  const uint8_t n = cfg_.leg_count;
  bool changed = false;
  for (uint8_t i = 0; i < n; ++i) {
    if (!contact_[i]) continue;
    const bool crossed = clock_.crossed(phases_.offset[i]);
    // Lift at the offset, when the stance is a sixteenth of a cycle overdue
    // (a gait change), or at the edge of the stride (a command change).
    if (crossed || stance_elapsed_[i] >= int32_t(kPhaseOne - phases_.swing_len + kPhaseOne / 16) ||
        (edge[i] && at_edge(i)))
      pending_[i] = true;
    if (!pending_[i]) continue;
    if (done(i)) {
      pending_[i] = false;  // home already: this foot stays down
      continue;
    }
    uint8_t down = 0;
    for (uint8_t k = 0; k < n; ++k)
      if (contact_[k]) ++down;
    if (down <= cfg_.min_support) continue;
    lift_foot(i, crossed);
    changed = true;
  }
  return changed;
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_ENGINE_WALK_H
