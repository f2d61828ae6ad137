// The two settings slots (settings_store.h): the record's bytes, slots and
// sequence numbers taking turns, a damaged slot A, B or both, sequence
// numbers wrapping round, the single record of the firmware before the
// slots (loaded, kept by the first save, replaced by the second), a value
// out of range, a failed write, and a save cut short at every byte, with the
// byte being written left as it was, erased or garbled.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "control/crc.h"
#include "control/settings_store.h"
#include "fakes/fake_store.h"

using strider::Settings;
using strider::SettingsRecord;
using strider::SettingsStatus;
using strider_test::FakeStore;

namespace {

constexpr uint16_t kSlot1 = strider::kSettingsSlotBytes;

Settings settings_with_trim(int16_t trim0) {
  Settings s = strider::default_settings();
  s.trim_decideg[0] = trim0;
  s.deadman_ms = uint16_t(500 + trim0);
  return s;
}

// What a load gives: status, record, and trim 0 (which tells the saves apart).
struct Loaded {
  SettingsStatus status;
  SettingsRecord record;
  int16_t trim0;
};

Loaded load(const FakeStore& store) {
  Loaded l;
  Settings s;
  l.status = strider::load_settings(store, &s, &l.record);
  EXPECT_EQ(l.record.load_status, l.status);
  l.trim0 = s.trim_decideg[0];
  if (l.status != SettingsStatus::kOk) {
    EXPECT_EQ(s.trim_decideg[0], 0) << "defaults";
    EXPECT_EQ(s.deadman_ms, strider::default_settings().deadman_ms) << "defaults";
  }
  return l;
}

// The 54-byte payload of the layouts before the accelerometer's offsets
// (versions 1 and 2): today's payload without its last two bytes.
constexpr uint8_t kOldPayloadBytes = 54;
static_assert(strider::kSettingsPayloadBytes == kOldPayloadBytes + 2, "the offsets are the payload's last two bytes");

// A record of a layout before the accelerometer's offsets, built here byte
// by byte from its documented layout, as that firmware wrote it at `at`:
// version 1, the single record at address 0: 'S' 'T' 1 54 payload crc (60
// bytes); version 2, a slot record: 'S' 'T' 2 54 seq payload crc (62 bytes).
void put_old_record(FakeStore* store, uint16_t at, uint8_t version, const Settings& s, uint16_t seq = 0) {
  uint8_t rec[6 + kOldPayloadBytes + 2];
  uint8_t payload[strider::kSettingsPayloadBytes];
  const uint8_t head = version == 1 ? 4 : 6, n = uint8_t(head + kOldPayloadBytes + 2);
  rec[0] = 'S';
  rec[1] = 'T';
  rec[2] = version;
  rec[3] = kOldPayloadBytes;
  rec[4] = uint8_t(seq);  // version 1: the payload's first bytes, written over below
  rec[5] = uint8_t(seq >> 8);
  strider::encode_settings(s, payload);
  std::memcpy(rec + head, payload, kOldPayloadBytes);
  const uint16_t crc = strider::crc16_ccitt(rec, n - 2);
  rec[n - 2] = uint8_t(crc);
  rec[n - 1] = uint8_t(crc >> 8);
  std::memcpy(store->bytes + at, rec, n);
}
void put_single_record(FakeStore* store, const Settings& s) { put_old_record(store, 0, 1, s); }
void put_v2_record(FakeStore* store, uint16_t at, const Settings& s, uint16_t seq) { put_old_record(store, at, 2, s, seq); }

// A record of the current layout with any sequence number at `at`.
void put_record(FakeStore* store, uint16_t at, const Settings& s, uint16_t seq) {
  ASSERT_EQ(strider::write_record(*store, at, s, seq), SettingsStatus::kOk);
}

TEST(SettingsSlots, RecordLayoutBytes) {
  FakeStore store;
  Settings s = settings_with_trim(-123);
  s.accel_x_mg = -37;
  s.accel_y_mg = 52;
  put_record(&store, 0, s, 0x1234);
  EXPECT_EQ(strider::kSettingsRecordBytes, 64);
  EXPECT_EQ(store.bytes[0], 'S');
  EXPECT_EQ(store.bytes[1], 'T');
  EXPECT_EQ(store.bytes[2], 3);
  EXPECT_EQ(store.bytes[3], 56);
  EXPECT_EQ(store.bytes[4], 0x34);  // sequence number, little-endian
  EXPECT_EQ(store.bytes[5], 0x12);
  uint8_t payload[strider::kSettingsPayloadBytes];
  strider::encode_settings(s, payload);
  EXPECT_EQ(std::memcmp(store.bytes + 6, payload, sizeof payload), 0);
  EXPECT_EQ(store.bytes[60], uint8_t(int8_t(-37)));  // the accelerometer's offsets [mg], after the trims
  EXPECT_EQ(store.bytes[61], 52);
  const uint16_t crc = strider::crc16_ccitt(store.bytes, 62);
  EXPECT_EQ(store.bytes[62], uint8_t(crc));
  EXPECT_EQ(store.bytes[63], uint8_t(crc >> 8));
  EXPECT_EQ(store.bytes[64], 0xFF);  // nothing beyond the record: the slot is full
}

TEST(SettingsSlots, SavesTakeTurnsAndNumberTheRecords) {
  FakeStore store;
  SettingsRecord record;
  Settings s;
  ASSERT_EQ(strider::load_settings(store, &s, &record), SettingsStatus::kEmpty);
  EXPECT_EQ(record.slot, strider::kNoSettingsSlot);
  for (int n = 1; n <= 5; ++n) {
    ASSERT_EQ(strider::save_settings(store, settings_with_trim(int16_t(n)), &record), SettingsStatus::kOk);
    EXPECT_EQ(record.slot, (n - 1) % 2) << "save " << n;
    EXPECT_EQ(record.seq, n);
    const Loaded l = load(store);
    EXPECT_EQ(l.status, SettingsStatus::kOk);
    EXPECT_EQ(l.trim0, n);
    EXPECT_EQ(l.record.slot, record.slot);
    EXPECT_EQ(l.record.seq, n);
    EXPECT_EQ(l.record.version, strider::kSettingsVersion);
    EXPECT_EQ(l.record.other, n == 1 ? SettingsStatus::kEmpty : SettingsStatus::kOk);
  }
  // The convenience save (no record kept) looks the newest up first.
  ASSERT_EQ(strider::save_settings(store, settings_with_trim(6)), SettingsStatus::kOk);
  const Loaded l = load(store);
  EXPECT_EQ(l.trim0, 6);
  EXPECT_EQ(l.record.slot, 1);
  EXPECT_EQ(l.record.seq, 6);
}

// Slot A holds seq 1 (trim 1), slot B seq 2 (trim 2).
FakeStore two_records() {
  FakeStore store;
  SettingsRecord record;
  EXPECT_EQ(strider::save_settings(store, settings_with_trim(1), &record), SettingsStatus::kOk);
  EXPECT_EQ(strider::save_settings(store, settings_with_trim(2), &record), SettingsStatus::kOk);
  return store;
}

TEST(SettingsSlots, CorruptSlotAKeepsB) {
  FakeStore store = two_records();
  store.bytes[20] ^= 0x08;  // slot A's payload
  const Loaded l = load(store);
  EXPECT_EQ(l.status, SettingsStatus::kOk);
  EXPECT_EQ(l.trim0, 2);
  EXPECT_EQ(l.record.slot, 1);
  EXPECT_EQ(l.record.seq, 2);
  EXPECT_EQ(l.record.other, SettingsStatus::kCorrupt);
}

TEST(SettingsSlots, CorruptSlotBFallsBackToA) {
  FakeStore store = two_records();
  store.bytes[kSlot1 + 61] ^= 0x80;  // slot B's CRC
  const Loaded l = load(store);
  EXPECT_EQ(l.status, SettingsStatus::kOk);
  EXPECT_EQ(l.trim0, 1);
  EXPECT_EQ(l.record.slot, 0);
  EXPECT_EQ(l.record.seq, 1);
  EXPECT_EQ(l.record.other, SettingsStatus::kCorrupt);
  // The next save replaces the damaged slot B, not the record in force.
  SettingsRecord record = l.record;
  ASSERT_EQ(strider::save_settings(store, settings_with_trim(3), &record), SettingsStatus::kOk);
  EXPECT_EQ(record.slot, 1);
  EXPECT_EQ(record.seq, 2);
  const Loaded after = load(store);
  EXPECT_EQ(after.trim0, 3);
  EXPECT_EQ(after.record.other, SettingsStatus::kOk);
}

TEST(SettingsSlots, BothCorruptGiveDefaults) {
  FakeStore store = two_records();
  store.bytes[0] = 'X';
  store.bytes[kSlot1 + 3] = 53;  // wrong payload length
  const Loaded l = load(store);
  EXPECT_EQ(l.status, SettingsStatus::kCorrupt);
  EXPECT_EQ(l.record.slot, strider::kNoSettingsSlot);
  EXPECT_EQ(l.trim0, 0);
  // One erased, one corrupt: corrupt (it says more than empty).
  FakeStore half = two_records();
  std::memset(half.bytes, 0xFF, strider::kSettingsSlotBytes);
  half.bytes[kSlot1 + 7] ^= 1;
  EXPECT_EQ(load(half).status, SettingsStatus::kCorrupt);
}

TEST(SettingsSlots, NewestOutOfRangeFallsBackToOlder) {
  FakeStore store = two_records();
  Settings bad = settings_with_trim(2);
  bad.pwm_hz = 1000;  // out of range, but a good CRC
  put_record(&store, kSlot1, bad, 2);
  const Loaded l = load(store);
  EXPECT_EQ(l.status, SettingsStatus::kOk);
  EXPECT_EQ(l.trim0, 1);
  EXPECT_EQ(l.record.slot, 0);
  EXPECT_EQ(l.record.other, SettingsStatus::kInvalid);
  put_record(&store, 0, bad, 1);
  EXPECT_EQ(load(store).status, SettingsStatus::kInvalid);
}

TEST(SettingsSlots, UnknownVersionInOtherSlotIsReported) {
  FakeStore store = two_records();
  store.bytes[kSlot1 + 2] = strider::kSettingsVersion + 1;
  const Loaded l = load(store);
  EXPECT_EQ(l.status, SettingsStatus::kOk);
  EXPECT_EQ(l.trim0, 1);
  EXPECT_EQ(l.record.other, SettingsStatus::kOldVersion);
}

TEST(SettingsSlots, SequenceNumbersWrapRound) {
  EXPECT_TRUE(strider::settings_record_newer(2, 1, 2, 0));
  EXPECT_FALSE(strider::settings_record_newer(2, 0, 2, 1));
  EXPECT_TRUE(strider::settings_record_newer(2, 0, 2, 0xFFFF));
  EXPECT_FALSE(strider::settings_record_newer(2, 0xFFFF, 2, 0));
  EXPECT_TRUE(strider::settings_record_newer(2, 0x7FFF, 2, 0));
  EXPECT_FALSE(strider::settings_record_newer(2, 0, 2, 0));
  EXPECT_TRUE(strider::settings_record_newer(2, 0, 1, 0));  // any slot record is newer than a version-1 one
  EXPECT_FALSE(strider::settings_record_newer(1, 0, 2, 0));

  for (uint8_t newer_slot = 0; newer_slot < 2; ++newer_slot) {
    SCOPED_TRACE(int(newer_slot));
    FakeStore store;
    const uint16_t at_newer = newer_slot == 0 ? 0 : kSlot1;
    const uint16_t at_older = newer_slot == 0 ? kSlot1 : 0;
    put_record(&store, at_older, settings_with_trim(1), 0xFFFF);
    put_record(&store, at_newer, settings_with_trim(2), 0x0000);
    Loaded l = load(store);
    EXPECT_EQ(l.trim0, 2);
    EXPECT_EQ(l.record.slot, newer_slot);
    EXPECT_EQ(l.record.seq, 0);
    // Saves go on counting: 1, then 2, each in the other slot.
    SettingsRecord record = l.record;
    ASSERT_EQ(strider::save_settings(store, settings_with_trim(3), &record), SettingsStatus::kOk);
    l = load(store);
    EXPECT_EQ(l.trim0, 3);
    EXPECT_EQ(l.record.slot, 1 - newer_slot);
    EXPECT_EQ(l.record.seq, 1);
  }
  // A save after 65535 writes 0, which loads as the newer.
  FakeStore store;
  put_record(&store, 0, settings_with_trim(1), 0xFFFE);
  put_record(&store, kSlot1, settings_with_trim(2), 0xFFFF);
  SettingsRecord record = load(store).record;
  ASSERT_EQ(strider::save_settings(store, settings_with_trim(3), &record), SettingsStatus::kOk);
  EXPECT_EQ(record.seq, 0);
  EXPECT_EQ(record.slot, 0);
  const Loaded l = load(store);
  EXPECT_EQ(l.trim0, 3);
  EXPECT_EQ(l.record.seq, 0);
}

TEST(SettingsSlots, SingleRecordImageLoadsAndMigrates) {
  FakeStore store;
  put_single_record(&store, settings_with_trim(-7));
  const FakeStore image = store;
  Loaded l = load(store);
  EXPECT_EQ(l.status, SettingsStatus::kOk);
  EXPECT_EQ(l.trim0, -7);
  EXPECT_EQ(l.record.version, 1);
  EXPECT_EQ(l.record.slot, 0);
  EXPECT_EQ(l.record.other, SettingsStatus::kEmpty);
  // The first save goes to slot 1 and leaves the old record as it was.
  SettingsRecord record = l.record;
  ASSERT_EQ(strider::save_settings(store, settings_with_trim(8), &record), SettingsStatus::kOk);
  EXPECT_EQ(record.slot, 1);
  EXPECT_EQ(record.seq, 1);
  EXPECT_EQ(std::memcmp(store.bytes, image.bytes, strider::kSettingsSlotBytes), 0);
  l = load(store);
  EXPECT_EQ(l.trim0, 8);
  EXPECT_EQ(l.record.slot, 1);
  EXPECT_EQ(l.record.version, strider::kSettingsVersion);
  EXPECT_EQ(l.record.other, SettingsStatus::kOk);  // the old record, older than any slot record
  // The second replaces it.
  ASSERT_EQ(strider::save_settings(store, settings_with_trim(9), &record), SettingsStatus::kOk);
  EXPECT_EQ(record.slot, 0);
  l = load(store);
  EXPECT_EQ(l.trim0, 9);
  EXPECT_EQ(l.record.slot, 0);
  EXPECT_EQ(l.record.seq, 2);
  EXPECT_EQ(store.bytes[2], strider::kSettingsVersion);
  // A version-1 record belongs at the base only: in slot 1's place it is no record.
  FakeStore moved;
  put_single_record(&moved, settings_with_trim(-7));
  std::memcpy(moved.bytes + kSlot1, moved.bytes, strider::kSettingsSingleRecordBytes);
  std::memset(moved.bytes, 0xFF, strider::kSettingsSlotBytes);
  EXPECT_EQ(load(moved).status, SettingsStatus::kCorrupt);
  // A damaged version-1 record: defaults, as before.
  store = image;
  store.bytes[30] ^= 0x10;
  EXPECT_EQ(load(store).status, SettingsStatus::kCorrupt);
}

TEST(SettingsSlots, FailedWriteKeepsTheRecordInForce) {
  FakeStore store = two_records();
  SettingsRecord record = load(store).record;  // slot 1, seq 2
  store.fail_at_write = store.writes + 20;
  EXPECT_EQ(strider::save_settings(store, settings_with_trim(3), &record), SettingsStatus::kWriteFailed);
  EXPECT_EQ(record.slot, 1);
  EXPECT_EQ(record.seq, 2);
  Loaded l = load(store);
  EXPECT_EQ(l.trim0, 2);
  EXPECT_EQ(l.record.other, SettingsStatus::kCorrupt);  // slot A half written
  store.fail_at_write = -1;
  ASSERT_EQ(strider::save_settings(store, settings_with_trim(3), &record), SettingsStatus::kOk);
  EXPECT_EQ(record.slot, 0);
  EXPECT_EQ(record.seq, 3);
  EXPECT_EQ(load(store).trim0, 3);
}

// A store that loses power at its n-th write: that byte is left as it was
// (torn < 0) or holds `torn` (an interrupted erase and write), and nothing
// after it is written.
struct CutStore : strider::ArrayByteStore<4096> {
  int cut_at = -1;
  int torn = -1;
  int writes = 0;
  bool write(uint16_t addr, uint8_t v) {
    const int n = writes++;
    if (cut_at >= 0 && n >= cut_at) {
      if (n == cut_at && torn >= 0) bytes[addr] = uint8_t(torn);
      return false;
    }
    return ArrayByteStore<4096>::write(addr, v);
  }
};

// Every cut point of one save from `before`: the next load has the record
// in force before (old) or the new one, never defaults, and names it. Only
// the complete save gives the new one.
void cut_every_byte(const FakeStore& before, int16_t old_trim, int16_t new_trim, const char* what) {
  SCOPED_TRACE(what);
  const Loaded old_load = load(before);
  ASSERT_EQ(old_load.status, SettingsStatus::kOk);
  ASSERT_EQ(old_load.trim0, old_trim);
  CutStore ref;
  std::memcpy(ref.bytes, before.bytes, sizeof ref.bytes);
  SettingsRecord ref_record = old_load.record;
  ASSERT_EQ(strider::save_settings(ref, settings_with_trim(new_trim), &ref_record), SettingsStatus::kOk);
  const int total = ref.writes;
  EXPECT_EQ(total, int(strider::kSettingsRecordBytes) + 1);  // the first byte twice
  for (int cut = 0; cut <= total; ++cut) {
    for (int torn : {-1, 0x00, 0xFF, int('S'), 0x5A}) {
      CutStore store;
      std::memcpy(store.bytes, before.bytes, sizeof store.bytes);
      store.cut_at = cut;
      store.torn = torn;
      SettingsRecord record = old_load.record;
      const SettingsStatus saved = strider::save_settings(store, settings_with_trim(new_trim), &record);
      EXPECT_EQ(saved, cut == total ? SettingsStatus::kOk : SettingsStatus::kWriteFailed);
      FakeStore after;
      std::memcpy(after.bytes, store.bytes, sizeof after.bytes);
      const Loaded l = load(after);
      ASSERT_EQ(l.status, SettingsStatus::kOk) << "cut at write " << cut << " torn " << torn;
      const bool is_new = cut == total || (cut == total - 1 && torn == 'S');
      if (is_new) {
        EXPECT_EQ(l.trim0, new_trim) << "cut at write " << cut << " torn " << torn;
        EXPECT_EQ(l.record.slot, ref_record.slot);
        EXPECT_EQ(l.record.seq, ref_record.seq);
      } else {
        EXPECT_EQ(l.trim0, old_trim) << "cut at write " << cut << " torn " << torn;
        EXPECT_EQ(l.record.slot, old_load.record.slot);
        EXPECT_EQ(l.record.seq, old_load.record.seq);
        EXPECT_EQ(l.record.version, old_load.record.version);
      }
    }
  }
}

// The slot record before the accelerometer's offsets (version 2) loads with
// offsets of 0, is older than nothing of its own kind (sequence numbers
// decide), and the next save writes the other slot with version 3.
TEST(SettingsSlots, Version2ImageLoadsWithZeroOffsetsAndMigrates) {
  FakeStore store;
  Settings old = settings_with_trim(11);
  old.accel_x_mg = 99;  // not in a version-2 payload: must not come back
  old.accel_y_mg = -99;
  put_v2_record(&store, 0, settings_with_trim(10), 4);
  put_v2_record(&store, kSlot1, old, 5);
  const FakeStore image = store;
  Settings s;
  SettingsRecord record;
  ASSERT_EQ(strider::load_settings(store, &s, &record), SettingsStatus::kOk);
  EXPECT_EQ(s.trim_decideg[0], 11);
  EXPECT_EQ(s.accel_x_mg, 0);
  EXPECT_EQ(s.accel_y_mg, 0);
  EXPECT_EQ(record.version, 2);
  EXPECT_EQ(record.slot, 1);
  EXPECT_EQ(record.seq, 5);
  EXPECT_EQ(record.other, SettingsStatus::kOk);
  // Saving with offsets: slot 0, sequence 6, version 3; slot 1 untouched.
  s.accel_x_mg = 49;
  s.accel_y_mg = -26;
  ASSERT_EQ(strider::save_settings(store, s, &record), SettingsStatus::kOk);
  EXPECT_EQ(record.slot, 0);
  EXPECT_EQ(record.seq, 6);
  EXPECT_EQ(store.bytes[2], strider::kSettingsVersion);
  EXPECT_EQ(std::memcmp(store.bytes + kSlot1, image.bytes + kSlot1, strider::kSettingsSlotBytes), 0);
  Settings back;
  SettingsRecord r2;
  ASSERT_EQ(strider::load_settings(store, &back, &r2), SettingsStatus::kOk);
  EXPECT_EQ(back.accel_x_mg, 49);
  EXPECT_EQ(back.accel_y_mg, -26);
  EXPECT_EQ(back.trim_decideg[0], 11);
  EXPECT_EQ(r2.slot, 0);
  EXPECT_EQ(r2.other, SettingsStatus::kOk);  // the version-2 record, older
  // A version-2 record newer by sequence number than a version-3 one wins
  // (a firmware downgraded and saved again): the numbers decide, not the layout.
  FakeStore mixed;
  put_record(&mixed, 0, settings_with_trim(1), 7);
  put_v2_record(&mixed, kSlot1, settings_with_trim(2), 8);
  Settings m;
  ASSERT_EQ(strider::load_settings(mixed, &m), SettingsStatus::kOk);
  EXPECT_EQ(m.trim_decideg[0], 2);
  EXPECT_EQ(m.accel_x_mg, 0);
  // A version-2 header on a 56-byte payload (or the reverse) is corrupt.
  FakeStore bad = image;
  bad.bytes[3] = 56;
  bad.bytes[kSlot1 + 3] = 56;
  EXPECT_EQ(strider::load_settings(bad, &m), SettingsStatus::kCorrupt);
  FakeStore bad3;
  put_record(&bad3, 0, settings_with_trim(1), 1);
  bad3.bytes[3] = 54;
  EXPECT_EQ(strider::load_settings(bad3, &m), SettingsStatus::kCorrupt);
  // An offset out of range with a good CRC: invalid, the defaults (0 offsets).
  Settings far = settings_with_trim(3);
  far.accel_x_mg = 101;
  EXPECT_FALSE(strider::settings_valid(far));
  EXPECT_EQ(strider::save_settings(bad3, far), SettingsStatus::kInvalid);
  far.accel_x_mg = -100;
  EXPECT_TRUE(strider::settings_valid(far));
}

TEST(SettingsSlots, SaveCutAtEveryByteKeepsOldOrNew) {
  FakeStore one;  // slot A only: the save writes the erased slot B
  SettingsRecord r;
  ASSERT_EQ(strider::save_settings(one, settings_with_trim(1), &r), SettingsStatus::kOk);
  cut_every_byte(one, 1, 2, "into an erased slot");
  cut_every_byte(two_records(), 2, 3, "over the older record");
  FakeStore single;
  put_single_record(&single, settings_with_trim(-7));
  cut_every_byte(single, -7, 5, "from a version-1 record");
  FakeStore v2;
  put_v2_record(&v2, kSlot1, settings_with_trim(4), 9);
  cut_every_byte(v2, 4, 5, "from a version-2 record");
  FakeStore wrap;
  put_record(&wrap, 0, settings_with_trim(1), 0xFFFE);
  put_record(&wrap, kSlot1, settings_with_trim(2), 0xFFFF);
  cut_every_byte(wrap, 2, 3, "to sequence number 0");
}

}  // namespace
