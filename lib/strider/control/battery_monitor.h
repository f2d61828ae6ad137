//! BatteryMonitor: the pack's voltage from an analog pin behind a divider,
//! and its level: absent (no divider), ok, low or critical (sit down before
//! the sag browns the Mega out). Integer millivolts, one reading a tick: the
//! level follows a 16-reading average and changes only after holding for
//! `hold_readings`, rising needs `recover_mv_per_cell` more (the sag:
//! docs/imu.md). The cell count is the smallest whose full charge (4.25 V a
//! cell) holds the first settled reading.
#ifndef STRIDER_CONTROL_BATTERY_MONITOR_H
#define STRIDER_CONTROL_BATTERY_MONITOR_H

#include <stdint.h>

namespace strider {

enum class BatteryLevel : uint8_t { kAbsent = 0, kOk = 1, kLow = 2, kCritical = 3 };

struct BatteryConfig {
  uint16_t adc_ref_mv = 5000;         //!< the ADC's reference (the Mega's AVCC) [mV]
  uint16_t adc_counts = 1024;         //!< codes of the ADC (10 bits)
  uint16_t divider_x100 = 300;        //!< pack volts per pin volt, times 100 (20k over 10k: 3.00)
  uint16_t absent_below_mv = 1000;    //!< a pack under this is no pack: nothing on the pin [mV]
  uint16_t low_mv_per_cell = 3500;    //!< `info battery low` below this a cell [mV]
  uint16_t critical_mv_per_cell = 3300;  //!< sit down below this a cell [mV]
  uint16_t recover_mv_per_cell = 100;    //!< back up only this far above the threshold [mV]
  uint16_t hold_readings = 100;       //!< a new level holds this many readings before it counts
};

class BatteryMonitor {
 public:
  static constexpr uint16_t kCellFullMv = 4250;
  static constexpr uint8_t kSettleReadings = 16;

  explicit BatteryMonitor(const BatteryConfig& config = BatteryConfig()) : cfg_(config) {}

  //! One ADC reading (codes past the ADC's range count as its top). True
  //! when level() changed with it.
  bool add(uint16_t code) {
    if (code >= cfg_.adc_counts) code = uint16_t(cfg_.adc_counts - 1);
    const uint32_t mv = uint32_t(code) * cfg_.adc_ref_mv / cfg_.adc_counts * cfg_.divider_x100 / 100u;
    // Exponential average, kept as 16 x mV.
    filtered_x16_ = readings_ == 0 ? mv * 16u : filtered_x16_ - filtered_x16_ / 16u + mv;
    if (readings_ < kSettleReadings) {
      if (++readings_ < kSettleReadings) return false;
      cells_ = cells_for(this->mv());
      const BatteryLevel first = level_for(this->mv(), BatteryLevel::kOk);
      const bool changed = first != level_;
      level_ = first;
      return changed;
    }
    const BatteryLevel want = level_for(this->mv(), level_);
    if (want == level_) {
      held_ = 0;
      return false;
    }
    if (want != pending_) {
      pending_ = want;
      held_ = 0;
    }
    if (++held_ < cfg_.hold_readings) return false;
    if (level_ == BatteryLevel::kAbsent) cells_ = cells_for(this->mv());  // a pack plugged in later
    level_ = want;
    held_ = 0;
    return true;
  }

  //! The filtered pack voltage [mV] (0 before the first reading).
  uint16_t mv() const { return uint16_t(filtered_x16_ / 16u); }
  //! The cells found (0 while absent or settling).
  uint8_t cells() const { return level_ == BatteryLevel::kAbsent ? 0 : cells_; }
  BatteryLevel level() const { return level_; }
  bool present() const { return level_ != BatteryLevel::kAbsent; }
  bool critical() const { return level_ == BatteryLevel::kCritical; }

 private:
  static uint8_t cells_for(uint16_t mv) {
    uint8_t n = 1;
    while (n < 12 && uint32_t(n) * kCellFullMv < mv) ++n;
    return n;
  }
  //! The level for a filtered voltage coming from `now` (rising needs the margin).
  BatteryLevel level_for(uint16_t mv, BatteryLevel now) const {
    if (mv < cfg_.absent_below_mv) return BatteryLevel::kAbsent;
    const uint8_t cells = now == BatteryLevel::kAbsent ? cells_for(mv) : cells_;
    const uint32_t per_cell = mv / cells;
    const uint32_t up = cfg_.recover_mv_per_cell;
    const uint32_t critical = cfg_.critical_mv_per_cell + (now == BatteryLevel::kCritical ? up : 0u);
    const uint32_t low = cfg_.low_mv_per_cell + (now == BatteryLevel::kCritical || now == BatteryLevel::kLow ? up : 0u);
    if (per_cell < critical) return BatteryLevel::kCritical;
    if (per_cell < low) return BatteryLevel::kLow;
    return BatteryLevel::kOk;
  }

  BatteryConfig cfg_;
  uint32_t filtered_x16_ = 0;
  uint8_t readings_ = 0;
  uint8_t cells_ = 0;
  BatteryLevel level_ = BatteryLevel::kAbsent;
  BatteryLevel pending_ = BatteryLevel::kAbsent;
  uint16_t held_ = 0;
};

}  // namespace strider

#endif  // STRIDER_CONTROL_BATTERY_MONITOR_H
