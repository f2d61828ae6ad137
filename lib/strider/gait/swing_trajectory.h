//! Swing trajectories: where a foot is in the air at swing phase s in [0, 1]
//! (0 lift-off, 1 touch-down): u the fraction of the way from lift-off to
//! touch-down point, w the height as a fraction of the apex (the shapes'
//! formulas: docs/gaits.md, "Swing trajectories").
#ifndef STRIDER_GAIT_SWING_TRAJECTORY_H
#define STRIDER_GAIT_SWING_TRAJECTORY_H

#include <stdint.h>
#include <string.h>

#include "../math/scalar.h"
#include "bezier_table.h"

namespace strider {

enum class SwingShape : uint8_t {
  kRectangle = 0,   //!< lift, carry, lower (seed 001 section 3.2)
  kSemicircle = 1,  //!< circle of diameter L
  kEllipse = 2,     //!< semi-axes L/2 and h
  kCycloid = 3,     //!< zero speed at both ends
  kParabola = 4,
  kBezier = 5       //!< 12-point Bezier, CHAMP's control points
};

constexpr uint8_t kSwingShapeCount = 6;

//! The shapes' names in SwingShape's order, each ended by a NUL (in flash on the AVR).
constexpr char kSwingShapeNames[] STRIDER_PROGMEM = "rectangle\0semicircle\0ellipse\0cycloid\0parabola\0bezier";

//! The shape's name: a pointer into kSwingShapeNames; "ellipse" for a value out of range.
inline const char* to_string(SwingShape shape) {
  const char* p = kSwingShapeNames;
  for (uint8_t i = uint8_t(shape) < kSwingShapeCount ? uint8_t(shape) : uint8_t(SwingShape::kEllipse); i > 0; --i)
    while (flash_u8(p++) != 0) {}
  return p;
}

//! Parses a shape name; returns false and leaves `shape` alone otherwise.
inline bool parse_swing_shape(const char* text, SwingShape& shape) {
  if (text == nullptr) return false;
  for (uint8_t i = 0; i < kSwingShapeCount; ++i) {
    if (strcmp(text, to_string(SwingShape(i))) == 0) {
      shape = SwingShape(i);
      return true;
    }
  }
  return false;
}

//! A point of a swing: horizontal fraction u and height fraction w.
template <typename S>
struct SwingPoint {
  S u;  //!< 0 at the lift-off point, 1 at the touch-down point
  S w;  //!< height / apex height, in [0, 1]
};

//! The smallest and largest u a shape reaches (the Bezier overshoots).
constexpr double swing_u_min(SwingShape shape) { return shape == SwingShape::kBezier ? -0.1837 : 0.0; }
constexpr double swing_u_max(SwingShape shape) { return shape == SwingShape::kBezier ? 1.1504 : 1.0; }

namespace swing_detail {

inline float table_value(uint16_t v, float) { return float(v) * (1.0f / 16384.0f) - 0.5f; }
inline Fixed table_value(uint16_t v, Fixed) { return Fixed::from_raw(int32_t(uint32_t(v) << 2) - 32768); }
//! x * 0.5 with the bits of the product: Fixed's rounds the magnitude half
//! up ((|raw| + 1) / 2, fixed.h's mul_mag_parts), here without the multiply.
inline float half_of(float x) { return x * 0.5f; }
inline Fixed half_of(Fixed x) {
  const int32_t r = x.raw();
  const uint32_t m = ((r < 0 ? 0u - uint32_t(r) : uint32_t(r)) + 1u) >> 1;
  return Fixed::from_raw(r < 0 ? -int32_t(m) : int32_t(m));
}
//! floor(x) for x in [0, 64].
inline int16_t floor_index(float x) { return int16_t(x); }
inline int16_t floor_index(Fixed x) { return int16_t(x.raw() >> Fixed::kFracBits); }

//! The tabulated Bezier at s in [0, 1], linear between the 65 nodes.
template <typename S>
SwingPoint<S> bezier(S s) {
  const S x = s * S(detail::kBezierNodes - 1);
  int16_t k = floor_index(x);
  if (k > detail::kBezierNodes - 2) k = detail::kBezierNodes - 2;
  if (k < 0) k = 0;
  const S f = clamp(x - S(k), S(0), S(1));
  const uint16_t* tu = detail::BezierTables<>::kU;
  const uint16_t* tw = detail::BezierTables<>::kW;
  const S u0 = table_value(flash_u16(tu, uint16_t(k)), S()), u1 = table_value(flash_u16(tu, uint16_t(k + 1)), S());
  const S w0 = table_value(flash_u16(tw, uint16_t(k)), S()), w1 = table_value(flash_u16(tw, uint16_t(k + 1)), S());
  return SwingPoint<S>{u0 + (u1 - u0) * f, w0 + (w1 - w0) * f};
}

}  // namespace swing_detail

//! The swing point of `shape` at swing phase s (clamped into [0, 1]).
template <typename S>
SwingPoint<S> swing_point(SwingShape shape, S s) {
  s = clamp(s, S(0), S(1));
  constexpr S one = S(1), inv_two_pi = scalar<S>(0.15915494309189535);
  constexpr S k_pi = pi<S>(), k_two_pi = two_pi<S>();
  switch (shape) {
    case SwingShape::kRectangle: {
      const S three_s = s * S(3);
      if (three_s < one) return SwingPoint<S>{S(0), three_s};
      if (three_s < S(2)) return SwingPoint<S>{three_s - one, one};
      return SwingPoint<S>{one, S(3) - three_s};
    }
    case SwingShape::kCycloid: {
      const S a = k_two_pi * s;
      return SwingPoint<S>{s - sin(a) * inv_two_pi, swing_detail::half_of(one - cos(a))};
    }
    case SwingShape::kParabola:
      return SwingPoint<S>{s, S(4) * s * (one - s)};
    case SwingShape::kBezier:
      return swing_detail::bezier(s);
    case SwingShape::kSemicircle:
    case SwingShape::kEllipse: break;
  }
  const S a = k_pi * s;
  return SwingPoint<S>{swing_detail::half_of(one - cos(a)), sin(a)};
}

//! The apex height of a swing [mm] for a step of length stride_mm and the
//! robot's step height step_mm: step_mm, except for the semicircle.
template <typename S>
S swing_apex_mm(SwingShape shape, S stride_mm, S step_mm) {
  constexpr S half = scalar<S>(0.5);
  if (shape != SwingShape::kSemicircle) return step_mm;
  return clamp(stride_mm * half, step_mm * half, step_mm);
}

}  // namespace strider

#endif  // STRIDER_GAIT_SWING_TRAJECTORY_H
