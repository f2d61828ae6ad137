// VirtualMega on libsimavr (see virtual_mega.h).
#include "virtual_mega.h"

#include "virtual_mega_impl.h"

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
#include "sim_core.h"
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

// `out A, Rr` (1011 1AAr rrrr AAAA) to I/O address io.
constexpr uint8_t kIoSpl = 0x3D;
constexpr uint8_t kIoSph = 0x3E;
bool is_out_to(uint16_t op, uint8_t io) {
  return (op & 0xF800) == 0xB800 && (((op >> 5) & 0x30) | (op & 0x0F)) == io;
}

}  // namespace
using namespace regs;



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
  s.attached.assign(s.boards.size(), true);
  s.last_width.assign(s.boards.size() * Pca9685::kChannels, 0.0);
  static const char* twi_names[2] = {"8>vmega.twi.out", "32<vmega.twi.in"};
  s.twi_irq = avr_alloc_irq(&s.avr->irq_pool, 0, 2, twi_names);
  avr_irq_register_notify(s.twi_irq + TWI_IRQ_OUTPUT, Impl::on_twi, &s);
  avr_connect_irq(s.twi_irq + TWI_IRQ_INPUT, avr_io_getirq(s.avr, AVR_IOCTL_TWI_GETIRQ(0), TWI_IRQ_INPUT));
  avr_connect_irq(avr_io_getirq(s.avr, AVR_IOCTL_TWI_GETIRQ(0), TWI_IRQ_OUTPUT), s.twi_irq + TWI_IRQ_OUTPUT);
  s.hook_twcr();
  if (options.imu_address != 0) {
    s.imu.set_address(options.imu_address);
    s.imu_present = true;
  }
  s.hook_adc();

  // HC-SR04 on PE5 (trigger, D3) and PE4 (echo, D2 = INT4); LED on PB7 (D13).
  avr_irq_register_notify(avr_io_getirq(s.avr, AVR_IOCTL_IOPORT_GETIRQ('E'), 5), Impl::on_trigger, &s);
  s.echo_irq = avr_io_getirq(s.avr, AVR_IOCTL_IOPORT_GETIRQ('E'), 4);
  avr_irq_register_notify(avr_io_getirq(s.avr, AVR_IOCTL_IOPORT_GETIRQ('B'), 7), Impl::on_led, &s);
  s.range_mm = options.sonar_range_mm;
  s.hook_eeprom();

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
    // The stack pointer is written a byte at a time, SPH first, then SREG,
    // then SPL (avr-gcc's frame set-up): in between it points up to 255 bytes
    // off. Not counted until SPL follows, at most two instructions later.
    const uint16_t op = pc_before + 1 <= s.avr->flashend
                            ? uint16_t(s.avr->flash[pc_before] | (s.avr->flash[pc_before + 1] << 8))
                            : 0;
    if (is_out_to(op, kIoSph)) {
      s.sp_unsettled = 2;
    } else if (s.sp_unsettled > 0) {
      s.sp_unsettled = is_out_to(op, kIoSpl) ? 0 : uint8_t(s.sp_unsettled - 1);
    }
    if (s.sp_unsettled == 0 && sp < s.lowest_sp) {
      s.lowest_sp = sp;
      if (sp < s.static_ram_end && s.stack_overflow_us == 0) s.stack_overflow_us = std::max<uint64_t>(1, s.now_us());
    }
    if (s.avr->pc == reset_pc && pc_before != reset_pc) {
      ++s.unexpected_resets;
      s.after_reset();
    }
    if (s.power_cut_pending) s.power_cycle();
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

void VirtualMega::set_range_mm(double mm) {
  impl_->range_mm = mm < 0 ? -1 : mm;
  impl_->unstick_echo();
}
void VirtualMega::set_no_echo() { set_range_mm(-1); }
void VirtualMega::set_echo_stuck() { impl_->echo_stuck = true; }
int VirtualMega::sonar_triggers() const { return impl_->triggers; }
int VirtualMega::sonar_short_triggers() const { return impl_->short_triggers; }
double VirtualMega::sonar_min_trigger_width_us() const {
  return double(impl_->min_trigger_width_cycles) * 1e6 / double(impl_->options.f_cpu_hz);
}
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
  avr_regbit_set(s.avr, s.avr->reset_flags.extrf);  // the RESET pin's flag in MCUSR
  ++s.external_resets;
  s.after_reset();
}

void VirtualMega::hang() {
  Impl& s = *impl_;
  if (!s.avr) return;
  // `rjmp .-2` (0xCFFF) in the last word below the top of the flash: no
  // firmware of this project reaches the boot section.
  const avr_flashaddr_t at = (s.avr->flashend - 3) & ~avr_flashaddr_t(1);
  s.avr->flash[at] = 0xFF;
  s.avr->flash[at + 1] = 0xCF;
  avr_sreg_set(s.avr, S_I, 0);  // cli
  s.avr->state = cpu_Running;   // awake, if it was idling
  s.avr->pc = at;
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
