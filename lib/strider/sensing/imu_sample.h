//! ImuSample: one reading of a 6-axis IMU in SI units, body frame (x
//! forward, y left, z up).
#ifndef STRIDER_SENSING_IMU_SAMPLE_H
#define STRIDER_SENSING_IMU_SAMPLE_H

#include "../math/vec3.h"

namespace strider {

constexpr double kStandardGravity = 9.80665;  //!< [m/s^2]: the "g" of accelerometer data sheets

template <typename S>
struct ImuSample {
  //! Specific force [m/s^2]: acceleration minus gravity, so a part at rest
  //! reads +9.81 along up.
  Vec3<S> accel_m_s2;
  Vec3<S> gyro_rad_s;  //!< angular rate [rad/s], right-handed about each axis
  S temp_c;            //!< die temperature [deg C]
};

}  // namespace strider

#endif  // STRIDER_SENSING_IMU_SAMPLE_H
