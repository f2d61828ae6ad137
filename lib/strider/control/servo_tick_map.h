//! ServoTickMap: joint angle [rad] -> PCA9685 ticks per frame, a joint's
//! servo map (servo_map.h) folded into a few constants at configuration:
//! d = base + direction * joint [rad], clamped into [0, travel]; ticks =
//! round(ticks(0) + d * ticks_per_rad): ~150 cycles per Fixed joint instead
//! of ~2,000 for map_joint(), same contract, ticks within one of its.
#ifndef STRIDER_CONTROL_SERVO_TICK_MAP_H
#define STRIDER_CONTROL_SERVO_TICK_MAP_H

#include <stdint.h>

#include "../math/scalar.h"
#include "pca9685_timing.h"
#include "servo_tick_math.h"
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

//! What a non-finite joint sends [ticks]: float only (a Fixed joint is
//! always finite, and an empty base takes no RAM).
template <typename S>
struct ServoTickCentre {
  uint16_t centre_ticks;
};
template <>
struct ServoTickCentre<Fixed> {};

//! The constants of a joint that its limits, servo part and the PWM fix
//! (legs of one geometry have the same).
template <typename S>
struct ServoTickRange : ServoTickCentre<S> {
  S travel_rad;           //!< max - min [rad]
  ServoTickScale<S> scale;
  uint16_t lo_ticks;      //!< ticks at the lowest limit (map_joint's, the bounds of the output)
  uint16_t hi_ticks;      //!< ticks at the highest limit
};
//! The constants of a joint of its own: output, direction, zero and trim.
template <typename S>
struct ServoTickOwn {
  S base_rad;             //!< centre - direction zero + trim - min: d = base + direction joint [rad]
  uint8_t channel;        //!< PCA9685 output
  int8_t direction;       //!< +1 or -1
};
template <typename S>
struct ServoTickJoint : ServoTickRange<S>, ServoTickOwn<S> {};

namespace servo_ticks_detail {
//! A ServoTickMap's constants: per joint, or (kSlots > 0) the range of
//! joint i shared in slot i % kSlots (legs of one geometry).
template <typename S, uint8_t N, uint8_t kSlots>
struct TickJoints {
  TickJoints() : own_(), range_() {}
  const ServoTickOwn<S>& own(uint8_t i) const { return own_[i]; }
  ServoTickOwn<S>& own(uint8_t i) { return own_[i]; }
  const ServoTickRange<S>& range(uint8_t, uint8_t slot) const { return range_[slot]; }
  //! The first joint of a slot sets its range.
  void set_range(uint8_t i, const ServoTickRange<S>& r) {
    if (i < kSlots) range_[i] = r;
  }

  ServoTickOwn<S> own_[N];
  ServoTickRange<S> range_[kSlots];
};
template <typename S, uint8_t N>
struct TickJoints<S, N, 0> {
  TickJoints() : joint_() {}
  const ServoTickOwn<S>& own(uint8_t i) const { return joint_[i]; }
  ServoTickOwn<S>& own(uint8_t i) { return joint_[i]; }
  const ServoTickRange<S>& range(uint8_t i, uint8_t) const { return joint_[i]; }
  void set_range(uint8_t i, const ServoTickRange<S>& r) { static_cast<ServoTickRange<S>&>(joint_[i]) = r; }

  ServoTickJoint<S> joint_[N];
};
}  // namespace servo_ticks_detail

//! N: most joints it holds. kSlots > 0: the joints of slot i % kSlots share
//! limits and servo part, and joint i < kSlots is configured first.
template <typename S, uint8_t N = kMaxServoTickJoints, uint8_t kSlots = 0>
class ServoTickMap {
 public:
  ServoTickMap() : count_(0) {}

  //! Folds count channels, their trims (settings.trim_decideg[first_trim +
  //! i]) and the timing into constants; kUnsupported leaves count() == 0.
  ServoTickStatus configure(const ServoChannel<S>* channels, uint8_t count, const Settings& settings,
                            const Pca9685Timing& timing, uint8_t first_trim = 0) {
    count_ = 0;
    if (count > N) return ServoTickStatus::kUnsupported;
    for (uint8_t i = 0; i < count; ++i) {
      const uint8_t t = uint8_t(first_trim + i);
      const S trim = t < kMaxServoJoints ? trim_from_decideg<S>(settings.trim_decideg[t]) : S(0);
      if (configure_joint(i, channels[i], trim, timing) != ServoTickStatus::kOk) return ServoTickStatus::kUnsupported;
    }
    count_ = count;
    return ServoTickStatus::kOk;
  }

  //! Joint i alone (channel and direction set even on kUnsupported).
  ServoTickStatus configure_joint(uint8_t i, const ServoChannel<S>& ch, S trim, const Pca9685Timing& timing) {
    ServoTickOwn<S>& own = joints_.own(i);
    own.channel = ch.channel;
    own.direction = ch.direction < 0 ? int8_t(-1) : int8_t(1);
    const bool flipped = ch.max_rad < ch.min_rad;
    const S lo = flipped ? ch.max_rad : ch.min_rad, hi = flipped ? ch.min_rad : ch.max_rad;
    const S zero = ch.direction < 0 ? -ch.zero_rad : ch.zero_rad;
    own.base_rad = ch.centre_rad - zero + trim - lo;
    ServoTickRange<S> j;
    j.travel_rad = hi - lo;
    if (!servo_ticks_detail::set_scale(j.scale, ch, lo, hi, timing)) return ServoTickStatus::kUnsupported;
    // The bounds and the centre exactly as map_joint() sends them.
    limit_ticks(ch, timing, &j.lo_ticks, &j.hi_ticks);
    const uint16_t centre = timing.pulse_ticks(servo_pulse_us(ch, clamp(ch.centre_rad, lo, hi)));
    set_centre(j, centre < j.lo_ticks ? j.lo_ticks : centre > j.hi_ticks ? j.hi_ticks : centre);
    joints_.set_range(i, j);
    return ServoTickStatus::kOk;
  }

  //! Joint i's output before configure_joint() (a caller that must relax it first).
  void set_channel(uint8_t i, uint8_t channel) { joints_.own(i).channel = channel; }

  uint8_t count() const { return count_; }
  //! Joint i's constants (a copy: joints may share their ranges).
  ServoTickJoint<S> joint(uint8_t i) const {
    ServoTickJoint<S> j;
    static_cast<ServoTickRange<S>&>(j) = joints_.range(i, slot_of(i));
    static_cast<ServoTickOwn<S>&>(j) = joints_.own(i);
    return j;
  }
  uint8_t channel(uint8_t i) const { return joints_.own(i).channel; }

  //! Joint i's command for joint_rad [rad] (pulse_us left 0).
  ServoCommand map(uint8_t i, S joint_rad) const { return map(i, slot_of(i), joint_rad); }
  //! The same with joint i's slot (i % kSlots) given.
  ServoCommand map(uint8_t i, uint8_t slot, S joint_rad) const {
    const ServoTickOwn<S>& o = joints_.own(i);
    const ServoTickRange<S>& j = joints_.range(i, slot);
    ServoCommand cmd;
    cmd.channel = o.channel;
    cmd.pulse_us = 0;
    if (!detail::is_finite(joint_rad)) {
      cmd.ticks = centre_ticks(j);
      cmd.status = ServoStatus::kNotFinite;
      return cmd;
    }
    S d = o.direction < 0 ? o.base_rad - joint_rad : o.base_rad + joint_rad;
    cmd.status = ServoStatus::kOk;
    if (!detail::is_finite(d)) {
      cmd.ticks = centre_ticks(j);
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
    const uint16_t t = servo_ticks_detail::ticks(j.scale, d);
    cmd.ticks = t < j.lo_ticks ? j.lo_ticks : t > j.hi_ticks ? j.hi_ticks : t;
    return cmd;
  }

  //! Writes joints [first, first + n) through out; the worst status.
  template <typename Output>
  ServoStatus write(Output& out, uint8_t first, const S* joint_rad, uint8_t n) const {
    return write_joints(out, first, joint_rad, n, PerJoint<kSlots == 0>());
  }

 private:
  static uint8_t slot_of(uint8_t i) { return kSlots == 0 ? uint8_t(0) : uint8_t(i % (kSlots == 0 ? 1 : kSlots)); }
  static void set_centre(ServoTickRange<float>& j, uint16_t ticks) { j.centre_ticks = ticks; }
  static void set_centre(ServoTickRange<Fixed>&, uint16_t) {}
  static uint16_t centre_ticks(const ServoTickRange<float>& j) { return j.centre_ticks; }
  static uint16_t centre_ticks(const ServoTickRange<Fixed>& j) { return j.lo_ticks; }  // never: Fixed is finite
  template <bool kOn>
  struct PerJoint {};
  // Float, and shared ranges: each joint through map().
  template <typename Output, typename T, bool kOn>
  ServoStatus write_joints(Output& out, uint8_t first, const T* joint_rad, uint8_t n, PerJoint<kOn>) const {
    ServoStatus worst_status = ServoStatus::kOk;
    for (uint8_t i = 0; i < n && uint8_t(first + i) < count_; ++i) {
      const ServoCommand cmd = map(uint8_t(first + i), joint_rad[i]);
      out.write_ticks(cmd.channel, cmd.ticks);
      if (uint8_t(cmd.status) > uint8_t(worst_status)) worst_status = cmd.status;
    }
    return worst_status;
  }
  // Fixed: map() written out, bit for bit, walking the joints by pointer:
  // through map() avr-gcc spends ~310 more cycles per joint.
  template <typename Output>
  ServoStatus write_joints(Output& out, uint8_t first, const Fixed* joint_rad, uint8_t n, PerJoint<true>) const {
    if (first >= count_) return ServoStatus::kOk;
    if (n > uint8_t(count_ - first)) n = uint8_t(count_ - first);
    const ServoTickJoint<Fixed>* j = joints_.joint_ + first;
    bool limited = false;
    for (; n != 0; --n, ++j, ++joint_rad) {
      // Fixed's saturating sum in place (avr-gcc keeps the operator out of line).
      int32_t d = j->direction < 0 ? Fixed::sat_sub_fast(j->base_rad.raw(), joint_rad->raw())
                                   : Fixed::sat_add_fast(j->base_rad.raw(), joint_rad->raw());
      if (d < 0) {
        d = 0;
        limited = true;
      } else if (d > j->travel_rad.raw()) {
        d = j->travel_rad.raw();
        limited = true;
      }
      const uint16_t t = servo_ticks_detail::ticks_of(Fixed::from_raw(d), j->scale.k, j->scale.shift, j->scale.base_q16);
      out.write_ticks(j->channel, t < j->lo_ticks ? j->lo_ticks : t > j->hi_ticks ? j->hi_ticks : t);
    }
    return limited ? ServoStatus::kLimited : ServoStatus::kOk;
  }

  servo_ticks_detail::TickJoints<S, N, kSlots> joints_;
  uint8_t count_;  // zero, by the constructors
};

}  // namespace strider

#endif  // STRIDER_CONTROL_SERVO_TICK_MAP_H
