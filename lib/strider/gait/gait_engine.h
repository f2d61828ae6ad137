//! GaitEngine: per tick, the foot targets of a legged robot walking a gait
//! table at a commanded velocity (time is a parameter: tick(dt)).
//!
//! Frames: feet are in the stance frame (kinematics/body_pose.h: the body
//! frame of the neutral standing pose); body_pose() says where the body is
//! in it (body shift, height, sit/stand, the user's pose offsets).
//!
//! Each tick: the command ramps toward its target (acceleration limited); the
//! body moves by v dt and turns by w dt; feet on the ground move by the
//! inverse (stance.h), so they stay put on the ground and reproduce the
//! command exactly; a foot lifts when the phase clock passes its offset
//! (gait_table.h), if enough feet stay down; a foot in the air follows the
//! swing shape from where it lifted to its touch-down point, home moved
//! forward by half a stance's travel (stance.h), which moves at most
//! max_target_step per tick; it lands when its swing time is over. Walking
//! starts from standing (all feet home) and stops back to it: with the
//! command at zero, a foot away from home takes one more step and a foot at
//! home stays down, until every foot is home and the body shift is back to
//! zero. Gait changes keep feet in the air on their old swing until they
//! land, so no foot jumps. Body shift for walk and crawl: body_shift.h.
#ifndef STRIDER_GAIT_GAIT_ENGINE_H
#define STRIDER_GAIT_GAIT_ENGINE_H

#include "../kinematics/body_pose.h"
#include "body_shift.h"
#include "gait_config.h"
#include "gait_table.h"
#include "phase.h"
#include "stance.h"
#include "swing_trajectory.h"

namespace strider {

enum class GaitState : uint8_t {
  kSitting = 0,     //!< body lowered, all feet down
  kStandingUp = 1,  //!< rising to the standing height
  kStanding = 2,    //!< all feet home, not stepping
  kWalking = 3,     //!< stepping
  kStopping = 4,    //!< command at zero, finishing the last steps
  kSittingDown = 5  //!< lowering the body
};

inline const char* to_string(GaitState s) {
  switch (s) {
    case GaitState::kSitting: return "sitting";
    case GaitState::kStandingUp: return "standing_up";
    case GaitState::kStanding: return "standing";
    case GaitState::kWalking: return "walking";
    case GaitState::kStopping: return "stopping";
    case GaitState::kSittingDown: return "sitting_down";
  }
  return "standing";
}

//! The user's body pose offsets (applied while standing and walking).
template <typename S>
struct BodyOffsets {
  Vec3<S> translation_mm;  //!< body shift x, y and height change z [mm]
  S roll_rad, pitch_rad, yaw_rad;
  static BodyOffsets zero() { return BodyOffsets{Vec3<S>(), S(0), S(0), S(0)}; }
};

template <typename S>
class GaitEngine {
 public:
  //! Takes the configuration and a gait; the robot stands (or sits).
  void configure(const GaitConfig<S>& config, const GaitTable& gait, bool sitting = false) {
    cfg_ = config;
    base_ = gait;
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
    period_ = S(1) / hz_;
    from_ = to_ = VelocityPlan<S>{S(0), S(0), S(0), hz_, false};
    ramp_ = S(1);
    shift_.reset();
    pose_ = goal_pose_ = BodyOffsets<S>::zero();
    odo_x_ = odo_y_ = odo_yaw_ = S(0);
    odo_c_ = S(1);
    odo_s_ = S(0);
    support_.build(foot_, contact_, cfg_.leg_count, cfg_.foot_radius_mm, cfg_.unit_shift);
    update_margin();
  }

  // ---- commands --------------------------------------------------------------

  //! Velocity (vx, vy [mm/s], wz [rad/s], body frame) at speed_pct [0, 100]
  //! percent. Clamped to the robot's limits (limited() tells). A non-zero
  //! command starts walking from standing; zero stops at the end of a step.
  void set_command(S vx, S vy, S wz, S speed_pct = scalar<S>(100.0)) {
    const S k = clamp(speed_pct, S(0), scalar<S>(100.0)) * scalar<S>(0.01);
    cmd_vx_ = vx * k;
    cmd_vy_ = vy * k;
    cmd_wz_ = wz * k;
    replan();
  }
  //! Keep stepping in place when the command is zero (default: stop).
  void set_step_in_place(bool on) { step_in_place_ = on; }
  //! Changes the gait, also while walking (feet in the air finish their swing).
  void set_gait(const GaitTable& gait) {
    base_ = gait;
    load_table(relabel_ ? gait_table::relabeled(gait, quarter_) : gait);
    replan();
  }
  void stand_up() { if (state_ == GaitState::kSitting) state_ = GaitState::kStandingUp; }
  //! Sits down from standing; while walking, stops first.
  void sit_down() {
    sit_requested_ = true;
    set_command(S(0), S(0), S(0));
  }
  //! Body pose offsets to move to (rate limited), also while walking.
  void set_body_offsets(const BodyOffsets<S>& o) { goal_pose_ = o; }

  // ---- per tick --------------------------------------------------------------

  void tick(S dt) {
    if (!(dt > S(0))) return;
    step_pose(dt);
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
    update_margin();
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
    const S drop = cfg_.sit_drop_mm * (S(1) - BodyShift<S>::smoothstep(progress_));
    return BodyPose<S>::make(Vec3<S>(shift_.x_mm() + pose_.translation_mm.x, shift_.y_mm() + pose_.translation_mm.y,
                                     pose_.translation_mm.z - drop),
                             pose_.roll_rad, pose_.pitch_rad, pose_.yaw_rad);
  }
  S shift_x_mm() const { return shift_.x_mm(); }
  S shift_y_mm() const { return shift_.y_mm(); }
  //! Static stability margin of the CoM [mm] (stability.h), this tick.
  S margin_mm() const { return margin_; }
  //! The velocity being walked (vx, vy [mm/s], wz [rad/s]) and step rate [Hz].
  S vx() const { return vx_; }
  S vy() const { return vy_; }
  S wz() const { return wz_; }
  S step_hz() const { return hz_; }
  //! True when the last command was scaled down to the robot's limits.
  bool limited() const { return to_.limited; }
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
  S stopping_distance_mm() const { return hypot(vx_, vy_) * stop_time() * scalar<S>(0.5); }
  S stopping_angle_rad() const { return abs(wz_) * stop_time() * scalar<S>(0.5); }
  Phase16 phase() const { return clock_.now(); }
  const GaitTable& table() const { return table_; }
  const GaitConfig<S>& config() const { return cfg_; }
  const SupportPolygon<S>& support() const { return support_; }

 private:
  void load_table(const GaitTable& t) {
    table_ = t;
    swing_len_ = phase_span(1.0 - double(t.duty));
    duty_ = scalar<S>(double(t.duty));
    inv_swing_ = scalar<S>(1.0 / (1.0 - double(t.duty)));
    inv_stance_ = scalar<S>(1.0 / double(t.duty));
    uint32_t latest_end = 0;
    for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
      offset_[i] = phase16(double(t.offset[i]));
      const uint32_t end = uint32_t(offset_[i]) + swing_len_;
      if (end <= kPhaseOne && end > latest_end) latest_end = end;
    }
    // Start just before the first lift-off, or at the four-foot window
    // before it when the body must shift first.
    start_phase_ = t.shift_body && latest_end > 0 && latest_end < kPhaseOne ? Phase16(latest_end) : Phase16(0xFFFF);
  }

  S budget() const { return table_.shift_body ? cfg_.shift_budget_mm : S(0); }

  void replan() {
    from_ = VelocityPlan<S>{vx_, vy_, wz_, hz_, false};
    to_ = cfg_.limits.plan(cfg_.home, cmd_vx_, cmd_vy_, cmd_wz_, duty_, budget(), table_.shift_body);
    const S dv = max_of(abs(to_.vx_mm_s - vx_), abs(to_.vy_mm_s - vy_));
    const S dw = abs(to_.wz_rad_s - wz_);
    S time = max_of(dv / cfg_.accel_mm_s2, dw / cfg_.yaw_accel_rad_s2);
    // At least one cycle at the slower step rate: a foot's first stance after
    // a start (or a change) then stays within its stride.
    if (dv > S(0) || dw > S(0)) time = max_of(time, S(1) / min_of(hz_, to_.step_hz));
    ramp_rate_ = time > scalar<S>(0.001) ? S(1) / time : scalar<S>(1000.0);
    ramp_ = S(0);
    // A faster step rate starts at once (feet keep their place, only their
    // speed changes): stances get shorter, never longer than planned. A
    // slower one waits for the end of the ramp, when the velocity matches it.
    if (to_.step_hz > hz_ || ramp_rate_ >= scalar<S>(1000.0)) set_rate(to_.step_hz);
  }

  S stop_time() const {
    const S rest_hz = min_of(cfg_.limits.min_hz, cfg_.limits.servo_hz(S(0), duty_));
    const S t = max_of(max_of(abs(vx_), abs(vy_)) / cfg_.accel_mm_s2, abs(wz_) / cfg_.yaw_accel_rad_s2);
    return max_of(t, S(1) / min_of(hz_, rest_hz));
  }

  bool command_zero() const {
    return to_.vx_mm_s == S(0) && to_.vy_mm_s == S(0) && to_.wz_rad_s == S(0);
  }
  bool wants_to_walk() const { return !command_zero() || step_in_place_; }
  bool at_rest() const { return ramp_ >= S(1) && vx_ == S(0) && vy_ == S(0) && wz_ == S(0) && !step_in_place_; }

  void start_walking() {
    relabel_ = base_.relabel_by_direction && (to_.vx_mm_s != S(0) || to_.vy_mm_s != S(0));
    quarter_ = 0;
    if (relabel_) {
      // The quadrant of the direction of travel (seed 000 section 3.3).
      const S ax = abs(to_.vx_mm_s), ay = abs(to_.vy_mm_s);
      quarter_ = ax >= ay ? (to_.vx_mm_s >= S(0) ? 0 : 2) : (to_.vy_mm_s > S(0) ? 1 : 3);
      load_table(gait_table::relabeled(base_, quarter_));
    } else {
      load_table(base_);
    }
    clock_.reset(start_phase_);
    for (uint8_t i = 0; i < cfg_.leg_count; ++i) {
      pending_[i] = false;
      stance_elapsed_[i] = 0;
    }
    in_window_ = false;
    window_group_ = kNoGroup;
    state_ = GaitState::kWalking;
  }

  void step_transition(S dt) {
    const S d = dt / cfg_.transition_s;
    if (state_ == GaitState::kStandingUp) {
      progress_ = min_of(progress_ + d, S(1));
      if (progress_ >= S(1)) state_ = GaitState::kStanding;
    } else {
      progress_ = max_of(progress_ - d, S(0));
      if (progress_ <= S(0)) state_ = GaitState::kSitting;
    }
  }

  void step_pose(S dt) {
    const S dp = cfg_.pose_speed_mm_s * dt, da = cfg_.pose_rate_rad_s * dt;
    pose_.translation_mm.x += clamp(goal_pose_.translation_mm.x - pose_.translation_mm.x, -dp, dp);
    pose_.translation_mm.y += clamp(goal_pose_.translation_mm.y - pose_.translation_mm.y, -dp, dp);
    pose_.translation_mm.z += clamp(goal_pose_.translation_mm.z - pose_.translation_mm.z, -dp, dp);
    pose_.roll_rad += clamp(goal_pose_.roll_rad - pose_.roll_rad, -da, da);
    pose_.pitch_rad += clamp(goal_pose_.pitch_rad - pose_.pitch_rad, -da, da);
    pose_.yaw_rad += clamp(goal_pose_.yaw_rad - pose_.yaw_rad, -da, da);
  }

  void step_command(S dt) {
    if (ramp_ >= S(1)) return;
    ramp_ = min_of(ramp_ + dt * ramp_rate_, S(1));
    vx_ = from_.vx_mm_s + (to_.vx_mm_s - from_.vx_mm_s) * ramp_;
    vy_ = from_.vy_mm_s + (to_.vy_mm_s - from_.vy_mm_s) * ramp_;
    wz_ = from_.wz_rad_s + (to_.wz_rad_s - from_.wz_rad_s) * ramp_;
    if (ramp_ >= S(1)) set_rate(to_.step_hz);
  }

  void set_rate(S hz) {
    if (hz == hz_) return;
    hz_ = hz;
    period_ = S(1) / hz_;
  }

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

  Vec3<S> touchdown(uint8_t i) const {
    return touchdown_point(cfg_.home[i], land_vx_, land_vy_, land_wz_, duty_ * period_);
  }

  //! The mean velocity of the next stance (duty / f seconds) along the
  //! command ramp: a foot landing now is placed for it, so that its stance
  //! stays centred on home while the command ramps (stance.h).
  void update_landing_velocity() {
    land_vx_ = vx_;
    land_vy_ = vy_;
    land_wz_ = wz_;
    if (ramp_ >= S(1)) return;
    const S stance = duty_ * period_;
    const S left = S(1) - ramp_;             // ramp still to go
    const S finish = left / ramp_rate_;      // its time [s]
    // lag = (integral over the stance of (1 - ramp)) / stance
    const S lag = finish >= stance ? left - ramp_rate_ * stance * scalar<S>(0.5)
                                   : left * finish * scalar<S>(0.5) / stance;
    const S ahead = left - lag;  // how much further than now the mean is along the ramp
    land_vx_ += (to_.vx_mm_s - from_.vx_mm_s) * ahead;
    land_vy_ += (to_.vy_mm_s - from_.vy_mm_s) * ahead;
    land_wz_ += (to_.wz_rad_s - from_.wz_rad_s) * ahead;
  }

  void step_walk(S dt);
  void step_shift(S dt);
  void update_margin();

  static constexpr uint8_t kNoGroup = 0xFF;

  GaitConfig<S> cfg_;
  GaitTable base_{};   // as given
  GaitTable table_{};  // as walked (relabelled)
  Phase16 offset_[kMaxLegs] = {};
  uint32_t swing_len_ = 0;
  S duty_ = scalar<S>(0.5), inv_swing_ = S(2), inv_stance_ = S(2);
  Phase16 start_phase_ = 0;
  bool relabel_ = false;
  int8_t quarter_ = 0;

  GaitState state_ = GaitState::kStanding;
  S progress_ = S(1);  // 0 sitting .. 1 standing
  bool sit_requested_ = false;
  bool step_in_place_ = false;

  S cmd_vx_ = S(0), cmd_vy_ = S(0), cmd_wz_ = S(0);
  VelocityPlan<S> from_{}, to_{};
  S ramp_ = S(1), ramp_rate_ = S(1);
  S vx_ = S(0), vy_ = S(0), wz_ = S(0), hz_ = S(1), period_ = S(1);
  S land_vx_ = S(0), land_vy_ = S(0), land_wz_ = S(0);  // mean velocity of the next stance

  PhaseClock clock_;
  Vec3<S> foot_[kMaxLegs];
  bool contact_[kMaxLegs] = {};
  bool pending_[kMaxLegs] = {};
  Vec3<S> lift_[kMaxLegs];
  Vec3<S> target_[kMaxLegs];
  S apex_[kMaxLegs];
  S leg_inv_swing_[kMaxLegs];
  uint32_t leg_swing_len_[kMaxLegs] = {};
  uint32_t swing_elapsed_[kMaxLegs] = {};
  uint32_t stance_elapsed_[kMaxLegs] = {};

  SupportPolygon<S> support_;
  SupportPolygon<S> next_support_;
  BodyShift<S> shift_;
  bool in_window_ = false;           // every foot down, shifting for the next swing
  uint8_t window_group_ = kNoGroup;  // leg that leads the next swing group
  Phase16 window_start_ = 0;
  S window_inv_ = S(0);

  BodyOffsets<S> pose_{}, goal_pose_{};
  S margin_ = S(0);
  S odo_x_ = S(0), odo_y_ = S(0), odo_yaw_ = S(0), odo_c_ = S(1), odo_s_ = S(0);
};

}  // namespace strider

#include "gait_engine_step.h"

#endif  // STRIDER_GAIT_GAIT_ENGINE_H
