//! GaitEngine: per tick, the foot targets of a legged robot walking a gait
//! table at a commanded velocity (time is a parameter: tick(dt)).
//!
//! Frames: feet are in the stance frame (kinematics/body_pose.h: the body
//! frame of the neutral standing pose); body_pose() says where the body is
//! in it (body shift, height, sit/stand, the user's pose offsets).
//!
//! Each tick: the command ramps toward its plan (velocity_limits.h) in
//! stride per cycle, so a stance's travel depends on the phase only; the body
//! moves along the arc of v dt and w dt, and feet on the ground move by the
//! inverse (stance.h): they stay put on the ground and reproduce the command
//! exactly. A foot lifts when the phase clock passes its offset (gait
//! table), if enough feet stay down; a foot in the air follows the swing
//! shape from where it lifted to its touch-down point (home moved forward by
//! half its coming stance's travel; the point moves at most
//! target_speed_mm_s) and lands when its swing time is over. Walking starts
//! from standing and stops back to it: with the command at zero a foot away
//! from home takes one more step and a foot at home stays down, until every
//! foot is home and the body shift is back to zero. Gait changes keep feet
//! in the air on their old swing, so no foot jumps. Body shift for walk and
//! crawl: body_shift.h. Set-up and ramps: gait_engine_ramp.h; the walking
//! tick: gait_engine_step.h.
#ifndef STRIDER_GAIT_GAIT_ENGINE_H
#define STRIDER_GAIT_GAIT_ENGINE_H

#include "../kinematics/body_pose.h"
#include "../kinematics/leg_ik_common.h"
#include "body_offsets.h"
#include "body_shift.h"
#include "gait_config.h"
#include "gait_state.h"
#include "gait_table.h"
#include "phase.h"
#include "stance.h"
#include "swing_trajectory.h"

namespace strider {

template <typename S>
class GaitEngine {
 public:
  //! The robot stands with no configuration (configure() before use).
  GaitEngine()
      : base_(), offset_(), swing_len_(0), start_phase_(0), relabel_(false), quarter_(0), sit_requested_(false),
        step_in_place_(false), cmd_vx_(), cmd_vy_(), cmd_wz_(), to_(), from_s_(), to_s_(), now_s_(), land_s_(),
        vx_(), vy_(), wz_(), foot_(), contact_(), pending_(), lift_(), target_(), apex_(), leg_inv_swing_(),
        leg_swing_len_(), leg_shape_(), swing_elapsed_(), stance_elapsed_(), edge_r2_(), settled_(), vel_fresh_(false),
        land_fresh_(false), odo_dx_(), odo_dy_(), odo_wx_(), odo_wy_(), held_(false), in_window_(false),
        window_start_(0), window_inv_(), pose_(), goal_pose_(), margin_(), margin_fresh_(false), step_cache_(),
        td_fresh_(false), td_sin_(), td_dx_(), td_dy_(), odo_x_(), odo_y_(), odo_yaw_(), odo_s_() {}

  //! Takes the configuration and a gait; the robot stands (or sits).
  void configure(const GaitConfig<S>& config, const GaitTable& gait, bool sitting = false);
  //! The same with the configuration built in place (fill_gait_config()).
  void configure(const RobotModel& model, const AnyLeg<S>* legs, const GaitParams& params, SwingShape shape,
                 const GaitTable& gait, bool sitting = false) {
    fill_gait_config(cfg_, model, legs, params, shape);
    configure(cfg_, gait, sitting);
  }
  //! The same from a configuration in flash (stored_gait_config(): a
  //! firmware's constant), copied into place and, without its ramps
  //! (float: stored_ramps_given()), finished there (finish_gait_config()):
  //! no copy on the stack.
  void configure_stored(const GaitConfig<S>* flash_config, const GaitTable& gait, bool sitting = false) {
    flash_copy(&cfg_, flash_config, sizeof cfg_);
    finish_stored(cfg_);
    configure(cfg_, gait, sitting);
  }

  // ---- commands --------------------------------------------------------------

  //! Velocity (vx, vy [mm/s], wz [rad/s], body frame) at speed_pct [0, 100]
  //! percent. Clamped to the robot's limits (limited() tells). A non-zero
  //! command starts walking from standing; zero stops at the end of a step.
  void set_command(S vx, S vy, S wz, S speed_pct = scalar<S>(100.0)) {
    constexpr S hundred = scalar<S>(100.0);
    const S k = clamp(speed_pct, S(0), hundred) / hundred;  // exact at 100 %
    cmd_vx_ = vx * k;
    cmd_vy_ = vy * k;
    cmd_wz_ = wz * k;
    replan();
  }
  //! Live gait parameters (gait_tuning.h): the swing of the feet that lift
  //! from now on, its apex [mm] and shape; feet in the air finish theirs.
  void set_swing(S step_height_mm, SwingShape shape) {
    cfg_.step_height_mm = step_height_mm;
    cfg_.shape = shape;
  }
  //! The preferred stride [mm] and the step rate at low speed [Hz]: the
  //! command is planned again and reached along the ramp.
  void set_step(S stride_mm, S min_hz) {
    cfg_.limits.preferred_stride_mm = stride_mm;
    cfg_.limits.min_hz = min_hz;
    replan();
  }
  //! Keep stepping in place when the command is zero (default: stop).
  void set_step_in_place(bool on) { step_in_place_ = on; }
  //! Changes the gait, also while walking (feet in the air finish their swing).
  void set_gait(const GaitTable& gait);
  void stand_up() { if (state_ == GaitState::kSitting) state_ = GaitState::kStandingUp; }
  //! Sits down from standing; while walking, stops first.
  void sit_down() {
    sit_requested_ = true;
    set_command(S(0), S(0), S(0));
  }
  //! Body pose offsets to move to (rate limited), also while walking.
  void set_body_offsets(const BodyOffsets<S>& o) {
    goal_pose_ = o;
    pose_at_goal_ = false;  // step_pose() compares
  }

  // ---- per tick --------------------------------------------------------------

  void tick(S dt) {
    if (!(dt > S(0))) return;
    if (!pose_at_goal_) step_pose(dt);  // at its goal (the usual case): no call
    switch (state_) {
      case GaitState::kSitting: break;
      case GaitState::kStandingUp:
      case GaitState::kSittingDown: step_transition(dt); break;
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

  // ---- outputs ---------------------------------------------------------------

  GaitState state() const { return state_; }
  uint8_t leg_count() const { return cfg_.leg_count; }
  const Vec3<S>& foot(uint8_t i) const { return foot_[i]; }  //!< stance frame [mm]
  const Vec3<S>* feet() const { return foot_; }
  bool contact(uint8_t i) const { return contact_[i]; }
  const bool* contacts() const { return contact_; }
  //! The body in the stance frame: shift + offsets + sit/stand height.
  BodyPose<S> body_pose() const {
    // Standing (progress 1): no drop, and no products for it.
    const S drop = progress_ >= S(1) ? S(0) : cfg_.sit_drop_mm * (S(1) - BodyShift<S>::smoothstep(progress_));
    return BodyPose<S>::make(Vec3<S>(shift_.x_mm() + pose_.translation_mm.x, shift_.y_mm() + pose_.translation_mm.y,
                                     pose_.translation_mm.z - drop),
                             pose_.roll_rad, pose_.pitch_rad, pose_.yaw_rad);
  }
  //! body_pose()'s translation, and whether its roll, pitch and yaw are all
  //! zero (integer tests of float bits): a walker with a level body needs
  //! no more of the pose.
  Vec3<S> body_translation() const {
    const S drop = progress_ >= S(1) ? S(0) : cfg_.sit_drop_mm * (S(1) - BodyShift<S>::smoothstep(progress_));
    return Vec3<S>(add_inline(shift_.x_mm(), pose_.translation_mm.x), add_inline(shift_.y_mm(), pose_.translation_mm.y),
                   sub_inline(pose_.translation_mm.z, drop));
  }
  bool body_level() const {
    return leg_ik::is_zero(pose_.roll_rad) && leg_ik::is_zero(pose_.pitch_rad) && leg_ik::is_zero(pose_.yaw_rad);
  }
  S shift_x_mm() const { return shift_.x_mm(); }
  S shift_y_mm() const { return shift_.y_mm(); }
  //! Static stability margin of the CoM [mm] (stability.h), this tick;
  //! computed when asked (once per tick), so a firmware that does not ask
  //! does not pay for it.
  S margin_mm() const {
    if (!margin_fresh_) update_margin();
    return margin_;
  }
  //! The velocity being walked (vx, vy [mm/s], wz [rad/s]) and step rate [Hz].
  S vx() const { return vx_; }
  S vy() const { return vy_; }
  S wz() const { return wz_; }
  S step_hz() const { return hz_; }
  //! True when the last command was scaled down to the robot's limits.
  bool limited() const { return to_.limited; }
  //! True when the body stood still this tick because a foot on the ground
  //! was at the edge of its reach and could not lift (after abrupt changes).
  bool held() const { return held_; }
  const VelocityPlan<S>& target_plan() const { return to_; }
  //! Body odometry since configure(): position [mm] and heading [rad].
  S odometry_x() const { return odo_x_; }
  S odometry_y() const { return odo_y_; }
  S odometry_yaw() const { return odo_yaw_; }
  //! cos and sin of the odometry heading (kept without trig).
  S odometry_cos() const { return odo_c_; }
  S odometry_sin() const { return odo_s_; }
  //! How far the body travels [mm] and turns [rad] if the command is set to
  //! zero now (the ramp down, see replan()).
  S stopping_distance_mm() const { return hypot(now_s_.x, now_s_.y) * stop_cycles() / S(2); }
  S stopping_angle_rad() const { return abs(now_s_.yaw) * stop_cycles() / S(2); }
  Phase16 phase() const { return clock_.now(); }
  //! True when foot p of leg i is beyond kEdgeShare of the longest stride
  //! it may make in its direction from home (velocity limits; the IK limit
  //! is at 0.5 / kStrideShare = 0.556): a foot on the ground there lifts
  //! early, or, without the support to lift, holds the body still. Never
  //! while the command is steady (the plan keeps strides within the limits).
  STRIDER_ALWAYS_INLINE bool beyond_edge(uint8_t i, const Vec3<S>& p) const {
    const S dx = sub_inline(p.x, cfg_.home[i].x), dy = sub_inline(p.y, cfg_.home[i].y);
    const S r = cfg_.edge_mm[i];
    // inside the shortest stride's diamond: no product (sums in place, scalar.h)
    if (add_inline(abs_inline(dx), abs_inline(dy)) <= r) return false;
    return beyond_diamond(i, dx, dy);
  }
  //! The share of a leg's longest stride beyond which a foot is at its edge.
  static constexpr double edge_share() { return kEdgeShare; }
  //! The gait as walked: gait() relabelled for the direction of travel
  //! (rebuilt on each call: the engine keeps the offsets only as phases).
  GaitTable table() const { return relabel_ ? gait_table::relabeled(base_, quarter_) : base_; }
  //! The gait as given to configure() or set_gait() (table() may be relabelled).
  const GaitTable& gait() const { return base_; }
  const GaitConfig<S>& config() const { return cfg_; }
  const SupportPolygon<S>& support() const {
    if (support_dirty_) build_support();
    return support_;
  }

 private:
  // A stored configuration with its ramps (Fixed) needs no finishing.
  static void finish_stored(GaitConfig<float>& c) { finish_gait_config(c); }
  static void finish_stored(GaitConfig<Fixed>&) {}

  void load_table(const GaitTable& t);
  void set_fractions(const GaitTable& t, float);
  void set_fractions(const GaitTable& t, Fixed);
  static Phase16 table_phase(float offset, float);
  static Phase16 table_phase(float offset, Fixed);

  S budget() const { return base_.shift_body ? cfg_.shift_budget_mm : S(0); }

  //! A command as a stride per cycle (so that a foot's travel over a stance
  //! depends on the phase only, not on how the step rate changes meanwhile)
  //! and the step rate.
  struct Stride {
    S x, y;  //!< body travel per cycle [mm]
    S yaw;   //!< body turn per cycle [rad]
    S hz;    //!< step rate [Hz]
  };

  //! Plans the command and starts the ramp to it (gait_engine_ramp.h).
  void replan();

  //! Cycles a stop from now takes (replan() with a zero command).
  S stop_cycles() const {
    const S rest_hz = min_of(cfg_.limits.min_hz, cfg_.limits.servo_hz(S(0), duty_));
    const S t = max_of(max_of(abs(vx_), abs(vy_)) / cfg_.accel_mm_s2, abs(wz_) / cfg_.yaw_accel_rad_s2);
    return max_of(t * max_of(rest_hz, hz_), S(1));
  }

  bool command_zero() const {
    return to_.vx_mm_s == S(0) && to_.vy_mm_s == S(0) && to_.wz_rad_s == S(0);
  }
  bool wants_to_walk() const { return !command_zero() || step_in_place_; }
  bool at_rest() const { return ramp_ >= S(1) && vx_ == S(0) && vy_ == S(0) && wz_ == S(0) && !step_in_place_; }

  void start_walking();

  //! Stand-up / sit-down progress, and the body offsets' rate limit.
  void step_transition(S dt);
  void step_pose(S dt);

  //! Moves the ramp on by this tick's phase; the velocity is stride x rate.
  void step_command(S dt);

  //! out = from_s_ + (to_s_ - from_s_) t, field by field into place (a
  //! returned Stride is copied with a byte loop by avr-gcc, twice per ramp
  //! tick).
  STRIDER_NOINLINE void ramp_stride(Stride& out, S t) const;
  //! a + (b - a) t; a itself when b has a's bits (a ramp's unchanged parts:
  //! the yaw of a straight walk, a rate kept), the formula's value then.
  //! Sums in place (scalar.h's add_inline: the same bits as the operators).
  STRIDER_ALWAYS_INLINE static S mix(S a, S b, S t) { return leg_ik::same_bits(a, b) ? a : add_inline(a, sub_inline(b, a) * t); }

  bool near_home(uint8_t i) const {
    return abs(foot_[i].x - cfg_.home[i].x) <= cfg_.home_tolerance_mm &&
           abs(foot_[i].y - cfg_.home[i].y) <= cfg_.home_tolerance_mm;
  }
  //! A foot that need not step any more (stopping, already home).
  bool done(uint8_t i) const { return at_rest() && near_home(i); }

  bool may_lift(uint8_t i) const {
    if (done(i)) return false;
    uint8_t down = 0;
    for (uint8_t k = 0; k < cfg_.leg_count; ++k)
      if (contact_[k]) ++down;
    return down > cfg_.min_support;
  }

  //! beyond_edge() for a foot (dx, dy) [mm] from home outside the shortest
  //! stride's diamond: apart, so that the usual answer (inside it) costs no
  //! call.
  STRIDER_NOINLINE bool beyond_diamond(uint8_t i, S dx, S dy) const {
    // Inside the shortest stride's circle (a little smaller, for rounding):
    // two products instead of the atan2, the square root and the lookup.
    const S ux = units::to_unit(dx, cfg_.unit_shift), uy = units::to_unit(dy, cfg_.unit_shift);
    if (ux * ux + uy * uy <= edge_r2_[i]) return false;
    const S stride = cfg_.limits.leg_stride(i, dx, dy);
    const S d = units::norm_in(dx, dy, S(0), cfg_.unit_shift);
    constexpr S share = scalar<S>(kEdgeShare);
    return d > stride * share;
  }
  bool at_edge(uint8_t i) const { return beyond_edge(i, foot_[i]); }
  //! Where foot i lands, x and y (z is home's; stance.h's touchdown_point
  //! with cached terms): into place, no point returned and copied.
  //! Inline in its two callers (a ramp's every tick steers each foot in the
  //! air): the straight case is two sums, the rest out of line.
  STRIDER_ALWAYS_INLINE void touchdown_xy(uint8_t i, S& x, S& y);
  //! touchdown_xy()'s offset and rotation of the landing stride (out of
  //! line: the straight path's registers and member addresses stay few).
  STRIDER_NOINLINE void refresh_touchdown();
  //! touchdown_xy() of a turning landing stride (rotation and offset).
  STRIDER_NOINLINE void touchdown_turned(uint8_t i, S& x, S& y) const;
  //! The mean stride per cycle over the next stance along the ramp.
  void update_landing();

  void step_walk(S dt);
  //! step_walk()'s feet in the air, apart so that its locals do not widen
  //! step_walk()'s stack frame (on the AVR, offsets past 63 bytes cost extra).
  STRIDER_NOINLINE void step_swing(S dt);
  //! step_swing()'s move of foot i's touch-down point toward touchdown_xy(i) by at
  //! most max_step (out of line: its point stays out of the loop's frame).
  STRIDER_NOINLINE void settle_target(uint8_t i, S max_step);
  //! step_walk()'s test of a foot at its edge: would `step` take it farther
  //! from home? (Out of line: its point stays out of step_walk()'s frame.)
  STRIDER_NOINLINE bool step_takes_out(uint8_t i, const BodyStep<S>& step) const;
  //! step_walk()'s clock, touch-downs and feet on the ground (moved by
  //! `step`), apart for the same reason; true when a foot landed.
  STRIDER_NOINLINE bool step_ground(const BodyStep<S>& step, S dt);
  //! step_walk()'s lift-offs (edge: the feet at the edge of their reach
  //! before the step), apart for the same reason; true when a foot lifted.
  STRIDER_NOINLINE bool step_lift(const bool* edge);
  //! step_lift()'s lift-off of foot i (out of line: the loop over the legs
  //! keeps its registers; the touch-down point is written in place).
  STRIDER_NOINLINE void lift_foot(uint8_t i, bool crossed);
  void step_shift(S dt);
  void update_margin() const;
  //! The support polygon of the feet down now (stability.h), built when
  //! first needed after a lift-off or touch-down: gaits that do not shift
  //! the body need it only for margin_mm().
  void build_support() const {
    support_.build(foot_, contact_, cfg_.leg_count, cfg_.foot_radius_mm, cfg_.unit_shift);
    support_dirty_ = false;
  }
  //! The touch-down points changed: every swinging foot steers again.
  void invalidate_touchdown() {
    td_fresh_ = false;
    for (uint8_t i = 0; i < kWalkerLegs; ++i) settled_[i] = false;
  }

  static constexpr uint8_t kNoGroup = 0xFF;
  static constexpr double kEdgeShare = 0.53;

  // Members without a default here are set by the constructor (zero).
  GaitConfig<S> cfg_;
  GaitTable base_;   // as given; as walked: table()
  Phase16 offset_[kWalkerLegs];
  uint32_t swing_len_;
  S duty_ = scalar<S>(0.5), inv_swing_ = S(2), inv_stance_ = S(2);
  Phase16 start_phase_;
  bool relabel_;
  int8_t quarter_;

  GaitState state_ = GaitState::kStanding;
  S progress_ = S(1);  // 0 sitting .. 1 standing
  bool sit_requested_;
  bool step_in_place_;

  S cmd_vx_, cmd_vy_, cmd_wz_;
  VelocityPlan<S> to_;
  Stride from_s_, to_s_, now_s_, land_s_;
  S ramp_ = S(1), ramp_per_cycle_ = S(1), ramp_cycles_ = S(1);  // ramp_cycles_ = 1 / ramp_per_cycle_
  S vx_, vy_, wz_, hz_ = S(1);

  PhaseClock clock_;
  Vec3<S> foot_[kWalkerLegs];
  bool contact_[kWalkerLegs];
  bool pending_[kWalkerLegs];
  Vec3<S> lift_[kWalkerLegs];
  Vec3<S> target_[kWalkerLegs];
  S apex_[kWalkerLegs];
  S leg_inv_swing_[kWalkerLegs];
  uint32_t leg_swing_len_[kWalkerLegs];
  SwingShape leg_shape_[kWalkerLegs];  // the shape each foot lifted with
  uint32_t swing_elapsed_[kWalkerLegs];
  int32_t stance_elapsed_[kWalkerLegs];  // phase since touch-down (may start negative)

  mutable SupportPolygon<S> support_;
  mutable bool support_dirty_ = true;
  SupportPolygon<S> next_support_;
  // beyond_edge(): squared radius [unit^2] inside which no foot is at its edge
  S edge_r2_[kWalkerLegs];
  bool settled_[kWalkerLegs];  // swinging foot's touch-down point already at touchdown_xy(i)
  bool vel_fresh_;       // vx_, vy_, wz_ are now_s_ x hz_
  bool land_fresh_;      // the ramp is over and land_s_ is now_s_ (update_landing() has nothing to do)
  // Odometry step in the world frame, kept while the body does not turn.
  S odo_dx_, odo_dy_, odo_wx_, odo_wy_;
  BodyShift<S> shift_;
  bool held_;
  bool in_window_;                   // every foot down, shifting for the next swing
  uint8_t window_group_ = kNoGroup;  // leg that leads the next swing group
  Phase16 window_start_;
  S window_inv_;

  BodyOffsets<S> pose_, goal_pose_;
  bool pose_at_goal_ = true;  // pose_ == goal_pose_ known: step_pose() has nothing to do
  mutable S margin_;
  mutable bool margin_fresh_;
  // Per-tick work that only changes with the command: the body step and the
  // rotation and offset of every touch-down point.
  struct StepCache {
    S dt;  // the tick the step is for; 0 (no tick has it): vx_, vy_ or wz_ changed since
    BodyStep<S> step;
  } step_cache_;
  bool td_fresh_;
  S td_cos_ = S(1), td_sin_, td_dx_, td_dy_;
  S odo_x_, odo_y_, odo_yaw_, odo_c_ = S(1), odo_s_;
};

}  // namespace strider

#include "gait_engine_ramp.h"
#include "gait_engine_step.h"

#endif  // STRIDER_GAIT_GAIT_ENGINE_H
