//! Particle swarm optimisation, global-best topology (seed 003 section 4.1,
//! algorithm 1, table 3), for D <= 6 dimensions in fixed arrays, in pyswarms'
//! form of eq 12 (docs/kinematics.md, "Generic chains").
#ifndef STRIDER_KINEMATICS_PSO_H
#define STRIDER_KINEMATICS_PSO_H

#include "../math/prng.h"
#include "../math/working_units.h"
#include "dh_chain.h"
#include "ik_status.h"

namespace strider {

enum class PsoStatus : uint8_t {
  kConverged = 0,      //!< best cost fell below cost_threshold
  kMaxIterations = 1,  //!< ran max_iterations; the best found is returned
  kBadParams = 2       //!< empty swarm, too many particles or lo > hi: nothing run
};

//! Seed 003's table 3 gives the defaults.
template <typename S, uint8_t D>
struct PsoParams {
  S lo[D];                          //!< lower bound per dimension
  S hi[D];                          //!< upper bound per dimension
  uint8_t swarm_size = 20;          //!< particles used (<= Capacity)
  uint16_t max_iterations = 1000;   //!< swarm evaluations at most
  S c1 = S(1.5);                    //!< cognitive coefficient
  S c2 = S(1.5);                    //!< social coefficient
  S w = S(0.5);                     //!< inertia weight
  S cost_threshold = S(0);          //!< stop once best cost < this (0: never, for costs >= 0)
  S velocity_clamp = S(0);          //!< |v_d| <= this * (hi_d - lo_d); 0: no clamp
  uint32_t seed = 1;                //!< PRNG seed
  //! Where particle 0 starts (clamped to the box; nullptr: a uniform draw).
  const JointVector<S, D>* start = nullptr;

  void set_bounds(S lo_all, S hi_all) {
    for (uint8_t d = 0; d < D; ++d) {
      lo[d] = lo_all;
      hi[d] = hi_all;
    }
  }
};

template <typename S, uint8_t D>
struct PsoResult {
  JointVector<S, D> position;  //!< best position found (global best)
  S cost;                      //!< its cost
  uint16_t iterations;         //!< swarm evaluations done
  PsoStatus status;
};

//! The swarm state; keep one (static on the AVR: about Capacity * (12 D + 8)
//! bytes for float) and call minimize() as often as needed.
template <typename S, uint8_t D, uint8_t Capacity = 20>
class ParticleSwarm {
  static_assert(D >= 1 && D <= 6, "PSO supports 1 to 6 dimensions");
  static_assert(Capacity >= 1, "PSO needs at least one particle");

 public:
  using Point = JointVector<S, D>;

  //! Minimises cost(const Point&) -> S over the box of `p` (seed 003
  //! algorithm 1), the particles evaluated one by one in index order.
  template <typename Cost>
  PsoResult<S, D> minimize(const PsoParams<S, D>& p, Cost&& cost) {
    return minimize_swarm(p, EachParticle<Cost>{cost});
  }

  //! The same with a cost vectorised over the swarm, as pyswarms' costs are:
  //! cost(const Point* x, uint8_t n, S* c) sets c[i] to the cost of x[i].
  template <typename SwarmCost>
  PsoResult<S, D> minimize_swarm(const PsoParams<S, D>& p, SwarmCost&& cost) {
    PsoResult<S, D> r;
    r.iterations = 0;
    r.cost = S(0);
    r.status = PsoStatus::kBadParams;
    const uint8_t n = p.swarm_size;
    for (uint8_t d = 0; d < D; ++d) r.position[d] = p.lo[d];
    if (n == 0 || n > Capacity) return r;
    for (uint8_t d = 0; d < D; ++d)
      if (p.hi[d] < p.lo[d]) return r;

    Prng rng(p.seed);
    for (uint8_t i = 0; i < n; ++i) {
      for (uint8_t d = 0; d < D; ++d) {
        x_[i][d] = clamp(p.lo[d] + (p.hi[d] - p.lo[d]) * unit(rng, static_cast<S*>(nullptr)), p.lo[d], p.hi[d]);
        v_[i][d] = S(0);
      }
    }
    if (p.start != nullptr)
      for (uint8_t d = 0; d < D; ++d) x_[0][d] = clamp((*p.start)[d], p.lo[d], p.hi[d]);
    uint8_t g = 0;  // index of the global best among the personal bests
    for (uint16_t t = 0; t < p.max_iterations; ++t) {
      cost(static_cast<const Point*>(x_), n, cost_);
      for (uint8_t i = 0; i < n; ++i) {
        if (t == 0 || cost_[i] < pbest_cost_[i]) {
          pbest_cost_[i] = cost_[i];
          pbest_[i] = x_[i];
        }
        if (pbest_cost_[i] < pbest_cost_[g]) g = i;
      }
      r.iterations = uint16_t(t + 1);
      if (pbest_cost_[g] < p.cost_threshold) break;
      if (t + 1 == p.max_iterations) break;  // the last move would go unevaluated
      move(p, g, rng);
    }
    r.position = pbest_[g];
    r.cost = pbest_cost_[g];
    r.status = pbest_cost_[g] < p.cost_threshold ? PsoStatus::kConverged : PsoStatus::kMaxIterations;
    return r;
  }

 private:
  template <typename Cost>
  struct EachParticle {
    Cost& cost;
    void operator()(const Point* x, uint8_t n, S* c) const {
      for (uint8_t i = 0; i < n; ++i) c[i] = cost(x[i]);
    }
  };

  // Uniform in [0, 1) from one draw: float 24 bits, Fixed 16, double 32
  // (a second draw adds no randomness to xorshift32's 32 bits of state).
  static float unit(Prng& rng, float*) { return rng.uniform<float>(); }
  static Fixed unit(Prng& rng, Fixed*) { return rng.uniform<Fixed>(); }
  static double unit(Prng& rng, double*) {
    return sizeof(double) >= 8 ? double(rng.next_u32()) * (1.0 / 4294967296.0) : double(rng.uniform<float>());
  }

  // Eqs 12-13 in pyswarms' form. The parameters are copied to locals, as
  // the stores to the swarm (S too) could alias them.
  void move(const PsoParams<S, D>& p, uint8_t g, Prng& rng) {
    const S w = p.w, c1 = p.c1, c2 = p.c2;
    S lo[D], hi[D], vmax[D];
    for (uint8_t d = 0; d < D; ++d) {
      lo[d] = p.lo[d];
      hi[d] = p.hi[d];
      vmax[d] = p.velocity_clamp * (hi[d] - lo[d]);
    }
    const bool clamp_v = S(0) < p.velocity_clamp;
    const Point gbest = pbest_[g];
    const uint8_t n = p.swarm_size;
    for (uint8_t i = 0; i < n; ++i) {
      Point& xi = x_[i];
      Point& vi = v_[i];
      const Point& pi = pbest_[i];
      for (uint8_t d = 0; d < D; ++d) {
        const S r1 = unit(rng, static_cast<S*>(nullptr));
        const S r2 = unit(rng, static_cast<S*>(nullptr));
        const S xd = xi[d];
        S v = w * vi[d] + c1 * r1 * (pi[d] - xd) + c2 * r2 * (gbest[d] - xd);
        if (clamp_v) v = clamp(v, -vmax[d], vmax[d]);
        const S x = xd + v;
        const bool out = x < lo[d] || hi[d] < x;
        vi[d] = out ? v * S(-0.5) : v;
        xi[d] = clamp(x, lo[d], hi[d]);
      }
    }
  }

  Point x_[Capacity];
  Point v_[Capacity];
  Point pbest_[Capacity];
  S pbest_cost_[Capacity];
  S cost_[Capacity];  // this iteration's costs
};

//! PSO as inverse kinematics: the cost of joints q is |fk(q) - target| [mm]
//! (seed 003 eq 15).
template <typename S, typename Fk>
struct FkDistanceCost {
  const Fk* fk;
  Vec3<S> target_mm;
  template <typename Joints>
  S operator()(const Joints& q) const { return units::distance((*fk)(q), target_mm); }
};

template <typename S, typename Fk>
FkDistanceCost<S, Fk> make_fk_distance_cost(const Fk& fk, const Vec3<S>& target_mm) {
  return FkDistanceCost<S, Fk>{&fk, target_mm};
}

//! IK by PSO in the box of (finite) `limits`, other settings from `params`.
//! kOk within opt.tolerance_mm, kJointLimit when the best sits within 1/1024
//! of the range of a bound, else kClamped; kUnreachable beyond max_clamp_mm.
template <typename S, uint8_t D, uint8_t Capacity, typename Fk>
IkStatus pso_ik(ParticleSwarm<S, D, Capacity>& swarm, const Fk& fk, const JointLimits<S, D>& limits,
                const Vec3<S>& target_mm, JointVector<S, D>& q, Vec3<S>& reached,
                PsoParams<S, D> params, const IkOptions<S>& opt = IkOptions<S>(),
                PsoResult<S, D>* result = nullptr) {
  for (uint8_t d = 0; d < D; ++d) {
    params.lo[d] = limits.lo[d];
    params.hi[d] = limits.hi[d];
  }
  const PsoResult<S, D> r = swarm.minimize(params, make_fk_distance_cost(fk, target_mm));
  if (result != nullptr) *result = r;
  if (r.status == PsoStatus::kBadParams || opt.max_clamp_mm < r.cost) return IkStatus::kUnreachable;
  IkStatus status = IkStatus::kOk;
  if (opt.tolerance_mm < r.cost) {
    status = IkStatus::kClamped;
    for (uint8_t d = 0; d < D; ++d) {
      const S margin = (limits.hi[d] - limits.lo[d]) * S(1.0 / 1024.0);
      if (!(limits.lo[d] + margin < r.position[d]) || !(r.position[d] < limits.hi[d] - margin))
        status = IkStatus::kJointLimit;
    }
  }
  q = r.position;
  reached = fk(r.position);
  return status;
}

}  // namespace strider

#endif  // STRIDER_KINEMATICS_PSO_H
