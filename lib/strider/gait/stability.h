//! Static stability (seed 003 section 3): the support polygon of the feet on
//! the ground (the hull of foot pads of radius r) and the CoM's margin, its
//! signed distance to the boundary (docs/gaits.md, "Static stability"). Fixed
//! works in units of 2^shift mm so squares of body-sized distances fit.
#ifndef STRIDER_GAIT_STABILITY_H
#define STRIDER_GAIT_STABILITY_H

#include "../robots/robot_model.h"
#include "../math/working_units.h"

namespace strider {

//! The margin reported when no foot is on the ground [mm].
constexpr double kNoSupportMarginMm = -999.0;

template <typename S, uint8_t kLegs = kMaxLegs>
class SupportPolygon {
  static_assert(kLegs >= 4 && kLegs <= kMaxLegs, "4 slots at least: a two-foot support region has four corners");

 public:
  SupportPolygon() : count_(0), idx_(), inv_len_(), corner_(), radius_(S(0)), shift_(0) {}
  //! The hull of the feet i < n with contact[i] (their x, y) [mm], feet of
  //! radius foot_radius_mm; shift: working units 2^shift mm (0 for float).
  void build(const Vec3<S>* feet, const bool* contact, uint8_t n, S foot_radius_mm, int8_t shift) {
    shift_ = shift;
    radius_ = foot_radius_mm;
    count_ = 0;
    uint8_t pts[kLegs];
    uint8_t m = 0;
    for (uint8_t i = 0; i < n && i < kLegs; ++i)
      if (contact[i]) pts[m++] = i;
    if (m == 0) return;
    // The feet in working units once (the wrapping visits each many times).
    Vec3<S> pu[kLegs];
    for (uint8_t k = 0; k < m; ++k) pu[pts[k]] = at(feet, pts[k]);
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
        const S c = cross(diff(pu[next], pu[current]), diff(pu[i], pu[current]));
        // i is right of current->next: wrap tighter; collinear: take the farther.
        if (c < S(0) || (c == S(0) && dist2(pu[current], pu[i]) > dist2(pu[current], pu[next]))) next = i;
      }
      current = next;
    } while (current != start && count_ < m);
    if (count_ == 2 && dist2(pu[idx_[0]], pu[idx_[1]]) == S(0)) count_ = 1;
    for (uint8_t k = 0; k < count_; ++k) {
      const Vec3<S> e = diff(pu[idx_[next(k)]], pu[idx_[k]]);
      const S len = sqrt(dot(e, e));
      inv_len_[k] = len > S(0) ? S(1) / len : S(0);
    }
    // Shrinking by d moves vertex k (edges k-1 in, k out) to a_k + d n_k + s u_k
    // on both shrunk lines: n_{k-1} . (d n_k + s u_k) = d gives
    // s = d (1 - n_{k-1} . n_k) / (n_{k-1} . u_k), a constant of the shape.
    for (uint8_t k = 0; count_ >= 3 && k < count_; ++k) {
      const uint8_t j = k == 0 ? uint8_t(count_ - 1) : uint8_t(k - 1);
      const Vec3<S> uk = scaled(diff(pu[idx_[next(k)]], pu[idx_[k]]), inv_len_[k]);
      const Vec3<S> uj = scaled(diff(pu[idx_[k]], pu[idx_[j]]), inv_len_[j]);
      const S nn = dot(uj, uk);    // n_j . n_k = u_j . u_k
      const S nu = cross(uj, uk);  // n_j . u_k = cross(u_j, u_k) > 0
      corner_[k] = nu > S(0) ? (S(1) - nn) / nu : S(0);
    }
  }

  uint8_t size() const { return count_; }        //!< hull vertices
  uint8_t vertex(uint8_t k) const { return idx_[k]; }  //!< foot index of vertex k (CCW)

  //! The stability margin [mm] of the point (x, y) [mm].
  S margin(const Vec3<S>* feet, S x_mm, S y_mm) const {
    constexpr S none = scalar<S>(kNoSupportMarginMm);
    if (count_ == 0) return none;
    const Vec3<S> p(unit(x_mm), unit(y_mm), S(0));
    S inside = S(0);
    bool is_inside = count_ >= 3;
    for (uint8_t k = 0; k < count_ && is_inside; ++k) {
      const S d = line_distance(feet, k, p);
      if (d < S(0)) is_inside = false;
      if (k == 0 || d < inside) inside = d;
    }
    if (is_inside) return radius_ + units::from_unit(inside, shift_);
    S best = S(0);
    for (uint8_t k = 0; k < count_; ++k) {
      const S d = segment_distance(feet, k, p);
      if (k == 0 || d < best) best = d;
      if (count_ <= 2) break;  // one segment (or one point)
    }
    return radius_ - units::from_unit(best, shift_);
  }

  //! Moves the point (x, y) [mm] to the nearest point whose margin is at
  //! least want_mm (region()); with x_only along x only (legs that cannot
  //! step sideways), to the nearest x the region allows on its line y.
  void constrain(const Vec3<S>* feet, S& x_mm, S& y_mm, S want_mm, bool x_only) const {
    if (count_ == 0) return;
    Vec3<S> v[kLegs], u[kLegs];
    S len[kLegs];
    const uint8_t n = region(feet, unit(want_mm), v, u, len);
    const Vec3<S> p(unit(x_mm), unit(y_mm), S(0));
    Vec3<S> q = p;
    if (n == 1) {
      q = x_only ? Vec3<S>(v[0].x, p.y, S(0)) : v[0];
    } else if (x_only) {
      q.x = p.x + along_x(v, u, n, p);
    } else if (!inside(v, u, n, p)) {
      S best = S(0);
      for (uint8_t k = 0; k < n; ++k) {
        const S t = clamp(dot(diff(p, v[k]), u[k]), S(0), max_of(len[k], S(0)));
        const Vec3<S> c = along(v[k], u[k], t);
        const S d2 = dist2(c, p);
        if (k == 0 || d2 < best) {
          best = d2;
          q = c;
        }
      }
    }
    x_mm = units::from_unit(q.x, shift_);
    y_mm = units::from_unit(q.y, shift_);
  }

 private:
  S unit(S mm) const { return units::to_unit(mm, shift_); }
  //! The vertex after k (no modulo: a 16-bit division on the AVR).
  uint8_t next(uint8_t k) const { return uint8_t(k + 1) == count_ ? uint8_t(0) : uint8_t(k + 1); }
  Vec3<S> at(const Vec3<S>* feet, uint8_t i) const { return Vec3<S>(unit(feet[i].x), unit(feet[i].y), S(0)); }
  Vec3<S> edge(const Vec3<S>* feet, uint8_t k) const { return diff(at(feet, idx_[next(k)]), at(feet, idx_[k])); }
  // Vectors in the ground plane (x, y; z is 0), each operation written once
  // and called (build() and the region are cold; the rest a few calls per edge).
  static STRIDER_NOINLINE Vec3<S> diff(const Vec3<S>& a, const Vec3<S>& b) {
    return Vec3<S>(a.x - b.x, a.y - b.y, S(0));
  }
  static STRIDER_NOINLINE Vec3<S> sum(const Vec3<S>& a, const Vec3<S>& b) {
    return Vec3<S>(a.x + b.x, a.y + b.y, S(0));
  }
  static STRIDER_NOINLINE Vec3<S> scaled(const Vec3<S>& a, S k) { return Vec3<S>(a.x * k, a.y * k, S(0)); }
  static STRIDER_NOINLINE Vec3<S> along(const Vec3<S>& a, const Vec3<S>& u, S t) {
    return Vec3<S>(a.x + u.x * t, a.y + u.y * t, S(0));
  }
  static STRIDER_NOINLINE S dot(const Vec3<S>& a, const Vec3<S>& b) { return a.x * b.x + a.y * b.y; }
  static STRIDER_NOINLINE S cross(const Vec3<S>& a, const Vec3<S>& b) { return a.x * b.y - a.y * b.x; }
  //! |b - a|^2.
  static S dist2(const Vec3<S>& a, const Vec3<S>& b) {
    const Vec3<S> d = diff(b, a);
    return dot(d, d);
  }
  //! Signed distance of p [unit] from edge k's line, positive inside (left).
  S line_distance(const Vec3<S>* feet, uint8_t k, const Vec3<S>& p) const {
    return cross(edge(feet, k), diff(p, at(feet, idx_[k]))) * inv_len_[k];
  }
  //! Distance of p [unit] from edge k as a segment (a point for one foot).
  S segment_distance(const Vec3<S>* feet, uint8_t k, const Vec3<S>& p) const {
    const Vec3<S> r = diff(p, at(feet, idx_[k]));
    if (count_ == 1) return hypot(r.x, r.y);
    const Vec3<S> e = edge(feet, k);
    const S t = clamp(dot(r, e) * inv_len_[k] * inv_len_[k], S(0), S(1));
    return hypot(r.x - e.x * t, r.y - e.y * t);
  }
  //! The region with margin >= want [unit] as a convex polygon, counter-
  //! clockwise: vertices v, unit edge directions u, edge lengths len (a
  //! negative length: the region is empty there); the vertex count. 3 or
  //! more feet: the foot-centre polygon shrunk by max(want - r, 0), by the
  //! corner_ factors build() caches; two: the rectangle between them of
  //! half-width r - want; one foot: the foot.
  uint8_t region(const Vec3<S>* feet, S want, Vec3<S>* v, Vec3<S>* u, S* len) const {
    const S r = unit(radius_);
    if (count_ == 1) {
      v[0] = at(feet, idx_[0]);
      return 1;
    }
    if (count_ == 2) {  // the rectangle between the two feet
      const Vec3<S> a = at(feet, idx_[0]), b = at(feet, idx_[1]);
      const Vec3<S> e = scaled(diff(b, a), inv_len_[0]);
      const S w = max_of(r - want, S(0));
      const Vec3<S> nw(-e.y * w, e.x * w, S(0));  // left normal, half-width long
      const Vec3<S> n(-e.y, e.x, S(0));
      v[0] = diff(a, nw);
      v[1] = diff(b, nw);
      v[2] = sum(b, nw);
      v[3] = sum(a, nw);
      u[0] = e;
      u[1] = n;
      u[2] = Vec3<S>(-e.x, -e.y, S(0));
      u[3] = Vec3<S>(e.y, -e.x, S(0));
      len[0] = len[2] = S(1) / inv_len_[0];
      len[1] = len[3] = w + w;
      return 4;
    }
    const S shrink = max_of(want - r, S(0));
    for (uint8_t k = 0; k < count_; ++k) {
      const Vec3<S> a = at(feet, idx_[k]);
      u[k] = scaled(diff(at(feet, idx_[next(k)]), a), inv_len_[k]);
      const Vec3<S> nk(-u[k].y, u[k].x, S(0));
      v[k] = along(a, along(nk, u[k], corner_[k]), shrink);
    }
    for (uint8_t k = 0; k < count_; ++k) len[k] = dot(diff(v[next(k)], v[k]), u[k]);
    return count_;
  }

  static bool inside(const Vec3<S>* v, const Vec3<S>* u, uint8_t n, const Vec3<S>& p) {
    for (uint8_t k = 0; k < n; ++k)
      if (cross(u[k], diff(p, v[k])) < S(0)) return false;
    return true;
  }

  //! The x move that brings p into the region along its line y: the nearest
  //! end of the allowed interval (0 inside; the interval's middle if empty).
  static S along_x(const Vec3<S>* v, const Vec3<S>* u, uint8_t n, const Vec3<S>& p) {
    S lo = S(0), hi = S(0);
    bool has_lo = false, has_hi = false;
    for (uint8_t k = 0; k < n; ++k) {
      // Inside edge k: u.x (y - v.y) - u.y (x + t - v.x) = c - u.y t >= 0.
      const S c = cross(u[k], diff(p, v[k]));
      constexpr S flat = scalar<S>(0.05);
      if (abs(u[k].y) < flat) continue;  // an edge along x: no x move helps
      const S t = c / u[k].y;
      if (u[k].y < S(0)) {  // t >= c / u.y
        if (!has_lo || t > lo) lo = t;
        has_lo = true;
      } else {  // t <= c / u.y
        if (!has_hi || t < hi) hi = t;
        has_hi = true;
      }
    }
    constexpr S half = scalar<S>(0.5);
    if (has_lo && has_hi && hi < lo) return (lo + hi) * half;
    if (has_lo && lo > S(0)) return lo;
    if (has_hi && hi < S(0)) return hi;
    return S(0);
  }

  uint8_t count_;
  uint8_t idx_[kLegs];
  S inv_len_[kLegs];
  S corner_[kLegs];  //!< vertex k of the shrunk polygon: a_k + d (n_k + corner_k u_k)
  S radius_;
  int8_t shift_;
};

}  // namespace strider

#endif  // STRIDER_GAIT_STABILITY_H
