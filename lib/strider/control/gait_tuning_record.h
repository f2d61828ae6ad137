//! The gait tunings in a ByteStore after the settings' two slots, a record
//! of its own (settings images written before it load unchanged): one entry
//! per gait of the model's list, two slots written in turn like the settings:
//!   'G' 'T' version entry_bytes seq_lo seq_hi  entries[kTunedGaits]  crc_lo crc_hi
//!   entry: used h_lo h_hi l_lo l_hi c_lo c_hi duty shape z_lo z_hi   (GaitTuning)
#ifndef STRIDER_CONTROL_GAIT_TUNING_RECORD_H
#define STRIDER_CONTROL_GAIT_TUNING_RECORD_H

#include <stdint.h>

#include "../gait/gait_tuning.h"
#include "settings_record.h"
#include "settings_store.h"

namespace strider {

constexpr uint8_t kTunedGaits = 4;  //!< the longest gait list (quadrupeds: walk trot pace crawl)
constexpr uint8_t kGaitTuningVersion = 1;
constexpr uint8_t kGaitTuningEntryBytes = 11;
constexpr uint8_t kGaitTuningHeaderBytes = 6;
constexpr uint16_t kGaitTuningRecordBytes = kGaitTuningHeaderBytes + kTunedGaits * kGaitTuningEntryBytes + 2;
constexpr uint16_t kGaitTuningSlotBytes = 64;
constexpr uint16_t kGaitTuningBase = kSettingsStoreBytes;
constexpr uint16_t kGaitTuningStoreEnd = kGaitTuningBase + 2 * kGaitTuningSlotBytes;
constexpr uint8_t kGaitTuningMagic0 = 'G', kGaitTuningMagic1 = 'T';
static_assert(kGaitTuningRecordBytes <= kGaitTuningSlotBytes, "a tuning record fits its slot");

//! The newest valid tuning record's slot (kNoSettingsSlot: none) and seq.
struct GaitTuningSlot {
  uint8_t slot = kNoSettingsSlot;
  uint16_t seq = 0;
};

namespace gait_tuning_record_detail {
constexpr uint16_t slot_address(uint8_t slot) { return uint16_t(kGaitTuningBase + slot * kGaitTuningSlotBytes); }
constexpr uint16_t entry_address(uint8_t slot, uint8_t gait) {
  return uint16_t(slot_address(slot) + kGaitTuningHeaderBytes + gait * kGaitTuningEntryBytes);
}
//! Whether slot holds a whole record (magic, layout, CRC); its seq.
template <typename Store>
bool valid_slot(const Store& store, uint8_t slot, uint16_t* seq) {
  const uint16_t at = slot_address(slot);
  if (store.read(at) != kGaitTuningMagic0 || store.read(uint16_t(at + 1)) != kGaitTuningMagic1 ||
      store.read(uint16_t(at + 2)) != kGaitTuningVersion || store.read(uint16_t(at + 3)) != kGaitTuningEntryBytes)
    return false;
  if (!detail::crc_follows(store, at, uint16_t(kGaitTuningRecordBytes - 2))) return false;
  *seq = detail::read_u16(store, uint16_t(at + 4));
  return true;
}
//! The entry's bytes of t (used = 1).
inline void entry_bytes(const GaitTuning& t, uint8_t* b) {
  b[0] = 1;
  b[1] = uint8_t(t.step_height_cmm), b[2] = uint8_t(t.step_height_cmm >> 8);
  b[3] = uint8_t(t.step_length_cmm), b[4] = uint8_t(t.step_length_cmm >> 8);
  b[5] = uint8_t(t.cycle_cs), b[6] = uint8_t(t.cycle_cs >> 8);
  b[7] = t.duty_pct, b[8] = t.shape;
  b[9] = uint8_t(uint16_t(t.height_dmm)), b[10] = uint8_t(uint16_t(t.height_dmm) >> 8);
}
}  // namespace gait_tuning_record_detail

template <typename Store>
bool gait_tuning_fits(const Store& store) {
  return uint32_t(kGaitTuningStoreEnd) <= store.size();
}

//! The newest whole record in the store (none: slot kNoSettingsSlot).
template <typename Store>
GaitTuningSlot find_gait_tuning(const Store& store) {
  GaitTuningSlot best;
  if (!gait_tuning_fits(store)) return best;
  for (uint8_t s = 0; s < 2; ++s) {
    uint16_t seq = 0;
    if (!gait_tuning_record_detail::valid_slot(store, s, &seq)) continue;
    if (best.slot == kNoSettingsSlot || int16_t(uint16_t(seq - best.seq)) > 0) {
      best.slot = s;
      best.seq = seq;
    }
  }
  return best;
}

//! Gait number `gait`'s tuning from the newest record into *out; false (out
//! untouched) when there is none (no record, or that gait never saved).
template <typename Store>
bool read_gait_tuning(const Store& store, uint8_t gait, GaitTuning* out) {
  const GaitTuningSlot found = find_gait_tuning(store);
  if (found.slot == kNoSettingsSlot || gait >= kTunedGaits) return false;
  const uint16_t at = gait_tuning_record_detail::entry_address(found.slot, gait);
  if (store.read(at) != 1) return false;
  out->step_height_cmm = detail::read_u16(store, uint16_t(at + 1));
  out->step_length_cmm = detail::read_u16(store, uint16_t(at + 3));
  out->cycle_cs = detail::read_u16(store, uint16_t(at + 5));
  out->duty_pct = store.read(uint16_t(at + 7));
  out->shape = store.read(uint16_t(at + 8));
  out->height_dmm = int16_t(detail::read_u16(store, uint16_t(at + 9)));
  return true;
}

//! Writes gait `gait`'s entry t and the newest record's others into the
//! older slot: kOk, kWriteFailed or kNoSpace.
template <typename Store>
STRIDER_NOINLINE SettingsStatus save_gait_tuning(Store& store, uint8_t gait, const GaitTuning& t) {
  using namespace gait_tuning_record_detail;
  if (!gait_tuning_fits(store) || gait >= kTunedGaits) return SettingsStatus::kNoSpace;
  const GaitTuningSlot found = find_gait_tuning(store);
  const uint8_t slot = found.slot == 0 ? 1 : 0;
  const uint16_t seq = uint16_t(found.seq + 1);
  const uint16_t at = slot_address(slot);
  uint8_t mine[kGaitTuningEntryBytes];
  entry_bytes(t, mine);
  const uint8_t head[kGaitTuningHeaderBytes] = {kGaitTuningMagic0, kGaitTuningMagic1, kGaitTuningVersion,
                                                kGaitTuningEntryBytes, uint8_t(seq), uint8_t(seq >> 8)};
  return write_checked_record(store, at, uint16_t(kGaitTuningRecordBytes - 2), [&](uint16_t i) -> uint8_t {
    if (i < kGaitTuningHeaderBytes) return head[i];
    const uint8_t g = uint8_t((i - kGaitTuningHeaderBytes) / kGaitTuningEntryBytes);
    const uint8_t k = uint8_t((i - kGaitTuningHeaderBytes) % kGaitTuningEntryBytes);
    if (g == gait) return mine[k];
    return found.slot == kNoSettingsSlot ? uint8_t(0) : store.read(uint16_t(entry_address(found.slot, g) + k));
  });
}

}  // namespace strider

#endif  // STRIDER_CONTROL_GAIT_TUNING_RECORD_H
