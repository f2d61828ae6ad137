// VirtualMega: EEPROM writes seen one by one, and power cuts, immediate or
// at a chosen EEPROM write (fault injection for the settings store).
//
// simavr programs an EEPROM byte the moment the firmware sets EEPE after
// EEMPE (and clears EEPE at once, so the firmware never waits the 3.4 ms a
// real write takes). Its EECR handler is wrapped here: each write is
// counted and logged, and an armed cut stops the write before simavr makes
// it, then restarts the Mega as a power cut would, between instructions.
#include <cstring>

#include "avr_eeprom.h"
#include "sim_regbit.h"
#include "virtual_mega_impl.h"

namespace strider_vmega {

namespace {

// ATmega2560 EEPROM registers (data space) and EECR bits.
constexpr uint16_t kEecr = 0x3F;
constexpr uint16_t kEedr = 0x40;
constexpr uint16_t kEearl = 0x41;
constexpr uint16_t kEearh = 0x42;
constexpr uint8_t kEepe = 1 << 1;
constexpr uint8_t kEempe = 1 << 2;

avr_eeprom_t* eeprom_module(avr_t* avr) {
  for (avr_io_t* port = avr->io_port; port != nullptr; port = port->next)
    if (port->kind != nullptr && std::strcmp(port->kind, "eeprom") == 0) return reinterpret_cast<avr_eeprom_t*>(port);
  return nullptr;
}

// SRAM after a power-up holds no data a program may rely on: a fixed
// pseudo-random pattern (xorshift32), so that runs repeat.
void scramble_sram(avr_t* avr, uint32_t seed) {
  uint32_t x = seed | 1u;
  for (uint32_t a = 0x200; a <= avr->ramend; ++a) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    avr->data[a] = uint8_t(x);
  }
}

}  // namespace

void VirtualMega::Impl::hook_eeprom() {
  const avr_io_addr_t io = AVR_DATA_TO_IO(kEecr);
  eecr_write = avr->io[io].w.c;
  eecr_param = avr->io[io].w.param;
  avr->io[io].w.c = on_eecr_write;
  avr->io[io].w.param = this;
}

void VirtualMega::Impl::on_eecr_write(avr_t* avr, avr_io_addr_t addr, uint8_t v, void* param) {
  Impl* self = static_cast<Impl*>(param);
  // A write starts when EEPE is set while EEMPE is (simavr's rule too).
  if ((avr->data[kEecr] & kEempe) != 0 && (v & kEepe) != 0 && !self->power_cut_pending) {
    const uint16_t address = uint16_t((avr->data[kEearl] | (avr->data[kEearh] << 8)) & (regs::kEepromBytes - 1));
    const uint64_t index = self->eeprom_writes;
    if (self->cut_at_write >= 0 && index == uint64_t(self->cut_at_write)) {
      if (self->cut_torn == TornByte::kErased) {
        if (avr_eeprom_t* ee = eeprom_module(avr)) ee->eeprom[address] = 0xFF;
      }
      self->cut_at_write = -1;
      self->power_cut_pending = true;
      self->power_cuts.push_back(PowerCut{self->now_us(), int64_t(index), address});
      return;  // the write never happens
    }
    ++self->eeprom_writes;
    self->eeprom_log.push_back(EepromWrite{self->now_us(), address, avr->data[kEedr]});
    self->trim_log(self->eeprom_log);
  }
  if (self->eecr_write) self->eecr_write(avr, addr, v, self->eecr_param);
}

void VirtualMega::Impl::power_cycle() {
  power_cut_pending = false;
  avr_reset(avr);
  if (avr->reset_flags.porf.reg != 0) {
    avr->data[avr->reset_flags.porf.reg] = 0;
    avr_regbit_set(avr, avr->reset_flags.porf);
  }
  scramble_sram(avr, uint32_t(power_cuts.size()) * 2654435761u);
  // The boards lost their power too; the HC-05's link and whatever was on
  // its way in is gone.
  for (Pca9685& b : boards) b.power_on_reset();
  imu.power_on_reset();
  update_pulses();
  for (Uart& p : uart) p.input.clear();
  after_reset();
}

uint64_t VirtualMega::eeprom_writes() const { return impl_->eeprom_writes; }
const std::vector<EepromWrite>& VirtualMega::eeprom_write_log() const { return impl_->eeprom_log; }
void VirtualMega::clear_eeprom_write_log() { impl_->eeprom_log.clear(); }

void VirtualMega::cut_power_after_eeprom_writes(uint64_t n, TornByte torn) {
  impl_->cut_at_write = int64_t(impl_->eeprom_writes + n);
  impl_->cut_torn = torn;
}

void VirtualMega::cancel_eeprom_cut() { impl_->cut_at_write = -1; }
bool VirtualMega::eeprom_cut_armed() const { return impl_->cut_at_write >= 0; }

void VirtualMega::power_cut() {
  Impl& s = *impl_;
  if (!s.avr) return;
  s.power_cuts.push_back(PowerCut{s.now_us(), -1, 0});
  s.power_cycle();
}

const std::vector<PowerCut>& VirtualMega::power_cut_log() const { return impl_->power_cuts; }

}  // namespace strider_vmega
