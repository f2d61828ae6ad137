//! GaitConfig: everything the gait engine needs about one robot, in the
//! scalar S, built once at configuration time from the robot model, its gait
//! defaults (gait_params.h) and its legs (the velocity limits need IK).
#ifndef STRIDER_GAIT_GAIT_CONFIG_H
#define STRIDER_GAIT_GAIT_CONFIG_H

#include "gait_params.h"
#include "stance.h"
#include "stored_velocity_limits.h"
#include "velocity_search.h"

namespace strider {

//! kLegs: legs held; kSearch: strides in RAM from the IK search (else in flash).
template <typename S, uint8_t kLegs = kMaxLegs, bool kSearch = true>
struct GaitConfig {
  constexpr GaitConfig()
      : leg_count(0), step_height_mm(), stance_depth_mm(), foot_radius_mm(), com_x_mm(), com_y_mm(), margin_mm(),
        shift_budget_mm(), sit_drop_mm(), accel_mm_s2(), yaw_accel_rad_s2(), shift_speed_mm_s(), target_speed_mm_s(),
        pose_speed_mm_s(), pose_rate_rad_s(), home_tolerance_mm(), shift_x_only(false), unit_shift(0) {}

  uint8_t leg_count;
  Vec3<S> home[kLegs];       //!< standing feet, body frame [mm]
  SwingShape shape = SwingShape::kEllipse;
  S step_height_mm;             //!< swing apex [mm]
  S stance_depth_mm;            //!< [mm]
  S foot_radius_mm;             //!< foot pads [mm]
  S com_x_mm;                   //!< CoM, body frame [mm]
  S com_y_mm;
  S margin_mm;                  //!< body shift's target margin [mm]
  S shift_budget_mm;            //!< reach kept for the shift [mm]
  S sit_drop_mm;                //!< [mm]
  S transition_s = S(1);        //!< stand-up / sit-down time [s]
  S accel_mm_s2;                //!< command ramp, translation [mm/s^2]
  S yaw_accel_rad_s2;           //!< command ramp, yaw [rad/s^2]
  S shift_speed_mm_s;           //!< fastest body shift [mm/s]
  S target_speed_mm_s;          //!< fastest move of a swinging foot's touch-down point [mm/s]
  S pose_speed_mm_s;            //!< fastest change of the body pose offset [mm/s]
  S pose_rate_rad_s;            //!< fastest change of the body rotation [rad/s]
  S home_tolerance_mm;          //!< a foot this close to home needs no final step [mm]
  bool shift_x_only;            //!< planar legs: the body can only shift along x
  uint8_t min_support = 2;      //!< never lift a foot if fewer would stay down
  int8_t unit_shift;            //!< working units of the support polygon (stability.h)
  S edge_mm[kLegs] = {};     //!< half the leg's shortest stride: inside it no foot is at its edge [mm]
  VelocityLimits<S, kSearch> limits;
};

//! Where make_gait_config() takes the velocity limits from.
enum class LimitsSource : uint8_t {
  kStoredOrSearch = 0,  //!< the generated table when it has the model and parameters, else the search
  kSearch = 1           //!< always the IK search (velocity_limits.h)
};

namespace gait_config_detail {
template <typename S>
constexpr S magnitude(S v) { return v < S(0) ? -v : v; }
//! The largest |x| or |y| of the standing feet [mm].
template <typename S, uint8_t kLegs, bool kSearch>
constexpr S reach_of(const GaitConfig<S, kLegs, kSearch>& c) {
  S reach = S(0);
  for (uint8_t i = 0; i < c.leg_count; ++i) reach = max_of(reach, max_of(magnitude(c.home[i].x), magnitude(c.home[i].y)));
  return reach;
}
//! The fixed speed limits of every configuration.
template <typename S, uint8_t kLegs, bool kSearch>
constexpr void set_speeds(GaitConfig<S, kLegs, kSearch>& c) {
  c.shift_speed_mm_s = scalar<S>(400.0);
  c.pose_speed_mm_s = scalar<S>(50.0);
  c.pose_rate_rad_s = scalar<S>(0.5);
  c.home_tolerance_mm = scalar<S>(0.5);
}
//! The fields of the gait defaults and the model's kind (reach: reach_of()).
template <typename S, uint8_t kLegs, bool kSearch>
constexpr void set_params(GaitConfig<S, kLegs, kSearch>& c, const RobotModel& model, const GaitParams& params, SwingShape shape,
                          S reach) {
  c.shape = shape;
  c.step_height_mm = scalar<S>(params.step_height_mm);
  c.stance_depth_mm = scalar<S>(params.stance_depth_mm);
  c.foot_radius_mm = scalar<S>(params.foot_radius_mm);
  c.com_x_mm = scalar<S>(params.com_x_mm);
  c.com_y_mm = scalar<S>(params.com_y_mm);
  c.margin_mm = scalar<S>(params.margin_mm);
  c.shift_budget_mm = scalar<S>(params.shift_budget_mm);
  c.sit_drop_mm = scalar<S>(params.sit_drop_mm);
  c.transition_s = scalar<S>(params.transition_s);
  c.shift_x_only = model.kind == LegKind::kPlanar;
  c.min_support = model.leg_count == 6 ? 3 : 2;
  c.unit_shift = units::unit_shift(reach + reach);
}
//! The velocity limits: stored, or from the IK search.
template <typename S>
void set_limits(VelocityLimits<S, true>& lim, const RobotModel& model, const AnyLeg<S>* legs, const Vec3<S>* home,
                const GaitParams& params, SwingShape shape, S step_height_mm, LimitsSource source) {
  if (source == LimitsSource::kSearch || !stored_velocity_limits(model, params, shape, lim))
    lim = compute_velocity_limits(model, legs, home, shape, step_height_mm, scalar<S>(params.step_length_mm),
                                  scalar<S>(params.cycle_s));
}
//! Without the search: the stored limits, or none (the robot cannot walk).
template <typename S>
void set_limits(VelocityLimits<S, false>& lim, const RobotModel& model, const AnyLeg<S>*, const Vec3<S>*,
                const GaitParams& params, SwingShape shape, S, LimitsSource) {
  if (!stored_velocity_limits(model, params, shape, lim)) lim = VelocityLimits<S, false>();
}
//! Half of each leg's shortest stride of the limits [mm].
template <typename S, uint8_t kLegs, bool kSearch>
void set_edges(GaitConfig<S, kLegs, kSearch>& c) {
  for (uint8_t i = 0; i < c.leg_count; ++i) {
    S shortest = c.limits.stride_mm(i, 0);
    for (uint8_t k = 1; k < kStrideDirections; ++k) shortest = min_of(shortest, c.limits.stride_mm(i, k));
    c.edge_mm[i] = shortest * scalar<S>(0.5);
  }
}
}  // namespace gait_config_detail

//! The ramps of a configuration whose other fields are set: to a trot's top
//! speed in one default cycle (first stances stay within their strides).
template <typename S, uint8_t kLegs, bool kSearch>
void finish_gait_config(GaitConfig<S, kLegs, kSearch>& c) {
  const S reach = gait_config_detail::reach_of(c);
  const S top_speed = c.limits.max_speed_mm_s(c.home, S(1), S(0), scalar<S>(0.5));
  const S top_yaw = c.limits.max_yaw_rate(c.home, scalar<S>(0.5));
  c.accel_mm_s2 = max_of(top_speed * c.limits.min_hz, S(1));
  c.yaw_accel_rad_s2 = max_of(top_yaw * c.limits.min_hz, scalar<S>(0.05));
  c.target_speed_mm_s = max_of((top_speed + top_yaw * reach) * S(2), scalar<S>(10.0));
}

//! Builds (in c) the configuration of `model` with `legs` (an AnyLeg per
//! leg), `params` and `shape`: at start-up (IK search), not per tick.
template <typename S, uint8_t kLegs, bool kSearch>
void fill_gait_config(GaitConfig<S, kLegs, kSearch>& c, const RobotModel& model, const AnyLeg<S>* legs, const GaitParams& params,
                      SwingShape shape, LimitsSource source = LimitsSource::kStoredOrSearch) {
  if (model.leg_count > kLegs) {
    c.leg_count = 0;
    return;
  }
  c.leg_count = model.leg_count;
  for (uint8_t i = 0; i < model.leg_count; ++i) c.home[i] = Vec3<S>::from(model.legs[i].stand_mm);
  gait_config_detail::set_params(c, model, params, shape, gait_config_detail::reach_of(c));
  gait_config_detail::set_limits(c.limits, model, legs, c.home, params, shape, c.step_height_mm, source);
  gait_config_detail::set_edges(c);
  gait_config_detail::set_speeds(c);
  finish_gait_config(c);
}

//! fill_gait_config() as a value (that one builds in place: no AVR stack copy).
template <typename S>
GaitConfig<S> make_gait_config(const RobotModel& model, const AnyLeg<S>* legs, const GaitParams& params,
                               SwingShape shape, LimitsSource source = LimitsSource::kStoredOrSearch) {
  GaitConfig<S> c;
  fill_gait_config(c, model, legs, params, shape, source);
  return c;
}

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_CONFIG_H
