//! AttitudeFilter: roll and pitch [rad] from an accelerometer [m/s^2] and a
//! gyro [rad/s], a Mahony-style complementary filter on the unit "up" vector
//! with a gyro bias estimate (docs/imu.md, "The attitude filter"). Total:
//! NaN or infinite inputs count as missing, inputs are clamped to the
//! MPU-6050's ranges, dt <= 0 changes nothing.
#ifndef STRIDER_SENSING_ATTITUDE_FILTER_H
#define STRIDER_SENSING_ATTITUDE_FILTER_H

#include <stdint.h>

#include "../math/scalar.h"
#include "../math/vec3.h"
#include "imu_sample.h"

namespace strider {

constexpr double kAttitudeMaxAccelG = 16.0;    //!< accel clamp per axis [g]: the MPU-6050's widest range
constexpr double kAttitudeMaxRateRadS = 34.91; //!< gyro clamp per axis [rad/s]: 2000 deg/s, its widest range
constexpr double kAttitudeMaxBiasRadS = 0.6;   //!< bias estimate clamp per axis [rad/s] (34 deg/s; the part: 20)
constexpr double kAttitudeMaxDtS = 0.2;        //!< longer gaps are not integrated [s]
constexpr double kAttitudeMaxTurnRad = 0.5;    //!< turn integrated per update and axis [rad] (25 rad/s at 50 Hz)

enum class AttitudeStatus : uint8_t {
  kOk = 0,        //!< gyro integrated and corrected by the accelerometer
  kGyroOnly = 1,  //!< the accelerometer was not trusted (|a| far from 1 g): gyro only
  kLevelled = 2,  //!< attitude taken from the accelerometer alone (first sample, after a gap, or > 90 deg off)
  kHeld = 3       //!< nothing changed: dt <= 0, or no trusted sample to start from
};

//! Gains and accelerometer trust window.
template <typename S>
struct AttitudeGains {
  S kp;        //!< accelerometer gain [1/s]: tilt errors decay at about this rate
  S ki;        //!< gyro-bias gain [1/s^2]
  S trust_g;   //!< |a| within this of 1 g: full trust [g]
  S reject_g;  //!< |a| this far from 1 g or further: ignored [g]
};

template <typename S>
constexpr AttitudeGains<S> attitude_gains_default() {
  return AttitudeGains<S>{scalar<S>(1.0), scalar<S>(0.25), scalar<S>(0.1), scalar<S>(0.3)};
}

namespace detail {
// The bias is kept scaled by 256: in Fixed, ki e dt is often below one LSB
// (1.5e-5 rad/s) and would be lost; 2^8 is exact in float too.
constexpr double kAttitudeBiasScale = 256.0;

//! v clamped to [-limit, limit]; NaN or an infinity gives 0 and sets bad.
inline float attitude_input(float v, float limit, bool& bad) {
  if (!is_finite(v)) {
    bad = true;
    return 0.0f;
  }
  return clamp(v, -limit, limit);
}
inline Fixed attitude_input(Fixed v, Fixed limit, bool&) { return clamp(v, -limit, limit); }
}  // namespace detail

template <typename S>
class AttitudeFilter {
 public:
  AttitudeFilter() { set_gains(attitude_gains_default<S>()); reset(); }

  //! False (gains unchanged) unless 0 <= kp <= 10, 0 <= ki <= 10 and
  //! 0 <= trust_g < reject_g <= 0.9.
  bool set_gains(const AttitudeGains<S>& g) {
    const S zero = S(), ten = scalar<S>(10.0);
    if (g.kp < zero || ten < g.kp || g.ki < zero || ten < g.ki || g.trust_g < zero || !(g.trust_g < g.reject_g) ||
        scalar<S>(0.9) < g.reject_g)
      return false;
    gains_ = g;
    inv_span_ = scalar<S>(1.0) / (g.reject_g - g.trust_g);
    ki_scaled_ = g.ki * scalar<S>(detail::kAttitudeBiasScale);
    return true;
  }
  const AttitudeGains<S>& gains() const { return gains_; }

  //! Forgets the attitude and the bias estimate.
  void reset() {
    up_ = Vec3<S>(S(), S(), scalar<S>(1.0));
    last_w_ = Vec3<S>();
    bias_scaled_ = Vec3<S>();
    has_attitude_ = false;
  }

  //! Seeds the bias estimate (e.g. the mean gyro reading while still) [rad/s].
  void set_gyro_bias(const Vec3<S>& b_rad_s) {
    bool bad = false;
    const S lim = scalar<S>(kAttitudeMaxBiasRadS);
    const Vec3<S> b(detail::attitude_input(b_rad_s.x, lim, bad), detail::attitude_input(b_rad_s.y, lim, bad),
                    detail::attitude_input(b_rad_s.z, lim, bad));
    bias_scaled_ = b * scalar<S>(detail::kAttitudeBiasScale);
  }

  //! One sample in the body frame; dt [s] since the previous one.
  AttitudeStatus update(const Vec3<S>& accel_m_s2, const Vec3<S>& gyro_rad_s, S dt_s) {
    const S zero = S(), one = scalar<S>(1.0);
    if (!(zero < dt_s)) return AttitudeStatus::kHeld;
    bool accel_bad = false, gyro_bad = false;
    const S inv_g = scalar<S>(1.0 / kStandardGravity), g_lim = scalar<S>(kAttitudeMaxAccelG);
    const Vec3<S> a(detail::attitude_input(accel_m_s2.x * inv_g, g_lim, accel_bad),
                    detail::attitude_input(accel_m_s2.y * inv_g, g_lim, accel_bad),
                    detail::attitude_input(accel_m_s2.z * inv_g, g_lim, accel_bad));
    const S w_lim = scalar<S>(kAttitudeMaxRateRadS);
    const Vec3<S> w(detail::attitude_input(gyro_rad_s.x, w_lim, gyro_bad),
                    detail::attitude_input(gyro_rad_s.y, w_lim, gyro_bad),
                    detail::attitude_input(gyro_rad_s.z, w_lim, gyro_bad));
    const S mag = accel_bad ? zero : sqrt(dot(a, a));
    const S dev = abs(mag - one);
    const S k = accel_bad ? zero : clamp((gains_.reject_g - dev) * inv_span_, zero, one);
    const bool full = !accel_bad && !(gains_.trust_g < dev);
    // reject_g <= 0.9 keeps a trusted |a| above 0.1 g: 1 / mag stays small.
    const Vec3<S> a_unit = zero < k ? a * (one / mag) : Vec3<S>();
    if (!has_attitude_ || scalar<S>(kAttitudeMaxDtS) < dt_s || (full && dot(a_unit, up_) < zero)) {
      // Nothing to integrate from, or lost by over 90 deg.
      if (!full) return AttitudeStatus::kHeld;
      up_ = a_unit;
      last_w_ = w;
      has_attitude_ = true;
      return AttitudeStatus::kLevelled;
    }
    // Gyro prediction first, trapezoidal rate, turn to second order
    // (docs/imu.md). Fixed: halving dt first would round 0.01 s by 5e-4.
    const Vec3<S> w_mean = (w + last_w_) * scalar<S>(0.5) - bias_scaled_ * scalar<S>(1.0 / detail::kAttitudeBiasScale);
    last_w_ = w;
    const S r_lim = scalar<S>(kAttitudeMaxTurnRad);
    const Vec3<S> r_raw = w_mean * dt_s;
    const Vec3<S> r(clamp(r_raw.x, -r_lim, r_lim), clamp(r_raw.y, -r_lim, r_lim), clamp(r_raw.z, -r_lim, r_lim));
    const Vec3<S> c = cross(up_, r);
    const Vec3<S> u_pred = up_ + c + cross(c, r) * scalar<S>(0.5);
    const Vec3<S> e = cross(a_unit, u_pred) * k;
    const S bias_lim = scalar<S>(kAttitudeMaxBiasRadS * detail::kAttitudeBiasScale);
    const Vec3<S> db = e * (ki_scaled_ * dt_s);
    bias_scaled_ = Vec3<S>(clamp(bias_scaled_.x - db.x, -bias_lim, bias_lim),
                           clamp(bias_scaled_.y - db.y, -bias_lim, bias_lim),
                           clamp(bias_scaled_.z - db.z, -bias_lim, bias_lim));
    const Vec3<S> u = u_pred + cross(up_, e * (gains_.kp * dt_s));
    // u is up_ (1 - |r across up_|^2 / 2) plus a part across up_, and |r|^2
    // <= 3 kAttitudeMaxTurnRad^2 = 0.75: |u| >= 5/8, the reciprocal is safe.
    up_ = u * (one / sqrt(dot(u, u)));
    return zero < k ? AttitudeStatus::kOk : AttitudeStatus::kGyroOnly;
  }

  AttitudeStatus update(const ImuSample<S>& s, S dt_s) { return update(s.accel_m_s2, s.gyro_rad_s, dt_s); }

  //! A first attitude exists (a trusted accelerometer sample arrived).
  bool has_attitude() const { return has_attitude_; }
  //! Unit vector against gravity in the body frame (0, 0, 1 before the first).
  const Vec3<S>& up() const { return up_; }
  //! Rotation about body x [rad], (-pi, pi]; 0 when pitch is +-90 deg.
  S roll_rad() const { return atan2(up_.y, up_.z); }
  //! Rotation about body y [rad], [-pi/2, pi/2]; positive nose down.
  S pitch_rad() const { return atan2(-up_.x, hypot(up_.y, up_.z)); }
  //! Angle between body z and the vertical [rad], [0, pi].
  S tilt_rad() const { return atan2(hypot(up_.x, up_.y), up_.z); }
  //! The gyro bias estimate [rad/s] (its component along up() is not observable).
  Vec3<S> gyro_bias_rad_s() const { return bias_scaled_ * scalar<S>(1.0 / detail::kAttitudeBiasScale); }

 private:
  AttitudeGains<S> gains_;
  S inv_span_;   // 1 / (reject_g - trust_g)
  S ki_scaled_;  // ki * kAttitudeBiasScale
  Vec3<S> up_;
  Vec3<S> last_w_;       // the previous gyro sample [rad/s]
  Vec3<S> bias_scaled_;  // b * kAttitudeBiasScale [rad/s]
  bool has_attitude_;
};

}  // namespace strider

#endif  // STRIDER_SENSING_ATTITUDE_FILTER_H
