//! Walker: a whole robot walking: gait engine -> body pose -> reachable-set
//! projection (2-DOF legs) -> leg IK, per tick, with each leg's LegResult
//! (leg_result.h), sized by its build profile P (robots/build_profile.h).
#ifndef STRIDER_GAIT_WALKER_H
#define STRIDER_GAIT_WALKER_H

#include "../kinematics/any_leg.h"
#include "../robots/build_profile.h"
#include "gait_engine.h"
#include "leg_result.h"
#include "mount_turn.h"
#include "reach_projection.h"
#include "walker_legs.h"

namespace strider {

template <typename S, typename P = HostProfile<S>>
class Walker {
  static constexpr uint8_t kLegs = P::kLegs;
  static constexpr bool kFeet = P::kFeet;
  using Result = LegResult<S, kFeet>;
  using Scratch = LegScratch<S, kFeet>;

 public:
  Walker() : dof_(0), turn_(), proj_() {}

  //! Builds the legs, the configuration and the engine: false when they do
  //! not fit. solve_now false leaves the legs' IK to a later refresh().
  bool configure(const RobotModel& model, const GaitTable& gait, const GaitParams& params, SwingShape shape,
                 bool sitting = false, bool solve_now = true) {
    // Without the IK search, fill_gait_config() needs the model's stored velocity limits.
    const bool limits_known = P::kSearch || stored_limits_index(model, params, shape) < kRobotCount;
    if (model.leg_count > kLegs || gait.leg_count != model.leg_count || !limits_known || !build_legs(model)) return false;
    configure_engine(model, params, shape, gait, sitting);
    reset_legs(solve_now);
    return true;
  }

  //! The same with a configuration built before (make_gait_config).
  bool configure(const RobotModel& model, const GaitTable& gait, const GaitConfig<S, kLegs, P::kSearch>& config,
                 bool sitting = false) {
    if (model.leg_count > kLegs || gait.leg_count != model.leg_count || config.leg_count != model.leg_count)
      return false;
    if (!build_legs(model)) return false;
    engine_.configure(config, gait, sitting);
    reset_legs();
    return true;
  }

  //! Starts over with the legs built before and `config` (which may be the
  //! engine's own): false when no legs are built or the leg counts differ.
  bool restart(const GaitTable& gait, const GaitConfig<S, kLegs, P::kSearch>& config, bool sitting = false) {
    if (dof_ == 0 || gait.leg_count != config.leg_count || config.leg_count != leg_count()) return false;
    engine_.configure(config, gait, sitting);
    reset_legs();
    return true;
  }

  GaitEngine<S, kLegs, P::kSearch>& engine() { return engine_; }
  const GaitEngine<S, kLegs, P::kSearch>& engine() const { return engine_; }
  //! Leg i as one AnyLeg: its solver at its mount (a copy).
  AnyLeg<S> leg_model(uint8_t i) const { return legs_.leg(i); }
  const LegMount<S>& leg_mount(uint8_t i) const { return legs_.mount(i); }
  //! Leg i's IK for a target in its leg frame (AnyLeg::ik).
  IkStatus leg_ik(uint8_t i, const Vec3<S>& target, typename AnyLeg<S>::Joints& q, Vec3<S>& reached,
                  const IkOptions<S>& opt = IkOptions<S>()) const {
    return legs_.solver(i).ik(target, q, reached, opt);
  }
  uint8_t leg_count() const { return engine_.leg_count(); }
  uint8_t dof() const { return dof_; }

  //! One control tick of dt [s]: engine, then every leg.
  void tick(S dt) {
    engine_.tick(dt);
    refresh();
  }

  //! Every leg for the engine's feet and body pose as they are.
  void refresh() {
    // A level body (the usual case): its translation only, no rotation.
    if (engine_.body_level()) {
      const Vec3<S> shift = engine_.body_translation();
      solve_legs(nullptr, shift);
      return;
    }
    const BodyPose<S> pose = engine_.body_pose();
    const Transform<S> body = body_transform(pose);
    solve_legs(&body, pose.translation_mm);
  }

  const Result& leg(uint8_t i) const { return out_[i]; }
  //! Every leg's result, leg_count() of them (ServoStage::frame()).
  const Result* results() const { return out_; }
  //! A body-frame point [mm] in leg i's frame, as the walker computes it.
  STRIDER_ALWAYS_INLINE Vec3<S> to_leg(uint8_t i, const Vec3<S>& body_mm) const {
    return to_leg_turned(turn_[i], legs_.mount(i), body_mm);
  }
  //! Static stability margin [mm] (negative: CoM outside the support).
  S margin_mm() const { return engine_.margin_mm(); }
  IkStatus worst_status() const {
    IkStatus w = IkStatus::kOk;
    for (uint8_t i = 0; i < leg_count(); ++i) w = worst(w, out_[i].status);
    return w;
  }

 private:
  //! Every leg for the body posed by `body` (nullptr: only moved by `shift`
  //! [mm]). Vectors are copied field by field (avr-gcc loops over bytes).
  void solve_legs(const Transform<S>* body, const Vec3<S>& shift) {
    // The body at the stance frame's origin: the feet are in the body frame.
    const bool still = leg_ik::is_zero(shift.x) && leg_ik::is_zero(shift.y) && leg_ik::is_zero(shift.z);
    const bool projects = proj_.projects();
    Scratch scratch;  // nothing when the results keep the feet
    Result* r = out_;
    const Vec3<S>* p = engine_.feet();
    const bool* contact = engine_.contacts();
    const uint8_t n = leg_count();
    for (uint8_t i = 0; i < n; ++i, ++r, ++p) {
      Vec3<S>& t = r->target(scratch);
      if (body != nullptr) {
        t = foot_in_body(*body, *p);
      } else if (still) {
        leg_ik::copy_point(*p, t);
      } else {
        t.x = sub_inline(p->x, shift.x);
        t.y = sub_inline(p->y, shift.y);
        t.z = sub_inline(p->z, shift.z);
      }
      r->contact = contact[i];
      // Fast IK of a body-frame target (Fixed coxa/femur/tibia), reached.
      if (!projects && legs_.solver(i).ik_body_fast(legs_.mount(i), t, r->q, ik_options_)) {
        r->set_clamp(S(0));
        r->set_ik_status(IkStatus::kOk);
        r->status = IkStatus::kOk;
        if (kFeet) leg_ik::copy_point(t, r->foot(scratch));
        continue;
      }
      solve_leg(i, *r, scratch, projects);
    }
  }

  //! solve_legs()'s leg i when the fast IK does not take it.
  STRIDER_NOINLINE void solve_leg(uint8_t i, Result& r, Scratch& scratch, bool projects) {
    const Vec3<S> leg_target = to_leg(i, r.target(scratch));
    if (!projects) {  // 3-DOF legs: the target as it is, nothing can slide
      // The point reached goes into foot (leg frame, then body frame).
      r.set_clamp(S(0));
      const IkStatus ik = legs_.solver(i).ik(leg_target, r.q, r.foot(scratch), ik_options_);
      r.set_ik_status(ik);
      r.status = ik;
      // A target reached as given is the body-frame target itself.
      if (!kFeet || ik == IkStatus::kUnreachable) return;
      if (same(r.foot(scratch), leg_target)) {
        leg_ik::copy_point(r.target(scratch), r.foot(scratch));
      } else {
        r.foot(scratch) = to_body(i, r.foot(scratch));
      }
      return;
    }
    Vec3<S> reached;
    S moved = S(0);
    const Vec3<S> t = proj_.apply(leg_target, moved);
    r.set_clamp(moved);
    const IkStatus ik = legs_.solver(i).ik(t, r.q, reached, ik_options_);
    r.set_ik_status(ik);
    if (kFeet && ik != IkStatus::kUnreachable)
      r.foot(scratch) = moved == S(0) && same(reached, leg_target) ? r.target(scratch) : to_body(i, reached);
    constexpr S tolerance = scalar<S>(kClampToleranceMm);
    const bool slid = r.contact ? moved > tolerance : abs(t.z - leg_target.z) > tolerance;
    r.status = worst(ik, slid ? IkStatus::kClamped : IkStatus::kOk);
  }

  //! The engine's configuration from the model (an AnyLeg per leg).
  // Out of line, as build_legs(): at a firmware's start-up the stack holds
  // the model's copy, and the two frames come one after the other.
  STRIDER_NOINLINE void configure_engine(const RobotModel& model, const GaitParams& params, SwingShape shape, const GaitTable& gait,
                        bool sitting) {
    if (P::kSearch && legs_.per_leg() == nullptr) {
      AnyLeg<S> legs[kLegs];
      for (uint8_t i = 0; i < model.leg_count; ++i) legs[i] = leg_model(i);
      engine_.configure(model, legs, params, shape, gait, sitting);
      return;
    }
    engine_.configure(model, legs_.per_leg(), params, shape, gait, sitting);
  }

  void reset_legs(bool solve_now = true) {
    for (uint8_t i = 0; i < leg_count(); ++i) {
      out_[i].q = typename AnyLeg<S>::Joints();  // zeros
      Scratch unused;
      out_[i].foot(unused) = engine_.foot(i);
    }
    if (solve_now) refresh();
  }

  Vec3<S> to_body(uint8_t i, const Vec3<S>& p) const { return to_body_turned(turn_[i], legs_.mount(i), p); }

  // Same bits (an IK that reached its target copies it): no float compare.
  STRIDER_ALWAYS_INLINE static bool same(const Vec3<S>& a, const Vec3<S>& b) {
    return leg_ik::same_bits(a.x, b.x) && leg_ik::same_bits(a.y, b.y) && leg_ik::same_bits(a.z, b.z);
  }

  STRIDER_NOINLINE bool build_legs(const RobotModel& model) {
    dof_ = 0;
    if (!legs_.fits(model)) return false;
    legs_.build(model);
    for (uint8_t i = 0; i < model.leg_count; ++i) turn_[i] = mount_turn_of(legs_.mount(i));
    proj_ = ReachProjection<S>::make(model);
    dof_ = model.dof();
    return true;
  }

  uint8_t dof_;  // joints per leg; 0 before the legs are built
  walker_detail::LegSolvers<S, kLegs, P::kSolvers> legs_;
  MountTurn turn_[kLegs];  // of each leg's mount (mount_turn.h)
  ReachProjection<S> proj_;
  IkOptions<S> ik_options_{};  // the defaults, built once
  GaitEngine<S, kLegs, P::kSearch> engine_;
  Result out_[kLegs];
};

}  // namespace strider

#endif  // STRIDER_GAIT_WALKER_H
