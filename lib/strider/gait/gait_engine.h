//! GaitEngine: per tick, the foot targets of a legged robot walking a gait
//! table at a commanded velocity, in the stance frame (kinematics/body_pose.h).
//! Walking tick: gait_engine_walk.h; feet in the air: gait_engine_swing.h;
//! body shift and margin: gait_engine_balance.h; the behaviour: docs/gaits.md.
#ifndef STRIDER_GAIT_GAIT_ENGINE_H
#define STRIDER_GAIT_GAIT_ENGINE_H

#include "body_posture.h"
#include "gait_state.h"
#include "odometry.h"
#include "reach_edge.h"
#include "speed_ramp.h"
#include "stance_ratchet.h"
#include "swing_feet.h"
#include "table_phases.h"
#include "touchdown.h"

namespace strider {

//! kLegs, kSearch: as GaitConfig's.
template <typename S, uint8_t kLegs = kMaxLegs, bool kSearch = true>
class GaitEngine {
 public:
  GaitEngine()
      : phases_(), sit_requested_(false), step_in_place_(false), ramp_(), foot_(), contact_(), pending_(), swing_(),
        stance_elapsed_(), td_(), edge_(), margin_(), margin_fresh_(false), odo_(), held_(false),
        window_(), posture_(), home_draw_mm_() {}

  //! Takes the configuration and a gait; the robot stands (or sits).
  void configure(const GaitConfig<S, kLegs, kSearch>& config, const GaitTable& gait, bool sitting = false);
  //! The same with the configuration built in place (fill_gait_config()).
  void configure(const RobotModel& model, const AnyLeg<S>* legs, const GaitParams& params, SwingShape shape,
                 const GaitTable& gait, bool sitting = false) {
    home_draw_mm_ = S(0);  // the homes built afresh
    fill_gait_config(cfg_, model, legs, params, shape);
    configure(cfg_, gait, sitting);
  }
  //! Velocity (vx, vy [mm/s], wz [rad/s], body frame) at speed_pct [0, 100]
  //! percent, clamped to the robot's limits (limited()); steer_wz [rad/s]
  //! turns on top of wz as a correction of the heading (a heading hold's),
  //! for which planar legs do not draw their feet in (draw_homes_for_turn()).
  void set_command(S vx, S vy, S wz, S speed_pct = scalar<S>(100.0), S steer_wz = S(0)) {
    constexpr S hundred = scalar<S>(100.0);
    const S k = clamp(speed_pct, S(0), hundred) / hundred;
    ramp_.cmd_vx = vx * k;
    ramp_.cmd_vy = vy * k;
    ramp_.cmd_wz = (wz + steer_wz) * k;
    steer_wz_ = steer_wz * k;
    if (cfg_.shift_x_only) draw_homes_for_turn();
    replan();
  }
  //! The swing of the feet that lift from now on: apex [mm], shape and the
  //! servo time of its lift alone [ms] (VelocityLimits::lift_ms).
  void set_swing(S step_height_mm, SwingShape shape, S lift_ms) {
    cfg_.step_height_mm = step_height_mm;
    cfg_.shape = shape;
    cfg_.limits.lift_ms = lift_ms;
    replan();
  }
  //! The preferred stride [mm] and the step rate at low speed [Hz].
  void set_step(S stride_mm, S min_hz) {
    cfg_.limits.preferred_stride_mm = stride_mm;
    cfg_.limits.min_hz = min_hz;
    // A cycle set while standing is the one the next walk starts at: the
    // rate there was the cycle's before (and a gait change's, which slows
    // it by the duties' ratio: mammal8's walk -> trot left 0.29 Hz).
    ramp_.rest_at(min_of(min_hz, cfg_.limits.servo_hz(S(0), phases_.duty)));
    replan();
  }
  //! Stance feet moved in steps of at least `step_mm` [mm], all at once
  //! (0: every tick), and on all feet: only while every foot is down, in a
  //! gait whose duty leaves four-foot windows (stance_ratchet.h).
  void set_stance_motion(S step_mm, bool on_all_feet) { ratchet_.set(step_mm, on_all_feet); }
  //! Keep stepping in place when the command is zero (default: stop).
  void set_step_in_place(bool on) { step_in_place_ = on; }
  //! Changes the gait, also while walking.
  void set_gait(const GaitTable& gait);
  void stand_up() { if (state_ == GaitState::kSitting) state_ = GaitState::kStandingUp; }
  void sit_down() {
    sit_requested_ = true;
    set_command(S(0), S(0), S(0));
  }
  //! Body pose offsets to move to (rate limited), also while walking.
  void set_body_offsets(const BodyOffsets<S>& o) {
    posture_.goal = o;
    posture_.at_goal = false;
  }

  void tick(S dt) {
    if (!(dt > S(0))) return;
    if (!posture_.at_goal) posture_.step_pose(cfg_, dt);
    switch (state_) {
      case GaitState::kSitting: break;
      case GaitState::kStandingUp:
      case GaitState::kSittingDown: {
        const bool up = state_ == GaitState::kStandingUp;
        if (posture_.step_progress(up, dt / cfg_.transition_s)) state_ = up ? GaitState::kStanding : GaitState::kSitting;
        break;
      }
      case GaitState::kStanding:
        if (sit_requested_) { sit_requested_ = false; state_ = GaitState::kSittingDown; break; }
        if (wants_to_walk()) start_walking();
        if (state_ == GaitState::kWalking) step_walk(dt);
        break;
      case GaitState::kWalking:
      case GaitState::kStopping: step_walk(dt); break;
    }
    margin_fresh_ = false;
  }

  GaitState state() const { return state_; }
  uint8_t leg_count() const { return cfg_.leg_count; }
  const Vec3<S>& foot(uint8_t i) const { return foot_[i]; }  //!< stance frame [mm]
  const Vec3<S>* feet() const { return foot_; }
  bool contact(uint8_t i) const { return contact_[i]; }
  const bool* contacts() const { return contact_; }
  //! The body in the stance frame: shift + offsets + sit/stand height.
  BodyPose<S> body_pose() const { return posture_.body_pose(shift_, cfg_); }
  //! body_pose()'s translation, and whether its rotation is zero.
  Vec3<S> body_translation() const { return posture_.translation(shift_, cfg_); }
  bool body_level() const { return posture_.level(); }
  S shift_x_mm() const { return shift_.x_mm(); }
  S shift_y_mm() const { return shift_.y_mm(); }
  //! Static stability margin of the CoM [mm], computed when asked.
  S margin_mm() const {
    if (!margin_fresh_) update_margin();
    return margin_;
  }
  //! The velocity being walked (vx, vy [mm/s], wz [rad/s]) and step rate [Hz].
  S vx() const { return ramp_.vx; }
  S vy() const { return ramp_.vy; }
  S wz() const { return ramp_.wz; }
  S step_hz() const { return ramp_.hz; }
  //! True when the last command was scaled down to the robot's limits.
  bool limited() const { return ramp_.plan.limited; }
  const VelocityPlan<S>& target_plan() const { return ramp_.plan; }
  //! Body odometry since configure(): x, y [mm], heading [rad], its cos and sin.
  S odometry_x() const { return odo_.x; }
  S odometry_y() const { return odo_.y; }
  S odometry_yaw() const { return odo_.yaw; }
  S odometry_cos() const { return odo_.c; }
  S odometry_sin() const { return odo_.s; }
  //! How far the body travels [mm] and turns [rad] if the command goes to zero now.
  S stopping_distance_mm() const {
    return hypot(ramp_.now.x, ramp_.now.y) * ramp_.stop_cycles(cfg_, phases_.duty) / S(2);
  }
  S stopping_angle_rad() const { return abs(ramp_.now.yaw) * ramp_.stop_cycles(cfg_, phases_.duty) / S(2); }
  Phase16 phase() const { return clock_.now(); }
  //! True when foot p of leg i is at the edge of its reach (reach_edge.h).
  STRIDER_ALWAYS_INLINE bool beyond_edge(uint8_t i, const Vec3<S>& p) const { return edge_.beyond(cfg_, i, p); }
  //! The share of a leg's longest stride beyond which a foot is at its edge.
  static constexpr double edge_share() { return ReachEdge<S, kLegs>::kEdgeShare; }
  //! The gait as walked: gait() relabelled for the direction of travel.
  GaitTable table() const { return phases_.table(); }
  const GaitTable& gait() const { return phases_.base; }
  //! The configuration (planar legs turning: homes drawn in, draw_homes_for_turn()).
  const GaitConfig<S, kLegs, kSearch>& config() const { return cfg_; }
  const SupportPolygon<S, kLegs>& support() const {
    if (support_dirty_) build_support();
    return support_;
  }

 private:
  void load_table(const GaitTable& t) {
    phases_.load(t, cfg_.leg_count);
    invalidate_touchdown();
  }
  S budget() const { return phases_.base.shift_body ? cfg_.shift_budget_mm : S(0); }
  void replan() { ramp_.replan(cfg_, phases_.duty, budget(), phases_.base.shift_body); }

  bool wants_to_walk() const { return !ramp_.command_zero() || step_in_place_; }
  bool at_rest() const { return ramp_.at_rest() && !step_in_place_; }
  bool near_home(uint8_t i) const {
    return abs(foot_[i].x - cfg_.home[i].x) <= cfg_.home_tolerance_mm &&
           abs(foot_[i].y - cfg_.home[i].y) <= cfg_.home_tolerance_mm;
  }
  //! A foot that need not step any more (stopping, already home).
  bool done(uint8_t i) const { return at_rest() && near_home(i); }
  bool at_edge(uint8_t i) const { return beyond_edge(i, foot_[i]); }
  //! Where foot i lands, x and y (z is home's), into place.
  STRIDER_ALWAYS_INLINE void touchdown_xy(uint8_t i, S& x, S& y) {
    td_.xy(cfg_.home[i], ramp_.land, phases_.duty, x, y);
  }
  //! The touch-down points changed: every swinging foot steers again.
  void invalidate_touchdown() {
    td_.fresh = false;
    swing_.unsettle();
  }

  STRIDER_NOINLINE void draw_homes_for_turn();
  void start_walking();
  void step_walk(S dt);
  bool stance_moves_now() const;
  STRIDER_NOINLINE bool step_ground(const BodyStep<S>& step, S dt);
  STRIDER_NOINLINE bool step_lift(const bool* edge);
  STRIDER_NOINLINE void lift_foot(uint8_t i, bool crossed);
  STRIDER_NOINLINE void step_swing(S dt);
  STRIDER_NOINLINE void settle_target(uint8_t i, S max_step);
  void step_shift(S dt);
  void update_margin() const;
  void build_support() const;

  GaitConfig<S, kLegs, kSearch> cfg_;
  TablePhases<S, kLegs> phases_;
  GaitState state_ = GaitState::kStanding;
  bool sit_requested_;
  bool step_in_place_;
  SpeedRamp<S> ramp_;

  PhaseClock clock_;
  Vec3<S> foot_[kLegs];
  bool contact_[kLegs];
  bool pending_[kLegs];
  SwingFeet<S, kLegs> swing_;
  int32_t stance_elapsed_[kLegs];  // phase since touch-down (may start negative)
  Touchdown<S> td_;
  ReachEdge<S, kLegs> edge_;

  mutable SupportPolygon<S, kLegs> support_;
  mutable bool support_dirty_ = true;
  mutable S margin_;
  mutable bool margin_fresh_;
  Odometry<S> odo_;
  BodyShift<S> shift_;
  bool held_;  // a foot at its edge held the body still this tick
  ShiftWindow<S, kLegs> window_;
  BodyPosture<S> posture_;
  S home_draw_mm_;  // planar legs turning: how far the homes are drawn in along x [mm]
  S steer_wz_ = S(0);  // the part of ramp_.cmd_wz that steers (set_command()) [rad/s]
  StanceRatchet<S> ratchet_;
};

}  // namespace strider

#include "gait_engine_walk.h"
#include "gait_engine_swing.h"
#include "gait_engine_balance.h"

#endif  // STRIDER_GAIT_GAIT_ENGINE_H
