//! DhChain: a serial chain of N <= 6 revolute joints in standard DH
//! parameters (math/dh.h), with joint limits and a base transform (DH frame
//! 0 in the chain's reference frame); the tip is the origin of frame N, at
//! base * A1(q1) * ... * AN(qN) (seed 002 eq 4, seed 000 eq 3).
#ifndef STRIDER_KINEMATICS_DH_CHAIN_H
#define STRIDER_KINEMATICS_DH_CHAIN_H

#include "../math/dh.h"
#include "joints.h"

namespace strider {

//! The positional Jacobian of a chain: col[i] = d tip / d q_i [mm/rad].
template <typename S, uint8_t N>
struct PositionJacobian {
  Vec3<S> col[N];
};

template <typename S, uint8_t N>
class DhChain {
  static_assert(N >= 1 && N <= 6, "DhChain supports 1 to 6 joints");

 public:
  static constexpr uint8_t kDof = N;
  using Joints = JointVector<S, N>;
  using Limits = JointLimits<S, N>;

  DhChain() : base_(Transform<S>::identity()), limits_(Limits::unlimited()) {
    for (uint8_t i = 0; i < N; ++i) set_link(i, DhParams<S>{S(0), S(0), S(0), S(0)});
  }

  DhChain(const DhParams<S> (&links)[N], const Limits& limits = Limits::unlimited(),
          const Transform<S>& base = Transform<S>::identity())
      : base_(base), limits_(limits) {
    for (uint8_t i = 0; i < N; ++i) set_link(i, links[i]);
  }

  //! Replaces link i (0-based) and its cached twist.
  void set_link(uint8_t i, const DhParams<S>& p) {
    links_[i] = p;
    cos_alpha_[i] = cos(p.alpha_rad);
    sin_alpha_[i] = sin(p.alpha_rad);
  }
  const Limits& limits() const { return limits_; }
  void set_limits(const Limits& l) { limits_ = l; }
  const Transform<S>& base() const { return base_; }
  void set_base(const Transform<S>& b) { base_ = b; }

  //! A_(i+1): frame i+1 in frame i for joint value q [rad] (seed 003 eq 1).
  Transform<S> link_transform(uint8_t i, S q_rad) const {
    const S theta = q_rad + links_[i].theta_offset_rad;
    return dh_transform_cs(cos(theta), sin(theta), cos_alpha_[i], sin_alpha_[i], links_[i].a_mm,
                           links_[i].d_mm);
  }

  //! All frames in the reference frame: out[0] = base (frame 0), out[i] =
  //! base * A1 ... Ai, out[N] = the tip frame.
  void frames(const Joints& q, Transform<S> (&out)[N + 1]) const {
    out[0] = base_;
    for (uint8_t i = 0; i < N; ++i) out[i + 1] = out[i] * link_transform(i, q[i]);
  }

  //! The tip frame in the reference frame.
  Transform<S> fk_pose(const Joints& q) const {
    Transform<S> t = base_;
    for (uint8_t i = 0; i < N; ++i) t = t * link_transform(i, q[i]);
    return t;
  }

  //! The tip position in the reference frame [mm].
  Vec3<S> fk(const Joints& q) const { return fk_pose(q).translation; }

  //! Fills the positional Jacobian at q and returns the tip [mm]:
  //! col_i = z_(i-1) x (tip - p_(i-1)), within the reach in Fixed.
  Vec3<S> jacobian(const Joints& q, PositionJacobian<S, N>& jac) const {
    Transform<S> f[N + 1];
    frames(q, f);
    const Vec3<S> tip = f[N].translation;
    for (uint8_t i = 0; i < N; ++i) jac.col[i] = cross(f[i].rotation.col(2), tip - f[i].translation);
    return tip;
  }

  //! An upper bound of |tip - origin of frame 0| for any q: sum(|a| + |d|) [mm].
  S reach_bound_mm() const {
    S r = S(0);
    for (uint8_t i = 0; i < N; ++i) r = r + abs(links_[i].a_mm) + abs(links_[i].d_mm);
    return r;
  }

 private:
  Transform<S> base_;
  Limits limits_;
  DhParams<S> links_[N];
  S cos_alpha_[N];
  S sin_alpha_[N];
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_DH_CHAIN_H
