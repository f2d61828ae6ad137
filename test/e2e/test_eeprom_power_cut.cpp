// End-to-end: `cal save` on the real firmware ELF of each model, with the
// power cut by the virtual Mega (tools/vbench) at every EEPROM byte write of
// the save, the byte being written left as it was (and, on sprawl8, erased
// too: the store's code is the same in every build). After each cut
// the next boot must have the record in force before the save (old) or the
// new one, never the defaults, say which in its `info eeprom` notice, and
// `cal show` must give that record's trim. Three starting points: two
// records (the save overwrites the older), one record (the save goes to the
// erased slot), and the single record of firmware before the slots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

#include "control/crc.h"
#include "control/settings.h"
#include "virtual_mega.h"

using strider_vmega::RunStatus;
using strider_vmega::TornByte;
using strider_vmega::VirtualMega;

namespace {

constexpr uint64_t kBootTimeoutUs = 3000000;
constexpr uint64_t kReplyTimeoutUs = 1000000;

std::string elf_path(const std::string& model) {
  const char* dir = std::getenv("STRIDER_FIRMWARE_DIR");
  return (dir && *dir ? std::string(dir) : std::string(STRIDER_FIRMWARE_DIR)) + "/strider_firmware_" + model + ".elf";
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The firmware over USB (UART0, 115200 baud): the protocol's fastest port.
class Usb {
 public:
  bool load(const std::string& model, std::string* error) {
    strider_vmega::Options o;
    o.elf_path = elf_path(model);
    return mega_.load(o, error);
  }
  VirtualMega& mega() { return mega_; }
  const std::vector<std::string>& lines() const { return lines_; }

  // The next line satisfying pred within timeout_us ("" if none).
  template <typename Pred>
  std::string wait_for(Pred pred, uint64_t timeout_us) {
    const uint64_t end = mega_.now_us() + timeout_us;
    for (;;) {
      while (seen_ < lines_.size()) {
        const std::string& l = lines_[seen_++];
        if (pred(l)) return l;
      }
      if (mega_.now_us() >= end || mega_.run_for_us(1000) != RunStatus::kOk) return std::string();
      collect();
    }
  }
  // A boot's settings notice.
  std::string boot_notice() {
    return wait_for([](const std::string& l) { return starts_with(l, "info eeprom"); }, kBootTimeoutUs);
  }
  // Sends a line; its reply (ok/err).
  std::string command(const std::string& line) {
    seen_ = lines_.size();
    mega_.send(0, line + "\n");
    return wait_for([](const std::string& l) { return starts_with(l, "ok") || starts_with(l, "err"); },
                    kReplyTimeoutUs);
  }
  // Runs until the power has been cut n times in all (false on a time-out).
  bool run_until_cuts(size_t n) {
    const uint64_t end = mega_.now_us() + kReplyTimeoutUs;
    while (mega_.power_cut_log().size() < n) {
      if (mega_.now_us() >= end || mega_.run_for_us(100) != RunStatus::kOk) return false;
    }
    collect();
    seen_ = lines_.size();  // what the firmware said before the cut is over
    return true;
  }
  // Power off and on: the Mega boots from the EEPROM as it is.
  void power_cycle() {
    mega_.power_cut();
    collect();
    seen_ = lines_.size();
  }
  std::string transcript() const {
    std::string t;
    for (size_t i = lines_.size() > 12 ? lines_.size() - 12 : 0; i < lines_.size(); ++i) t += "  " + lines_[i] + "\n";
    return t;
  }

 private:
  void collect() {
    pending_ += mega_.take_output(0);
    size_t nl;
    while ((nl = pending_.find('\n')) != std::string::npos) {
      std::string l = pending_.substr(0, nl);
      if (!l.empty() && l.back() == '\r') l.pop_back();
      lines_.push_back(l);
      pending_.erase(0, nl + 1);
    }
  }
  VirtualMega mega_;
  std::string pending_;
  std::vector<std::string> lines_;
  size_t seen_ = 0;
};

// Trim of joint 0 from `ok cal osc=... trims=T0,T1,...` [0.1 deg].
int trim0_decideg(const std::string& cal_show) {
  const size_t at = cal_show.find("trims=");
  if (at == std::string::npos) return -9999;
  return int(std::lround(std::strtod(cal_show.c_str() + at + 6, nullptr) * 10.0));
}

// The single record of firmware before the slots, from its documented
// layout: 'S' 'T' 1 54 payload crc, at address 0.
std::vector<uint8_t> single_record_image(int16_t trim0_decideg) {
  strider::Settings s = strider::default_settings();
  s.trim_decideg[0] = trim0_decideg;
  std::vector<uint8_t> image(4096, 0xFF);
  image[0] = 'S';
  image[1] = 'T';
  image[2] = 1;
  constexpr uint8_t n = strider::kSettingsPayloadBytesV2;  // its layout: no accelerometer offsets
  image[3] = n;
  uint8_t payload[strider::kSettingsPayloadBytes];
  strider::encode_settings(s, payload);
  std::copy(payload, payload + n, image.begin() + 4);
  const uint16_t crc = strider::crc16_ccitt(image.data(), 4 + n);
  image[4 + n] = uint8_t(crc);
  image[5 + n] = uint8_t(crc >> 8);
  return image;
}

enum class Start { kTwoRecords, kOneRecord, kSingleRecordLayout };

struct Case {
  std::string model;
  Start start;
  bool erased_too;  // also cut with the byte being written erased
};

std::string case_name(const ::testing::TestParamInfo<Case>& p) {
  const char* start = p.param.start == Start::kTwoRecords  ? "TwoRecords"
                      : p.param.start == Start::kOneRecord ? "OneRecord"
                                                           : "SingleRecordLayout";
  return p.param.model + "_" + start;
}

void PrintTo(const Case& c, std::ostream* os) { *os << case_name(::testing::TestParamInfo<Case>(c, 0)); }

class EepromPowerCut : public ::testing::TestWithParam<Case> {};

// `cal start`, `cal trim 0 D`: the calibration the save under test writes.
void edit_trim(Usb& usb, int deg) {
  ASSERT_EQ(usb.command("cal start"), "ok cal start") << usb.transcript();
  ASSERT_TRUE(starts_with(usb.command("cal trim 0 " + std::to_string(deg)), "ok cal trim")) << usb.transcript();
}

void save_trim(Usb& usb, int deg) {
  edit_trim(usb, deg);
  ASSERT_EQ(usb.command("cal save"), "ok cal saved") << usb.transcript();
}

TEST_P(EepromPowerCut, EveryByteOfASaveKeepsTheOldOrTheNewRecord) {
  const Case& c = GetParam();
  Usb usb;
  std::string error;
  ASSERT_TRUE(usb.load(c.model, &error)) << error;
  ASSERT_EQ(usb.boot_notice(), "info eeprom empty, defaults") << usb.transcript();

  // The EEPROM before the save under test, the record in force then, and
  // the records before and after the save as the boot notice names them.
  std::string old_record, new_record;
  int old_trim = 0;
  switch (c.start) {
    case Start::kTwoRecords:
      save_trim(usb, 5);
      save_trim(usb, 6);
      old_record = "info eeprom ok slot=1 seq=2";
      new_record = "info eeprom ok slot=0 seq=3";
      old_trim = 60;
      break;
    case Start::kOneRecord:
      save_trim(usb, 6);
      old_record = "info eeprom ok slot=0 seq=1";
      new_record = "info eeprom ok slot=1 seq=2";
      old_trim = 60;
      break;
    case Start::kSingleRecordLayout:
      usb.mega().set_eeprom(single_record_image(-40));
      old_record = "info eeprom ok version=1";
      new_record = "info eeprom ok slot=1 seq=1";
      old_trim = -40;
      break;
  }
  const std::vector<uint8_t> before = usb.mega().eeprom();
  constexpr int kNewDeg = 7;

  // The whole save: how many EEPROM writes it makes.
  usb.power_cycle();
  const std::string before_notice = usb.boot_notice();
  ASSERT_TRUE(starts_with(before_notice, "info eeprom ok")) << usb.transcript();
  EXPECT_EQ(before_notice, old_record);
  ASSERT_EQ(trim0_decideg(usb.command("cal show")), old_trim);
  edit_trim(usb, kNewDeg);
  const uint64_t writes_before = usb.mega().eeprom_writes();
  ASSERT_EQ(usb.command("cal save"), "ok cal saved") << usb.transcript();
  const int writes = int(usb.mega().eeprom_writes() - writes_before);
  ASSERT_GT(writes, 2);
  usb.power_cycle();
  EXPECT_EQ(usb.boot_notice(), new_record) << usb.transcript();
  ASSERT_EQ(trim0_decideg(usb.command("cal show")), kNewDeg * 10);

  // The power cut at each of its writes: every write on sprawl8 (and on every
  // model with STRIDER_EEPROM_EVERY_WRITE=1, `tools/dev soak`); the other
  // models run the same save code over records of another length, so the test
  // command cuts them at every 5th write and at the last three.
  const bool every_write = c.erased_too || std::getenv("STRIDER_EEPROM_EVERY_WRITE") != nullptr;
  int cuts = 0, gave_old = 0;
  for (int n = 0; n < writes; ++n) {
    if (!every_write && n % 5 != 0 && n < writes - 3) continue;
    for (TornByte torn : {TornByte::kOld, TornByte::kErased}) {
      if (torn == TornByte::kErased && !c.erased_too) continue;
      const char* torn_name = torn == TornByte::kOld ? "left" : "erased";
      usb.mega().set_eeprom(before);
      usb.power_cycle();
      ASSERT_EQ(usb.boot_notice(), before_notice) << usb.transcript();
      edit_trim(usb, kNewDeg);
      const size_t cuts_before = usb.mega().power_cut_log().size();
      usb.mega().cut_power_after_eeprom_writes(uint64_t(n), torn);
      usb.mega().send(0, "cal save\n");
      ASSERT_TRUE(usb.run_until_cuts(cuts_before + 1)) << "no cut at write " << n << "\n" << usb.transcript();
      ++cuts;
      const std::string notice = usb.boot_notice();
      const std::string trims = usb.command("cal show");
      SCOPED_TRACE("cut at write " + std::to_string(n) + " of " + std::to_string(writes) + ", byte " + torn_name +
                   ": " + notice + " / " + trims);
      // Never the defaults: the old record or the new one, and the notice
      // names the one in force (the old with the damaged slot, if any).
      ASSERT_TRUE(starts_with(notice, "info eeprom ok"));
      const int trim = trim0_decideg(trims);
      ASSERT_TRUE(trim == old_trim || trim == kNewDeg * 10);
      if (trim == old_trim) {
        ++gave_old;
        EXPECT_TRUE(starts_with(notice, old_record));
        const std::string rest = notice.substr(std::min(old_record.size(), notice.size()));
        EXPECT_TRUE(rest.empty() || rest == " other=corrupt");
      } else {
        EXPECT_EQ(notice, new_record);
      }
    }
  }
  // The record changes with the save's last write alone: every cut before
  // it keeps the old one.
  EXPECT_EQ(gave_old, cuts);
  EXPECT_EQ(usb.mega().unexpected_resets(), 0);
  ::testing::Test::RecordProperty("save_writes", writes);
  ::testing::Test::RecordProperty("cuts", cuts);
  std::printf("%s: a save makes %d EEPROM writes; %d power cuts, every boot after one had the old record\n",
              case_name(::testing::TestParamInfo<Case>(c, 0)).c_str(), writes, cuts);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const char* model : {"sprawl8", "mammal8", "dog12", "hexapod18", "spider12"})
    for (Start s : {Start::kTwoRecords, Start::kOneRecord, Start::kSingleRecordLayout})
      cases.push_back(Case{model, s, std::string(model) == "sprawl8"});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Models, EepromPowerCut, ::testing::ValuesIn(all_cases()), case_name);

}  // namespace
