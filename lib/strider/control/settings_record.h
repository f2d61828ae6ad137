//! One settings record in a ByteStore (the Mega's EEPROM), in any layout:
//!   version 3, a slot:  'S' 'T' 3 payload_len seq_lo seq_hi payload crc_lo crc_hi  (64 bytes)
//!   version 2: the same without the accelerometer's offsets (they load as 0)
//!   version 1, the single record before the slots: no seq             (60 bytes)
//! The CRC (CRC-16/CCITT-FALSE, crc.h) covers everything before it; checked
//! and written byte by byte, no copy in RAM.
#ifndef STRIDER_CONTROL_SETTINGS_RECORD_H
#define STRIDER_CONTROL_SETTINGS_RECORD_H

#include <stdint.h>

#include "crc.h"
#include "reply.h"
#include "settings.h"

namespace strider {

enum class SettingsStatus : uint8_t {
  kOk = 0,           //!< record loaded
  kEmpty = 1,        //!< erased store (all 0xFF): defaults
  kCorrupt = 2,      //!< bad magic, length or CRC (a save cut short, a worn cell): defaults
  kOldVersion = 3,   //!< record of a layout version this firmware does not know: defaults
  kInvalid = 4,      //!< CRC fine but a value out of range: defaults
  kWriteFailed = 5,  //!< save: the store rejected a write or read back differently
  kNoSpace = 6       //!< save/load: the records do not fit the store
};

constexpr char kSettingsStatusNames[] STRIDER_PROGMEM =
    "ok\0empty\0corrupt\0old_version\0invalid\0write_failed\0no_space";
inline FlashText to_flash(SettingsStatus s) { return flash_name(kSettingsStatusNames, 7, uint8_t(s)); }

constexpr uint8_t kSettingsMagic0 = 'S';
constexpr uint8_t kSettingsMagic1 = 'T';
constexpr uint8_t kSettingsSingleRecordVersion = 1;  //!< the layout without a sequence number
constexpr uint8_t kSettingsNoOffsetsVersion = 2;     //!< the slot layout before the accelerometer's offsets
constexpr uint8_t kSettingsHeaderBytes = 4;          //!< magic, version, payload length
constexpr uint8_t kSettingsSeqBytes = 2;
constexpr uint8_t kErasedByte = 0xFF;
constexpr uint16_t kSettingsRecordBytes = kSettingsHeaderBytes + kSettingsSeqBytes + kSettingsPayloadBytes + 2;
constexpr uint16_t kSettingsSingleRecordBytes = kSettingsHeaderBytes + kSettingsPayloadBytes + 2;

//! Where a record's payload starts and how long it is, by layout version.
constexpr uint8_t settings_payload_offset(uint8_t version) {
  return version == kSettingsSingleRecordVersion ? kSettingsHeaderBytes : kSettingsHeaderBytes + kSettingsSeqBytes;
}
constexpr uint8_t settings_payload_bytes(uint8_t version) {
  return version == kSettingsVersion ? kSettingsPayloadBytes : kSettingsPayloadBytesV2;
}

namespace detail {
template <typename Store>
uint16_t read_u16(const Store& store, uint16_t at) {
  return uint16_t(store.read(at) | (uint16_t(store.read(uint16_t(at + 1))) << 8));
}
template <typename Store>
bool all_erased(const Store& store, uint16_t at, uint16_t n) {
  for (uint16_t i = 0; i < n; ++i)
    if (store.read(uint16_t(at + i)) != kErasedByte) return false;
  return true;
}
//! Writes one byte and reads it back (a worn cell is reported, not trusted).
template <typename Store>
bool put_byte(Store& store, uint16_t at, uint8_t v) {
  return store.write(at, v) && store.read(at) == v;
}
//! Whether the n bytes at `at` are followed by their CRC.
template <typename Store>
bool crc_follows(const Store& store, uint16_t at, uint16_t n) {
  uint16_t crc = kCrc16Init;
  for (uint16_t i = 0; i < n; ++i) crc = crc16_ccitt_update(crc, store.read(uint16_t(at + i)));
  return crc == read_u16(store, uint16_t(at + n));
}
}  // namespace detail

//! Writes the n bytes byte(0..n) of a record at `at`, each read back, then
//! their CRC; the first byte is erased first and written last, so a write
//! cut short at any byte leaves no record. kOk or kWriteFailed.
template <typename Store, typename Byte>
SettingsStatus write_checked_record(Store& store, uint16_t at, uint16_t n, Byte byte) {
  const uint8_t first = byte(0);
  if (!detail::put_byte(store, at, kErasedByte)) return SettingsStatus::kWriteFailed;
  uint16_t crc = crc16_ccitt_update(kCrc16Init, first);
  for (uint16_t i = 1; i < n; ++i) {
    const uint8_t b = byte(i);
    crc = crc16_ccitt_update(crc, b);
    if (!detail::put_byte(store, uint16_t(at + i), b)) return SettingsStatus::kWriteFailed;
  }
  const uint16_t crc_at = uint16_t(at + n);
  if (!detail::put_byte(store, crc_at, uint8_t(crc)) || !detail::put_byte(store, uint16_t(crc_at + 1), uint8_t(crc >> 8)) ||
      !detail::put_byte(store, at, first))
    return SettingsStatus::kWriteFailed;
  return SettingsStatus::kOk;
}

//! Checks the record at `at`: kOk with its *version and *seq (0 for
//! version 1, which counts only where single_ok), kEmpty, kOldVersion or
//! kCorrupt.
template <typename Store>
STRIDER_NOINLINE SettingsStatus check_record(const Store& store, uint16_t at, bool single_ok, uint8_t* version,
                                             uint16_t* seq) {
  uint8_t head[kSettingsHeaderBytes + kSettingsSeqBytes];
  for (uint8_t i = 0; i < sizeof head; ++i) head[i] = store.read(uint16_t(at + i));
  if (head[0] != kSettingsMagic0 || head[1] != kSettingsMagic1)
    return detail::all_erased(store, at, kSettingsRecordBytes) ? SettingsStatus::kEmpty : SettingsStatus::kCorrupt;
  const uint8_t v = head[2];
  if (v == kSettingsSingleRecordVersion && !single_ok) return SettingsStatus::kCorrupt;
  if (v != kSettingsVersion && v != kSettingsNoOffsetsVersion && v != kSettingsSingleRecordVersion)
    return SettingsStatus::kOldVersion;
  if (head[3] != settings_payload_bytes(v)) return SettingsStatus::kCorrupt;
  const uint8_t crc_at = uint8_t(settings_payload_offset(v) + settings_payload_bytes(v));
  if (!detail::crc_follows(store, at, crc_at)) return SettingsStatus::kCorrupt;
  *version = v;
  *seq = v == kSettingsSingleRecordVersion ? 0 : uint16_t(head[4] | (uint16_t(head[5]) << 8));
  return SettingsStatus::kOk;
}

//! Decodes the payload of a record check_record() accepted (no range
//! check); what an older layout lacks reads as 0.
template <typename Store>
void read_record_payload(const Store& store, uint16_t at, uint8_t version, Settings* s) {
  uint8_t copy[kSettingsBytesArePayload ? 1 : kSettingsPayloadBytes];
  uint8_t* bytes = kSettingsBytesArePayload ? reinterpret_cast<uint8_t*>(s) : copy;
  const uint16_t from = uint16_t(at + settings_payload_offset(version));
  const uint8_t n = settings_payload_bytes(version);
  for (uint8_t i = 0; i < kSettingsPayloadBytes; ++i) bytes[i] = i < n ? store.read(uint16_t(from + i)) : 0;
  if (!kSettingsBytesArePayload) {
    __builtin_memset(s, 0, sizeof *s);  // a host's padding too: whole copies compare byte for byte
    decode_settings(copy, s);
  }
}

//! Writes s as a current record with sequence number seq at `at`.
template <typename Store>
SettingsStatus write_record(Store& store, uint16_t at, const Settings& s, uint16_t seq) {
  uint8_t copy[kSettingsBytesArePayload ? 1 : kSettingsPayloadBytes];
  const uint8_t* payload = reinterpret_cast<const uint8_t*>(&s);
  if (!kSettingsBytesArePayload) {
    encode_settings(s, copy);
    payload = copy;
  }
  const uint8_t header[kSettingsHeaderBytes + kSettingsSeqBytes] = {
      kSettingsMagic0, kSettingsMagic1, kSettingsVersion, kSettingsPayloadBytes, uint8_t(seq), uint8_t(seq >> 8)};
  return write_checked_record(store, at, sizeof header + kSettingsPayloadBytes,
                              [&](uint16_t i) { return i < sizeof header ? header[i] : payload[i - sizeof header]; });
}

}  // namespace strider

#endif  // STRIDER_CONTROL_SETTINGS_RECORD_H
