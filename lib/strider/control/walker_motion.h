//! WalkerMotion: the controller's motion commands in protocol units
//! ([0.1 mm/s], [0.1 deg/s], [0.1 deg], [0.1 mm]) applied to a Walker; a pose
//! or height a standing leg cannot reach is refused and changes nothing.
//! Power-up and relax leave the robot sitting; stand_up() raises it.
#ifndef STRIDER_CONTROL_WALKER_MOTION_H
#define STRIDER_CONTROL_WALKER_MOTION_H

#include <stdint.h>
#include <string.h>

#include "../gait/gait_choice.h"
#include "../gait/gait_library.h"
#include "../gait/gait_params.h"
#include "../gait/speed_correction.h"
#include "../gait/walker.h"
#include "avoidance.h"
#include "motion_reach.h"
#include "robot_mode.h"

namespace strider {

template <typename S, typename P = HostProfile<S>>
class WalkerMotion {
 public:
  WalkerMotion() = default;

  //! The walker for `model` with its default gait parameters, sitting.
  bool configure(const RobotModel& model) {
    GaitParams params;
    return gait_params_of(model, &params) && configure(model, params);
  }

  //! The same with other gait parameters; solve_now false: the legs' IK
  //! waits for walker().refresh().
  bool configure(const RobotModel& model, const GaitParams& params, bool solve_now = true) {
    GaitTable gait;
    if (!load_gait(model, params.default_gait, &gait) ||
        !walker_.configure(model, gait, params, params.shape, true, solve_now))
      return false;
    configured(model);
    return true;
  }

  Walker<S, P>& walker() { return walker_; }
  const Walker<S, P>& walker() const { return walker_; }
  const GaitTable& gait() const { return walker_.engine().gait(); }
  const char* robot() const { return robot_; }  //!< the model's name; nullptr before configure()

  //! Protocol velocity -> engine command. An unchanged one (a repeated RC
  //! button) is not planned again: planning costs more than a tick.
  void set_velocity(const Twist& v) {
    if (have_command_ && v.vx == last_.vx && v.vy == last_.vy && v.wz == last_.wz) return;
    have_command_ = true;
    last_ = v;
    yaw_trim_ = 0;  // the heading hold starts over with each command (yaw_hold.h)
    walk_command();
  }

  //! The command in force (protocol units; zero before the first).
  const Twist& command() const { return last_; }

  //! A turn [0.1 deg/s] the gait walks on top of the command's, after its
  //! speed correction (the IMU's heading hold, yaw_hold.h: its loop closes
  //! on the body, and a curve measured turning in place would make a
  //! straight walk's small trims large); command() and status keep the
  //! command's own.
  void set_yaw_trim(int16_t wz_tenths) {
    if (wz_tenths == yaw_trim_) return;
    yaw_trim_ = wz_tenths;
    if (have_command_) walk_command();
  }
  int16_t yaw_trim() const { return yaw_trim_; }

 private:
  //! The command in force and the trim -> the engine's command.
  STRIDER_NOINLINE void walk_command() {
    const Twist& v = last_;
    constexpr S tenth = scalar<S>(0.1);
    constexpr S decideg_to_rad = scalar<S>(kDegToRad / 10.0);
    // The gait's own speed that makes the commanded body speed (speed_correction.h).
    const SpeedCurve* linear = speed_curve<P::kModelIndex>(correction_, false);
    walker_.engine().set_command(S(speed_corrected(int32_t(v.vx), linear)) * tenth,
                                 S(speed_corrected(int32_t(v.vy), linear)) * tenth,
                                 S(speed_corrected(int32_t(v.wz), speed_curve<P::kModelIndex>(correction_, true))) * decideg_to_rad,
                                 scalar<S>(100.0), S(int32_t(yaw_trim_)) * decideg_to_rad);
  }

 public:

  //! Whether the gait walks with the parameters its speed correction was
  //! measured at (its own; gait_tuner.h): a tuned gait or a preset steps
  //! otherwise and slips otherwise, so it walks uncorrected (slip-free).
  void correct_speeds(bool as_measured) {
    const uint8_t before = correction_;
    as_measured_ = as_measured;
    correct_for_gait();
    if (correction_ != before) recommand();
  }

  //! A preset's own speed correction, once its parameters are in:
  //! speed_correction.h lists it by the preset's name (none: as before).
  void correct_as_preset(const char* preset) {
    const uint8_t i = robot_ != nullptr ? speed_correction_index<P::kModelIndex>(robot_, preset) : kNoSpeedCorrection;
    if (i == kNoSpeedCorrection) return;
    correction_ = i;
    recommand();
  }

  //! The gait's own speed [0.1 mm/s] -> the body speed it makes on the
  //! ground (speed_correction.h); turn: a turn rate [0.1 deg/s].
  int32_t body_speed(int32_t gait_tenths, bool turn = false) const {
    return body_speed_of(gait_tenths, speed_curve<P::kModelIndex>(correction_, turn));
  }

  //! The gait the RC pad walks body speed v in (gait_choice.h): true and
  //! its name in `to` (kGaitNameBytes) when that is not the gait walked now.
  bool pad_gait(const Twist& v, char* to) const {
    return robot_ != nullptr && gait_choice_for(robot_, gait().name, v.vx, v.vy, v.wz, to);
  }

  //! The RC buttons' speeds at 100 %: RcLimits, or less where the gait the
  //! pad walks then makes less (speed_correction.h).
  RcLimits pad_limits() const {
    RcLimits lim;
    if (robot_ == nullptr) return lim;
    char fast[kGaitNameBytes];
    const bool other = gait_choice_for(robot_, gait().name, lim.linear, 0, lim.turn, fast);
    pad_top_of<P::kModelIndex>(robot_, other ? fast : gait().name, &lim.linear, &lim.turn, &lim.min_turn);
    return lim;
  }
  //! Stop stepping; the feet finish their swing and the robot stands.
  void stand() { set_velocity(Twist{0, 0, 0}); }

  //! The servos went limp: starts over sitting, keeping gait, pose and height.
  void sit_now() { restart(true); }

  //! The servos hold a standing robot (a warm start): starts over standing.
  void stand_now() { restart(false); }

  void stand_up() { walker_.engine().stand_up(); }
  bool sitting() const { return walker_.engine().state() == GaitState::kSitting; }

  //! Switches gait by name, also while walking; false: no such gait here.
  bool set_gait(const char* name) {
    GaitTable g;
    if (!load_gait(walker_.leg_count(), name, &g)) return false;
    set_gait_table(g);
    return true;
  }

  //! The gait walked now with another duty [0.01] (gait_tuning.h's
  //! duty_allowed() checked it), also while walking.
  void set_duty(uint8_t duty_pct) {
    GaitTable g = gait();
    g.duty = detail::ratio_float(duty_pct, 100);
    set_gait_table(g);
  }

  //! Stance feet moved in steps of `step_dmm` [0.1 mm], all at once (0:
  //! every tick), on all feet or not (gait/stance_ratchet.h).
  void set_stance_motion(int32_t step_dmm, bool on_all_feet) {
    walker_.engine().set_stance_motion(S(step_dmm) * scalar<S>(0.1), on_all_feet);
  }

  //! Body rotation [0.1 deg]; refused when a standing foot would be out of reach.
  bool set_body_pose(int32_t roll, int32_t pitch, int32_t yaw) {
    constexpr S decideg_to_rad = scalar<S>(kDegToRad / 10.0);
    BodyOffsets<S> o = offsets_;
    o.roll_rad = S(int32_t(roll)) * decideg_to_rad;
    o.pitch_rad = S(int32_t(pitch)) * decideg_to_rad;
    o.yaw_rad = S(int32_t(yaw)) * decideg_to_rad;
    return try_offsets(o);
  }

  //! Body roll and pitch [rad], yaw and height kept (level_body.h); refused
  //! when a standing foot would be out of reach.
  bool set_body_tilt(S roll_rad, S pitch_rad) {
    BodyOffsets<S> o = offsets_;
    o.roll_rad = roll_rad;
    o.pitch_rad = pitch_rad;
    return try_offsets(o);
  }

  //! Body height above the ground [0.1 mm]; refused when out of reach.
  bool set_body_height(int32_t decimm) {
    if (decimm <= 0) return false;
    BodyOffsets<S> o = offsets_;
    o.translation_mm.z = S(int32_t(decimm)) * scalar<S>(0.1) - stand_height_mm_;
    return try_offsets(o);
  }

  S stand_height_mm() const { return stand_height_mm_; }
  const BodyOffsets<S>& offsets() const { return offsets_; }

  //! What the legs reach from standing (motion_reach.h); 0 before find_reach().
  const MotionReach& reach() const { return reach_; }
  //! After configure(): about 50 checks of every leg's IK.
  STRIDER_NOINLINE void find_reach() {
    const int16_t stand_mm = whole_mm(stand_height_mm_);
    reach_ = find_motion_reach(
        stand_mm,
        [this](int16_t mm) {
          BodyOffsets<S> o = BodyOffsets<S>::zero();
          o.translation_mm.z = S(int32_t(mm)) - stand_height_mm_;
          return reachable(o);
        },
        [this](uint8_t axis, int16_t deg) {
          BodyOffsets<S> o = BodyOffsets<S>::zero();
          const S rad = S(int32_t(deg)) * scalar<S>(kDegToRad);
          (axis == 0 ? o.roll_rad : axis == 1 ? o.pitch_rad : o.yaw_rad) = rad;
          return reachable(o);
        });
  }

 private:
  void set_gait_table(const GaitTable& g) {
    walker_.engine().set_gait(g);
    correct_for_gait();
    recommand();
  }

  //! The body speed commanded last, again, through the gait and correction now in force.
  void recommand() {
    if (!have_command_) return;
    have_command_ = false;
    set_velocity(last_);
  }

  void restart(bool sitting) {
    have_command_ = false;
    yaw_trim_ = 0;
    const GaitTable gait = walker_.engine().gait();  // a copy: restart() overwrites the engine's
    walker_.restart(gait, walker_.engine().config(), sitting);
    walker_.engine().set_body_offsets(offsets_);
  }

  //! The speed correction of the model and the gait in force.
  void correct_for_gait() {
    correction_ = robot_ != nullptr && as_measured_ ? speed_correction_index<P::kModelIndex>(robot_, gait().name)
                                                    : kNoSpeedCorrection;
  }

  //! After the walker's configuration: no offsets, no command, the standing height.
  void configured(const RobotModel& model) {
    robot_ = model.name;
    correct_for_gait();
    offsets_ = BodyOffsets<S>::zero();
    have_command_ = false;
    yaw_trim_ = 0;
    stand_height_mm_ = -walker_.engine().config().home[0].z;
  }

  //! Every standing foot within the joint limits; a 2-DOF leg reaches only a
  //! surface, so its nearest point (kClamped) counts, as in the walker.
  bool try_offsets(const BodyOffsets<S>& o) {
    if (!reachable(o)) return false;
    offsets_ = o;
    walker_.engine().set_body_offsets(o);
    return true;
  }
  bool reachable(const BodyOffsets<S>& o) {
    BodyPose<S> pose = BodyPose<S>::zero();
    pose.translation_mm = o.translation_mm;
    pose.roll_rad = o.roll_rad;
    pose.pitch_rad = o.pitch_rad;
    pose.yaw_rad = o.yaw_rad;
    const Transform<S> body = body_transform(pose);
    const auto& cfg = walker_.engine().config();
    for (uint8_t i = 0; i < walker_.leg_count(); ++i) {
      const Vec3<S> target = walker_.leg_mount(i).body_to_leg(foot_in_body(body, cfg.home[i]));
      typename AnyLeg<S>::Joints q;
      Vec3<S> reached;
      const IkStatus st = walker_.leg_ik(i, target, q, reached);
      const bool two_dof = walker_.dof() == 2;
      if (!(st == IkStatus::kOk || (two_dof && st == IkStatus::kClamped))) return false;
    }
    return true;
  }

  Walker<S, P> walker_;
  BodyOffsets<S> offsets_ = BodyOffsets<S>::zero();
  S stand_height_mm_ = S(0);
  Twist last_{0, 0, 0};
  bool have_command_ = false;
  int16_t yaw_trim_ = 0;  //!< set_yaw_trim()
  const char* robot_ = nullptr;     //!< the model's name (configure)
  uint8_t correction_ = kNoSpeedCorrection;  //!< the gait's entry in speed_correction.h; none: slip-free
  bool as_measured_ = true;  //!< correct_speeds()
  MotionReach reach_{0, 0, {0, 0, 0}, {0, 0, 0}};
};

}  // namespace strider

#endif  // STRIDER_CONTROL_WALKER_MOTION_H
