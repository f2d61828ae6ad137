//! Settings: everything the firmware keeps across power cycles, its
//! defaults, valid ranges and byte layout. Integers only: the record is the
//! same on the AVR and the host.
#ifndef STRIDER_CONTROL_SETTINGS_H
#define STRIDER_CONTROL_SETTINGS_H

#include <stdint.h>

#include "pca9685_timing.h"

namespace strider {

constexpr uint8_t kMaxServoJoints = 18;     //!< hexapod18 has the most joints
constexpr int16_t kMaxTrimDecideg = 300;    //!< |trim| <= 30.0 deg
constexpr int8_t kMaxAccelOffsetMg = 100;   //!< |accelerometer offset| <= 100 mg (5.7 deg)
//! Layout version of the stored record (settings_record.h).
constexpr uint8_t kSettingsVersion = 3;

struct Settings {
  uint32_t pca_osc_hz;                   //!< measured PCA9685 oscillator [Hz], 20-30 MHz
  uint16_t pwm_hz;                       //!< servo PWM frequency [Hz], 40-400 (digital servos)
  uint32_t baud;                         //!< Bluetooth UART rate [baud]
  uint16_t deadman_ms;                   //!< stop when no command for this long while moving [ms], 0 = off
  uint16_t avoid_stop_mm;                //!< obstacle nearer than this ahead -> sidestep [mm]
  uint16_t avoid_slow_mm;                //!< obstacle nearer than this -> slow down [mm]
  uint8_t avoid_enabled;                 //!< 1 = obstacle avoidance on
  uint8_t speed_pct;                     //!< speed at power-up [%], 0-100
  int16_t trim_decideg[kMaxServoJoints]; //!< per-joint trim [0.1 deg], +-300
  int8_t accel_x_mg;                     //!< accelerometer x offset (`cal level`) [mg], +-100
  int8_t accel_y_mg;                     //!< accelerometer y offset [mg], +-100
};

//! Payload size [bytes]: little-endian fields in declaration order.
constexpr uint8_t kSettingsPayloadBytes = 4 + 2 + 4 + 2 + 2 + 2 + 1 + 1 + 2 * kMaxServoJoints + 1 + 1;
//! The payload of versions 1 and 2: up to the trims.
constexpr uint8_t kSettingsPayloadBytesV2 = kSettingsPayloadBytes - 2;

//! Factory settings: nominal oscillator, 50 Hz, 9600 baud (HC-05 default),
//! 1 s deadman, seed 000's 20 cm avoidance distance with a 40 cm slow band.
constexpr Settings default_settings() {
  return Settings{kPca9685NominalOscHz, 50, 9600, 1000, 200, 400, 1, 50,
                  {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 0, 0};
}

//! *s = default_settings(), field by field: a copy of the constant would
//! keep its 54 bytes in RAM on the AVR.
inline void set_default_settings(Settings* s) {
  constexpr Settings d = default_settings();
  // A host's padding zeroed: whole copies compare byte for byte.
  if (sizeof(Settings) != kSettingsPayloadBytes) __builtin_memset(s, 0, sizeof *s);
  s->pca_osc_hz = d.pca_osc_hz;
  s->pwm_hz = d.pwm_hz;
  s->baud = d.baud;
  s->deadman_ms = d.deadman_ms;
  s->avoid_stop_mm = d.avoid_stop_mm;
  s->avoid_slow_mm = d.avoid_slow_mm;
  s->avoid_enabled = d.avoid_enabled;
  s->speed_pct = d.speed_pct;
  for (uint8_t i = 0; i < kMaxServoJoints; ++i) s->trim_decideg[i] = 0;
  s->accel_x_mg = s->accel_y_mg = 0;
  static_assert(d.trim_decideg[0] == 0 && d.trim_decideg[kMaxServoJoints - 1] == 0, "default trims are zero");
}

//! True for the UART rates the HC-05 AT+UART command accepts that the Mega
//! can run reliably at 16 MHz.
constexpr bool valid_baud(uint32_t baud) {
  return baud == 9600ul || baud == 19200ul || baud == 38400ul || baud == 57600ul || baud == 115200ul;
}

//! Range check of every field.
inline bool settings_valid(const Settings& s) {
  if (s.pca_osc_hz < kPca9685MinOscHz || s.pca_osc_hz > kPca9685MaxOscHz) return false;
  if (s.pwm_hz < 40 || s.pwm_hz > 400) return false;
  if (!valid_baud(s.baud)) return false;
  if (s.deadman_ms > 60000u) return false;
  if (s.avoid_stop_mm < 20 || s.avoid_stop_mm > 3000) return false;
  if (s.avoid_slow_mm < s.avoid_stop_mm || s.avoid_slow_mm > 3000) return false;
  if (s.avoid_enabled > 1 || s.speed_pct > 100) return false;
  for (uint8_t i = 0; i < kMaxServoJoints; ++i) {
    if (s.trim_decideg[i] > kMaxTrimDecideg || s.trim_decideg[i] < -kMaxTrimDecideg) return false;
  }
  return s.accel_x_mg <= kMaxAccelOffsetMg && s.accel_x_mg >= -kMaxAccelOffsetMg && s.accel_y_mg <= kMaxAccelOffsetMg &&
         s.accel_y_mg >= -kMaxAccelOffsetMg;
}

namespace detail {
inline void put_u16(uint8_t*& p, uint16_t v) { *p++ = uint8_t(v); *p++ = uint8_t(v >> 8); }
inline void put_u32(uint8_t*& p, uint32_t v) { put_u16(p, uint16_t(v)); put_u16(p, uint16_t(v >> 16)); }
inline uint16_t get_u16(const uint8_t*& p) { const uint16_t v = uint16_t(p[0] | (uint16_t(p[1]) << 8)); p += 2; return v; }
inline uint32_t get_u32(const uint8_t*& p) { const uint32_t lo = get_u16(p); return lo | (uint32_t(get_u16(p)) << 16); }
}  // namespace detail

#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr bool kLittleEndianTarget = true;
#else
constexpr bool kLittleEndianTarget = false;
#endif
//! True where a Settings' bytes are its payload (the AVR): encode/decode copy.
constexpr bool kSettingsBytesArePayload = kLittleEndianTarget && sizeof(Settings) == kSettingsPayloadBytes;
static_assert(!kSettingsBytesArePayload ||
                  (__builtin_offsetof(Settings, pwm_hz) == 4 && __builtin_offsetof(Settings, baud) == 6 &&
                   __builtin_offsetof(Settings, deadman_ms) == 10 && __builtin_offsetof(Settings, avoid_stop_mm) == 12 &&
                   __builtin_offsetof(Settings, avoid_slow_mm) == 14 && __builtin_offsetof(Settings, avoid_enabled) == 16 &&
                   __builtin_offsetof(Settings, speed_pct) == 17 && __builtin_offsetof(Settings, trim_decideg) == 18 &&
                   __builtin_offsetof(Settings, accel_x_mg) == 54 && __builtin_offsetof(Settings, accel_y_mg) == 55),
              "the payload's layout (encode_settings) is the struct's");

namespace detail {
inline void copy_bytes(uint8_t* to, const uint8_t* from, uint8_t n) {
  for (uint8_t i = 0; i < n; ++i) to[i] = from[i];
}
}  // namespace detail

//! Writes the payload (kSettingsPayloadBytes) of s into out.
inline void encode_settings(const Settings& s, uint8_t* out) {
  if (kSettingsBytesArePayload) {
    detail::copy_bytes(out, reinterpret_cast<const uint8_t*>(&s), kSettingsPayloadBytes);
    return;
  }
  uint8_t* p = out;
  detail::put_u32(p, s.pca_osc_hz);
  detail::put_u16(p, s.pwm_hz);
  detail::put_u32(p, s.baud);
  detail::put_u16(p, s.deadman_ms);
  detail::put_u16(p, s.avoid_stop_mm);
  detail::put_u16(p, s.avoid_slow_mm);
  *p++ = s.avoid_enabled;
  *p++ = s.speed_pct;
  for (uint8_t i = 0; i < kMaxServoJoints; ++i) detail::put_u16(p, uint16_t(s.trim_decideg[i]));
  *p++ = uint8_t(s.accel_x_mg);
  *p++ = uint8_t(s.accel_y_mg);
}

//! Reads a payload written by encode_settings (no validation).
inline void decode_settings(const uint8_t* in, Settings* s) {
  if (kSettingsBytesArePayload) {
    detail::copy_bytes(reinterpret_cast<uint8_t*>(s), in, kSettingsPayloadBytes);
    return;
  }
  const uint8_t* p = in;
  s->pca_osc_hz = detail::get_u32(p);
  s->pwm_hz = detail::get_u16(p);
  s->baud = detail::get_u32(p);
  s->deadman_ms = detail::get_u16(p);
  s->avoid_stop_mm = detail::get_u16(p);
  s->avoid_slow_mm = detail::get_u16(p);
  s->avoid_enabled = *p++;
  s->speed_pct = *p++;
  for (uint8_t i = 0; i < kMaxServoJoints; ++i) s->trim_decideg[i] = int16_t(detail::get_u16(p));
  s->accel_x_mg = int8_t(*p++);
  s->accel_y_mg = int8_t(*p++);
}

}  // namespace strider

#endif  // STRIDER_CONTROL_SETTINGS_H
