//! The arithmetic of one damped-least-squares step (kinematics/dls_ik.h):
//! power-of-two scaling that keeps Q16.16 in range and precise, a 3x3
//! symmetric positive definite solve, and the step itself.
#ifndef STRIDER_KINEMATICS_DLS_STEP_H
#define STRIDER_KINEMATICS_DLS_STEP_H

#include "../math/prng.h"
#include "dh_chain.h"

namespace strider {

//! The internal length unit is L / 2^kDlsHeadroomBits (see dls_ik.h).
constexpr int kDlsHeadroomBits = 3;

namespace dls_detail {

// v * 2^n, exact for float (n within the exponent range), rounded for Fixed.
template <typename S>
S mul_pow2(S v, int n) {
  for (; n > 0; --n) v = v * S(2);
  for (; n < 0; ++n) v = v * scalar<S>(0.5);
  return v;
}
inline Fixed mul_pow2(Fixed v, int n) { return v.scaled_pow2(n); }
template <typename S>
Vec3<S> mul_pow2(const Vec3<S>& v, int n) {
  return Vec3<S>(mul_pow2(v.x, n), mul_pow2(v.y, n), mul_pow2(v.z, n));
}

// Solves the symmetric positive definite system a y = b by elimination
// without pivoting (LDL^T). False when a pivot is not positive.
template <typename S>
bool solve_spd3(const S (&a)[3][3], const Vec3<S>& b, Vec3<S>& y) {
  if (!(a[0][0] > S(0))) return false;
  const S l1 = a[1][0] / a[0][0];
  const S l2 = a[2][0] / a[0][0];
  const S a11 = a[1][1] - l1 * a[1][0];
  const S a12 = a[1][2] - l1 * a[2][0];
  const S a22 = a[2][2] - l2 * a[2][0];
  if (!(a11 > S(0))) return false;
  const S l = a12 / a11;
  const S a22b = a22 - l * a12;
  if (!(a22b > S(0))) return false;
  const S b1 = b.y - l1 * b.x;
  const S b2 = b.z - l2 * b.x - l * b1;
  y.z = b2 / a22b;
  y.y = (b1 - a12 * y.z) / a11;
  y.x = (b.x - a[0][1] * y.y - a[0][2] * y.z) / a[0][0];
  return true;
}

template <typename S>
bool finite(S v) { return v == v && v - v == S(0); }  // false for NaN and +-inf

template <typename S, uint8_t N>
bool at_any_limit(const JointVector<S, N>& q, const JointLimits<S, N>& lim) {
  for (uint8_t i = 0; i < N; ++i)
    if (!(lim.lo[i] < q[i]) || !(q[i] < lim.hi[i])) return true;
  return false;
}

// Random joints within the limits, narrowed to one turn around zero.
template <typename S, uint8_t N>
void random_joints(Prng& rng, const JointLimits<S, N>& lim, JointVector<S, N>& q) {
  for (uint8_t i = 0; i < N; ++i) {
    S lo = max_of(lim.lo[i], -pi<S>());
    S hi = min_of(lim.hi[i], pi<S>());
    if (hi < lo) { lo = lim.lo[i]; hi = lim.hi[i]; }
    q[i] = rng.uniform(lo, hi);
  }
}

// dq = js^T (js js^T + lambda_sq I)^-1 e 2^-k_jac for error e [mm] and js
// already divided by 2^k_jac; e is first scaled into [0.125, 0.25) so that
// Fixed keeps its bits. Locked joints get no step. False when the solve fails.
template <typename S, uint8_t N>
bool dls_step(const PositionJacobian<S, N>& js, const bool (&locked)[N], const Vec3<S>& e, int k_jac,
              S lambda_sq, JointVector<S, N>& dq) {
  for (uint8_t i = 0; i < N; ++i) dq[i] = S(0);
  S m = max_of(abs(e.x), max_of(abs(e.y), abs(e.z)));
  if (!(m > S(0))) return true;
  int t = 0;
  while (m < scalar<S>(0.125) && t < 48) { m = m * S(2); ++t; }
  while (!(m < scalar<S>(0.25)) && t > -48) { m = m * scalar<S>(0.5); --t; }
  const Vec3<S> es = mul_pow2(e, t);
  const S l2 = lambda_sq;
  S a[3][3] = {{l2, S(0), S(0)}, {S(0), l2, S(0)}, {S(0), S(0), l2}};
  for (uint8_t i = 0; i < N; ++i) {
    if (locked[i]) continue;
    const Vec3<S>& c = js.col[i];
    for (uint8_t r = 0; r < 3; ++r)
      for (uint8_t k = 0; k < 3; ++k) a[r][k] = a[r][k] + c[r] * c[k];
  }
  Vec3<S> y;
  if (!solve_spd3(a, es, y)) return false;
  for (uint8_t i = 0; i < N; ++i)
    if (!locked[i]) dq[i] = mul_pow2(dot(js.col[i], y), -(t + k_jac));
  return true;
}

// Jacobian of the chain at q, divided by 2^k_jac; returns the tip [mm].
template <typename S, uint8_t N>
Vec3<S> scaled_jacobian(const DhChain<S, N>& chain, const JointVector<S, N>& q, int k_jac,
                        PositionJacobian<S, N>& js) {
  const Vec3<S> tip = chain.jacobian(q, js);
  for (uint8_t i = 0; i < N; ++i) js.col[i] = mul_pow2(js.col[i], -k_jac);
  return tip;
}

}  // namespace dls_detail

}  // namespace strider

#endif  // STRIDER_KINEMATICS_DLS_STEP_H
