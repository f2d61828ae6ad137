// strider-sim's trace metrics on made-up traces (no physics): the drift in
// the starting body frame (lateral_drift_mm) against the drift in the body
// frame of each instant (body_drift_mm, body_track.h).
#include <gtest/gtest.h>

#include <cmath>

#include "body_track.h"
#include "sim_run.h"

namespace {

using strider_sim::RunResult;
using strider_sim::Scenario;
using strider_sim::TraceRow;

constexpr double kDeg = M_PI / 180.0;

// A trace of `seconds` at 50 rows/s: speed v [mm/s] at `crab_deg` to the
// left of the heading, which starts at `yaw0_deg`, is turned by `offset_deg`
// within the first second and then turns at `rate_deg_s`.
RunResult walk(double seconds, double v, double crab_deg, double yaw0_deg, double offset_deg, double rate_deg_s) {
  RunResult r;
  double x = 0, y = 0;
  const double dt = 0.02;
  const long n = std::lround(seconds / dt);
  auto yaw_at = [&](double t) { return yaw0_deg + offset_deg * std::fmin(t, 1.0) + rate_deg_s * t; };
  for (long k = 0; k <= n; ++k) {
    const double t = double(k) * dt;
    if (k > 0) {
      const double a = yaw_at(t - 0.5 * dt) * kDeg + crab_deg * kDeg;
      x += v * dt * std::cos(a);
      y += v * dt * std::sin(a);
    }
    TraceRow row;
    row.t_s = t;
    row.body.pos_mm.x = x;
    row.body.pos_mm.y = y;
    row.body.yaw_deg = yaw_at(t);
    r.trace.push_back(row);
  }
  strider_sim::compute_metrics(Scenario{}, r);
  return r;
}

// Walking straight ahead along a heading 5 deg off the start's: the drift
// in the starting frame grows with the distance, the body frame's does not.
TEST(SimMetrics, ConstantHeadingOffsetIsNoBodyFrameDrift) {
  const RunResult a = walk(10.0, 150.0, 0.0, 30.0, 5.0, 0.0);
  const RunResult b = walk(40.0, 150.0, 0.0, 30.0, 5.0, 0.0);
  EXPECT_NEAR(a.metrics.distance_mm, 1500.0, 5.0);
  EXPECT_NEAR(b.metrics.lateral_drift_mm, std::sin(5.0 * kDeg) * 6000.0, 10.0);
  EXPECT_GT(b.metrics.lateral_drift_mm, 3.5 * a.metrics.lateral_drift_mm);
  EXPECT_LT(a.metrics.body_drift_mm, 0.5);
  EXPECT_LT(b.metrics.body_drift_mm, 0.5);
}

// A slow turn (1 deg/s) while walking straight ahead: 40 s, 40 deg: the
// starting frame sees a third of the distance sideways, the body frame none.
TEST(SimMetrics, SlowTurnIsNoBodyFrameDrift) {
  const RunResult r = walk(40.0, 150.0, 0.0, -60.0, 0.0, 1.0);
  EXPECT_GT(r.metrics.lateral_drift_mm, 0.3 * r.metrics.distance_mm);
  EXPECT_LT(r.metrics.body_drift_mm, 0.5);
  EXPECT_NEAR(r.metrics.heading_change_deg, 40.0, 1e-6);
}

// Crabbing: moving 3 deg to the left of a constant heading is drift in both
// frames, the same amount; with the slow turn on top only the body frame
// still measures the crab alone.
TEST(SimMetrics, CrabbingIsBodyFrameDrift) {
  const double crab = std::sin(3.0 * kDeg) * 150.0 * 40.0;
  const RunResult straight = walk(40.0, 150.0, 3.0, 0.0, 0.0, 0.0);
  EXPECT_NEAR(straight.metrics.body_drift_mm, crab, 1.0);
  EXPECT_NEAR(straight.metrics.lateral_drift_mm, crab, 1.0);
  const RunResult turning = walk(40.0, 150.0, 3.0, 0.0, 0.0, -1.0);
  EXPECT_NEAR(turning.metrics.body_drift_mm, crab, 1.0);
  EXPECT_GT(turning.metrics.lateral_drift_mm, 4.0 * crab);
}

// A trot's zig-zag (sprawl8: the body moves 40 deg left and right of its
// heading, half a cycle each, its yaw swinging 5 deg the other way): the
// track's forward part is the distance made good, its sideways part near 0.
// Rotating each 20 ms sample by its own yaw would lose 4-5 % to the sway.
TEST(SimMetrics, GaitSwayIsNeitherDriftNorLostDistance) {
  strider_sim::BodyTrack track;
  strider_sim::BodyState b;
  const double heading = 20.0, cycle_s = 0.8, v = 150.0;
  double per_sample_forward = 0;
  for (int k = 0; k <= 1520; ++k) {  // 30.4 s: 38 whole cycles
    const double t = 0.02 * k;
    const double s = std::sin(2.0 * M_PI * (t + 0.01) / cycle_s);
    const double dir = (heading + (s > 0 ? 40.0 : -40.0)) * kDeg;
    const double yaw = heading - 5.0 * s;
    if (k > 0) {
      const double step = v / std::cos(40.0 * kDeg) * 0.02;
      b.pos_mm.x += step * std::cos(dir);
      b.pos_mm.y += step * std::sin(dir);
      per_sample_forward += step * std::cos(dir - (yaw + b.yaw_deg) * 0.5 * kDeg);
    }
    b.yaw_deg = yaw;
    track.add(t, b);
  }
  const double distance = std::hypot(b.pos_mm.x, b.pos_mm.y);
  EXPECT_NEAR(distance, 4560.0, 30.0);
  EXPECT_NEAR(track.forward_mm(), distance, 0.01 * distance);
  EXPECT_LT(std::fabs(track.left_mm()), 0.01 * distance);
  EXPECT_LT(per_sample_forward, 0.97 * distance);  // what the segments avoid
  EXPECT_NEAR(track.turned_deg(), 0.0, 5.0);
}

// Strafing: the drift is the forward part, in both frames.
TEST(SimMetrics, StrafingDriftIsTheForwardPart) {
  const RunResult r = walk(10.0, 40.0, 88.0, 10.0, 0.0, 0.0);
  EXPECT_NEAR(r.metrics.body_drift_mm, std::cos(88.0 * kDeg) * 400.0, 0.5);
  EXPECT_NEAR(r.metrics.lateral_drift_mm, r.metrics.body_drift_mm, 0.5);
}

}  // namespace
