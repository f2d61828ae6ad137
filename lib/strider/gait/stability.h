//! Static stability (seed 003 section 3): the support polygon of the feet on
//! the ground, and the stability margin of the CoM's ground projection.
//!
//! Seed 003: a robot is statically stable when its CoM lies inside the
//! support polygon, "the polygon with the vertices described by the position
//! of legs in contact with the ground" (fig. 2, eq 11). Feet are not points:
//! seed 000 section 3.3 relies on "the wide ends of the legs" for support
//! while two legs are up. So each foot is a disc of radius r (the foot pad,
//! gait_params.h) and the support region is the convex hull of the discs,
//! which is the hull of the foot centres grown by r. The margin is the signed
//! distance from the CoM projection to that region's boundary: positive
//! inside, negative outside (-(distance to the region)). Two feet down give a
//! strip of half-width r around their segment; one foot a disc.
//!
//! The hull is built once per change of the feet in contact (build()), as
//! foot indices in counter-clockwise order plus each edge's length: feet on
//! the ground move rigidly with respect to the body, so neither changes until
//! the next lift-off or touch-down. Per tick, margin() and constrain() cost a
//! few products per edge and no division (except constrain() along x only).
//! Fixed works in units of 2^shift mm so squares of body-sized distances fit.
#ifndef STRIDER_GAIT_STABILITY_H
#define STRIDER_GAIT_STABILITY_H

#include "../kinematics/leg_ik_common.h"
#include "../robots/robot_model.h"

namespace strider {

//! The margin reported when no foot is on the ground [mm].
constexpr double kNoSupportMarginMm = -999.0;

template <typename S>
class SupportPolygon {
 public:
  //! The hull of the feet i < n with contact[i] (their x, y) [mm], feet of
  //! radius foot_radius_mm; shift: working units 2^shift mm (0 for float).
  void build(const Vec3<S>* feet, const bool* contact, uint8_t n, S foot_radius_mm, int8_t shift) {
    shift_ = shift;
    radius_ = foot_radius_mm;
    count_ = 0;
    uint8_t pts[kMaxLegs];
    uint8_t m = 0;
    for (uint8_t i = 0; i < n && i < kMaxLegs; ++i)
      if (contact[i]) pts[m++] = i;
    if (m == 0) return;
    // Gift wrapping from the lowest-x (then lowest-y) foot, counter-clockwise.
    uint8_t start = pts[0];
    for (uint8_t k = 1; k < m; ++k) {
      const uint8_t i = pts[k];
      if (feet[i].x < feet[start].x || (feet[i].x == feet[start].x && feet[i].y < feet[start].y)) start = i;
    }
    uint8_t current = start;
    do {
      idx_[count_++] = current;
      uint8_t next = current;
      for (uint8_t k = 0; k < m; ++k) {
        const uint8_t i = pts[k];
        if (i == current) continue;
        if (next == current) { next = i; continue; }
        const S c = cross(feet, current, next, i);
        // i is right of current->next: wrap tighter; collinear: take the farther.
        if (c < S(0) || (c == S(0) && dist2(feet, current, i) > dist2(feet, current, next))) next = i;
      }
      current = next;
    } while (current != start && count_ < m);
    if (count_ == 2 && same_point(feet, idx_[0], idx_[1])) count_ = 1;
    for (uint8_t k = 0; k < count_; ++k) {
      const Vec3<S> e = edge(feet, k);
      const S len = sqrt(e.x * e.x + e.y * e.y);
      inv_len_[k] = len > S(0) ? S(1) / len : S(0);
    }
  }

  uint8_t size() const { return count_; }        //!< hull vertices
  uint8_t vertex(uint8_t k) const { return idx_[k]; }  //!< foot index of vertex k (CCW)

  //! The stability margin [mm] of the point (x, y) [mm]: signed distance to
  //! the boundary of the hull of the contact discs, positive inside.
  S margin(const Vec3<S>* feet, S x_mm, S y_mm) const {
    if (count_ == 0) return scalar<S>(kNoSupportMarginMm);
    const Vec3<S> p(unit(x_mm), unit(y_mm), S(0));
    S inside = S(0);
    bool is_inside = count_ >= 3;
    for (uint8_t k = 0; k < count_ && is_inside; ++k) {
      const S d = line_distance(feet, k, p);
      if (d < S(0)) is_inside = false;
      if (k == 0 || d < inside) inside = d;
    }
    if (is_inside) return radius_ + leg_ik::from_unit(inside, shift_);
    S best = S(0);
    for (uint8_t k = 0; k < count_; ++k) {
      const S d = segment_distance(feet, k, p);
      if (k == 0 || d < best) best = d;
      if (count_ <= 2) break;  // one segment (or one point)
    }
    return radius_ - leg_ik::from_unit(best, shift_);
  }

  //! Moves the point (x, y) [mm] to where its margin is at least want_mm,
  //! close to where it was: alternating projections onto the half-planes of
  //! the shrunken region, 4 sweeps (continuous in the feet and the point).
  //! With x_only the point moves along x only (legs that cannot step
  //! sideways), to the nearest x the half-planes allow. The region used: the
  //! foot-centre polygon shrunk by max(want - r, 0) for 3 or more feet; for
  //! two feet the part of their strip of half-width r - want between them.
  void constrain(const Vec3<S>* feet, S& x_mm, S& y_mm, S want_mm, bool x_only) const {
    if (count_ == 0) return;
    Plane planes[kMaxLegs];
    const uint8_t n = half_planes(feet, unit(want_mm), planes);
    S x = unit(x_mm), y = unit(y_mm);
    if (!x_only) {
      for (uint8_t sweep = 0; sweep < 4; ++sweep)
        for (uint8_t k = 0; k < n; ++k) {
          const S gap = planes[k].c - (planes[k].nx * x + planes[k].ny * y);
          if (gap > S(0)) {
            x += gap * planes[k].nx;
            y += gap * planes[k].ny;
          }
        }
    } else {
      S lo = S(0), hi = S(0);
      bool has_lo = false, has_hi = false;
      for (uint8_t k = 0; k < n; ++k) {
        const S nx = planes[k].nx;
        if (abs(nx) < scalar<S>(0.05)) continue;  // an edge along x: no x fixes it
        const S t = (planes[k].c - (nx * x + planes[k].ny * y)) / nx;
        if (nx > S(0)) { if (!has_lo || t > lo) lo = t; has_lo = true; }
        else { if (!has_hi || t < hi) hi = t; has_hi = true; }
      }
      S t = S(0);
      if (has_lo && has_hi && hi < lo) t = (lo + hi) * scalar<S>(0.5);  // empty: the middle
      else if (has_lo && lo > S(0)) t = lo;
      else if (has_hi && hi < S(0)) t = hi;
      x += t;
    }
    x_mm = leg_ik::from_unit(x, shift_);
    y_mm = leg_ik::from_unit(y, shift_);
  }

 private:
  struct Plane {
    S nx, ny, c;  //!< n . p >= c, |n| = 1 [unit]
  };

  S unit(S mm) const { return leg_ik::to_unit(mm, shift_); }
  Vec3<S> at(const Vec3<S>* feet, uint8_t i) const { return Vec3<S>(unit(feet[i].x), unit(feet[i].y), S(0)); }
  Vec3<S> edge(const Vec3<S>* feet, uint8_t k) const {
    return at(feet, idx_[(k + 1) % count_]) - at(feet, idx_[k]);
  }
  S cross(const Vec3<S>* feet, uint8_t o, uint8_t a, uint8_t b) const {
    const Vec3<S> u = at(feet, a) - at(feet, o), v = at(feet, b) - at(feet, o);
    return u.x * v.y - u.y * v.x;
  }
  S dist2(const Vec3<S>* feet, uint8_t a, uint8_t b) const {
    const Vec3<S> d = at(feet, b) - at(feet, a);
    return d.x * d.x + d.y * d.y;
  }
  bool same_point(const Vec3<S>* feet, uint8_t a, uint8_t b) const { return dist2(feet, a, b) == S(0); }
  //! Signed distance of p [unit] from edge k's line, positive inside (left).
  S line_distance(const Vec3<S>* feet, uint8_t k, const Vec3<S>& p) const {
    const Vec3<S> e = edge(feet, k), r = p - at(feet, idx_[k]);
    return (e.x * r.y - e.y * r.x) * inv_len_[k];
  }
  //! Distance of p [unit] from edge k as a segment (a point for one foot).
  S segment_distance(const Vec3<S>* feet, uint8_t k, const Vec3<S>& p) const {
    const Vec3<S> a = at(feet, idx_[k]);
    const Vec3<S> r = p - a;
    if (count_ == 1) return hypot(r.x, r.y);
    const Vec3<S> e = edge(feet, k);
    const S t = clamp((r.x * e.x + r.y * e.y) * inv_len_[k] * inv_len_[k], S(0), S(1));
    return hypot(r.x - e.x * t, r.y - e.y * t);
  }
  //! The half-planes of the region with margin >= want [unit].
  uint8_t half_planes(const Vec3<S>* feet, S want, Plane* out) const {
    const S r = unit(radius_);
    if (count_ == 1) {  // a square around the foot, inside its disc
      const Vec3<S> a = at(feet, idx_[0]);
      const S w = max_of(r - want, S(0)) * scalar<S>(0.7071);
      out[0] = Plane{S(1), S(0), a.x - w};
      out[1] = Plane{-S(1), S(0), -a.x - w};
      out[2] = Plane{S(0), S(1), a.y - w};
      out[3] = Plane{S(0), -S(1), -a.y - w};
      return 4;
    }
    if (count_ == 2) {  // the strip between the two feet
      const Vec3<S> a = at(feet, idx_[0]), b = at(feet, idx_[1]);
      const Vec3<S> e = (b - a) * inv_len_[0];
      const S w = max_of(r - want, S(0));
      const S na = -e.y * a.x + e.x * a.y;  // n = (-e.y, e.x)
      out[0] = Plane{-e.y, e.x, na - w};
      out[1] = Plane{e.y, -e.x, -na - w};
      out[2] = Plane{e.x, e.y, e.x * a.x + e.y * a.y};
      out[3] = Plane{-e.x, -e.y, -(e.x * b.x + e.y * b.y)};
      return 4;
    }
    const S shrink = max_of(want - r, S(0));
    for (uint8_t k = 0; k < count_; ++k) {
      const Vec3<S> a = at(feet, idx_[k]);
      const Vec3<S> e = edge(feet, k) * inv_len_[k];
      out[k] = Plane{-e.y, e.x, -e.y * a.x + e.x * a.y + shrink};
    }
    return count_;
  }

  uint8_t count_ = 0;
  uint8_t idx_[kMaxLegs] = {};
  S inv_len_[kMaxLegs] = {};
  S radius_ = S(0);
  int8_t shift_ = 0;
};

}  // namespace strider

#endif  // STRIDER_GAIT_STABILITY_H
