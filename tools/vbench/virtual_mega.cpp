// VirtualMega on libsimavr (see virtual_mega.h).
#include "virtual_mega.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <iterator>
#include <map>

#include "avr_eeprom.h"
#include "avr_extint.h"
#include "avr_ioport.h"
#include "avr_twi.h"
#include "avr_uart.h"
#include "sim_avr.h"
#include "sim_cycle_timers.h"
#include "sim_elf.h"
#include "sim_io.h"
#include "sim_irq.h"

namespace strider_vmega {

const char* to_string(RunStatus s) {
  switch (s) {
    case RunStatus::kOk: return "ok";
    case RunStatus::kStopped: return "stopped";
    case RunStatus::kCrashed: return "crashed";
    case RunStatus::kNotLoaded: return "not loaded";
  }
  return "?";
}

namespace {

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

// Port base (PINx) in data space: A..G at 0x20 + 3i, H..L at 0x100 + 3i.
int port_base(char port) {
  if (port >= 'A' && port <= 'G') return 0x20 + 3 * (port - 'A');
  switch (port) {
    case 'H': return 0x100;
    case 'J': return 0x103;
    case 'K': return 0x106;
    case 'L': return 0x109;
    default: return -1;
  }
}

void quiet_logger(avr_t*, const int level, const char* format, va_list ap) {
  if (level > LOG_ERROR) return;
  std::vfprintf(stderr, format, ap);
}

// Simulated sleep must not sleep the host.
void no_sleep(avr_t*, avr_cycle_count_t) {}

avr_cycle_count_t bound_timer(avr_t*, avr_cycle_count_t, void*) { return 0; }

}  // namespace

struct VirtualMega::Impl {
  Options options;
  avr_t* avr = nullptr;
  elf_firmware_t* fw = nullptr;
  std::vector<Pca9685> boards;
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

  // Sonar.
  double range_mm = -1;
  uint64_t trig_rise_cycle = 0;
  bool trig_high = false;
  bool sonar_busy = false;
  int triggers = 0;
  int short_triggers = 0;
  uint64_t last_trigger_cycle = 0;
  uint64_t min_trigger_interval_cycles = 0;

  uint16_t lowest_sp = 0xFFFF;
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
  uint64_t byte_cycles(int u) const {
    const uint32_t ubrr = uint32_t(avr->data[kUbrrL[u]] | ((avr->data[kUbrrH[u]] & 0x0F) << 8));
    const uint32_t div = (avr->data[kUcsrA[u]] & kU2x) ? 8 : 16;
    return uint64_t(ubrr + 1) * div * 10;  // start + 8 data + stop
  }
  uint32_t baud(int u) const {
    if (!avr || !(avr->data[kUcsrB[u]] & kRxen)) return 0;
    return uint32_t(uint64_t(options.f_cpu_hz) * 10 / byte_cycles(u));
  }
  void start_feed(int u) {
    if (uart[u].feeding || uart[u].input.empty()) return;
    uart[u].feeding = true;
    // Receiver off (not yet set up, or after a reset): look again in 1 ms.
    const bool rx_on = (avr->data[kUcsrB[u]] & kRxen) != 0;
    schedule(avr->cycle + (rx_on ? byte_cycles(u) : 1000 * cycles_per_us()), [this, u] { feed(u); });
  }
  void feed(int u) {
    Uart& p = uart[u];
    p.feeding = false;
    if (p.input.empty()) return;
    if ((avr->data[kUcsrB[u]] & kRxen) && !p.xoff) {
      avr_irq_t* in = avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0' + u), UART_IRQ_INPUT);
      const uint8_t b = p.input.front();
      p.input.pop_front();
      avr_raise_irq(in, b);
    }
    start_feed(u);
  }
  static void on_uart_out(avr_irq_t* irq, uint32_t value, void* param) {
    Impl* self = static_cast<Impl*>(param);
    const int u = irq == self->uart_out_irq[1] ? 1 : 0;
    const UartByte b{self->now_us(), uint8_t(value)};
    self->uart[u].output.push_back(char(b.value));
    if (self->output_cb) self->output_cb(u, b);
  }
  static void on_xoff(avr_irq_t* irq, uint32_t value, void* param) {
    Impl* self = static_cast<Impl*>(param);
    const int u = irq == self->uart_xoff_irq[1] ? 1 : 0;
    if (value) self->uart[u].xoff = true;
  }
  static void on_xon(avr_irq_t* irq, uint32_t, void* param) {
    Impl* self = static_cast<Impl*>(param);
    const int u = irq == self->uart_xon_irq[1] ? 1 : 0;
    self->uart[u].xoff = false;
  }
  avr_irq_t* uart_out_irq[2] = {nullptr, nullptr};
  avr_irq_t* uart_xon_irq[2] = {nullptr, nullptr};
  avr_irq_t* uart_xoff_irq[2] = {nullptr, nullptr};

  // --- TWI / PCA9685 ------------------------------------------------------
  void twi_ack(uint8_t addr8) {
    avr_raise_irq(twi_irq + TWI_IRQ_INPUT, avr_twi_irq_msg(TWI_COND_ACK, addr8, 1));
  }
  void end_transaction(bool stop) {
    if (stop)
      for (int i : selected) boards[size_t(i)].stop();
    selected.clear();
    general_call = false;
    in_transaction = false;
  }
  static void on_twi(avr_irq_t*, uint32_t value, void* param) {
    static_cast<Impl*>(param)->twi_message(value);
  }
  void twi_message(uint32_t value) {
    avr_twi_msg_irq_t m;
    m.u.v = value;
    const uint8_t msg = uint8_t(m.u.twi.msg);
    const uint8_t addr8 = uint8_t(m.u.twi.addr);
    const uint8_t data = uint8_t(m.u.twi.data);
    if (msg & TWI_COND_STOP) {
      end_transaction(true);
      update_pulses();
    }
    if (msg & TWI_COND_START) {
      // A repeated START keeps the boards' pending outputs until the STOP.
      std::vector<int> keep = selected;
      end_transaction(false);
      pending_stop.insert(pending_stop.end(), keep.begin(), keep.end());
      begin_transaction(addr8);
    }
    if ((msg & TWI_COND_WRITE) && in_transaction) {
      ++i2c_log.back().bytes;
      if (general_call) {
        twi_ack(addr8);
        if (data == 0x06)  // SWRST: every PCA9685 back to power-on values
          for (Pca9685& b : boards) b.power_on_reset();
      } else if (!selected.empty()) {
        twi_ack(addr8);
        for (int i : selected) boards[size_t(i)].write_byte(data, now_us());
      }
      update_pulses();
    }
    if ((msg & TWI_COND_READ) && in_transaction) {
      ++i2c_log.back().bytes;
      if (selected.size() == 1) {
        const uint8_t v = boards[size_t(selected[0])].read_byte();
        avr_raise_irq(twi_irq + TWI_IRQ_INPUT, avr_twi_irq_msg(TWI_COND_READ, addr8, v));
      }
    }
  }
  std::vector<int> pending_stop;  // boards addressed before a repeated START
  void begin_transaction(uint8_t addr8) {
    I2cTransaction t;
    t.start_us = now_us();
    t.address7 = uint8_t(addr8 >> 1);
    t.read = (addr8 & 1) != 0;
    t.bytes = 1;
    in_transaction = true;
    if (t.address7 == 0x00 && !t.read) {
      general_call = true;
    } else {
      for (size_t i = 0; i < boards.size(); ++i) {
        const Pca9685& b = boards[i];
        const bool allcall = !t.read && (b.reg(Pca9685::kMode1) & Pca9685::kAllCall) &&
                             t.address7 == (b.reg(0x05) >> 1);
        if (b.address() == t.address7 || allcall) selected.push_back(int(i));
      }
    }
    t.acked = general_call || !selected.empty();
    if (t.acked) {
      twi_ack(addr8);
      if (!t.read)
        for (int i : selected) boards[size_t(i)].begin_write();
    }
    i2c_log.push_back(t);
    trim_log(i2c_log);
  }
  template <typename T>
  void trim_log(std::vector<T>& log) const {
    if (options.log_limit > 1 && log.size() > options.log_limit)
      log.erase(log.begin(), log.begin() + long(log.size() / 2));
  }
  void flush_pending_stop() {
    for (int i : pending_stop) boards[size_t(i)].stop();
    pending_stop.clear();
  }
  void update_pulses() {
    if (!in_transaction) flush_pending_stop();
    const uint64_t t = now_us();
    for (size_t b = 0; b < boards.size(); ++b)
      for (int ch = 0; ch < Pca9685::kChannels; ++ch) {
        const size_t g = b * Pca9685::kChannels + size_t(ch);
        const double w = boards[b].pulse_us(ch);
        if (w != last_width[g]) {
          last_width[g] = w;
          pulse_log.push_back(PulseChange{t, int(g), w});
          trim_log(pulse_log);
        }
      }
  }

  // --- HC-SR04 --------------------------------------------------------------
  avr_irq_t* echo_irq = nullptr;
  static void on_trigger(avr_irq_t*, uint32_t value, void* param) {
    static_cast<Impl*>(param)->trigger_edge(value != 0);
  }
  void trigger_edge(bool high) {
    if (high == trig_high) return;
    trig_high = high;
    if (high) {
      trig_rise_cycle = avr->cycle;
      return;
    }
    if (avr->cycle - trig_rise_cycle < kMinTriggerUs * cycles_per_us()) {
      ++short_triggers;
      return;
    }
    if (sonar_busy) return;  // still measuring the previous ping
    ++triggers;
    if (last_trigger_cycle != 0) {
      const uint64_t d = avr->cycle - last_trigger_cycle;
      if (min_trigger_interval_cycles == 0 || d < min_trigger_interval_cycles) min_trigger_interval_cycles = d;
    }
    last_trigger_cycle = avr->cycle;
    if (range_mm < 0) return;  // no sensor / no echo: the line stays low
    const uint64_t width_us =
        range_mm > kMaxRangeMm ? kTimeoutEchoUs : uint64_t(range_mm * 2.0 / kSoundMmPerUs + 0.5);
    const uint64_t rise = avr->cycle + uint64_t(options.sonar_echo_delay_us) * cycles_per_us();
    sonar_busy = true;
    schedule(rise, [this] { avr_raise_irq(echo_irq, 1); });
    schedule(rise + width_us * cycles_per_us(), [this] {
      avr_raise_irq(echo_irq, 0);
      sonar_busy = false;
    });
  }
  bool led_level = false;
  static void on_led(avr_irq_t*, uint32_t value, void* param) {
    // The pin IRQ also fires when the port is set up: count level changes only.
    Impl* self = static_cast<Impl*>(param);
    if ((value != 0) != self->led_level) {
      self->led_level = value != 0;
      ++self->led_toggles;
    }
  }

  // simavr polls a low-level external interrupt every cycle while its pin is
  // low, enabled or not; port writes drive INT5-7's pins low at boot and the
  // run slows to a crawl. Edge-style handling of level mode avoids it (no
  // Strider firmware uses low-level interrupts).
  void relax_level_interrupts() {
    for (uint8_t i = 0; i < 8; ++i) avr_extint_set_strict_lvl_trig(avr, i, 0);
  }

  // --- reset ----------------------------------------------------------------
  void after_reset() {
    relax_level_interrupts();
    // The MCU's peripherals restarted; the boards, the sonar and the host
    // queues did not. Cycle timers may be gone: re-arm ours.
    end_transaction(false);
    pending_stop.clear();
    for (Uart& p : uart) {
      p.xoff = false;
    }
    trig_high = false;
    arm();
  }
};

VirtualMega::VirtualMega() : impl_(new Impl) {}
VirtualMega::~VirtualMega() = default;

bool VirtualMega::loaded() const { return impl_->avr != nullptr; }

bool VirtualMega::load(const Options& options, std::string* error) {
  impl_.reset(new Impl);
  Impl& s = *impl_;
  s.options = options;
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    s.release();
    return false;
  };
  if (options.f_cpu_hz % 1000000u != 0) return fail("f_cpu_hz must be a whole number of MHz");
  avr_global_logger_set(quiet_logger);
  // Spare room: libsimavr may be built with ELF_SYMBOLS, which appends
  // fields to elf_firmware_t that this header does not show.
  s.fw = static_cast<elf_firmware_t*>(std::calloc(1, sizeof(elf_firmware_t) + 1024));
  if (elf_read_firmware(options.elf_path.c_str(), s.fw) != 0) return fail("cannot read ELF " + options.elf_path);
  s.avr = avr_make_mcu_by_name("atmega2560");
  if (!s.avr) return fail("simavr has no atmega2560 core");
  avr_init(s.avr);
  s.avr->log = LOG_ERROR;
  avr_load_firmware(s.avr, s.fw);
  s.avr->frequency = options.f_cpu_hz;
  // The ATmega2560's SRAM starts at 0x200 with .data, then .bss.
  s.static_ram_end = uint16_t(0x200 + s.fw->datasize + s.fw->bsssize);
  s.avr->sleep = no_sleep;
  s.relax_level_interrupts();

  // UARTs: no console echo, no host sleeping while the firmware polls.
  for (int u = 0; u < 2; ++u) {
    uint32_t flags = 0;
    avr_ioctl(s.avr, AVR_IOCTL_UART_GET_FLAGS('0' + u), &flags);
    flags &= ~uint32_t(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
    avr_ioctl(s.avr, AVR_IOCTL_UART_SET_FLAGS('0' + u), &flags);
    s.uart_out_irq[u] = avr_io_getirq(s.avr, AVR_IOCTL_UART_GETIRQ('0' + u), UART_IRQ_OUTPUT);
    s.uart_xon_irq[u] = avr_io_getirq(s.avr, AVR_IOCTL_UART_GETIRQ('0' + u), UART_IRQ_OUT_XON);
    s.uart_xoff_irq[u] = avr_io_getirq(s.avr, AVR_IOCTL_UART_GETIRQ('0' + u), UART_IRQ_OUT_XOFF);
    avr_irq_register_notify(s.uart_out_irq[u], Impl::on_uart_out, &s);
    avr_irq_register_notify(s.uart_xon_irq[u], Impl::on_xon, &s);
    avr_irq_register_notify(s.uart_xoff_irq[u], Impl::on_xoff, &s);
  }

  // TWI: one bus object answers for every board (as simavr's i2c_eeprom part).
  for (size_t i = 0; i < options.pca_addresses.size(); ++i) {
    const double osc = i < options.pca_osc_per_board_hz.size() ? options.pca_osc_per_board_hz[i] : options.pca_osc_hz;
    s.boards.emplace_back(options.pca_addresses[i], osc);
  }
  s.last_width.assign(s.boards.size() * Pca9685::kChannels, 0.0);
  static const char* twi_names[2] = {"8>vmega.twi.out", "32<vmega.twi.in"};
  s.twi_irq = avr_alloc_irq(&s.avr->irq_pool, 0, 2, twi_names);
  avr_irq_register_notify(s.twi_irq + TWI_IRQ_OUTPUT, Impl::on_twi, &s);
  avr_connect_irq(s.twi_irq + TWI_IRQ_INPUT, avr_io_getirq(s.avr, AVR_IOCTL_TWI_GETIRQ(0), TWI_IRQ_INPUT));
  avr_connect_irq(avr_io_getirq(s.avr, AVR_IOCTL_TWI_GETIRQ(0), TWI_IRQ_OUTPUT), s.twi_irq + TWI_IRQ_OUTPUT);

  // HC-SR04 on PE5 (trigger, D3) and PE4 (echo, D2 = INT4); LED on PB7 (D13).
  avr_irq_register_notify(avr_io_getirq(s.avr, AVR_IOCTL_IOPORT_GETIRQ('E'), 5), Impl::on_trigger, &s);
  s.echo_irq = avr_io_getirq(s.avr, AVR_IOCTL_IOPORT_GETIRQ('E'), 4);
  avr_irq_register_notify(avr_io_getirq(s.avr, AVR_IOCTL_IOPORT_GETIRQ('B'), 7), Impl::on_led, &s);
  s.range_mm = options.sonar_range_mm;

  if (!options.eeprom_path.empty()) {
    std::ifstream probe(options.eeprom_path, std::ios::binary);
    if (probe.good()) {
      std::string err;
      if (!load_eeprom(options.eeprom_path, &err)) return fail(err);
    }
  }
  return true;
}

RunStatus VirtualMega::run_until_us(uint64_t t_us) {
  Impl& s = *impl_;
  if (!s.avr) return RunStatus::kNotLoaded;
  const uint64_t target = t_us * s.cycles_per_us();
  if (s.avr->cycle >= target) return RunStatus::kOk;
  // A timer at the target bounds a sleeping CPU's jump ahead.
  avr_cycle_timer_cancel(s.avr, bound_timer, &s);
  avr_cycle_timer_register(s.avr, target - s.avr->cycle, bound_timer, &s);
  // Every step advances the cycle counter; the guard only protects against a
  // simulator that stops doing so.
  uint64_t guard = (target - s.avr->cycle) + 1000000;
  const avr_flashaddr_t reset_pc = s.avr->reset_pc;
  while (s.avr->cycle < target) {
    const avr_flashaddr_t pc_before = s.avr->pc;
    const int state = avr_run(s.avr);
    const uint16_t sp = uint16_t(s.avr->data[R_SPL] | (s.avr->data[R_SPH] << 8));
    if (sp < s.lowest_sp) {
      s.lowest_sp = sp;
      if (sp < s.static_ram_end && s.stack_overflow_us == 0) s.stack_overflow_us = std::max<uint64_t>(1, s.now_us());
    }
    if (s.avr->pc == reset_pc && pc_before != reset_pc) {
      ++s.unexpected_resets;
      s.after_reset();
    }
    s.process_due();
    if (state == cpu_Done) return RunStatus::kStopped;
    if (state == cpu_Crashed || state == cpu_Stopped) return RunStatus::kCrashed;
    if (--guard == 0) return RunStatus::kCrashed;
  }
  return RunStatus::kOk;
}

uint64_t VirtualMega::now_us() const { return impl_->now_us(); }
uint64_t VirtualMega::cycles() const { return impl_->avr ? impl_->avr->cycle : 0; }

void VirtualMega::send(int uart, const std::string& bytes) {
  Impl& s = *impl_;
  if (!s.avr || uart < 0 || uart > 1) return;
  for (char c : bytes) s.uart[uart].input.push_back(uint8_t(c));
  s.start_feed(uart);
}

size_t VirtualMega::pending_input(int uart) const {
  return uart < 0 || uart > 1 ? 0 : impl_->uart[uart].input.size();
}

std::string VirtualMega::take_output(int uart) {
  if (uart < 0 || uart > 1) return std::string();
  std::string out;
  out.swap(impl_->uart[uart].output);
  return out;
}

void VirtualMega::set_output_callback(std::function<void(int, const UartByte&)> cb) {
  impl_->output_cb = std::move(cb);
}

uint32_t VirtualMega::baud(int uart) const { return uart < 0 || uart > 1 ? 0 : impl_->baud(uart); }

int VirtualMega::board_count() const { return int(impl_->boards.size()); }
const Pca9685& VirtualMega::board(int i) const { return impl_->boards.at(size_t(i)); }

double VirtualMega::pulse_us(int channel) const {
  const int b = channel / Pca9685::kChannels;
  if (channel < 0 || b >= board_count()) return 0.0;
  return impl_->boards[size_t(b)].pulse_us(channel % Pca9685::kChannels);
}

std::vector<double> VirtualMega::pulses_us() const {
  std::vector<double> out;
  for (int c = 0; c < board_count() * Pca9685::kChannels; ++c) out.push_back(pulse_us(c));
  return out;
}

const std::vector<PulseChange>& VirtualMega::pulse_log() const { return impl_->pulse_log; }
void VirtualMega::clear_pulse_log() { impl_->pulse_log.clear(); }
const std::vector<I2cTransaction>& VirtualMega::i2c_log() const { return impl_->i2c_log; }
void VirtualMega::clear_i2c_log() { impl_->i2c_log.clear(); }

std::vector<I2cFrame> VirtualMega::i2c_frames(uint64_t gap_us) const {
  std::vector<I2cFrame> frames;
  uint64_t last = 0;
  for (const I2cTransaction& t : impl_->i2c_log) {
    if (frames.empty() || t.start_us - last > gap_us) {
      frames.push_back(I2cFrame());
      frames.back().start_us = t.start_us;
    }
    ++frames.back().transactions;
    frames.back().bytes += t.bytes;
    last = t.start_us;
  }
  return frames;
}

void VirtualMega::set_range_mm(double mm) { impl_->range_mm = mm < 0 ? -1 : mm; }
void VirtualMega::set_no_echo() { impl_->range_mm = -1; }
int VirtualMega::sonar_triggers() const { return impl_->triggers; }
int VirtualMega::sonar_short_triggers() const { return impl_->short_triggers; }
uint64_t VirtualMega::sonar_min_trigger_interval_us() const {
  return impl_->min_trigger_interval_cycles / (impl_->options.f_cpu_hz / 1000000u);
}

std::vector<uint8_t> VirtualMega::eeprom() const {
  std::vector<uint8_t> bytes(kEepromBytes, 0xFF);
  if (!impl_->avr) return bytes;
  avr_eeprom_desc_t d;
  d.ee = bytes.data();
  d.offset = 0;
  d.size = kEepromBytes;
  avr_ioctl(impl_->avr, AVR_IOCTL_EEPROM_GET, &d);
  return bytes;
}

void VirtualMega::set_eeprom(const std::vector<uint8_t>& bytes) {
  if (!impl_->avr) return;
  std::vector<uint8_t> image(kEepromBytes, 0xFF);
  std::memcpy(image.data(), bytes.data(), std::min<size_t>(bytes.size(), kEepromBytes));
  avr_eeprom_desc_t d;
  d.ee = image.data();
  d.offset = 0;
  d.size = kEepromBytes;
  avr_ioctl(impl_->avr, AVR_IOCTL_EEPROM_SET, &d);
}

bool VirtualMega::load_eeprom(const std::string& path, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = "cannot open EEPROM file " + path;
    return false;
  }
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() > size_t(kEepromBytes)) {
    if (error) *error = "EEPROM file larger than 4096 bytes: " + path;
    return false;
  }
  set_eeprom(bytes);
  return true;
}

bool VirtualMega::save_eeprom(const std::string& path, std::string* error) const {
  const std::vector<uint8_t> bytes = eeprom();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out) {
    if (error) *error = "cannot write EEPROM file " + path;
    return false;
  }
  return true;
}

void VirtualMega::reset() {
  Impl& s = *impl_;
  if (!s.avr) return;
  avr_reset(s.avr);
  ++s.external_resets;
  s.after_reset();
}

int VirtualMega::unexpected_resets() const { return impl_->unexpected_resets; }
int VirtualMega::external_resets() const { return impl_->external_resets; }

bool VirtualMega::pin_output(char port, int bit) const {
  const int base = port_base(port);
  if (!impl_->avr || base < 0 || bit < 0 || bit > 7) return false;
  const uint8_t ddr = impl_->avr->data[base + 1];
  const uint8_t out = impl_->avr->data[base + 2];
  return ((ddr & out) >> bit) & 1;
}

int VirtualMega::led_toggles() const { return impl_->led_toggles; }

std::vector<uint8_t> VirtualMega::read_ram(uint16_t address, uint16_t count) const {
  std::vector<uint8_t> out;
  if (!impl_->avr) return out;
  for (uint32_t a = address; a < uint32_t(address) + count && a <= impl_->avr->ramend; ++a) out.push_back(impl_->avr->data[a]);
  return out;
}

uint32_t VirtualMega::static_ram_bytes() const { return impl_->static_ram_end >= 0x200 ? impl_->static_ram_end - 0x200u : 0; }
uint64_t VirtualMega::stack_overflow_us() const { return impl_->stack_overflow_us; }

uint32_t VirtualMega::stack_peak_bytes() const {
  if (!impl_->avr || impl_->lowest_sp == 0xFFFF) return 0;
  return uint32_t(impl_->avr->ramend - impl_->lowest_sp);
}

}  // namespace strider_vmega
