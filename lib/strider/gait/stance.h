//! Stance: a foot on the ground stays where it is while the body moves, so in
//! the body frame it moves by the inverse of the body's motion (the arc d = dt
//! (A v + B J v), A = sin(theta)/theta, B = (1 - cos theta)/theta from their
//! series: docs/gaits.md); the stance depth, and where a foot touches down.
#ifndef STRIDER_GAIT_STANCE_H
#define STRIDER_GAIT_STANCE_H

#include "../math/vec3.h"

namespace strider {

//! cos and sin of a small angle [rad] by their Taylor series to the 5th
//! power: error below 3e-5 for |a| <= 0.5, below 1e-7 for |a| <= 0.2.
template <typename S>
void small_angle_cos_sin(S a, S& c, S& s) {
  constexpr S k2 = scalar<S>(0.5), k3 = scalar<S>(1.0 / 6.0), k4 = scalar<S>(1.0 / 24.0), k5 = scalar<S>(1.0 / 120.0);
  const S a2 = a * a;
  c = S(1) - a2 * (k2 - a2 * k4);
  s = a * (S(1) - a2 * (k3 - a2 * k5));
}

//! sin(a)/a and (1 - cos a)/a of a small angle [rad] (series as above).
template <typename S>
void small_angle_arc(S a, S& sinc, S& cosc) {
  constexpr S k2 = scalar<S>(0.5), k3 = scalar<S>(1.0 / 6.0), k4 = scalar<S>(1.0 / 24.0);
  constexpr S k5 = scalar<S>(1.0 / 120.0), k6 = scalar<S>(1.0 / 720.0);
  const S a2 = a * a;
  sinc = S(1) - a2 * (k3 - a2 * k5);
  cosc = a * (k2 - a2 * (k4 - a2 * k6));
}

//! The body's motion over one tick, seen from the body.
template <typename S>
struct BodyStep {
  S dx_mm;   //!< forward translation this tick [mm]
  S dy_mm;   //!< leftward translation this tick [mm]
  S dyaw;    //!< yaw this tick [rad], counter-clockwise
  S cos_yaw; //!< cos(dyaw)
  S sin_yaw; //!< sin(dyaw)

  static BodyStep none() { return BodyStep{S(0), S(0), S(0), S(1), S(0)}; }

  //! The step of a body moving at (vx, vy) [mm/s] (its own frame) and
  //! turning at wz [rad/s] for dt [s]: the arc d = dt (A v + B J v).
  static BodyStep make(S vx, S vy, S wz, S dt) {
    const S th = wz * dt;
    // Not turning: A = 1, B = 0, cos = 1, sin = th (+-0), no products.
    if (wz == S(0)) return BodyStep{vx * dt, vy * dt, th, S(1), th};
    S a, b;
    small_angle_arc(th, a, b);
    BodyStep st{(a * vx - b * vy) * dt, (a * vy + b * vx) * dt, th, S(1), S(0)};
    small_angle_cos_sin(th, st.cos_yaw, st.sin_yaw);
    return st;
  }

  //! A ground-fixed point [mm] of the old body frame in the new one:
  //! Rz(-dyaw) (p - d); z is unchanged.
  Vec3<S> move_ground_point(const Vec3<S>& p) const {
    const S x = p.x - dx_mm, y = p.y - dy_mm;
    // Not turning: the rotation is the identity (the same result, no product).
    if (sin_yaw == S(0) && cos_yaw == S(1)) return Vec3<S>(x, y, p.z);
    return Vec3<S>(cos_yaw * x + sin_yaw * y, cos_yaw * y - sin_yaw * x, p.z);
  }
};

//! How far a stance foot sits below the ground line at stance phase
//! sigma in [0, 1] [mm]: depth 4 sigma (1 - sigma), zero at both ends.
template <typename S>
S stance_sink_mm(S depth_mm, S sigma) {
  if (depth_mm == S(0)) return S(0);
  sigma = clamp(sigma, S(0), S(1));
  return depth_mm * S(4) * sigma * (S(1) - sigma);
}

//! Where a foot touches down so that its stance of stance_s [s] at (vx, vy,
//! wz) is centred on `home` [mm]: home turned by half the stance's turn about
//! the instantaneous centre, without dividing by wz (docs/gaits.md).
template <typename S>
Vec3<S> touchdown_point(const Vec3<S>& home, S vx, S vy, S wz, S stance_s) {
  constexpr S kHalf = scalar<S>(0.5);
  const S half = stance_s * kHalf;
  const S alpha = wz * half;
  S c, s, a, b;
  small_angle_cos_sin(alpha, c, s);
  small_angle_arc(alpha, a, b);
  return Vec3<S>(c * home.x - s * home.y + (a * vx - b * vy) * half,
                 s * home.x + c * home.y + (a * vy + b * vx) * half, home.z);
}

//! touchdown_point() for every home at once: the offset (dx, dy) and the
//! rotation (c, s), from the points of homes at the origin and at (1, 0).
template <typename S>
void touchdown_frame(S vx, S vy, S wz, S stance_s, S& dx, S& dy, S& c, S& s) {
  const Vec3<S> o = touchdown_point(Vec3<S>(), vx, vy, wz, stance_s);
  const Vec3<S> e = touchdown_point(Vec3<S>(S(1), S(0), S(0)), vx, vy, wz, stance_s);
  dx = o.x;
  dy = o.y;
  c = e.x - o.x;
  s = e.y - o.y;
}
//! Fixed: the same bits without the two points (its products by 0 and 1 and
//! sums with 0 are exact; test/gait checks it bit for bit).
inline void touchdown_frame(Fixed vx, Fixed vy, Fixed wz, Fixed stance_s, Fixed& dx, Fixed& dy, Fixed& c, Fixed& s) {
  constexpr Fixed kHalf = scalar<Fixed>(0.5);
  const Fixed half = stance_s * kHalf;
  const Fixed alpha = wz * half;
  Fixed a, b;
  small_angle_cos_sin(alpha, c, s);
  small_angle_arc(alpha, a, b);
  dx = (a * vx - b * vy) * half;
  dy = (a * vy + b * vx) * half;
}

}  // namespace strider

#endif  // STRIDER_GAIT_STANCE_H
