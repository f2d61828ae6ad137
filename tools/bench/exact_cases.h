//! The bit-exact cases: Fixed arithmetic, elementary functions and leg
//! kinematics over a fixed input list, computed once on the simulated
//! ATmega2560 and once on the host; both must give identical raw int32
//! results (avr-gcc 5.4 has miscompiled 64-bit code before, and AVR int is 16
//! bits, so "same source" is not proof enough).
//!
//! A Sink provides section(name) and record(const int32_t* values, uint8_t n);
//! names are flash strings on the AVR (see STRIDER_BENCH_STR).
#ifndef STRIDER_TOOLS_BENCH_EXACT_CASES_H
#define STRIDER_TOOLS_BENCH_EXACT_CASES_H

#include <stdint.h>

#include "bench_inputs.h"
#include "bench_legs.h"
#include "math/fixed.h"
#include "math/scalar.h"

#if defined(__AVR__)
#define STRIDER_BENCH_STR(s) PSTR(s)
#else
#define STRIDER_BENCH_STR(s) (s)
#endif

namespace strider_bench {

using strider::Fixed;

//! Written into outputs before a call, so "left untouched" is compared too.
constexpr int32_t kSentinelRaw = 0x5A5A5A5A;
//! Random cases per function (edge tables come on top).
constexpr uint8_t kExactRandomCases = 48;

// Edge values for the binary operations [raw Q16.16]. Mind the AVR's 16-bit
// int: -0x8000 is the unsigned int 0x8000 there, hence the L suffixes.
const int32_t kEdgeRaw[] STRIDER_BENCH_FLASH = {
    0, 1, -1, 0x8000L, -0x8000L, 0x10000, -0x10000, 0x18000, 0x7FFFFFFF, -0x7FFFFFFF - 1,
    181 * 65536, -182 * 65536, 0x12345678, 0x00FFFF00, -0x00ABCDEF, 205887 /* pi */};
constexpr uint8_t kEdgeCount = sizeof(kEdgeRaw) / sizeof(kEdgeRaw[0]);

inline int32_t edge_raw(uint8_t i) {
#if defined(__AVR__)
  return int32_t(pgm_read_dword(&kEdgeRaw[i]));
#else
  return kEdgeRaw[i];
#endif
}

template <class Sink>
void emit(Sink& out, int32_t a, int32_t b) {
  const int32_t v[2] = {a, b};
  out.record(v, 2);
}
template <class Sink>
void emit(Sink& out, int32_t a, int32_t b, int32_t c) {
  const int32_t v[3] = {a, b, c};
  out.record(v, 3);
}

template <class Sink>
void exact_binary_ops(Sink& out) {
  out.section(STRIDER_BENCH_STR("fixed_mul"));
  for (uint8_t i = 0; i < kEdgeCount; ++i)
    for (uint8_t j = 0; j < kEdgeCount; ++j) {
      const Fixed a = Fixed::from_raw(edge_raw(i)), b = Fixed::from_raw(edge_raw(j));
      emit(out, a.raw(), b.raw(), (a * b).raw());
    }
  Lcg rng{1u};
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const Fixed a = Fixed::from_raw(rng.any_raw()), b = Fixed::from_raw(rng.any_raw());
    emit(out, a.raw(), b.raw(), (a * b).raw());
  }
  // Products with a factor below 1 in magnitude (the AVR's short product),
  // on either side.
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const Fixed a = Fixed::from_raw(rng.any_raw()), b = Fixed::from_raw(rng.within(0x10000));
    emit(out, a.raw(), b.raw(), (a * b).raw());
    emit(out, b.raw(), a.raw(), (b * a).raw());
  }
  // Sums and differences, saturating (the AVR's overflow-flag path).
  out.section(STRIDER_BENCH_STR("fixed_add"));
  for (uint8_t i = 0; i < kEdgeCount; ++i)
    for (uint8_t j = 0; j < kEdgeCount; ++j) {
      const Fixed a = Fixed::from_raw(edge_raw(i)), b = Fixed::from_raw(edge_raw(j));
      emit(out, a.raw(), b.raw(), (a + b).raw());
    }
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const Fixed a = Fixed::from_raw(rng.any_raw()), b = Fixed::from_raw(rng.any_raw());
    emit(out, a.raw(), b.raw(), (a + b).raw());
  }
  out.section(STRIDER_BENCH_STR("fixed_sub"));
  for (uint8_t i = 0; i < kEdgeCount; ++i)
    for (uint8_t j = 0; j < kEdgeCount; ++j) {
      const Fixed a = Fixed::from_raw(edge_raw(i)), b = Fixed::from_raw(edge_raw(j));
      emit(out, a.raw(), b.raw(), (a - b).raw());
    }
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const Fixed a = Fixed::from_raw(rng.any_raw()), b = Fixed::from_raw(rng.any_raw());
    emit(out, a.raw(), b.raw(), (a - b).raw());
  }
  out.section(STRIDER_BENCH_STR("fixed_div"));
  for (uint8_t i = 0; i < kEdgeCount; ++i)
    for (uint8_t j = 0; j < kEdgeCount; ++j) {
      const Fixed a = Fixed::from_raw(edge_raw(i)), b = Fixed::from_raw(edge_raw(j));
      emit(out, a.raw(), b.raw(), (a / b).raw());
    }
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const Fixed a = Fixed::from_raw(rng.any_raw()), b = Fixed::from_raw(rng.any_raw());
    emit(out, a.raw(), b.raw(), (a / b).raw());
  }
}

// One unary function over the edges plus random values within +-span.
template <class Sink, class Fn>
void exact_unary(Sink& out, uint32_t seed, int32_t span, Fn fn) {
  for (uint8_t i = 0; i < kEdgeCount; ++i) emit(out, edge_raw(i), fn(Fixed::from_raw(edge_raw(i))).raw());
  Lcg rng{seed};
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const Fixed a = Fixed::from_raw(k < kExactRandomCases / 2 ? rng.within(span) : rng.any_raw());
    emit(out, a.raw(), fn(a).raw());
  }
}

// sin and cos next to the edges of their reduction and folds: k pi/2 for
// k = -4..4 [raw, rounded], and 8 rad (the large-angle reduction's
// threshold), each -2..+2 raw.
template <class Sink, class Fn>
void exact_angle_edges(Sink& out, Fn fn) {
  for (int8_t k = -4; k <= 4; ++k) {
    const int32_t base = k == 4 ? int32_t(0x80000L) : k == -4 ? -int32_t(0x80000L) : int32_t(k) * 102944L;
    for (int8_t d = -2; d <= 2; ++d) emit(out, base + d, fn(Fixed::from_raw(base + d)).raw());
  }
  for (int8_t d = -2; d <= 2; ++d) {
    emit(out, 205887L + d, fn(Fixed::from_raw(205887L + d)).raw());  // pi
    emit(out, -205887L + d, fn(Fixed::from_raw(-205887L + d)).raw());
    emit(out, 411775L + d, fn(Fixed::from_raw(411775L + d)).raw());  // 2 pi
  }
}

struct SqrtFn { Fixed operator()(Fixed a) const { return strider::sqrt(a); } };
struct SinFn { Fixed operator()(Fixed a) const { return strider::sin(a); } };
struct CosFn { Fixed operator()(Fixed a) const { return strider::cos(a); } };
struct AsinFn { Fixed operator()(Fixed a) const { return strider::asin(a); } };
struct AcosFn { Fixed operator()(Fixed a) const { return strider::acos(a); } };

template <class Sink>
void exact_functions(Sink& out) {
  out.section(STRIDER_BENCH_STR("fixed_sqrt"));
  exact_unary(out, 2u, 200 * 65536, SqrtFn());
  out.section(STRIDER_BENCH_STR("fixed_sin"));
  exact_unary(out, 3u, 8 * 65536, SinFn());
  exact_angle_edges(out, SinFn());
  out.section(STRIDER_BENCH_STR("fixed_cos"));
  exact_unary(out, 4u, 8 * 65536, CosFn());
  exact_angle_edges(out, CosFn());
  out.section(STRIDER_BENCH_STR("fixed_asin"));
  exact_unary(out, 5u, 81920, AsinFn());
  out.section(STRIDER_BENCH_STR("fixed_acos"));
  exact_unary(out, 6u, 81920, AcosFn());
  out.section(STRIDER_BENCH_STR("fixed_atan2"));
  for (uint8_t i = 0; i < kEdgeCount; ++i)
    for (uint8_t j = 0; j < kEdgeCount; ++j) {
      const Fixed y = Fixed::from_raw(edge_raw(i)), x = Fixed::from_raw(edge_raw(j));
      emit(out, y.raw(), x.raw(), strider::atan2(y, x).raw());
    }
  Lcg rng{7u};
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const Fixed y = Fixed::from_raw(rng.any_raw()), x = Fixed::from_raw(rng.any_raw());
    emit(out, y.raw(), x.raw(), strider::atan2(y, x).raw());
  }
  // The square-root kernel every Fixed root goes through (AVR assembly
  // against the host's C): both ends of its domain, squares and their
  // neighbours, random radicands.
  out.section(STRIDER_BENCH_STR("fixed_isqrt"));
  for (uint8_t k = 0; k < 4 * kExactRandomCases; ++k) {
    uint32_t m;
    const uint32_t r = 0x8000UL + (rng.next() >> 17);  // a root in [2^15, 2^16)
    switch (k & 3) {
      case 0: m = 0x40000000UL + (rng.next() & 0xBFFFFFFFUL) % 0xC0000000UL; break;
      case 1: m = r * r; break;
      case 2: m = r * r - 1U; break;
      default: m = k < 8 ? 0xFFFFFFFFUL - k : r * r + 2U * r; break;
    }
    if (m < 0x40000000UL) m = 0x40000000UL;
    emit(out, int32_t(m), int32_t(strider::detail::isqrt_q22(m)));
  }
  // The two-link solver's sqrt(p q) (an AVR assembly kernel against the
  // host's C): p and q of every magnitude, so the final shift goes both ways.
  out.section(STRIDER_BENCH_STR("wide_sqrt_product"));
  for (uint8_t k = 0; k < 4 * kExactRandomCases; ++k) {
    uint32_t p = uint32_t(rng.next()) >> (rng.next() % 32u);
    uint32_t q = uint32_t(rng.next()) >> (rng.next() % 32u);
    if (k < 4) {  // the corners
      p = (k & 1) ? 0xFFFFFFFFUL : 1u;
      q = (k & 2) ? 0xFFFFFFFFUL : 1u;
    }
    if (p == 0) p = 1;
    if (q == 0) q = 3;
    emit(out, int32_t(p), int32_t(q), int32_t(strider::leg_ik::wide::sqrt_product(p, q)));
  }
  // The leg solvers' atan2 (an AVR assembly kernel against the host's C):
  // the edges, then pairs of every magnitude (a random shift of random
  // bits), half of them near the diagonal, where the ratio nears 1.
  out.section(STRIDER_BENCH_STR("fixed_atan2_lean"));
  for (uint8_t i = 0; i < kEdgeCount; ++i)
    for (uint8_t j = 0; j < kEdgeCount; ++j)
      emit(out, edge_raw(i), edge_raw(j), strider::detail::atan2_lean_raw(edge_raw(i), edge_raw(j)));
  for (uint8_t k = 0; k < 4 * kExactRandomCases; ++k) {
    const uint8_t shift = uint8_t(rng.next() % 32u);
    const uint32_t mx = uint32_t(rng.next()) >> 1 >> shift;
    uint32_t my = uint32_t(rng.next()) >> 1 >> shift;
    if (k & 1) my = mx + (rng.next() % 9u) - 4u;  // |y| ~ |x|, either side
    const int32_t x = (k & 2) ? -int32_t(mx & 0x7FFFFFFFUL) : int32_t(mx & 0x7FFFFFFFUL);
    const int32_t y = (k & 4) ? -int32_t(my & 0x7FFFFFFFUL) : int32_t(my & 0x7FFFFFFFUL);
    emit(out, y, x, strider::detail::atan2_lean_raw(y, x));
  }
  // The wide square root of the leg solvers (AVR assembly around the root
  // kernel against the host's C): radicands of every magnitude, so the
  // final shift goes both ways.
  out.section(STRIDER_BENCH_STR("wide_sqrt_sq"));
  for (uint8_t k = 0; k < 4 * kExactRandomCases; ++k) {
    uint32_t x = (uint32_t(rng.next()) >> 2) >> (rng.next() % 30u);
    if (k < 4) x = k < 2 ? uint32_t(k + 1) : 0x3FFFFFFFUL - (k & 1);
    if (x == 0) x = 5;
    emit(out, int32_t(x), strider::leg_ik::wide::sqrt_sq(x));
  }
  // sq(a) + sq(b) of the wide units (AVR assembly against the host's C):
  // both signs, every magnitude, and the ends of the range.
  out.section(STRIDER_BENCH_STR("wide_sq_sum"));
  for (uint8_t k = 0; k < 4 * kExactRandomCases; ++k) {
    int32_t a = int32_t(uint32_t(rng.next()) >> (rng.next() % 32u));
    int32_t b = int32_t(uint32_t(rng.next()) >> (rng.next() % 32u));
    if (k & 1) a = -a;
    if (k & 2) b = -b;
    if (k < 4) a = k < 2 ? int32_t(0x7FFFFFFFL) : -0x7FFFFFFFL - 1, b = k & 1 ? 0 : -1;
    emit(out, a, b, int32_t(strider::leg_ik::wide::sq_sum(a, b)));
  }
}

//! IK of one target: target, status, joints, point reached (sentinels when
//! the solver left them untouched).
template <class Leg, class Sink>
void exact_ik_case(const Leg& leg, const strider::Vec3<Fixed>& t, Sink& out) {
  constexpr uint8_t kDof = Leg::kDof;
  typename Leg::Joints q;
  for (uint8_t i = 0; i < kDof; ++i) q[i] = Fixed::from_raw(kSentinelRaw);
  strider::Vec3<Fixed> reached(Fixed::from_raw(kSentinelRaw), Fixed::from_raw(kSentinelRaw),
                               Fixed::from_raw(kSentinelRaw));
  const strider::IkStatus status = leg.ik(t, q, reached);
  int32_t v[3 + 1 + kDof + 3];
  v[0] = t.x.raw(), v[1] = t.y.raw(), v[2] = t.z.raw(), v[3] = int32_t(status);
  for (uint8_t i = 0; i < kDof; ++i) v[4 + i] = q[i].raw();
  v[4 + kDof] = reached.x.raw(), v[5 + kDof] = reached.y.raw(), v[6 + kDof] = reached.z.raw();
  out.record(v, uint8_t(7 + kDof));
}

//! IK over the workspace targets plus random targets in a box of +-span;
//! FK over the joint grid.
template <class Leg, class Sink>
void exact_leg(Sink& out, const Leg& leg, const char* ik_name, const char* fk_name, uint32_t seed,
               int32_t span) {
  out.section(ik_name);
  for (uint8_t i = 0; i < kGridCount; ++i)
    exact_ik_case(leg, workspace_target(leg, i), out);
  Lcg rng{seed};
  for (uint8_t k = 0; k < kExactRandomCases; ++k) {
    const int32_t x = rng.within(span), y = rng.within(span), z = rng.within(span);
    exact_ik_case(leg, strider::Vec3<Fixed>(Fixed::from_raw(x), Fixed::from_raw(y), Fixed::from_raw(z)), out);
  }
  out.section(fk_name);
  for (uint8_t i = 0; i < kGridCount; ++i) {
    typename Leg::Joints q;
    grid_joints(i, q);
    const strider::Vec3<Fixed> p = leg.fk(q);
    int32_t v[Leg::kDof + 3];
    for (uint8_t j = 0; j < Leg::kDof; ++j) v[j] = q[j].raw();
    v[Leg::kDof] = p.x.raw(), v[Leg::kDof + 1] = p.y.raw(), v[Leg::kDof + 2] = p.z.raw();
    out.record(v, uint8_t(Leg::kDof + 3));
  }
}

template <class Sink>
void exact_legs(Sink& out) {
  exact_leg(out, make_sprawl_leg<Fixed>(), STRIDER_BENCH_STR("sprawl_ik"), STRIDER_BENCH_STR("sprawl_fk"), 11u,
            160 * 65536);
#if STRIDER_BENCH_HAS_PLANAR_LEG
  exact_leg(out, make_planar_leg<Fixed>(), STRIDER_BENCH_STR("planar_ik"), STRIDER_BENCH_STR("planar_fk"), 12u,
            150 * 65536);
#endif
#if STRIDER_BENCH_HAS_CFT_LEG
  exact_leg(out, make_hexapod_leg<Fixed>(), STRIDER_BENCH_STR("cft_ik"), STRIDER_BENCH_STR("cft_fk"), 13u,
            250 * 65536);
#endif
#if STRIDER_BENCH_HAS_ABDUCTION_LEG
  exact_leg(out, make_abduction_leg<Fixed>(), STRIDER_BENCH_STR("abduction_ik"),
            STRIDER_BENCH_STR("abduction_fk"), 14u, 600 * 65536);
#endif
}

//! Everything, in a fixed order.
template <class Sink>
void run_exact_cases(Sink& out) {
  exact_binary_ops(out);
  exact_functions(out);
  exact_legs(out);
}

}  // namespace strider_bench

#endif  // STRIDER_TOOLS_BENCH_EXACT_CASES_H
