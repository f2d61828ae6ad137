// VirtualMega's implementation state (see virtual_mega.h), shared by its
// parts: virtual_mega.cpp (loading, running, the public interface),
// vmega_uart.cpp (the two UARTs), vmega_twi.cpp (the PCA9685 boards on TWI),
// vmega_sonar.cpp (the HC-SR04 and the LED pin), vmega_eeprom.cpp (EEPROM
// writes and power cuts) and vmega_imu.cpp (the MPU-6050 and the ADC).
#ifndef STRIDER_VBENCH_VIRTUAL_MEGA_IMPL_H
#define STRIDER_VBENCH_VIRTUAL_MEGA_IMPL_H

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "sim_avr.h"
#include "sim_cycle_timers.h"
#include "sim_elf.h"
#include "sim_irq.h"
#include "avr_twi.h"
#include "virtual_mega.h"

namespace strider_vmega {

namespace regs {
// ATmega2560 data-space addresses (datasheet, register summary).
constexpr uint16_t kUcsrA[2] = {0xC0, 0xC8};
constexpr uint16_t kUcsrB[2] = {0xC1, 0xC9};
constexpr uint16_t kUbrrL[2] = {0xC4, 0xCC};
constexpr uint16_t kUbrrH[2] = {0xC5, 0xCD};
constexpr uint8_t kU2x = 1 << 1;   // UCSRnA
constexpr uint8_t kRxen = 1 << 4;  // UCSRnB
constexpr int kEepromBytes = 4096;
// HC-SR04: the trigger must stay high 10 us; no echo beyond ~4 m, where the
// module times out with a ~38 ms pulse.
constexpr uint64_t kMinTriggerUs = 10;
constexpr double kMaxRangeMm = 4000.0;
constexpr uint64_t kTimeoutEchoUs = 38000;
constexpr double kSoundMmPerUs = 0.343;
}  // namespace regs

struct VirtualMega::Impl {
  Options options;
  avr_t* avr = nullptr;
  elf_firmware_t* fw = nullptr;
  std::vector<Pca9685> boards;
  std::vector<bool> attached;  // board i's bus wires connected (set_board_attached)
  std::vector<double> last_width;
  std::vector<PulseChange> pulse_log;
  std::vector<I2cTransaction> i2c_log;
  avr_irq_t* twi_irq = nullptr;  // [0] to the TWI, [1] from the TWI
  std::vector<int> selected;     // boards in the current transaction
  bool general_call = false;
  bool in_transaction = false;

  // Timed host events, by cycle.
  std::multimap<uint64_t, std::function<void()>> events;

  struct Uart {
    std::deque<uint8_t> input;
    bool feeding = false;  // a feed event is scheduled
    bool xoff = false;     // simavr's FIFO is full
    std::string output;
  } uart[2];
  std::function<void(int, const UartByte&)> output_cb;

  // Link floods (vmega_flood.cpp), one per UART.
  struct FloodState {
    Flood spec;
    FloodStats stats;
    uint64_t start_cycle = 0;
    uint64_t next_cycle = 0;    // when the next unit is due
    uint64_t generation = 0;    // a new flood cancels the old one's events
  } flood[2];
  void flood_step(int u, uint64_t generation);

  // Sonar.
  double range_mm = -1;
  uint64_t trig_rise_cycle = 0;
  bool trig_high = false;
  bool sonar_busy = false;
  int triggers = 0;
  int short_triggers = 0;
  uint64_t min_trigger_width_cycles = 0;  // shortest TRIG high time, accepted or not
  uint64_t last_trigger_cycle = 0;
  uint64_t min_trigger_interval_cycles = 0;

  uint16_t lowest_sp = 0xFFFF;
  uint8_t sp_unsettled = 0;       // instructions since SPH was written without SPL
  uint16_t static_ram_end = 0;    // first byte after .data + .bss
  uint64_t stack_overflow_us = 0;  // when the stack first grew into .bss
  int unexpected_resets = 0;
  int external_resets = 0;
  int led_toggles = 0;

  ~Impl() { release(); }

  void release() {
    if (avr) {
      avr_terminate(avr);
      std::free(avr);
      avr = nullptr;
    }
    if (fw) {
      std::free(fw->flash);
      std::free(fw->eeprom);
      std::free(fw);
      fw = nullptr;
    }
  }

  uint64_t cycles_per_us() const { return options.f_cpu_hz / 1000000u; }
  uint64_t now_us() const { return avr ? avr->cycle / cycles_per_us() : 0; }

  // --- events -------------------------------------------------------------
  static avr_cycle_count_t event_timer(avr_t*, avr_cycle_count_t, void* param) {
    Impl* self = static_cast<Impl*>(param);
    self->process_due();
    return self->events.empty() ? 0 : std::max<uint64_t>(self->events.begin()->first, self->avr->cycle + 1);
  }
  void arm() {
    avr_cycle_timer_cancel(avr, event_timer, this);
    if (events.empty()) return;
    const uint64_t when = events.begin()->first;
    const uint64_t delta = when > avr->cycle ? when - avr->cycle : 1;
    avr_cycle_timer_register(avr, delta, event_timer, this);
  }
  void schedule(uint64_t cycle, std::function<void()> fn) {
    const bool earliest = events.empty() || cycle < events.begin()->first;
    events.emplace(cycle, std::move(fn));
    if (earliest) arm();
  }
  void process_due() {
    while (!events.empty() && events.begin()->first <= avr->cycle) {
      auto fn = std::move(events.begin()->second);
      events.erase(events.begin());
      fn();
    }
  }

  // --- UART ---------------------------------------------------------------
  uint64_t byte_cycles(int u) const;
  uint32_t baud(int u) const;
  void start_feed(int u);
  void feed(int u);
  static void on_uart_out(avr_irq_t* irq, uint32_t value, void* param);
  static void on_xoff(avr_irq_t* irq, uint32_t value, void* param);
  static void on_xon(avr_irq_t* irq, uint32_t, void* param);
  avr_irq_t* uart_out_irq[2] = {nullptr, nullptr};
  avr_irq_t* uart_xon_irq[2] = {nullptr, nullptr};
  avr_irq_t* uart_xoff_irq[2] = {nullptr, nullptr};

  // --- TWI / PCA9685 ------------------------------------------------------
  void twi_ack(uint8_t addr8);
  void end_transaction(bool stop);
  static void on_twi(avr_irq_t*, uint32_t value, void* param);
  void twi_message(uint32_t value);
  std::vector<int> pending_stop;  // boards addressed before a repeated START
  void begin_transaction(uint8_t addr8);
  template <typename T>
  void trim_log(std::vector<T>& log) const {
    if (options.log_limit > 1 && log.size() > options.log_limit)
      log.erase(log.begin(), log.begin() + long(log.size() / 2));
  }
  void flush_pending_stop();
  void update_pulses();
  bool reachable(size_t i) const { return boards[i].powered() && attached[i]; }
  // The bus held low: TWCR's writes pass through twcr_write(), which keeps
  // back the ones that ask the TWI to act while it is stuck.
  avr_twi_t* twi = nullptr;
  avr_io_write_t twi_write = nullptr;  // simavr's own TWCR handler
  void* twi_write_param = nullptr;
  bool bus_stuck = false;
  void hook_twcr();
  static void twcr_write(avr_t* avr, avr_io_addr_t addr, uint8_t v, void* param);
  void release_bus();

  // --- MPU-6050, ADC (vmega_imu.cpp) ------------------------------------------
  Mpu6050 imu;
  bool imu_present = false;
  bool imu_selected = false;  // addressed in the current transaction
  static constexpr int kAdcPins = 8;
  double adc_volts[kAdcPins] = {};
  void hook_adc();
  void feed_adc();  // hands simavr the millivolts of every pin
  static void on_adc_trigger(avr_irq_t*, uint32_t value, void* param);

  // --- HC-SR04 --------------------------------------------------------------
  avr_irq_t* echo_irq = nullptr;
  bool echo_stuck = false;  // the next echo rises and stays high
  bool echo_high = false;
  static void on_trigger(avr_irq_t*, uint32_t value, void* param);
  void trigger_edge(bool high);
  void set_echo(bool high);
  void unstick_echo();  // a stuck echo falls, the sensor measures again
  bool led_level = false;
  static void on_led(avr_irq_t*, uint32_t value, void* param);

  // simavr polls a low-level external interrupt every cycle while its pin is
  // low, enabled or not; port writes drive INT5-7's pins low at boot and the
  // run slows to a crawl. Edge-style handling of level mode avoids it (no
  // Strider firmware uses low-level interrupts).
  void relax_level_interrupts();

  // --- EEPROM writes, power cuts (vmega_eeprom.cpp) --------------------------
  avr_io_write_t eecr_write = nullptr;  // simavr's EEPROM control handler, wrapped
  void* eecr_param = nullptr;
  uint64_t eeprom_writes = 0;
  std::vector<EepromWrite> eeprom_log;
  int64_t cut_at_write = -1;  // the power fails as this write begins; -1 = not armed
  TornByte cut_torn = TornByte::kOld;
  bool power_cut_pending = false;  // cut after the current instruction
  std::vector<PowerCut> power_cuts;
  void hook_eeprom();
  static void on_eecr_write(avr_t* avr, avr_io_addr_t addr, uint8_t v, void* param);
  //! Performs a pending cut between instructions (run_until_us()).
  void power_cycle();

  // --- reset ----------------------------------------------------------------
  void after_reset() {
    relax_level_interrupts();
    // The MCU's peripherals restarted; the boards, the sonar and the host
    // queues did not. Cycle timers may be gone: re-arm ours.
    end_transaction(false);
    pending_stop.clear();
    sp_unsettled = 0;
    for (Uart& p : uart) {
      p.xoff = false;
    }
    trig_high = false;
    arm();
  }
};

}  // namespace strider_vmega

#endif  // STRIDER_VBENCH_VIRTUAL_MEGA_IMPL_H
