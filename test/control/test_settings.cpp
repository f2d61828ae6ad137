// Settings record: CRC known answers, save/load round trip, every single-bit
// corruption detected, empty store and unknown versions -> defaults + status,
// failed writes, and calibration save/abort. The two slots: test_settings_slots.cpp.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>

#include "control/calibration.h"
#include "control/crc.h"
#include "control/settings_store.h"
#include "fakes/fake_store.h"

using strider::Settings;
using strider::SettingsStatus;
using strider_test::FakeStore;

namespace {

bool same(const Settings& a, const Settings& b) {
  if (a.pca_osc_hz != b.pca_osc_hz || a.pwm_hz != b.pwm_hz || a.baud != b.baud || a.deadman_ms != b.deadman_ms ||
      a.avoid_stop_mm != b.avoid_stop_mm || a.avoid_slow_mm != b.avoid_slow_mm ||
      a.avoid_enabled != b.avoid_enabled || a.speed_pct != b.speed_pct)
    return false;
  for (int i = 0; i < strider::kMaxServoJoints; ++i)
    if (a.trim_decideg[i] != b.trim_decideg[i]) return false;
  return true;
}

Settings sample_settings() {
  Settings s = strider::default_settings();
  s.pca_osc_hz = 26075000;
  s.pwm_hz = 60;
  s.baud = 38400;
  s.deadman_ms = 750;
  s.avoid_stop_mm = 180;
  s.avoid_slow_mm = 500;
  s.avoid_enabled = 0;
  s.speed_pct = 70;
  for (int i = 0; i < strider::kMaxServoJoints; ++i) s.trim_decideg[i] = int16_t((i * 37) % 601 - 300);
  return s;
}

TEST(Crc16, KnownAnswers) {
  const uint8_t check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(strider::crc16_ccitt(check, sizeof check), 0x29B1);  // CRC-16/CCITT-FALSE check value
  EXPECT_EQ(strider::crc16_ccitt(check, 0), 0xFFFF);
  const uint8_t a[] = {'A'};
  EXPECT_EQ(strider::crc16_ccitt(a, 1), 0xB915);
}

TEST(SettingsStore, DefaultsAreValid) { EXPECT_TRUE(strider::settings_valid(strider::default_settings())); }

TEST(SettingsStore, RoundTrip) {
  FakeStore store;
  const Settings s = sample_settings();
  ASSERT_TRUE(strider::settings_valid(s));
  EXPECT_EQ(strider::save_settings(store, s), SettingsStatus::kOk);
  Settings back{};
  EXPECT_EQ(strider::load_settings(store, &back), SettingsStatus::kOk);
  EXPECT_TRUE(same(s, back));
  // At another base address too.
  EXPECT_EQ(strider::save_settings(store, s, 1000), SettingsStatus::kOk);
  EXPECT_EQ(strider::load_settings(store, &back, 1000), SettingsStatus::kOk);
  EXPECT_TRUE(same(s, back));
}

TEST(SettingsStore, EmptyStoreGivesDefaults) {
  FakeStore store;  // erased: all 0xFF
  Settings out = sample_settings();
  EXPECT_EQ(strider::load_settings(store, &out), SettingsStatus::kEmpty);
  EXPECT_TRUE(same(out, strider::default_settings()));
  // All zero (never-erased part) is corrupt, also defaults.
  for (uint16_t i = 0; i < store.size(); ++i) store.bytes[i] = 0;
  out = sample_settings();
  EXPECT_EQ(strider::load_settings(store, &out), SettingsStatus::kCorrupt);
  EXPECT_TRUE(same(out, strider::default_settings()));
}

TEST(SettingsStore, EverySingleBitCorruptionDetected) {
  FakeStore store;
  ASSERT_EQ(strider::save_settings(store, sample_settings()), SettingsStatus::kOk);
  const FakeStore good = store;
  int detected = 0;
  for (uint16_t byte = 0; byte < strider::kSettingsRecordBytes; ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      store = good;
      store.bytes[byte] = uint8_t(store.bytes[byte] ^ (1u << bit));
      Settings out = sample_settings();
      const SettingsStatus st = strider::load_settings(store, &out);
      EXPECT_NE(st, SettingsStatus::kOk) << "byte " << byte << " bit " << bit;
      EXPECT_TRUE(same(out, strider::default_settings()));
      detected += st != SettingsStatus::kOk;
    }
  }
  EXPECT_EQ(detected, strider::kSettingsRecordBytes * 8);
}

TEST(SettingsStore, RandomMultiByteCorruptionDetected) {
  FakeStore store;
  ASSERT_EQ(strider::save_settings(store, sample_settings()), SettingsStatus::kOk);
  const FakeStore good = store;
  std::mt19937 rng(7u);
  std::uniform_int_distribution<int> pos(0, strider::kSettingsRecordBytes - 1);
  std::uniform_int_distribution<int> val(1, 255);
  for (int i = 0; i < STRIDER_RANDOM_CASES; ++i) {
    store = good;
    store.bytes[pos(rng)] ^= uint8_t(val(rng));  // one byte garbled (burst <= 8 bits)
    Settings out{};
    EXPECT_NE(strider::load_settings(store, &out), SettingsStatus::kOk);
  }
}

TEST(SettingsStore, UnknownVersionGivesDefaults) {
  FakeStore store;
  ASSERT_EQ(strider::save_settings(store, sample_settings()), SettingsStatus::kOk);
  store.bytes[2] = strider::kSettingsVersion + 1;  // a layout this firmware does not know, with a matching CRC
  const uint16_t crc_at = strider::kSettingsRecordBytes - 2;
  const uint16_t crc = strider::crc16_ccitt(store.bytes, crc_at);
  store.bytes[crc_at] = uint8_t(crc);
  store.bytes[crc_at + 1] = uint8_t(crc >> 8);
  Settings out = sample_settings();
  EXPECT_EQ(strider::load_settings(store, &out), SettingsStatus::kOldVersion);
  EXPECT_TRUE(same(out, strider::default_settings()));
}

TEST(SettingsStore, ValidCrcButOutOfRangeIsInvalid) {
  FakeStore store;
  Settings bad = sample_settings();
  bad.trim_decideg[4] = 301;
  EXPECT_EQ(strider::save_settings(store, bad), SettingsStatus::kInvalid);  // refused
  // Forge a record with a good CRC and a bad value.
  uint8_t rec[strider::kSettingsRecordBytes];
  rec[0] = 'S';
  rec[1] = 'T';
  rec[2] = strider::kSettingsVersion;
  rec[3] = strider::kSettingsPayloadBytes;
  rec[4] = 1;  // sequence number 1
  rec[5] = 0;
  strider::encode_settings(bad, rec + 6);
  const uint16_t crc = strider::crc16_ccitt(rec, sizeof rec - 2);
  rec[sizeof rec - 2] = uint8_t(crc);
  rec[sizeof rec - 1] = uint8_t(crc >> 8);
  std::memcpy(store.bytes, rec, sizeof rec);
  Settings out{};
  EXPECT_EQ(strider::load_settings(store, &out), SettingsStatus::kInvalid);
  EXPECT_TRUE(same(out, strider::default_settings()));
}

TEST(SettingsStore, WriteFailuresReported) {
  FakeStore store;
  store.fail_at_write = 10;
  EXPECT_EQ(strider::save_settings(store, sample_settings()), SettingsStatus::kWriteFailed);
  FakeStore worn;
  worn.stuck_bits = true;
  EXPECT_EQ(strider::save_settings(worn, sample_settings()), SettingsStatus::kWriteFailed);
  strider::ArrayByteStore<16> tiny;
  tiny.erase();
  EXPECT_EQ(strider::save_settings(tiny, sample_settings()), SettingsStatus::kNoSpace);
  Settings out{};
  EXPECT_EQ(strider::load_settings(tiny, &out), SettingsStatus::kNoSpace);
}

TEST(Calibration, AbortRestoresSaveKeeps) {
  FakeStore store;
  Settings saved = sample_settings();  // the caller's settings in force (the controller's)
  ASSERT_EQ(strider::save_settings(store, saved), SettingsStatus::kOk);
  strider::SettingsRecord record;  // the record in force, as the controller keeps it
  ASSERT_EQ(strider::load_settings(store, &saved, &record), SettingsStatus::kOk);
  strider::Calibration cal(saved);
  EXPECT_EQ(cal.set_trim(0, 10), strider::CalStatus::kNotActive);
  cal.start(saved);
  EXPECT_EQ(cal.set_trim(0, 123), strider::CalStatus::kOk);
  EXPECT_EQ(cal.set_trim(18, 0), strider::CalStatus::kOutOfRange);
  EXPECT_EQ(cal.set_trim(1, -301), strider::CalStatus::kOutOfRange);
  EXPECT_EQ(cal.set_oscillator(24500000), strider::CalStatus::kOk);
  EXPECT_EQ(cal.live().trim_decideg[0], 123);
  cal.abort(saved);
  EXPECT_TRUE(same(cal.live(), saved));
  EXPECT_FALSE(cal.active());

  cal.start(saved);
  ASSERT_EQ(cal.set_trim(5, -45), strider::CalStatus::kOk);
  ASSERT_EQ(cal.set_oscillator(26500000), strider::CalStatus::kOk);
  EXPECT_EQ(cal.save(store, saved, &record), strider::CalStatus::kOk);
  EXPECT_EQ(record.slot, 1);  // the first record (slot 0) kept
  EXPECT_EQ(record.seq, 2);
  EXPECT_FALSE(cal.active());
  Settings back{};
  ASSERT_EQ(strider::load_settings(store, &back), SettingsStatus::kOk);
  EXPECT_EQ(back.trim_decideg[5], -45);
  EXPECT_EQ(back.pca_osc_hz, 26500000u);
  EXPECT_TRUE(same(cal.live(), back));  // live() is what was saved
  saved = cal.live();                   // as the controller keeps it
  cal.start(saved);
  cal.set_trim(5, 99);
  cal.abort(saved);
  EXPECT_EQ(cal.live().trim_decideg[5], -45);  // abort goes back to the last save

  store.fail_at_write = store.writes;  // next save fails: calibration stays active, live kept
  cal.start(saved);
  cal.set_trim(2, 7);
  EXPECT_EQ(cal.save(store, saved, &record), strider::CalStatus::kStoreFailed);
  EXPECT_TRUE(cal.active());
  EXPECT_EQ(cal.live().trim_decideg[2], 7);
}

}  // namespace
