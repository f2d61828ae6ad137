// BatteryMonitor: ADC codes to pack millivolts through the divider, the cell
// count, the levels with their hold and hysteresis, a missing divider, a
// pack that sags under load without a false alarm, and garbage codes.
#include <gtest/gtest.h>

#include <cmath>

#include "control/battery_monitor.h"
#include "math/prng.h"

using strider::BatteryConfig;
using strider::BatteryLevel;
using strider::BatteryMonitor;

namespace {

// The code the Mega's ADC gives for a pack of `pack_mv` behind the 3:1 divider.
uint16_t code_for(double pack_mv) {
  const double pin_v = pack_mv / 3000.0;
  const long c = std::lround(pin_v / 5.0 * 1024.0);
  return uint16_t(c < 0 ? 0 : c > 1023 ? 1023 : c);
}

// Feeds n readings of one voltage; returns how many changed the level.
int feed(BatteryMonitor& m, double pack_mv, int n) {
  int changes = 0;
  for (int i = 0; i < n; ++i) changes += m.add(code_for(pack_mv)) ? 1 : 0;
  return changes;
}

TEST(BatteryMonitor, MillivoltsThroughTheDivider) {
  BatteryMonitor m;
  feed(m, 8000.0, 40);
  // One ADC code is 5000 / 1024 x 3 = 14.6 mV of pack.
  EXPECT_NEAR(m.mv(), 8000, 15);
  EXPECT_EQ(m.level(), BatteryLevel::kOk);
  EXPECT_EQ(m.cells(), 2);
}

TEST(BatteryMonitor, CellCountFromTheSettledVoltage) {
  const struct { double mv; int cells; } table[] = {
      {4100, 1}, {6700, 2}, {7400, 2}, {8400, 2}, {10000, 3}, {11100, 3}, {12600, 3}, {14000, 4}};
  for (const auto& row : table) {
    BatteryMonitor m;
    feed(m, row.mv, BatteryMonitor::kSettleReadings);
    EXPECT_EQ(m.cells(), row.cells) << row.mv << " mV";
  }
}

TEST(BatteryMonitor, NothingOnThePinIsNoBattery) {
  BatteryMonitor m;
  EXPECT_EQ(feed(m, 0.0, 200), 0);
  EXPECT_EQ(m.level(), BatteryLevel::kAbsent);
  EXPECT_FALSE(m.present());
  EXPECT_EQ(m.cells(), 0);
  // A pack plugged in later counts after the hold.
  EXPECT_EQ(feed(m, 8000.0, 150), 1);
  EXPECT_EQ(m.level(), BatteryLevel::kOk);
  EXPECT_EQ(m.cells(), 2);
}

TEST(BatteryMonitor, LevelsFallAfterTheHoldAndRiseOnlyPastTheHysteresis) {
  BatteryConfig c;
  BatteryMonitor m(c);
  feed(m, 7600.0, 50);  // 3.8 V a cell
  ASSERT_EQ(m.level(), BatteryLevel::kOk);
  // 3.45 V a cell: low, but only once it held (the filter takes some readings too).
  int n = 0;
  while (m.level() == BatteryLevel::kOk && n < 1000) {
    m.add(code_for(6900.0));
    ++n;
  }
  EXPECT_EQ(m.level(), BatteryLevel::kLow);
  EXPECT_GE(n, int(c.hold_readings));
  EXPECT_LE(n, int(c.hold_readings) + 60);
  // 3.55 V a cell is above 3.5 but inside the recovery margin: stays low.
  EXPECT_EQ(feed(m, 7100.0, 500), 0);
  EXPECT_EQ(m.level(), BatteryLevel::kLow);
  // 3.25 V a cell: critical.
  EXPECT_EQ(feed(m, 6500.0, 300), 1);
  EXPECT_EQ(m.level(), BatteryLevel::kCritical);
  EXPECT_TRUE(m.critical());
  // Resting at 3.35 V a cell (above 3.3, inside the margin): still critical.
  EXPECT_EQ(feed(m, 6700.0, 500), 0);
  EXPECT_TRUE(m.critical());
  // Charged: back to ok in two steps at most.
  EXPECT_GE(feed(m, 8200.0, 500), 1);
  EXPECT_EQ(m.level(), BatteryLevel::kOk);
}

TEST(BatteryMonitor, ServoLoadSagsDoNotRaiseAnAlarm) {
  // A 7.4 V pack that drops by 1.3 V for one tick in ten (a foot landing,
  // hexapod18's peaks in the simulator) and by 0.6 V for a second at a time.
  BatteryMonitor m;
  feed(m, 7400.0, 20);
  strider::Prng rng(7);
  int changes = 0;
  for (int i = 0; i < 5000; ++i) {
    double mv = 7400.0;
    if (i % 10 == 0) mv -= 1300.0;
    if ((i / 50) % 4 == 0) mv -= 600.0;
    mv += (int(rng.next_u32() % 61) - 30);  // ADC noise, +-30 mV
    changes += m.add(code_for(mv)) ? 1 : 0;
  }
  EXPECT_EQ(changes, 0);
  EXPECT_EQ(m.level(), BatteryLevel::kOk);
}

TEST(BatteryMonitor, GarbageCodesStayInRange) {
  BatteryMonitor m;
  for (uint32_t v : {1024u, 2000u, 65535u, 0u}) m.add(uint16_t(v));
  EXPECT_LE(m.mv(), 15000);
  strider::Prng rng(3);
  for (int i = 0; i < 10000; ++i) {
    m.add(uint16_t(rng.next_u32()));
    EXPECT_LE(m.mv(), 15000);
    EXPECT_LE(int(m.level()), int(BatteryLevel::kCritical));
  }
}

}  // namespace
