//! AnyLeg: one leg of a robot model, of whichever kind the model says,
//! behind one FK/IK interface with three joint slots. No heap, no virtual
//! calls: a tagged union of the four leg types and a switch on the kind.
//!
//! Joints: JointVector<S, 3> in the leg type's seed convention [rad]; 2-DOF
//! kinds use slots 0 and 1, read nothing from slot 2 and write 0 there.
//! Frames: fk/ik work in the leg frame, fk_body/ik_body in the body frame
//! through the leg's mount (seed 000 eqs 9-11 plus the mount yaw).
#ifndef STRIDER_KINEMATICS_ANY_LEG_H
#define STRIDER_KINEMATICS_ANY_LEG_H

#include "../robots/robot_model.h"
#include "abduction_leg.h"
#include "coxa_femur_tibia_leg.h"
#include "leg_mount.h"
#include "planar_leg.h"
#include "sprawl_leg.h"

namespace strider {

template <typename S>
class AnyLeg {
 public:
  static constexpr uint8_t kMaxDof = kMaxLegDof;
  using Joints = JointVector<S, kMaxDof>;

  //! A zero-length sprawl leg at the body centre; assign from from_model().
  AnyLeg() : kind_(LegKind::kSprawl), side_(BodySide::kLeft), mount_{Vec3<S>(), S(0), S(1), S(0)} {}

  //! Builds leg `index` of `model` in place; false, `out` untouched, past leg_count.
  static bool from_model(const RobotModel& model, uint8_t index, AnyLeg& out) {
    if (index >= model.leg_count || index >= kMaxLegs) return false;
    const LegModel& lm = model.legs[index];
    const LinkLengths& k = model.links;
    out.kind_ = model.kind;
    out.side_ = lm.side;
    out.mount_ = mount_of(model, index);
    switch (model.kind) {
      case LegKind::kSprawl:
        return make_leg(out.legs_.sprawl, k, lm);
      case LegKind::kPlanar:
        return make_leg(out.legs_.planar, k, lm);
      case LegKind::kCoxaFemurTibia:
        return make_leg(out.legs_.cft, k, lm);
      case LegKind::kAbduction:
        return make_leg(out.legs_.abduction, k, lm);
    }
    return true;
  }
  //! Where leg `index` of `model` is mounted (index < model.leg_count).
  static LegMount<S> mount_of(const RobotModel& model, uint8_t index) {
    return LegMount<S>::make(Vec3<S>::from(model.legs[index].mount_mm), deg_to_rad<S>(model.legs[index].mount_yaw_deg));
  }

  LegKind kind() const { return kind_; }
  uint8_t dof() const { return dof_of(kind_); }
  constexpr BodySide side() const { return side_; }
  constexpr const LegMount<S>& mount() const { return mount_; }
  //! The same leg mounted elsewhere (legs of one geometry share a solver).
  AnyLeg placed(const LegMount<S>& mount, BodySide side) const {
    AnyLeg leg(*this);
    leg.mount_ = mount;
    leg.side_ = side;
    return leg;
  }

  //! The joint limits [rad]; slot 2 of a 2-DOF leg is [0, 0].
  JointLimits<S, kMaxDof> limits() const {
    JointLimits<S, kMaxDof> l;
    for (uint8_t j = 0; j < kMaxDof; ++j) l.lo[j] = l.hi[j] = S(0);
    visit([&l](const auto& leg) { copy_limits(leg.limits, l); return true; }, true);
    return l;
  }

  bool within_limits(const Joints& q) const {
    const JointLimits<S, kMaxDof> l = limits();
    for (uint8_t j = 0; j < dof(); ++j)
      if (q[j] < l.lo[j] || l.hi[j] < q[j]) return false;
    return true;
  }

  //! Foot in the leg frame [mm].
  Vec3<S> fk(const Joints& q) const {
    return visit([&q](const auto& leg) { return leg.fk(narrow(q, leg.limits)); }, Vec3<S>());
  }

  //! IK in the leg frame; writes q and reached [mm] unless kUnreachable. Out
  //! of line: a firmware's LTO would otherwise copy the dispatch into each caller.
  STRIDER_NOINLINE IkStatus ik(const Vec3<S>& target, Joints& q, Vec3<S>& reached,
                               const IkOptions<S>& opt = IkOptions<S>()) const {
    return visit([&](const auto& leg) { return solve(leg, target, q, reached, opt); }, IkStatus::kUnreachable);
  }

  //! ik_body()'s fast path alone, for the walker's tick: true, with q
  //! written, when the leg solved the body-frame target [mm] exactly inside
  //! the joint limits; false leaves q alone. Fixed coxa/femur/tibia legs only.
  STRIDER_ALWAYS_INLINE bool ik_body_fast(const Vec3<S>& target_body, Joints& q, const IkOptions<S>& opt) const {
    return ik_body_fast(mount_, target_body, q, opt);
  }
  //! The same for this solver placed at another mount.
  STRIDER_ALWAYS_INLINE bool ik_body_fast(const LegMount<S>& mount, const Vec3<S>& target_body, Joints& q,
                                          const IkOptions<S>& opt) const {
    return kind_ == LegKind::kCoxaFemurTibia && !(opt.max_clamp_mm < S(0)) &&
           body_fast(legs_.cft, mount, target_body, q);
  }

  //! Foot in the body frame [mm].
  Vec3<S> fk_body(const Joints& q) const { return mount_.leg_to_body(fk(q)); }

  //! IK for a body-frame target; reached is in the body frame too [mm].
  IkStatus ik_body(const Vec3<S>& target_body, Joints& q, Vec3<S>& reached_body,
                   const IkOptions<S>& opt = IkOptions<S>()) const {
    Vec3<S> reached_leg;
    const IkStatus s = ik(mount_.body_to_leg(target_body), q, reached_leg, opt);
    if (s != IkStatus::kUnreachable) reached_body = mount_.leg_to_body(reached_leg);
    return s;
  }

 private:
  template <uint8_t N>
  static constexpr JointLimits<S, N> limits_of(const LegModel& lm) {
    JointLimits<S, N> l{};
    for (uint8_t j = 0; j < N; ++j) {
      l.lo[j] = deg_to_rad<S>(lm.joint[j].min_deg);
      l.hi[j] = deg_to_rad<S>(lm.joint[j].max_deg);
    }
    return l;
  }
  // Out of line: one leg type's temporaries at a time on the AVR's start-up stack.
  STRIDER_NOINLINE static bool make_leg(SprawlLeg<S>& to, const LinkLengths& k, const LegModel& lm) {
    to = SprawlLeg<S>::make(scalar<S>(k.l1_mm), scalar<S>(k.l2_mm), limits_of<2>(lm));
    return true;
  }
  STRIDER_NOINLINE static bool make_leg(PlanarLeg<S>& to, const LinkLengths& k, const LegModel& lm) {
    to = PlanarLeg<S>::make(scalar<S>(k.l1_mm), scalar<S>(k.l2_mm), limits_of<2>(lm));
    return true;
  }
  STRIDER_NOINLINE static bool make_leg(CoxaFemurTibiaLeg<S>& to, const LinkLengths& k, const LegModel& lm) {
    to = CoxaFemurTibiaLeg<S>::make(scalar<S>(k.d1_mm), scalar<S>(k.l1_mm), scalar<S>(k.l2_mm), scalar<S>(k.l3_mm),
                                    limits_of<3>(lm));
    return true;
  }
  STRIDER_NOINLINE static bool make_leg(AbductionLeg<S>& to, const LinkLengths& k, const LegModel& lm) {
    to = AbductionLeg<S>::make(scalar<S>(k.l1_mm), scalar<S>(k.l2_mm), scalar<S>(k.l3_mm), limits_of<3>(lm),
                               lm.side == BodySide::kLeft ? LegSide::kLeft : LegSide::kRight);
    return true;
  }
  template <uint8_t N>
  static void copy_limits(const JointLimits<S, N>& from, JointLimits<S, kMaxDof>& to) {
    for (uint8_t j = 0; j < N; ++j) to.lo[j] = from.lo[j], to.hi[j] = from.hi[j];
  }
  template <uint8_t N>
  static JointVector<S, N> narrow(const Joints& q, const JointLimits<S, N>&) {
    JointVector<S, N> r;
    for (uint8_t j = 0; j < N; ++j) r[j] = q[j];
    return r;
  }
  // f(the live leg), or fallback (kind_ is always one of the four).
  template <typename F, typename R>
  R visit(F f, R fallback) const {
    switch (kind_) {
      case LegKind::kSprawl:
        return f(legs_.sprawl);
      case LegKind::kPlanar:
        return f(legs_.planar);
      case LegKind::kCoxaFemurTibia:
        return f(legs_.cft);
      case LegKind::kAbduction:
        return f(legs_.abduction);
    }
    return fallback;
  }
  // A 3-DOF leg solves into q and reached directly (the same contract).
  template <bool kFull>
  struct Full {};
  template <typename Leg>
  static IkStatus solve(const Leg& leg, const Vec3<S>& target, Joints& q, Vec3<S>& reached,
                        const IkOptions<S>& opt) {
    return solve(leg, target, q, reached, opt, Full<Leg::kDof == kMaxDof>());
  }
  template <typename Leg>
  static IkStatus solve(const Leg& leg, const Vec3<S>& target, Joints& q, Vec3<S>& reached,
                        const IkOptions<S>& opt, Full<true>) {
    return leg.ik(target, q, reached, opt);
  }
  template <typename Leg>
  static IkStatus solve(const Leg& leg, const Vec3<S>& target, Joints& q, Vec3<S>& reached,
                        const IkOptions<S>& opt, Full<false>) {
    typename Leg::Joints sol;
    Vec3<S> at;
    const IkStatus s = leg.ik(target, sol, at, opt);
    if (s == IkStatus::kUnreachable) return s;
    for (uint8_t j = 0; j < kMaxDof; ++j) q[j] = j < Leg::kDof ? sol[j] : S(0);
    reached = at;
    return s;
  }

  // Differences in place: a Vec3 difference is an out-of-line call on the AVR.
  template <typename Leg>
  static bool body_fast(const Leg&, const LegMount<float>&, const Vec3<float>&, Joints&) {
    return false;
  }
  template <typename Leg>
  STRIDER_ALWAYS_INLINE static bool body_fast(const Leg& leg, const LegMount<Fixed>& m, const Vec3<Fixed>& p,
                                              Joints& q) {
    const Vec3<Fixed> d(sub_inline(p.x, m.origin_mm.x), sub_inline(p.y, m.origin_mm.y), sub_inline(p.z, m.origin_mm.z));
    return leg_ik::cft_solve_fast(leg, d, &m.yaw_rad, q);
  }

  // One leg of the four kinds; kind_ says which member is live.
  union Legs {
    Legs() : sprawl() {}
    SprawlLeg<S> sprawl;
    PlanarLeg<S> planar;
    CoxaFemurTibiaLeg<S> cft;
    AbductionLeg<S> abduction;
  };

  LegKind kind_;
  BodySide side_;
  LegMount<S> mount_;
  Legs legs_;
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_ANY_LEG_H
