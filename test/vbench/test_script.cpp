// vbench script parsing.
#include "script.h"

#include <gtest/gtest.h>

using strider_vmega::ScriptEvent;

TEST(VbenchScript, ParsesDirectivesAndSortsByTime) {
  const char* text =
      "# a comment\n"
      "\n"
      "at 2 range 150\n"
      "at 0.5 send F\\n\n"
      "at 1.25 send0 status\\r\\n\n"
      "at 3 range none\n"
      "at 4 reset\n";
  std::vector<ScriptEvent> ev;
  std::string err;
  ASSERT_TRUE(strider_vmega::parse_script(text, &ev, &err)) << err;
  ASSERT_EQ(ev.size(), 5u);
  EXPECT_EQ(ev[0].time_us, 500000u);
  EXPECT_EQ(ev[0].kind, ScriptEvent::Kind::kSend);
  EXPECT_EQ(ev[0].uart, 1);
  EXPECT_EQ(ev[0].text, "F\n");
  EXPECT_EQ(ev[1].uart, 0);
  EXPECT_EQ(ev[1].text, "status\r\n");
  EXPECT_EQ(ev[2].kind, ScriptEvent::Kind::kRange);
  EXPECT_EQ(ev[2].range_mm, 150.0);
  EXPECT_LT(ev[3].range_mm, 0.0);
  EXPECT_EQ(ev[4].kind, ScriptEvent::Kind::kReset);
  EXPECT_EQ(ev[4].time_us, 4000000u);
}

TEST(VbenchScript, PowerCutDirectives) {
  std::vector<ScriptEvent> ev;
  std::string err;
  ASSERT_TRUE(strider_vmega::parse_script("at 1 eeprom_cut 12\nat 2 eeprom_cut 0 erased\nat 3 power_cut\n", &ev, &err))
      << err;
  ASSERT_EQ(ev.size(), 3u);
  EXPECT_EQ(ev[0].kind, ScriptEvent::Kind::kEepromCut);
  EXPECT_EQ(ev[0].eeprom_writes, 12u);
  EXPECT_FALSE(ev[0].torn_erased);
  EXPECT_EQ(ev[1].eeprom_writes, 0u);
  EXPECT_TRUE(ev[1].torn_erased);
  EXPECT_EQ(ev[2].kind, ScriptEvent::Kind::kPowerCut);
  EXPECT_EQ(ev[2].time_us, 3000000u);
  uint64_t n = 0;
  bool erased = false;
  EXPECT_TRUE(strider_vmega::parse_eeprom_cut("7:erased", &n, &erased, &err));
  EXPECT_EQ(n, 7u);
  EXPECT_TRUE(erased);
  for (const char* bad : {"", "-1", "1.5", "x", "3:zero"}) EXPECT_FALSE(strider_vmega::parse_eeprom_cut(bad, &n, &erased, &err)) << bad;
}

TEST(VbenchScript, TextIsVerbatimWithEscapes) {
  ScriptEvent ev;
  bool has = false;
  std::string err;
  ASSERT_TRUE(strider_vmega::parse_script_line("at 1 send  set speed 5 \\x41\\\\", &ev, &has, &err)) << err;
  ASSERT_TRUE(has);
  EXPECT_EQ(ev.text, " set speed 5 A\\");
  ASSERT_TRUE(strider_vmega::parse_script_line("send S", &ev, &has, &err));
  EXPECT_TRUE(ev.immediate);
}

TEST(VbenchScript, FaultDirectives) {
  const char* text =
      "at 1 board 0x41 off\n"
      "at 2 board 65 on\n"
      "at 3 board 0x40 detach\n"
      "at 4 board 0x40 attach\n"
      "at 5 bus stuck\n"
      "at 6 bus free\n"
      "at 7 range stuck\n"
      "at 8 hang\n";
  std::vector<ScriptEvent> ev;
  std::string err;
  ASSERT_TRUE(strider_vmega::parse_script(text, &ev, &err)) << err;
  ASSERT_EQ(ev.size(), 8u);
  EXPECT_EQ(ev[0].kind, ScriptEvent::Kind::kBoard);
  EXPECT_EQ(ev[0].board_address, 0x41);
  EXPECT_EQ(ev[0].board_action, ScriptEvent::BoardAction::kOff);
  EXPECT_EQ(ev[1].board_address, 0x41);
  EXPECT_EQ(ev[1].board_action, ScriptEvent::BoardAction::kOn);
  EXPECT_EQ(ev[2].board_action, ScriptEvent::BoardAction::kDetach);
  EXPECT_EQ(ev[3].board_action, ScriptEvent::BoardAction::kAttach);
  EXPECT_EQ(ev[4].kind, ScriptEvent::Kind::kBus);
  EXPECT_TRUE(ev[4].bus_stuck);
  EXPECT_FALSE(ev[5].bus_stuck);
  EXPECT_EQ(ev[6].kind, ScriptEvent::Kind::kEchoStuck);
  EXPECT_EQ(ev[7].kind, ScriptEvent::Kind::kHang);
}

TEST(VbenchScript, FloodDirective) {
  ScriptEvent ev;
  bool has = false;
  std::string err;
  ASSERT_TRUE(strider_vmega::parse_script_line("at 2 flood0 1000 3.5 walk 10\\n", &ev, &has, &err)) << err;
  ASSERT_TRUE(has);
  EXPECT_EQ(ev.kind, ScriptEvent::Kind::kFlood);
  EXPECT_EQ(ev.uart, 0);
  EXPECT_EQ(ev.time_us, 2000000u);
  EXPECT_EQ(ev.per_s, 1000.0);
  EXPECT_EQ(ev.duration_s, 3.5);
  EXPECT_EQ(ev.text, "walk 10\n");
  ASSERT_TRUE(strider_vmega::parse_script_line("flood max 2 F", &ev, &has, &err)) << err;
  EXPECT_EQ(ev.uart, 1);
  EXPECT_EQ(ev.per_s, 0.0);  // back to back
  EXPECT_EQ(ev.text, "F");
}

TEST(VbenchScript, RejectsBadLines) {
  const char* bad[] = {"at x send F", "at 1 fly", "at 1 range -4", "at 1 range", "at 1 send",
                       "at 1 send \\q", "at 1 send \\x4", "at 1 reset now", "at -1 reset",
                       "at 1 eeprom_cut", "at 1 eeprom_cut -2", "at 1 eeprom_cut 3 zeroed", "at 1 eeprom_cut 3 erased x",
                       "at 1 power_cut now",
                       "at 1 board", "at 1 board 0x41", "at 1 board 0x41 sideways", "at 1 board 0x80 off",
                       "at 1 board x off", "at 1 bus", "at 1 bus jammed", "at 1 hang now", "at 1 range stuck now",
                       "at 1 flood", "at 1 flood 0 2 F", "at 1 flood fast 2 F", "at 1 flood 10 F",
                       "at 1 flood 10 0 F", "at 1 flood 10 2"};
  for (const char* line : bad) {
    ScriptEvent ev;
    bool has = false;
    std::string err;
    EXPECT_FALSE(strider_vmega::parse_script_line(line, &ev, &has, &err)) << line;
    EXPECT_FALSE(err.empty()) << line;
  }
  std::vector<ScriptEvent> ev;
  std::string err;
  EXPECT_FALSE(strider_vmega::parse_script("at 1 send F\nat 2 jump\n", &ev, &err));
  EXPECT_NE(err.find("line 2"), std::string::npos);
}
