//! Stance: a foot on the ground stays where it is on the ground while the
//! body moves, so in the body frame it moves by the inverse of the body's
//! motion; plus the optional stance depth (the foot pressed a little into
//! the ground mid-stance, as CHAMP does).
//!
//! Per tick the body moves by d = v dt [mm] (in the body frame at the start
//! of the tick) and turns by theta = w_z dt [rad]. A ground point p of the
//! old body frame is then at p' = Rz(-theta) (p - d) in the new one. theta
//! is small (below 0.2 rad per tick for every command the limits allow), so
//! cos and sin come from their Taylor series to the 5th power (error below
//! 1e-7): no trig call per tick.
#ifndef STRIDER_GAIT_STANCE_H
#define STRIDER_GAIT_STANCE_H

#include "../math/vec3.h"

namespace strider {

//! cos and sin of a small angle [rad] by their Taylor series to the 5th
//! power: error below 3e-5 for |a| <= 0.5, below 1e-7 for |a| <= 0.2.
template <typename S>
void small_angle_cos_sin(S a, S& c, S& s) {
  const S a2 = a * a;
  c = S(1) - a2 * (scalar<S>(0.5) - a2 * scalar<S>(1.0 / 24.0));
  s = a * (S(1) - a2 * (scalar<S>(1.0 / 6.0) - a2 * scalar<S>(1.0 / 120.0)));
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

  //! The step of a body moving at (vx, vy) [mm/s] and turning at wz [rad/s]
  //! for dt [s].
  static BodyStep make(S vx, S vy, S wz, S dt) {
    BodyStep b{vx * dt, vy * dt, wz * dt, S(1), S(0)};
    small_angle_cos_sin(b.dyaw, b.cos_yaw, b.sin_yaw);
    return b;
  }

  //! A ground-fixed point [mm] of the old body frame in the new one:
  //! Rz(-dyaw) (p - d); z is unchanged.
  Vec3<S> move_ground_point(const Vec3<S>& p) const {
    const S x = p.x - dx_mm, y = p.y - dy_mm;
    return Vec3<S>(cos_yaw * x + sin_yaw * y, cos_yaw * y - sin_yaw * x, p.z);
  }
};

//! How far a stance foot sits below the ground line at stance phase
//! sigma in [0, 1] [mm]: depth 4 sigma (1 - sigma), zero at touch-down and
//! lift-off so the foot path stays continuous (CHAMP uses a cosine arc; a
//! parabola costs no trig).
template <typename S>
S stance_sink_mm(S depth_mm, S sigma) {
  if (depth_mm == S(0)) return S(0);
  sigma = clamp(sigma, S(0), S(1));
  return depth_mm * S(4) * sigma * (S(1) - sigma);
}

//! Where a foot touches down so that its stance is centred on `home` [mm]:
//! home moved forward by half the stride the body makes during a stance of
//! stance_s [s], i.e. Rz(w stance/2) home + v stance/2 (the rotation by its
//! series; exact for a pure translation).
template <typename S>
Vec3<S> touchdown_point(const Vec3<S>& home, S vx, S vy, S wz, S stance_s) {
  const S half = stance_s * scalar<S>(0.5);
  S c, s;
  small_angle_cos_sin(wz * half, c, s);
  return Vec3<S>(c * home.x - s * home.y + vx * half, s * home.x + c * home.y + vy * half, home.z);
}

}  // namespace strider

#endif  // STRIDER_GAIT_STANCE_H
