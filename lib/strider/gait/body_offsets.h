//! BodyOffsets: the user's body pose offsets (translation, roll, pitch,
//! yaw), which the gait engine moves the body to at a limited rate.
#ifndef STRIDER_GAIT_BODY_OFFSETS_H
#define STRIDER_GAIT_BODY_OFFSETS_H

#include "../math/fixed.h"
#include "../math/vec3.h"

namespace strider {

//! The user's body pose offsets (applied while standing and walking).
template <typename S>
struct BodyOffsets {
  Vec3<S> translation_mm;  //!< body shift x, y and height change z [mm]
  S roll_rad, pitch_rad, yaw_rad;
  static BodyOffsets zero() { return BodyOffsets{Vec3<S>(), S(0), S(0), S(0)}; }
};
// BodyPosture::step_pose() walks the six offsets as an array.
static_assert(sizeof(BodyOffsets<float>) == 6 * sizeof(float) && sizeof(BodyOffsets<Fixed>) == 6 * sizeof(Fixed),
              "BodyOffsets: six scalars, no padding");

}  // namespace strider

#endif  // STRIDER_GAIT_BODY_OFFSETS_H
