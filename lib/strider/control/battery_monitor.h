//! BatteryMonitor: the pack's voltage from an analog pin behind a divider,
//! and what it means for the robot: absent (no divider wired: the pin reads
//! near 0 V), ok, low (a warning) or critical (sit down before the servos'
//! current sag browns the Mega out).
//!
//! Integer millivolts only (no float: the fixed-point firmwares link none).
//! One reading per control tick. The pack sags under servo load (1.3 V at
//! hexapod18's peaks in the simulator, docs/imu.md), so the level follows a
//! filtered voltage (exponential average, 16 readings: 0.3 s at 50 Hz) and
//! changes only after the new level has held for `hold_readings` readings
//! (2 s at 50 Hz); going back up needs `recover_mv_per_cell` more than the
//! threshold it fell below (the hysteresis), since a resting pack recovers
//! by some tenths of a volt.
//!
//! The cell count is found from the first settled reading: the smallest
//! count whose full charge (4.25 V a cell) holds the voltage, so 2S at
//! 6.6-8.4 V reads 2 and 3S at 9.9-12.6 V reads 3.
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
    // Exponential average over 16 readings, kept as 16 x mV; the first reading starts it.
    filtered_x16_ = readings_ == 0 ? mv * 16u : filtered_x16_ - filtered_x16_ / 16u + mv;
    if (readings_ < kSettleReadings) {
      if (++readings_ < kSettleReadings) return false;
      // Settled: the first level counts at once, without the hold.
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
  //! The level for a filtered voltage, coming from `now`: falling below a
  //! threshold counts at once, rising above one needs the recovery margin.
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
