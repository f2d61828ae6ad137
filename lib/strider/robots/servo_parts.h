//! ServoPart: the hobby servos the built-in robots use, with the makers'
//! datasheet figures at 6 V (every robot runs its servos from a 5-6 V BEC).
//! Travel: about 180 deg with a 500-2500 us pulse (the makers' "operating
//! angle" is for 1000-2000 us); per-servo calibration corrects the pulses.
#ifndef STRIDER_ROBOTS_SERVO_PARTS_H
#define STRIDER_ROBOTS_SERVO_PARTS_H

#include <stdint.h>

#include "../math/flash_table.h"

namespace strider {

enum class ServoPart : uint8_t {
  kSg90 = 0,    //!< Tower Pro SG90, 9 g micro servo, plastic gears
  kMg90s = 1,   //!< Tower Pro MG90S, 13.4 g micro servo, metal gears
  kMg995 = 2,   //!< Tower Pro MG995, 55 g standard servo, metal gears
  kMg996r = 3,  //!< Tower Pro MG996R, 55 g standard servo, metal gears
  kHs311 = 4,   //!< Hitec HS-311, 43 g standard servo, nylon gears
  kDs3235 = 5,  //!< DSSERVO DS3235SG, 65 g 35 kg cm class digital servo, steel gears
  kDs5160 = 6   //!< DSSERVO DS5160, 155 g 60 kg cm class digital servo, steel gears
};

constexpr uint8_t kServoPartCount = 7;

//! Datasheet figures of one servo part.
struct ServoSpec {
  const char* name;         //!< part name as sold
  float travel_deg;         //!< full mechanical travel for the pulse range [deg]
  uint16_t min_pulse_us;    //!< pulse at one end of the travel [us]
  uint16_t max_pulse_us;    //!< pulse at the other end [us]
  float stall_torque_kg_cm; //!< stall torque at 6 V [kg cm]
  float speed_s_per_60deg;  //!< no-load speed at 6 V [s / 60 deg]
  float mass_g;             //!< [g]
};

constexpr ServoSpec servo_spec(ServoPart part) {
  // SG90: 1.8 kg cm and 0.1 s/60 deg are its 4.8 V figures (no 6 V rating).
  return part == ServoPart::kSg90     ? ServoSpec{"SG90", 180.0f, 500, 2500, 1.8f, 0.10f, 9.0f}
         : part == ServoPart::kMg90s  ? ServoSpec{"MG90S", 180.0f, 500, 2500, 2.2f, 0.08f, 13.4f}
         : part == ServoPart::kMg995  ? ServoSpec{"MG995", 180.0f, 500, 2500, 10.0f, 0.16f, 55.0f}
         : part == ServoPart::kMg996r ? ServoSpec{"MG996R", 180.0f, 500, 2500, 11.0f, 0.14f, 55.0f}
         : part == ServoPart::kHs311  ? ServoSpec{"HS-311", 180.0f, 500, 2500, 3.7f, 0.15f, 43.0f}
         : part == ServoPart::kDs3235 ? ServoSpec{"DS3235", 180.0f, 500, 2500, 32.0f, 0.13f, 65.0f}
                                      : ServoSpec{"DS5160", 180.0f, 500, 2500, 58.0f, 0.17f, 155.0f};
}

//! Top speed of a part [deg/s] (60 deg over its no-load time).
constexpr float servo_speed_deg_s(ServoPart part) { return 60.0f / servo_spec(part).speed_s_per_60deg; }

//! What the servo map and the slew limit need of a part at run time, from a
//! flash table (servo_spec() at run time builds all seven specs in AVR RAM).
struct ServoTravel {
  float travel_deg;       //!< servo_spec().travel_deg [deg]
  uint16_t min_pulse_us;  //!< [us]
  uint16_t max_pulse_us;  //!< [us]
  float speed_deg_s;      //!< servo_speed_deg_s() [deg/s]
};

namespace servo_parts_detail {
constexpr ServoTravel travel_of(ServoPart p) {
  return ServoTravel{servo_spec(p).travel_deg, servo_spec(p).min_pulse_us, servo_spec(p).max_pulse_us,
                     servo_speed_deg_s(p)};
}
template <typename T = void>
struct Tables {
  static const ServoTravel kTravel[kServoPartCount];
};
template <typename T>
const ServoTravel Tables<T>::kTravel[kServoPartCount] STRIDER_PROGMEM = {
    travel_of(ServoPart(0)), travel_of(ServoPart(1)), travel_of(ServoPart(2)), travel_of(ServoPart(3)),
    travel_of(ServoPart(4)), travel_of(ServoPart(5)), travel_of(ServoPart(6))};
static_assert(kServoPartCount == 7, "servo_parts_detail::Tables lists every part");
}  // namespace servo_parts_detail

//! servo_spec(part)'s travel, pulses and speed, read from flash.
inline ServoTravel servo_travel(ServoPart part) {
  ServoTravel t;
  const uint8_t i = uint8_t(part) < kServoPartCount ? uint8_t(part) : uint8_t(kServoPartCount - 1);
  flash_copy(&t, &servo_parts_detail::Tables<>::kTravel[i], sizeof t);
  return t;
}

}  // namespace strider

#endif  // STRIDER_ROBOTS_SERVO_PARTS_H
