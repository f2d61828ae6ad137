//! ServoTickMap: the servo loop's per-joint mapping, joint angle [rad] ->
//! PCA9685 ticks, with everything that does not change per frame (zero,
//! direction, centre, trim, limits, pulse range, PWM timing) folded into a
//! few constants per joint when the PWM is configured or the calibration
//! changes.
//!
//! Per joint and frame: d = base + direction * joint [rad] (the servo angle
//! from its lowest limit), clamped into [0, travel]; ticks = round(ticks(0) +
//! d * ticks_per_rad). For Fixed that is one 16 x 16 -> 32-bit product (d in
//! Q2.14, ticks_per_rad scaled into 16 bits), a shift and an add: no 32-bit
//! multiplication, no division; a few hundred cycles instead of ~2,000 for
//! map_joint() (servo_map.h), whose rounding to whole microseconds it skips.
//!
//! Same contract as map_joint(): an angle outside the limits is clamped to
//! them (kLimited), a NaN or infinite joint holds the centre (kNotFinite),
//! ticks never leave the ticks of the limits' pulses (nor 4095). Against
//! map_joint() the ticks differ by at most one (test/control).
#ifndef STRIDER_CONTROL_SERVO_TICK_MAP_H
#define STRIDER_CONTROL_SERVO_TICK_MAP_H

#include <stdint.h>

#include "../math/float_bits.h"
#include "../math/mul16.h"
#include "../math/scalar.h"
#include "pca9685_timing.h"
#include "servo_map.h"
#include "settings.h"

namespace strider {

//! Joints a ServoTickMap holds (every built-in model fits).
constexpr uint8_t kMaxServoTickJoints = 18;

//! Why configure() refused a channel.
enum class ServoTickStatus : uint8_t {
  kOk = 0,
  kUnsupported = 1  //!< a travel of 4 rad or more, or a scale out of range: use map_joint()
};

namespace servo_ticks_detail {

using detail::float_bits;
using detail::kFloatInfBits;
using detail::kFloatSignBit;
using detail::magnitude_bits;

//! 2^(16 - n) for n in [1, 15] (entry 0 unused).
template <typename Dummy = void>
struct TickShiftTable {
  static const uint16_t kPow2[16];
};
template <typename Dummy>
const uint16_t TickShiftTable<Dummy>::kPow2[16] STRIDER_PROGMEM = {
    0, 32768, 16384, 8192, 4096, 2048, 1024, 512, 256, 128, 64, 32, 16, 8, 4, 2};

//! p >> n for n in [1, 15], exact: with m = 2^(16 - n) and p = h 2^16 + l,
//! h m + (l m) / 2^16 (floor), two 16 x 16 products instead of avr-gcc's
//! loop of n single-bit 32-bit shifts.
inline uint32_t shr_by_products(uint32_t p, uint8_t n) {
  const uint16_t m = flash_u16(TickShiftTable<>::kPow2, n);
  return detail::mul_u16(detail::hi16(p), m) + detail::hi16(detail::mul_u16(uint16_t(p), m));
}

//! ticks = (d [Q2.14] * k) >> (shift - 2) + base [Q16.16], rounded
//! (shift in [3, 17]: configure()).
inline uint16_t ticks_of(Fixed d, uint16_t k, uint8_t shift, uint32_t base_q16) {
  const uint16_t d14 = uint16_t(uint32_t(d.raw()) >> 2);  // 0 <= d < 4 rad: checked in configure()
  uint32_t p = detail::mul_u16(d14, k);                    // 16 x 16 -> 32 bits
  p = shr_by_products(p, uint8_t(shift - 2));
  p += base_q16 + 0x8000u;
  const uint16_t t = uint16_t(p >> 16);
  return t > kPca9685MaxTick ? kPca9685MaxTick : t;
}
//! base_half: ticks of the lowest limit + 0.5 (rounding folded in).
inline uint16_t ticks_of(float d, float ticks_per_rad, float base_half) {
  // 0 <= d <= travel and base + slope travel < 4096 (configure()): in range.
  const uint16_t t = uint16_t(d * ticks_per_rad + base_half);
  return t > kPca9685MaxTick ? kPca9685MaxTick : t;
}

// Decisions on float bits (float_bits.h): a float comparison is a library
// call on the AVR, an integer one a few cycles.
inline bool finite(float v) { return magnitude_bits(v) < kFloatInfBits; }
inline bool finite(Fixed) { return true; }
//! v < 0 (v finite; -0 is not).
inline bool below_zero(float v) { return (float_bits(v) & kFloatSignBit) != 0 && magnitude_bits(v) != 0; }
inline bool below_zero(Fixed v) { return v.raw() < 0; }
//! a > b for finite a >= 0 and b >= 0.
inline bool above(float a, float b) { return float_bits(a) > float_bits(b); }
inline bool above(Fixed a, Fixed b) { return a.raw() > b.raw(); }

}  // namespace servo_ticks_detail

//! The slope and offset of ticks over d, per scalar: Fixed keeps a 16-bit
//! slope with its scale (one 16 x 16-bit product per joint), float its own.
template <typename S>
struct ServoTickScale;
template <>
struct ServoTickScale<Fixed> {
  uint32_t base_q16;  //!< ticks of the lowest limit [Q16.16 ticks]
  uint16_t k;         //!< ticks_per_rad 2^shift, in [2^15, 2^16)
  uint8_t shift;      //!< scale of k
};
template <>
struct ServoTickScale<float> {
  float base;           //!< ticks of the lowest limit + 0.5 (rounding) [ticks]
  float ticks_per_rad;  //!< [ticks/rad]
};

//! One joint of a ServoTickMap (constants of the per-frame mapping).
template <typename S>
struct ServoTickJoint {
  S base_rad;             //!< centre - direction zero + trim - min: d = base + direction joint [rad]
  S travel_rad;           //!< max - min [rad]
  ServoTickScale<S> scale;
  uint16_t lo_ticks;      //!< ticks at the lowest limit (map_joint's, the bounds of the output)
  uint16_t hi_ticks;      //!< ticks at the highest limit
  uint16_t centre_ticks;  //!< what a non-finite joint sends [ticks]
  uint8_t channel;        //!< PCA9685 output
  int8_t direction;       //!< +1 or -1
};

template <typename S>
class ServoTickMap {
 public:
  //! Folds count channels (trims settings.trim_decideg[first_trim + i]) and
  //! the PWM timing into per-joint constants. Call after configure of the
  //! timing and after every calibration change. kUnsupported: some channel
  //! cannot use this path (the map is then empty: count() == 0).
  ServoTickStatus configure(const ServoChannel<S>* channels, uint8_t count, const Settings& settings,
                            const Pca9685Timing& timing, uint8_t first_trim = 0) {
    count_ = 0;
    if (count > kMaxServoTickJoints) return ServoTickStatus::kUnsupported;
    // Exact slope from the timing: ticks = us * 262144 / period_x64.
    const double ticks_per_us = 262144.0 / double(timing.period_x64());
    for (uint8_t i = 0; i < count; ++i) {
      const ServoChannel<S>& ch = channels[i];
      const uint8_t t = uint8_t(first_trim + i);
      const S trim = t < kMaxServoJoints ? trim_from_decideg<S>(settings.trim_decideg[t]) : S(0);
      ServoTickJoint<S>& j = joint_[i];
      j.channel = ch.channel;
      j.direction = ch.direction < 0 ? int8_t(-1) : int8_t(1);
      const S lo = min_of(ch.min_rad, ch.max_rad), hi = max_of(ch.min_rad, ch.max_rad);
      const S zero = ch.direction < 0 ? -ch.zero_rad : ch.zero_rad;
      j.base_rad = ch.centre_rad - zero + trim - lo;
      j.travel_rad = hi - lo;
      // The same pulse as servo_pulse_us() before rounding to whole us,
      // kept inside the pulse range (an angle limit beyond the travel).
      const double lo_us = double(ch.min_pulse_us < ch.max_pulse_us ? ch.min_pulse_us : ch.max_pulse_us);
      const double hi_us = double(ch.min_pulse_us < ch.max_pulse_us ? ch.max_pulse_us : ch.min_pulse_us);
      const double us_per_rad = to_double(ch.us_per_rad);
      double at_lo = double(ch.min_pulse_us) + to_double(lo) * us_per_rad;
      double at_hi = double(ch.min_pulse_us) + to_double(hi) * us_per_rad;
      if (at_lo < lo_us || at_hi > hi_us || !(us_per_rad >= 0.0)) return ServoTickStatus::kUnsupported;
      const double tpr = us_per_rad * ticks_per_us;
      const double base = at_lo * ticks_per_us;
      if (!set_scale(j.scale, to_double(j.travel_rad), tpr, base)) return ServoTickStatus::kUnsupported;
      // The bounds and the centre exactly as map_joint() sends them.
      j.lo_ticks = timing.pulse_ticks(servo_pulse_us(ch, lo));
      j.hi_ticks = timing.pulse_ticks(servo_pulse_us(ch, hi));
      j.centre_ticks = timing.pulse_ticks(servo_pulse_us(ch, clamp(ch.centre_rad, lo, hi)));
    }
    count_ = count;
    return ServoTickStatus::kOk;
  }

  uint8_t count() const { return count_; }
  const ServoTickJoint<S>& joint(uint8_t i) const { return joint_[i]; }

  //! Joint i's command for joint_rad [rad]: ticks and status (pulse_us is
  //! not computed by this path and left 0).
  ServoCommand map(uint8_t i, S joint_rad) const {
    const ServoTickJoint<S>& j = joint_[i];
    ServoCommand cmd;
    cmd.channel = j.channel;
    cmd.pulse_us = 0;
    if (!servo_ticks_detail::finite(joint_rad)) {
      cmd.ticks = j.centre_ticks;
      cmd.status = ServoStatus::kNotFinite;
      return cmd;
    }
    S d = j.direction < 0 ? j.base_rad - joint_rad : j.base_rad + joint_rad;
    cmd.status = ServoStatus::kOk;
    if (!servo_ticks_detail::finite(d)) {
      cmd.ticks = j.centre_ticks;
      cmd.status = ServoStatus::kNotFinite;
      return cmd;
    }
    if (servo_ticks_detail::below_zero(d)) {
      d = S(0);
      cmd.status = ServoStatus::kLimited;
    } else if (servo_ticks_detail::above(d, j.travel_rad)) {
      d = j.travel_rad;
      cmd.status = ServoStatus::kLimited;
    }
    const uint16_t t = ticks(j.scale, d);
    cmd.ticks = t < j.lo_ticks ? j.lo_ticks : t > j.hi_ticks ? j.hi_ticks : t;
    return cmd;
  }

  //! Writes joints [first, first + n) from joint_rad[0..n) through out
  //! (ServoOutput); returns the worst status.
  template <typename Output>
  ServoStatus write(Output& out, uint8_t first, const S* joint_rad, uint8_t n) const {
    ServoStatus worst_status = ServoStatus::kOk;
    for (uint8_t i = 0; i < n && uint8_t(first + i) < count_; ++i) {
      const ServoCommand cmd = map(uint8_t(first + i), joint_rad[i]);
      out.write_ticks(cmd.channel, cmd.ticks);
      if (uint8_t(cmd.status) > uint8_t(worst_status)) worst_status = cmd.status;
    }
    return worst_status;
  }

 private:
  static bool set_scale(ServoTickScale<float>& sc, double travel, double tpr, double base) {
    sc.ticks_per_rad = float(tpr);
    sc.base = float(base + 0.5);
    return travel < 4.0 && base + tpr * travel < 4096.0;
  }
  static bool set_scale(ServoTickScale<Fixed>& sc, double travel, double tpr, double base) {
    if (!(travel < 4.0) || !(tpr > 0.5) || !(tpr < 8192.0) || !(base >= 0.0) || base + tpr * travel >= 4096.0)
      return false;
    // k = tpr 2^shift in [2^15, 2^16): 16 significant bits whatever the PWM.
    uint8_t shift = 2;
    while (tpr * double(uint32_t(1) << (shift + 1)) < 65535.5 && shift < 17) ++shift;
    sc.shift = shift;
    sc.k = uint16_t(tpr * double(uint32_t(1) << shift) + 0.5);
    sc.base_q16 = uint32_t(base * 65536.0 + 0.5);
    return true;
  }
  static uint16_t ticks(const ServoTickScale<Fixed>& sc, Fixed d) {
    return servo_ticks_detail::ticks_of(d, sc.k, sc.shift, sc.base_q16);
  }
  static uint16_t ticks(const ServoTickScale<float>& sc, float d) {
    return servo_ticks_detail::ticks_of(d, sc.ticks_per_rad, sc.base);
  }

  ServoTickJoint<S> joint_[kMaxServoTickJoints];
  uint8_t count_ = 0;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_TICK_MAP_H
