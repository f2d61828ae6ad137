//! JointVector and JointLimits: N joint angles of a leg or chain [rad], in the
//! angle convention of the leg type's seed document.
#ifndef STRIDER_KINEMATICS_JOINTS_H
#define STRIDER_KINEMATICS_JOINTS_H

#include "../math/scalar.h"

namespace strider {

template <typename S, uint8_t N>
struct JointVector {
  S q[N];
  static constexpr uint8_t size() { return N; }
  S& operator[](uint8_t i) { return q[i]; }
  constexpr const S& operator[](uint8_t i) const { return q[i]; }
};

template <typename S, uint8_t N>
struct JointLimits {
  S lo[N];  //!< [rad]
  S hi[N];  //!< [rad]

  //! Limits that never bind.
  static JointLimits unlimited() {
    JointLimits l;
    for (uint8_t i = 0; i < N; ++i) {
      l.lo[i] = -scalar<S>(1000.0);
      l.hi[i] = scalar<S>(1000.0);
    }
    return l;
  }
  bool contains(const JointVector<S, N>& q) const {
    for (uint8_t i = 0; i < N; ++i)
      if (q[i] < lo[i] || hi[i] < q[i]) return false;
    return true;
  }
  //! Clamps q into the limits; returns true when any joint moved.
  bool clamp_into(JointVector<S, N>& q) const {
    bool moved = false;
    for (uint8_t i = 0; i < N; ++i) {
      if (q[i] < lo[i]) { q[i] = lo[i]; moved = true; }
      if (hi[i] < q[i]) { q[i] = hi[i]; moved = true; }
    }
    return moved;
  }
};

//! Options shared by the analytic leg solvers.
template <typename S>
struct IkOptions {
  //! A target closer than this to the workspace counts as reached [mm].
  S tolerance_mm = ScalarTraits<S>::ik_tolerance_mm();
  //! A target farther than this from the workspace is unreachable, not clamped [mm].
  S max_clamp_mm = scalar<S>(25.0);
};

}  // namespace strider

#endif  // STRIDER_KINEMATICS_JOINTS_H
