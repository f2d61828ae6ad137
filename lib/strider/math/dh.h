//! Denavit-Hartenberg link transforms, standard convention:
//!   A = Rz(theta) * Tz(d) * Tx(a) * Rx(alpha)
//!     = [ ct  -st*ca   st*sa   a*ct ]
//!       [ st   ct*ca  -ct*sa   a*st ]
//!       [ 0    sa      ca      d    ]      (seed 003 eq 1, seed 002 eqs 1-3)
//! It maps points of link frame i into frame i-1.
#ifndef STRIDER_MATH_DH_H
#define STRIDER_MATH_DH_H

#include "transform.h"

namespace strider {

//! The constant part of one revolute link; the joint variable q adds to
//! theta_offset_rad.
template <typename S>
struct DhParams {
  S a_mm;              //!< link length along x_i [mm]
  S alpha_rad;         //!< link twist about x_i [rad]
  S d_mm;              //!< link offset along z_(i-1) [mm]
  S theta_offset_rad;  //!< joint angle at q = 0 [rad]
};

//! The DH transform from the cosines and sines of theta and alpha, so that
//! constant twists are evaluated once (seed 003 eq 1).
template <typename S>
constexpr Transform<S> dh_transform_cs(S cos_theta, S sin_theta, S cos_alpha, S sin_alpha, S a_mm,
                                       S d_mm) {
  return Transform<S>{Mat3<S>{{{cos_theta, -sin_theta * cos_alpha, sin_theta * sin_alpha},
                               {sin_theta, cos_theta * cos_alpha, -cos_theta * sin_alpha},
                               {S(0), sin_alpha, cos_alpha}}},
                      Vec3<S>(a_mm * cos_theta, a_mm * sin_theta, d_mm)};
}

//! The DH transform for theta [rad], d [mm], a [mm], alpha [rad] (seed 003
//! eq 1).
template <typename S>
Transform<S> dh_transform(S theta_rad, S d_mm, S a_mm, S alpha_rad) {
  return dh_transform_cs(cos(theta_rad), sin(theta_rad), cos(alpha_rad), sin(alpha_rad), a_mm, d_mm);
}

//! The transform of link `p` at joint value q [rad]: theta = q + offset.
template <typename S>
Transform<S> dh_transform(const DhParams<S>& p, S q_rad) {
  return dh_transform(q_rad + p.theta_offset_rad, p.d_mm, p.a_mm, p.alpha_rad);
}

}  // namespace strider

#endif  // STRIDER_MATH_DH_H
