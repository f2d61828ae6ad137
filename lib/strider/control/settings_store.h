//! Settings persistence: two record slots in a ByteStore (settings_record.h),
//! slot 1 kSettingsSlotBytes after slot 0. A save writes the slot that does
//! not hold the record in force with the next sequence number; a load takes
//! the valid record with the newest (0 follows 65535): a save cut short
//! leaves the record before it loadable (docs/reliability.md, "EEPROM").
#ifndef STRIDER_CONTROL_SETTINGS_STORE_H
#define STRIDER_CONTROL_SETTINGS_STORE_H

#include <stdint.h>

#include "settings_record.h"

namespace strider {

constexpr uint8_t kSettingsSlots = 2;
constexpr uint16_t kSettingsSlotBytes = 64;  //!< slot i at base + i * kSettingsSlotBytes
constexpr uint16_t kSettingsStoreBytes = kSettingsSlots * kSettingsSlotBytes;
constexpr uint8_t kNoSettingsSlot = 0xFF;
static_assert(kSettingsRecordBytes <= kSettingsSlotBytes && kSettingsSingleRecordBytes <= kSettingsSlotBytes,
              "a record fits its slot");

//! Which record the settings in force came from, or the last one written:
//! where the next save goes.
struct SettingsRecord {
  uint16_t seq = 0;                //!< its sequence number (0 for a version-1 record)
  uint8_t slot = kNoSettingsSlot;  //!< 0 or 1; kNoSettingsSlot: none (defaults)
  uint8_t version = 0;             //!< its layout: kSettingsVersion, kSettingsNoOffsetsVersion or kSettingsSingleRecordVersion
  //! How the load went: kOk, or why the defaults are in force (the slot that says most).
  SettingsStatus load_status = SettingsStatus::kEmpty;
  //! At load: what the other slot held.
  SettingsStatus other = SettingsStatus::kEmpty;

  uint8_t next_slot() const { return slot == 0 ? 1 : 0; }
  uint16_t next_seq() const { return uint16_t(seq + 1); }
};
static_assert(sizeof(SettingsRecord) == 6, "SettingsRecord: no padding");

constexpr uint16_t settings_slot_address(uint16_t base, uint8_t slot) {
  return uint16_t(base + slot * kSettingsSlotBytes);
}

//! True when record (va, sa) is newer than (vb, sb): a slot record beats a
//! version-1 record; else sa follows sb by less than half the sequence space.
constexpr bool settings_record_newer(uint8_t va, uint16_t sa, uint8_t vb, uint16_t sb) {
  return (va == kSettingsSingleRecordVersion) != (vb == kSettingsSingleRecordVersion)
             ? vb == kSettingsSingleRecordVersion
             : int16_t(uint16_t(sa - sb)) > 0;
}

//! Loads the newest valid record of the two slots at base into *out, which
//! in *record; otherwise the defaults, with the reason of the slot that
//! says most. A record out of range counts as none: the older one is taken.
template <typename Store>
STRIDER_NOINLINE SettingsStatus load_settings(const Store& store, Settings* out, SettingsRecord* record,
                                              uint16_t base = 0) {
  *record = SettingsRecord();
  SettingsStatus result = SettingsStatus::kNoSpace;
  if (uint32_t(base) + kSettingsStoreBytes <= store.size()) {
    SettingsStatus status[kSettingsSlots] = {SettingsStatus::kEmpty, SettingsStatus::kEmpty};
    // The newest record; one whose values fail is marked and the search repeated.
    for (uint8_t attempt = 0; attempt < kSettingsSlots; ++attempt) {
      SettingsRecord best;
      for (uint8_t i = 0; i < kSettingsSlots; ++i) {
        if (attempt != 0 && status[i] != SettingsStatus::kOk) continue;
        uint8_t version = 0;
        uint16_t seq = 0;
        status[i] = check_record(store, settings_slot_address(base, i), i == 0, &version, &seq);
        if (status[i] == SettingsStatus::kOk &&
            (best.slot == kNoSettingsSlot || settings_record_newer(version, seq, best.version, best.seq))) {
          best.slot = i;
          best.version = version;
          best.seq = seq;
        }
      }
      if (best.slot == kNoSettingsSlot) break;
      read_record_payload(store, settings_slot_address(base, best.slot), best.version, out);
      if (settings_valid(*out)) {
        best.load_status = SettingsStatus::kOk;
        best.other = status[1 - best.slot];
        *record = best;
        return SettingsStatus::kOk;
      }
      status[best.slot] = SettingsStatus::kInvalid;
    }
    // The statuses but kOk are numbered empty < corrupt < old_version < invalid.
    result = uint8_t(status[0]) > uint8_t(status[1]) ? status[0] : status[1];
  }
  set_default_settings(out);
  record->load_status = result;
  return result;
}

//! load_settings() for a caller that does not save afterwards.
template <typename Store>
SettingsStatus load_settings(const Store& store, Settings* out, uint16_t base = 0) {
  SettingsRecord record;
  return load_settings(store, out, &record, base);
}

//! What load_settings() gave: a temporary, so no copy stays in RAM.
struct LoadedSettings {
  Settings settings;
  SettingsRecord record;
  template <typename Store>
  explicit LoadedSettings(const Store& store, uint16_t base = 0) {
    load_settings(store, &settings, &record, base);
  }
};

//! Writes s into the slot that does not hold *record, with the next
//! sequence number; *record is then the new one (unchanged on a failure).
//! Refuses invalid settings (kInvalid).
template <typename Store>
STRIDER_NOINLINE SettingsStatus save_settings(Store& store, const Settings& s, SettingsRecord* record,
                                              uint16_t base = 0) {
  if (!settings_valid(s)) return SettingsStatus::kInvalid;
  if (uint32_t(base) + kSettingsStoreBytes > store.size()) return SettingsStatus::kNoSpace;
  const uint8_t slot = record->next_slot();
  const uint16_t seq = record->next_seq();
  const SettingsStatus st = write_record(store, settings_slot_address(base, slot), s, seq);
  if (st != SettingsStatus::kOk) return st;
  record->seq = seq;
  record->slot = slot;
  record->version = kSettingsVersion;
  return SettingsStatus::kOk;
}

//! save_settings() after the newest valid record, looked up first.
template <typename Store>
SettingsStatus save_settings(Store& store, const Settings& s, uint16_t base = 0) {
  Settings scratch;
  SettingsRecord record;
  if (load_settings(store, &scratch, &record, base) == SettingsStatus::kNoSpace) return SettingsStatus::kNoSpace;
  return save_settings(store, s, &record, base);
}

}  // namespace strider

#endif  // STRIDER_CONTROL_SETTINGS_STORE_H
