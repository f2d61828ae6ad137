//! Where a 2-DOF leg can put its foot while walking (docs/gaits.md, "2-DOF
//! legs"): a planar leg drops the sideways component; a sprawling leg keeps
//! the height and the direction from the hip, at rho = a1 + sqrt(a2^2 - z^2)
//! (seed 000 eq 8); 3-DOF legs are unchanged.
#ifndef STRIDER_GAIT_REACH_PROJECTION_H
#define STRIDER_GAIT_REACH_PROJECTION_H

#include "../robots/robot_model.h"
#include "../math/working_units.h"

namespace strider {

//! The constants of one leg's projection, in S (built once per model).
template <typename S>
struct ReachProjection {
  LegKind kind;
  S a1_mm;      //!< sprawl: thigh a1
  S a2_mm;      //!< sprawl: shank a2
  int8_t shift; //!< working units for the sprawl's squares (math/working_units.h)

  static constexpr ReachProjection make(const RobotModel& model) {
    const S a1 = scalar<S>(model.links.l1_mm), a2 = scalar<S>(model.links.l2_mm);
    return ReachProjection{model.kind, a1, a2, units::unit_shift(a1 + a2)};
  }

  //! True for the kinds whose reachable set is a surface.
  bool projects() const { return sprawl() || planar(); }

  bool sprawl() const { return kind == LegKind::kSprawl; }
  bool planar() const { return kind == LegKind::kPlanar; }

  //! The target [mm, leg frame] moved onto the reachable set; moved_mm gets
  //! the distance it moved (0 for 3-DOF legs).
  Vec3<S> apply(const Vec3<S>& target, S& moved_mm) const {
    moved_mm = S(0);
    if (planar()) {
      moved_mm = abs(target.y);
      return Vec3<S>(target.x, S(0), target.z);
    }
    if (!sprawl()) return target;
    const S x = units::to_unit(target.x, shift), y = units::to_unit(target.y, shift);
    const S a1 = units::to_unit(a1_mm, shift), a2 = units::to_unit(a2_mm, shift);
    const S z = clamp(units::to_unit(target.z, shift), -a2, a2);
    const S rho = sqrt(x * x + y * y);
    const S rho_new = a1 + sqrt(a2 * a2 - z * z);
    Vec3<S> out;
    if (rho > S(0)) {
      const S k = rho_new / rho;
      out = Vec3<S>(x * k, y * k, z);
    } else {
      out = Vec3<S>(rho_new, S(0), z);  // on the yaw axis: face forward
    }
    const S dr = rho_new - rho, dz = z - units::to_unit(target.z, shift);
    moved_mm = units::from_unit(sqrt(dr * dr + dz * dz), shift);  // the move is radial and vertical
    return Vec3<S>(units::from_unit(out.x, shift), units::from_unit(out.y, shift),
                   units::from_unit(out.z, shift));
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_REACH_PROJECTION_H
