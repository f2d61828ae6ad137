//! Numeric IK for the tip position of a DhChain by damped least squares
//! (Levenberg-Marquardt): dq = J^T (J J^T + mu I)^-1 e, a 3x3 symmetric
//! solve, no heap. Scaling, damping, step limiting, joint limits, restarts
//! and the statuses: docs/kinematics.md, "Generic chains".
#ifndef STRIDER_KINEMATICS_DLS_IK_H
#define STRIDER_KINEMATICS_DLS_IK_H

#include "../math/working_units.h"
#include "dls_step.h"
#include "ik_status.h"

namespace strider {

template <typename S>
struct DlsOptions {
  S tolerance_mm = ScalarTraits<S>::ik_tolerance_mm();  //!< reached when closer [mm]
  S max_clamp_mm = scalar<S>(25.0);  //!< farther from the reached point: unreachable [mm]
  //! Initial damping lambda relative to the length scale L (dimensionless).
  S damping = scalar<S>(ScalarTraits<S>::kIsFixed ? 0.05 : 0.01);
  S max_step_rad = scalar<S>(0.5);  //!< largest joint change per iteration [rad]
  uint16_t max_iterations = 200;    //!< steps tried in total, over all attempts
  uint8_t restarts = 8;             //!< extra attempts from random joints after a stall
  uint32_t seed = 1;                //!< seeds the restart joints

  static DlsOptions from(const IkOptions<S>& o) {
    DlsOptions d;
    d.tolerance_mm = o.tolerance_mm;
    d.max_clamp_mm = o.max_clamp_mm;
    return d;
  }
};

template <typename S>
struct DlsReport {
  uint16_t iterations = 0;  //!< steps tried
  uint8_t restarts = 0;     //!< restarts used
  S residual_mm = S(0);     //!< |target - reached| [mm]
};

//! Solves the tip of `chain` onto `target` [mm] starting from q [rad];
//! writes q and reached unless kUnreachable.
template <typename S, uint8_t N>
IkStatus dls_ik(const DhChain<S, N>& chain, const Vec3<S>& target, JointVector<S, N>& q,
                Vec3<S>& reached, const DlsOptions<S>& opt = DlsOptions<S>(),
                DlsReport<S>* report = nullptr) {
  using Joints = JointVector<S, N>;
  if (!dls_detail::finite(target.x) || !dls_detail::finite(target.y) || !dls_detail::finite(target.z))
    return IkStatus::kUnreachable;
  // Farther than reach + max_clamp from frame 0: no joint values can help.
  const S reach = chain.reach_bound_mm();
  if (units::distance(target, chain.base().translation) > reach + opt.max_clamp_mm)
    return IkStatus::kUnreachable;
  int k_len = 0;  // L = 2^k_len >= reach
  for (S len = S(1); len < reach && k_len < 14; len = len * S(2)) ++k_len;
  // The solve works in units of L / 8: Jacobian entries up to 8, J J^T up
  // to 64 N, so the damping term keeps more bits in Fixed.
  const int k_jac = k_len - kDlsHeadroomBits;
  const bool fixed = ScalarTraits<S>::kIsFixed;
  const S lambda_min = scalar<S>(fixed ? 0.0025 : 1e-4);
  const S lambda_max = scalar<S>(fixed ? 8.0 : 1e3);
  const S lambda_start = clamp(opt.damping, lambda_min, lambda_max);
  const S stall_mm = opt.tolerance_mm * scalar<S>(0.01);
  const JointLimits<S, N>& lim = chain.limits();

  Joints cur = q;
  for (uint8_t i = 0; i < N; ++i)
    if (!dls_detail::finite(cur[i])) cur[i] = clamp(S(0), lim.lo[i], lim.hi[i]);
  lim.clamp_into(cur);
  PositionJacobian<S, N> jac;
  Vec3<S> tip = dls_detail::scaled_jacobian(chain, cur, k_jac, jac);
  S err = units::distance(target, tip);
  Joints best = cur;
  S best_err = err;
  S lambda = lambda_start;
  Prng rng(opt.seed);
  uint16_t it = 0;
  uint8_t restarts = 0, rejects = 0, slow = 0;
  // An equal share of the budget per attempt: a fresh start beats creeping.
  const uint16_t attempt_budget =
      max_of(uint16_t(16), uint16_t(opt.max_iterations / (uint16_t(opt.restarts) + 1u)));
  uint16_t attempt_start = 0;

  while (opt.tolerance_mm < err && it < opt.max_iterations) {
    ++it;
    bool locked[N] = {};
    Joints dq;
    // mu = lambda^2 + |e|^2 / 2 in the solver's unit L / 8 (Sugihara 2011).
    const S err_n = min_of(dls_detail::mul_pow2(err, -k_jac), S(32));
    const S lambda_n = dls_detail::mul_pow2(lambda, kDlsHeadroomBits);
    const S lambda_sq = lambda_n * lambda_n + scalar<S>(0.5) * err_n * err_n;
    bool ok = dls_detail::dls_step(jac, locked, target - tip, k_jac, lambda_sq, dq);
    // Active set: a joint on a limit that the step pushes outward is locked.
    bool any_locked = false;
    for (uint8_t i = 0; ok && i < N; ++i) {
      if ((!(lim.lo[i] < cur[i]) && dq[i] < S(0)) || (!(cur[i] < lim.hi[i]) && S(0) < dq[i])) {
        locked[i] = true;
        any_locked = true;
      }
    }
    if (any_locked) ok = dls_detail::dls_step(jac, locked, target - tip, k_jac, lambda_sq, dq);
    bool accepted = false;
    if (ok) {
      S m = S(0);
      for (uint8_t i = 0; i < N; ++i) m = max_of(m, abs(dq[i]));
      for (uint8_t h = 0; opt.max_step_rad < m && h < 40; ++h) {
        m = m * scalar<S>(0.5);
        for (uint8_t i = 0; i < N; ++i) dq[i] = dq[i] * scalar<S>(0.5);
      }
      Joints cand;
      for (uint8_t i = 0; i < N; ++i) cand[i] = cur[i] + dq[i];
      lim.clamp_into(cand);
      // The linear model's prediction of the new error [mm].
      Vec3<S> jdq;
      for (uint8_t i = 0; i < N; ++i) jdq += jac.col[i] * (cand[i] - cur[i]);
      const S predicted = units::distance(target - tip, dls_detail::mul_pow2(jdq, k_jac));
      PositionJacobian<S, N> jac_c;
      const Vec3<S> tip_c = dls_detail::scaled_jacobian(chain, cand, k_jac, jac_c);
      const S err_c = units::distance(target, tip_c);
      if (err_c < err) {
        const S err_prev = err;
        accepted = true;
        slow = (err - err_c < max_of(stall_mm, err * scalar<S>(0.001))) ? uint8_t(slow + 1) : uint8_t(0);
        cur = cand;
        jac = jac_c;
        tip = tip_c;
        err = err_c;
        rejects = 0;
        // Gain ratio: the actual decrease against the predicted one. A poor
        // model (a zigzag near a singularity) gets more damping.
        const S gain = err_prev - err_c, model = err_prev - predicted;
        if (scalar<S>(0.75) * model < gain) lambda = max_of(lambda * scalar<S>(0.5), lambda_min);
        else if (gain < scalar<S>(0.25) * model) lambda = min_of(lambda * S(2), lambda_max);
      }
    }
    if (!accepted) {
      lambda = min_of(lambda * S(4), lambda_max);
      ++rejects;
    }
    if (err < best_err) {
      best = cur;
      best_err = err;
    }
    // Stalled above the tolerance: a local minimum or the nearest point.
    if (opt.tolerance_mm < err && (rejects >= 8 || slow >= 4 || it - attempt_start >= attempt_budget)) {
      if (restarts >= opt.restarts) break;
      ++restarts;
      attempt_start = it;
      dls_detail::random_joints(rng, lim, cur);
      tip = dls_detail::scaled_jacobian(chain, cur, k_jac, jac);
      err = units::distance(target, tip);
      lambda = lambda_start;
      rejects = slow = 0;
      if (err < best_err) {
        best = cur;
        best_err = err;
      }
    }
  }

  if (report != nullptr) {
    report->iterations = it;
    report->restarts = restarts;
    report->residual_mm = best_err;
  }
  if (opt.max_clamp_mm < best_err) return IkStatus::kUnreachable;
  const IkStatus status = !(opt.tolerance_mm < best_err) ? IkStatus::kOk
                          : dls_detail::at_any_limit(best, lim) ? IkStatus::kJointLimit
                                                            : IkStatus::kClamped;
  q = best;
  reached = chain.fk(best);
  return status;
}

}  // namespace strider

#endif  // STRIDER_KINEMATICS_DLS_IK_H
