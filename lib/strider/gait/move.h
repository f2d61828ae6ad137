//! Move: walk a given distance or turn a given angle and stop there (seed
//! 003 section 5): it commands a velocity, follows the engine's odometry and
//! sets the command to zero as soon as the rest is what the ramp down still
//! covers (GaitEngine::stopping_distance_mm).
#ifndef STRIDER_GAIT_MOVE_H
#define STRIDER_GAIT_MOVE_H

#include "gait_engine.h"

namespace strider {

template <typename S>
class Move {
 public:
  //! Walks distance_mm [mm] along the body direction (dx, dy) at speed_mm_s
  //! [mm/s] (clamped to the robot's limits by the engine).
  void start_distance(GaitEngine<S>& e, S distance_mm, S dx, S dy, S speed_mm_s) {
    const S n = hypot(dx, dy);
    if (!(n > S(0)) || !(distance_mm > S(0))) return idle();
    dir_x_ = dx / n;
    dir_y_ = dy / n;
    // The direction in the odometry frame (heading at the start).
    wx_ = e.odometry_cos() * dir_x_ - e.odometry_sin() * dir_y_;
    wy_ = e.odometry_sin() * dir_x_ + e.odometry_cos() * dir_y_;
    x0_ = e.odometry_x();
    y0_ = e.odometry_y();
    goal_ = distance_mm;
    angular_ = false;
    active_ = true;
    stopping_ = false;
    e.set_command(dir_x_ * speed_mm_s, dir_y_ * speed_mm_s, S(0));
  }

  //! Turns in place by angle_rad [rad] (counter-clockwise positive) at
  //! rate_rad_s [rad/s] (its magnitude).
  void start_turn(GaitEngine<S>& e, S angle_rad, S rate_rad_s) {
    if (angle_rad == S(0) || !(rate_rad_s != S(0))) return idle();
    sign_ = angle_rad > S(0) ? S(1) : -S(1);
    yaw0_ = e.odometry_yaw();
    goal_ = abs(angle_rad);
    angular_ = true;
    active_ = true;
    stopping_ = false;
    e.set_command(S(0), S(0), sign_ * abs(rate_rad_s));
  }

  //! Call after each engine tick. Returns true while the move is running
  //! (until the engine stands again).
  bool update(GaitEngine<S>& e) {
    if (!active_) return false;
    if (!stopping_ && remaining(e) <= (angular_ ? e.stopping_angle_rad() : e.stopping_distance_mm())) {
      e.set_command(S(0), S(0), S(0));
      stopping_ = true;
    }
    if (stopping_ && e.state() == GaitState::kStanding) active_ = false;
    return active_;
  }

  bool active() const { return active_; }
  //! Progress so far: [mm] along the direction, or [rad] turned.
  S done(const GaitEngine<S>& e) const {
    if (angular_) return (e.odometry_yaw() - yaw0_) * sign_;
    return (e.odometry_x() - x0_) * wx_ + (e.odometry_y() - y0_) * wy_;
  }
  S remaining(const GaitEngine<S>& e) const { return goal_ - done(e); }

 private:
  void idle() {
    active_ = stopping_ = false;
    goal_ = S(0);
  }

  bool active_ = false, stopping_ = false, angular_ = false;
  S goal_ = S(0), sign_ = S(1);
  S dir_x_ = S(0), dir_y_ = S(0), wx_ = S(0), wy_ = S(0), x0_ = S(0), y0_ = S(0), yaw0_ = S(0);
};

}  // namespace strider

#endif  // STRIDER_GAIT_MOVE_H
