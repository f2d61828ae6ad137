//! GaitParams: each robot model's gait defaults (how it walks; the models
//! describe geometry), one entry per model in kAllRobots order. Float,
//! millimetres, seconds; test/gait checks every foot target reachable at
//! these defaults over whole cycles in every direction.
#ifndef STRIDER_GAIT_GAIT_PARAMS_H
#define STRIDER_GAIT_GAIT_PARAMS_H

#include <string.h>

#include "../math/flash_table.h"
#include "../robots/all_robots.h"
#include "gait_table.h"
#include "swing_trajectory.h"

namespace strider {

//! Longest model name, its terminating zero included.
constexpr uint8_t kRobotNameBytes = 10;

struct GaitParams {
  // Arrays, not pointers: kGaitParams is in flash on the AVR, and so are its
  // names (pointers would keep the strings in RAM).
  char robot[kRobotNameBytes];         //!< model name (kAllRobots order)
  char default_gait[kGaitNameBytes];   //!< gait used when none is named
  SwingShape shape;           //!< default swing trajectory
  float step_height_mm;       //!< swing apex above the ground [mm]
  float step_length_mm;       //!< preferred stride [mm]: faster walking raises the step rate first
  float cycle_s;              //!< cycle time at low speed [s]
  float stance_depth_mm;      //!< stance foot pressed below the ground line mid-stance [mm]
  float foot_radius_mm;       //!< foot pad radius: the support region is the hull of the pads [mm]
  float com_x_mm;             //!< CoM ground projection, body frame, unshifted [mm]
  float com_y_mm;             //!< [mm]
  float margin_mm;            //!< stability margin the body shift aims for (walk, crawl) [mm]
  float shift_budget_mm;      //!< reach kept free for the body shift [mm]
  float sit_drop_mm;          //!< how far the body lowers from standing to sitting [mm]
  float transition_s;         //!< stand-up and sit-down time [s]
};

//! One entry per model, in the order of kAllRobots. In flash on the AVR:
//! read it there through gait_params_of().
constexpr GaitParams kGaitParams[kRobotCount] STRIDER_PROGMEM = {
    // sprawl8 (seed 000): 20 mm steps clear a cable; 10 mm foot pads are the
    // seed's "wide ends of the legs".
    {"sprawl8", "crawl", SwingShape::kEllipse, 20.0f, 40.0f, 0.8f, 0.0f, 10.0f, 0.0f, 0.0f, 6.0f, 12.0f,
     30.0f, 1.0f},
    // mammal8 (seed 003): short steps and a 2 s cycle (the seed's walk is
    // slow); the 11 mm margin keeps the CoM 6 mm inside its 5 mm ball feet
    // (other margins: docs/simulator.md).
    {"mammal8", "walk", SwingShape::kEllipse, 20.0f, 30.0f, 2.0f, 0.0f, 5.0f, 0.0f, 0.0f, 11.0f, 20.0f, 40.0f,
     1.5f},
    // dog12 (seed 001): the seed's rectangle swing (section 3.2); it crawls (a trot tips: docs/simulator.md).
    {"dog12", "crawl", SwingShape::kRectangle, 50.0f, 120.0f, 1.0f, 0.0f, 15.0f, 0.0f, 0.0f, 10.0f, 40.0f,
     100.0f, 2.0f},
    {"hexapod18", "tripod", SwingShape::kCycloid, 30.0f, 60.0f, 1.0f, 0.0f, 5.0f, 0.0f, 0.0f, 10.0f, 0.0f,
     50.0f, 1.5f},
    {"spider12", "walk", SwingShape::kEllipse, 20.0f, 40.0f, 1.2f, 0.0f, 4.0f, 0.0f, 0.0f, 4.0f, 20.0f, 30.0f,
     1.0f},
};

namespace gait_params_detail {
constexpr bool matches_models() {
  for (uint8_t i = 0; i < kRobotCount; ++i)
    if (!model_checks::same_name(kGaitParams[i].robot, kAllRobots[i]->name)) return false;
  return true;
}
constexpr bool values_sane() {
  for (uint8_t i = 0; i < kRobotCount; ++i) {
    const GaitParams& p = kGaitParams[i];
    if (!(p.step_height_mm > 0.0f && p.step_length_mm > 0.0f && p.cycle_s > 0.0f)) return false;
    if (!(p.stance_depth_mm >= 0.0f && p.foot_radius_mm >= 0.0f && p.margin_mm >= 0.0f)) return false;
    if (!(p.shift_budget_mm >= 0.0f && p.sit_drop_mm >= 0.0f && p.transition_s > 0.0f)) return false;
  }
  return true;
}
}  // namespace gait_params_detail

static_assert(gait_params_detail::matches_models(), "kGaitParams: one entry per model, in kAllRobots order");
static_assert(gait_params_detail::values_sane(), "kGaitParams: positive sizes and times");

//! The index of `model`'s gait defaults in kGaitParams (by name), or
//! kRobotCount for a model not listed.
inline uint8_t gait_params_index(const RobotModel& model) {
  for (uint8_t i = 0; i < kRobotCount; ++i) {
    char robot[kRobotNameBytes];  // the name alone: a whole GaitParams is a large stack frame on the AVR
    flash_copy(robot, kGaitParams[i].robot, sizeof robot);
    if (strcmp(robot, model.name) == 0) return i;
  }
  return kRobotCount;
}

//! The gait defaults of `model` into *out; false (out untouched) for a
//! model not listed.
inline bool gait_params_of(const RobotModel& model, GaitParams* out) {
  const uint8_t i = gait_params_index(model);
  if (i >= kRobotCount) return false;
  flash_copy(out, &kGaitParams[i], sizeof *out);
  return true;
}

#if !defined(__AVR__)
//! The gait defaults of `model` (by name; nullptr for a model not listed).
//! Host only: on the AVR the table is in flash (gait_params_of()).
inline const GaitParams* gait_params_for(const RobotModel& model) {
  const uint8_t i = gait_params_index(model);
  return i < kRobotCount ? &kGaitParams[i] : nullptr;
}
#endif

}  // namespace strider

#endif  // STRIDER_GAIT_GAIT_PARAMS_H
