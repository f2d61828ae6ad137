//! ReachEdge: whether a foot is at the edge of its reach, beyond kEdgeShare
//! of the longest stride its leg may make in its direction from home (the
//! IK limit is at 0.556): a foot on the ground there lifts early, or holds
//! the body still (docs/gaits.md, "Starting, stopping and transitions").
#ifndef STRIDER_GAIT_REACH_EDGE_H
#define STRIDER_GAIT_REACH_EDGE_H

#include "gait_config.h"
#include "../math/working_units.h"
#include "stance.h"

namespace strider {

template <typename S, uint8_t kLegs>
struct ReachEdge {
  static constexpr double kEdgeShare = 0.53;
  // Squared radius [unit^2] inside which no foot is at its edge.
  S r2[kLegs];

  template <bool kSearch>
  void configure(const GaitConfig<S, kLegs, kSearch>& cfg) {
    // kEdgeShare of the shortest stride (2 edge_mm), 1 % less for rounding.
    constexpr S share = scalar<S>(kEdgeShare * 2.0 * 0.99);
    for (uint8_t i = 0; i < cfg.leg_count; ++i) {
      const S r = units::to_unit(cfg.edge_mm[i] * share, cfg.unit_shift);
      r2[i] = r * r;
    }
  }

  template <bool kSearch>
  STRIDER_ALWAYS_INLINE bool beyond(const GaitConfig<S, kLegs, kSearch>& cfg, uint8_t i, const Vec3<S>& p) const {
    const S dx = sub_inline(p.x, cfg.home[i].x), dy = sub_inline(p.y, cfg.home[i].y);
    const S r = cfg.edge_mm[i];
    // inside the shortest stride's diamond: no product (sums in place, scalar.h)
    if (add_inline(abs_inline(dx), abs_inline(dy)) <= r) return false;
    return beyond_diamond(cfg, i, dx, dy);
  }

  //! beyond() for a foot (dx, dy) [mm] from home outside the shortest
  //! stride's diamond: apart, so that the usual answer costs no call.
  template <bool kSearch>
  STRIDER_NOINLINE bool beyond_diamond(const GaitConfig<S, kLegs, kSearch>& cfg, uint8_t i, S dx, S dy) const {
    // Inside the shortest stride's circle: two products, no atan2 or root.
    const S ux = units::to_unit(dx, cfg.unit_shift), uy = units::to_unit(dy, cfg.unit_shift);
    if (ux * ux + uy * uy <= r2[i]) return false;
    const S stride = cfg.limits.leg_stride(i, dx, dy);
    const S d = units::norm_in(dx, dy, S(0), cfg.unit_shift);
    constexpr S share = scalar<S>(kEdgeShare);
    return d > stride * share;
  }

  //! Would `step` take foot p of `home` farther from home? (Out of line:
  //! its point stays out of the walking tick's frame.)
  STRIDER_NOINLINE static bool takes_out(const Vec3<S>& p, const Vec3<S>& home, const BodyStep<S>& step) {
    const Vec3<S> next = step.move_ground_point(p);
    const S before = abs(p.x - home.x) + abs(p.y - home.y);
    const S after = abs(next.x - home.x) + abs(next.y - home.y);
    return after > before;
  }
};

}  // namespace strider

#endif  // STRIDER_GAIT_REACH_EDGE_H
