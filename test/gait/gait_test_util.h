// Shared code of the gait tests: scalar conversions, a walker per model
// and gait, a recorder of whole runs, and the per-tick step bound.
#ifndef STRIDER_TEST_GAIT_GAIT_TEST_UTIL_H
#define STRIDER_TEST_GAIT_GAIT_TEST_UTIL_H

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "gait/gait_library.h"
#include "gait/walker.h"
#include "scalar_conv.h"

namespace gaittest {

using strider::Fixed;
using strider::GaitConfig;
using strider::GaitEngine;
using strider::GaitTable;
using strider::IkStatus;
using strider::RobotModel;
using strider::Vec3;
using strider::Walker;
using Scalars = ::testing::Types<float, Fixed>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDt = 0.02;  // the firmware's 50 Hz tick [s]

using strider_test::dbl;
using strider_test::sc;

struct P2 {
  double x, y, z;
};
template <typename S>
P2 p2(const Vec3<S>& v) {
  return P2{dbl(v.x), dbl(v.y), dbl(v.z)};
}
inline double dist(const P2& a, const P2& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

//! One tick of a run: engine feet (stance frame), leg results, margin.
struct Tick {
  double t;
  std::string state;
  double vx, vy, wz, hz, shift_x, shift_y, margin;
  uint16_t phase;
  std::vector<P2> foot;     // engine target, stance frame [mm]
  std::vector<P2> body;     // target in the body frame [mm]
  std::vector<P2> reached;  // foot the joints reach, body frame [mm]
  std::vector<bool> contact;
  std::vector<IkStatus> ik, status;
  std::vector<double> clamp;
  std::vector<std::vector<double>> q;  // [rad]
};

//! A walker built once per model, gait and scalar (config cached).
template <typename S>
struct Rig {
  const RobotModel* model = nullptr;
  const GaitTable* gait = nullptr;
  std::unique_ptr<Walker<S>> walker{new Walker<S>()};
  GaitConfig<S> config;

  Rig(const RobotModel& m, const GaitTable& g) : model(&m), gait(&g) {
    const strider::GaitParams& p = *strider::gait_params_for(m);
    strider::AnyLeg<S> legs[strider::kMaxLegs];
    for (uint8_t i = 0; i < m.leg_count; ++i) strider::AnyLeg<S>::from_model(m, i, legs[i]);
    config = strider::make_gait_config(m, legs, p, p.shape);
    reset();
  }
  void reset(bool sitting = false) { walker->configure(*model, *gait, config, sitting); }
  GaitEngine<S>& engine() { return walker->engine(); }

  Tick tick(double dt = kDt) {
    walker->tick(sc<S>(dt));
    return snapshot();
  }
  Tick snapshot() const {
    const GaitEngine<S>& e = walker->engine();
    Tick k{};
    k.state = strider::to_string(e.state());
    k.vx = dbl(e.vx());
    k.vy = dbl(e.vy());
    k.wz = dbl(e.wz());
    k.hz = dbl(e.step_hz());
    k.shift_x = dbl(e.shift_x_mm());
    k.shift_y = dbl(e.shift_y_mm());
    k.margin = dbl(e.margin_mm());
    k.phase = e.phase();
    for (uint8_t i = 0; i < model->leg_count; ++i) {
      const strider::LegResult<S>& r = walker->leg(i);
      k.foot.push_back(p2(e.foot(i)));
      k.body.push_back(p2(r.target_mm));
      k.reached.push_back(p2(r.foot_mm));
      k.contact.push_back(e.contact(i));
      k.ik.push_back(r.ik_status);
      k.status.push_back(r.status);
      k.clamp.push_back(dbl(r.clamp_mm));
      std::vector<double> q;
      for (uint8_t j = 0; j < model->dof(); ++j) q.push_back(dbl(r.q[j]));
      k.q.push_back(q);
    }
    return k;
  }
  //! Runs `seconds`, appending to `out`.
  void run(double seconds, std::vector<Tick>& out, double dt = kDt) {
    const int n = int(std::lround(seconds / dt));
    for (int i = 0; i < n; ++i) {
      Tick k = tick(dt);
      k.t = out.empty() ? dt : out.back().t + dt;
      out.push_back(k);
    }
  }
  //! Runs until the engine stands (at most `limit_s`); true if it did.
  bool run_until_standing(std::vector<Tick>& out, double limit_s, double dt = kDt) {
    const int n = int(std::lround(limit_s / dt));
    for (int i = 0; i < n; ++i) {
      Tick k = tick(dt);
      k.t = out.empty() ? dt : out.back().t + dt;
      out.push_back(k);
      if (walker->engine().state() == strider::GaitState::kStanding) return true;
    }
    return false;
  }
  double cycle_s() const { return 1.0 / dbl(walker->engine().step_hz()); }
};

//! Every (model, gait) pair of the library.
struct Case {
  const RobotModel* model;
  const GaitTable* gait;
  std::string name() const { return std::string(model->name) + "/" + gait->name; }
};
inline std::vector<Case> all_cases() {
  std::vector<Case> v;
  for (const RobotModel* m : strider::kAllRobots) {
    const strider::GaitList list = strider::gaits_for(*m);
    for (uint8_t i = 0; i < list.count; ++i) v.push_back(Case{m, list.items[i]});
  }
  return v;
}

//! A velocity command [mm/s, mm/s, deg/s].
struct Command {
  double vx, vy, wz_deg;
};
//! Every direction (8, 45 deg apart) at full speed, turning both ways, and
//! walking while turning.
inline std::vector<Command> sweep_commands() {
  std::vector<Command> v;
  for (int k = 0; k < 8; ++k) {
    const double a = k * kPi / 4.0;
    v.push_back(Command{1000.0 * std::cos(a), 1000.0 * std::sin(a), 0.0});
  }
  v.push_back(Command{0.0, 0.0, 360.0});
  v.push_back(Command{0.0, 0.0, -360.0});
  v.push_back(Command{600.0, 300.0, 90.0});
  v.push_back(Command{-400.0, 0.0, -60.0});
  return v;
}

//! Upper bound of a foot's travel in one tick [mm] while walking at the
//! engine's planned command (and any command up to it): stance
//! (|v| + |w| r) dt; swing (L max|u'| + h max|w'|) f dt / (1 - d) with
//! max|u'| <= 3, max|w'| <= 5 for every shape (rectangle 3 and 3, ellipse
//! pi/2 and pi, cycloid 2 and pi, parabola 1 and 4, Bezier 2.3 and 4.9,
//! checked in test_gait_parts), L the longest step |touch-down - lift-off|;
//! plus the body shift's and the pose's rate limits and the touch-down
//! point's rate limit (which moves a swinging foot by at most its step).
template <typename S>
double step_bound_mm(const GaitConfig<S>& c, double vx, double vy, double wz, double hz, double duty,
                     double longest_step_mm, double dt = kDt) {
  double r = 0.0;
  for (uint8_t i = 0; i < c.leg_count; ++i) r = std::max(r, std::hypot(dbl(c.home[i].x), dbl(c.home[i].y)));
  const double stance = (std::hypot(vx, vy) + std::fabs(wz) * (r + longest_step_mm)) * dt;
  const double swing = (3.0 * longest_step_mm + 5.0 * dbl(c.step_height_mm)) * hz * dt / (1.0 - duty);
  const double extras = (dbl(c.shift_speed_mm_s) + dbl(c.target_speed_mm_s) + 2.0 * dbl(c.pose_speed_mm_s)) * dt;
  return std::max(stance, swing) + extras;
}

}  // namespace gaittest

#endif  // STRIDER_TEST_GAIT_GAIT_TEST_UTIL_H
