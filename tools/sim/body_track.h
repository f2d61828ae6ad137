// BodyTrack: the body's horizontal displacement integrated in its own frame,
// the frame turning with the heading: the walk is cut into segments of
// segment_s (2 s), and each segment's displacement is split into forward and
// sideways along the segment's mean heading; the parts are summed.
//
// Unlike a displacement measured in the starting frame, this does not grow
// when the heading drifts: a robot that turns slowly while walking straight
// ahead along its heading makes forward distance only, however far it goes.
// What it does measure is crabbing, the gait's own sideways motion; heading
// drift is a separate measure (yaw rate). Segments rather than single
// samples: a gait sways its heading within a cycle in step with its zig-zag
// (sprawl8's trot: the body moves +-40 deg off its heading, half a cycle
// each way, and its yaw swings +-5 deg with it), and rotating every 20 ms
// sample by its own yaw would lose 4 % of the forward distance to that
// correlation; over a segment of a few cycles the sway averages out, and the
// heading moves little (1 deg/s: 2 deg).
#pragma once

#include <cmath>

#include "world.h"

namespace strider_sim {

class BodyTrack {
 public:
  explicit BodyTrack(double segment_s = 2.0) : segment_s_(segment_s) {}

  // The next sample (times ascending); yaw in degrees, wrapped or unwrapped.
  void add(double t_s, const BodyState& b) {
    if (!started_) {
      started_ = true;
      yaw_ = b.yaw_deg;
      begin(t_s, b);
      last_t_ = t_s;
      return;
    }
    double d = b.yaw_deg - last_yaw_;
    while (d > 180) d -= 360;
    while (d < -180) d += 360;
    const double yaw = yaw_ + d;
    yaw_area_ += 0.5 * (yaw_ + yaw) * (t_s - last_t_);
    yaw_ = yaw;
    last_yaw_ = b.yaw_deg;
    last_t_ = t_s;
    last_ = b.pos_mm;
    if (t_s - seg_t_ >= segment_s_ - 1e-9) {
      split(forward_mm_, left_mm_);
      begin(t_s, b);
    }
  }

  // Forward (along the heading) and sideways (left positive) parts so far [mm].
  double forward_mm() const {
    double f = forward_mm_, l = left_mm_;
    split(f, l);
    return f;
  }
  double left_mm() const {
    double f = forward_mm_, l = left_mm_;
    split(f, l);
    return l;
  }
  // Heading change since the first sample, unwrapped, anticlockwise positive [deg].
  double turned_deg() const { return started_ ? yaw_ - first_yaw_ : 0.0; }

  // The smaller of the two parts: the motion is the larger (walking forward:
  // the drift is the sideways part; strafing: the forward part).
  double drift_mm() const {
    const double f = std::fabs(forward_mm()), l = std::fabs(left_mm());
    return f >= l ? l : f;
  }

 private:
  void begin(double t_s, const BodyState& b) {
    if (seg_t_ < 0) first_yaw_ = yaw_;
    seg_t_ = t_s;
    seg_start_ = last_ = b.pos_mm;
    last_yaw_ = b.yaw_deg;
    yaw_area_ = 0;
  }
  // Adds the open segment's parts to f and l.
  void split(double& f, double& l) const {
    const double span = last_t_ - seg_t_;
    if (!started_ || span <= 0) return;
    const double h = yaw_area_ / span * M_PI / 180.0;
    const double dx = last_.x - seg_start_.x, dy = last_.y - seg_start_.y;
    f += std::cos(h) * dx + std::sin(h) * dy;
    l += -std::sin(h) * dx + std::cos(h) * dy;
  }

  double segment_s_;
  bool started_ = false;
  double forward_mm_ = 0, left_mm_ = 0;  // closed segments
  double seg_t_ = -1, last_t_ = 0;
  Vec seg_start_, last_;
  double yaw_ = 0, first_yaw_ = 0, last_yaw_ = 0, yaw_area_ = 0;  // unwrapped yaw [deg], its integral [deg s]
};

}  // namespace strider_sim
