//! Settings persistence: one versioned, CRC-checked record in a ByteStore
//! (the Mega's EEPROM). Layout at the base address:
//!   'S' 'T'  version  payload_len  payload[payload_len]  crc16_lo crc16_hi
//! The CRC (CRC-16/CCITT-FALSE, crc.h) covers everything before it.
//! A load that fails for any reason yields the factory defaults and says why.
#ifndef STRIDER_CONTROL_SETTINGS_STORE_H
#define STRIDER_CONTROL_SETTINGS_STORE_H

#include <stdint.h>

#include "crc.h"
#include "reply.h"
#include "settings.h"

namespace strider {

enum class SettingsStatus : uint8_t {
  kOk = 0,           //!< record loaded
  kEmpty = 1,        //!< erased store (all 0xFF): defaults
  kCorrupt = 2,      //!< bad magic, length or CRC: defaults
  kOldVersion = 3,   //!< record of another layout version: defaults
  kInvalid = 4,      //!< CRC fine but a value out of range: defaults
  kWriteFailed = 5,  //!< save: the store rejected a write or read back differently
  kNoSpace = 6       //!< save/load: the record does not fit the store
};

inline const char* to_string(SettingsStatus s) {
  switch (s) {
    case SettingsStatus::kOk: return "ok";
    case SettingsStatus::kEmpty: return "empty";
    case SettingsStatus::kCorrupt: return "corrupt";
    case SettingsStatus::kOldVersion: return "old_version";
    case SettingsStatus::kInvalid: return "invalid";
    case SettingsStatus::kWriteFailed: return "write_failed";
    case SettingsStatus::kNoSpace: return "no_space";
  }
  return "unknown";
}

constexpr char kSettingsStatusNames[] STRIDER_PROGMEM =
    "ok\0empty\0corrupt\0old_version\0invalid\0write_failed\0no_space";
//! to_string() with the text in flash (for replies on the AVR).
inline FlashText to_flash(SettingsStatus s) { return flash_name(kSettingsStatusNames, 7, uint8_t(s)); }

constexpr uint8_t kSettingsMagic0 = 'S';
constexpr uint8_t kSettingsMagic1 = 'T';
constexpr uint8_t kSettingsHeaderBytes = 4;
constexpr uint16_t kSettingsRecordBytes = kSettingsHeaderBytes + kSettingsPayloadBytes + 2;

//! Loads the record at base into *out. *out always holds usable settings
//! afterwards: the record on kOk, the factory defaults otherwise.
template <typename Store>
SettingsStatus load_settings(const Store& store, Settings* out, uint16_t base = 0) {
  set_default_settings(out);
  if (uint32_t(base) + kSettingsRecordBytes > store.size()) return SettingsStatus::kNoSpace;
  uint8_t rec[kSettingsRecordBytes];
  bool erased = true;
  for (uint16_t i = 0; i < kSettingsRecordBytes; ++i) {
    rec[i] = store.read(uint16_t(base + i));
    erased = erased && rec[i] == 0xFF;
  }
  if (erased) return SettingsStatus::kEmpty;
  const uint16_t crc_at = kSettingsRecordBytes - 2;
  const uint16_t crc = uint16_t(rec[crc_at] | (uint16_t(rec[crc_at + 1]) << 8));
  if (rec[0] != kSettingsMagic0 || rec[1] != kSettingsMagic1) return SettingsStatus::kCorrupt;
  // A different version may have a different length: check version before length and CRC,
  // but only trust the version byte once the magic matched.
  if (rec[2] != kSettingsVersion) return SettingsStatus::kOldVersion;
  if (rec[3] != kSettingsPayloadBytes) return SettingsStatus::kCorrupt;
  if (crc16_ccitt(rec, crc_at) != crc) return SettingsStatus::kCorrupt;
  Settings s;
  if (sizeof(Settings) != kSettingsPayloadBytes) s = *out;  // a host's padding zeroed (set_default_settings)
  decode_settings(rec + kSettingsHeaderBytes, &s);
  if (!settings_valid(s)) return SettingsStatus::kInvalid;
  *out = s;
  return SettingsStatus::kOk;
}

//! What load_settings() gave, with its status: handed to a constructor as a
//! temporary, so that no copy of the settings stays in RAM after start-up.
struct LoadedSettings {
  Settings settings;
  SettingsStatus status;
  template <typename Store>
  explicit LoadedSettings(const Store& store, uint16_t base = 0) : status(load_settings(store, &settings, base)) {}
};

//! Writes s at base and reads it back. Refuses invalid settings (kInvalid).
template <typename Store>
SettingsStatus save_settings(Store& store, const Settings& s, uint16_t base = 0) {
  if (!settings_valid(s)) return SettingsStatus::kInvalid;
  if (uint32_t(base) + kSettingsRecordBytes > store.size()) return SettingsStatus::kNoSpace;
  uint8_t rec[kSettingsRecordBytes];
  rec[0] = kSettingsMagic0;
  rec[1] = kSettingsMagic1;
  rec[2] = kSettingsVersion;
  rec[3] = kSettingsPayloadBytes;
  encode_settings(s, rec + kSettingsHeaderBytes);
  const uint16_t crc_at = kSettingsRecordBytes - 2;
  const uint16_t crc = crc16_ccitt(rec, crc_at);
  rec[crc_at] = uint8_t(crc);
  rec[crc_at + 1] = uint8_t(crc >> 8);
  for (uint16_t i = 0; i < kSettingsRecordBytes; ++i) {
    const uint16_t addr = uint16_t(base + i);
    if (!store.write(addr, rec[i]) || store.read(addr) != rec[i]) return SettingsStatus::kWriteFailed;
  }
  return SettingsStatus::kOk;
}

}  // namespace strider

#endif  // STRIDER_CONTROL_SETTINGS_STORE_H
