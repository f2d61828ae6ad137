// VirtualMega: the TWI bus with its PCA9685 boards (addressing, ALLCALL, general
// call SWRST, repeated START), the MPU-6050 when present, and the decoded
// pulse widths.
#include "virtual_mega_impl.h"

#include "avr_twi.h"

namespace strider_vmega {

using namespace regs;

void VirtualMega::Impl::twi_ack(uint8_t addr8) {
  avr_raise_irq(twi_irq + TWI_IRQ_INPUT, avr_twi_irq_msg(TWI_COND_ACK, addr8, 1));
}

void VirtualMega::Impl::end_transaction(bool stop) {
  if (stop)
    for (int i : selected) boards[size_t(i)].stop();
  selected.clear();
  imu_selected = false;
  general_call = false;
  in_transaction = false;
}

void VirtualMega::Impl::on_twi(avr_irq_t*, uint32_t value, void* param) {
  static_cast<Impl*>(param)->twi_message(value);
}

void VirtualMega::Impl::twi_message(uint32_t value) {
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
      if (data == 0x06)  // SWRST: every PCA9685 on the bus back to power-on values
        for (size_t i = 0; i < boards.size(); ++i)
          if (reachable(i)) boards[i].power_on_reset();
    } else if (!selected.empty()) {
      twi_ack(addr8);
      for (int i : selected) boards[size_t(i)].write_byte(data, now_us());
    } else if (imu_selected) {
      twi_ack(addr8);
      imu.write_byte(data, now_us());
    }
    update_pulses();
  }
  if ((msg & TWI_COND_READ) && in_transaction) {
    ++i2c_log.back().bytes;
    if (selected.size() == 1) {
      const uint8_t v = boards[size_t(selected[0])].read_byte();
      avr_raise_irq(twi_irq + TWI_IRQ_INPUT, avr_twi_irq_msg(TWI_COND_READ, addr8, v));
    } else if (imu_selected) {
      avr_raise_irq(twi_irq + TWI_IRQ_INPUT, avr_twi_irq_msg(TWI_COND_READ, addr8, imu.read_byte()));
    }
  }
}

void VirtualMega::Impl::begin_transaction(uint8_t addr8) {
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
      if (!reachable(i)) continue;  // unpowered or detached: no ACK
      const Pca9685& b = boards[i];
      const bool allcall = !t.read && (b.reg(Pca9685::kMode1) & Pca9685::kAllCall) &&
                           t.address7 == (b.reg(0x05) >> 1);
      if (b.address() == t.address7 || allcall) selected.push_back(int(i));
    }
    imu_selected = imu_present && selected.empty() && t.address7 == imu.address();
  }
  bool any_reachable = false;
  for (size_t i = 0; i < boards.size(); ++i) any_reachable = any_reachable || reachable(i);
  if (general_call && !any_reachable) general_call = false;  // nobody there to ACK it
  t.acked = general_call || !selected.empty() || imu_selected;
  if (t.acked) {
    twi_ack(addr8);
    if (!t.read)
      for (int i : selected) boards[size_t(i)].begin_write();
    if (imu_selected) {
      if (t.read) imu.begin_read(now_us());
      else imu.begin_write();
    }
  }
  i2c_log.push_back(t);
  trim_log(i2c_log);
}

void VirtualMega::Impl::flush_pending_stop() {
  for (int i : pending_stop) boards[size_t(i)].stop();
  pending_stop.clear();
}

void VirtualMega::Impl::update_pulses() {
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

// --- faults ----------------------------------------------------------------

// TWCR's bits (ATmega2560 datasheet 24.9.2).
constexpr uint8_t kTwint = 0x80, kTwsta = 0x20, kTwsto = 0x10, kTwen = 0x04;

void VirtualMega::Impl::hook_twcr() {
  for (avr_io_t* port = avr->io_port; port; port = port->next)
    if (port->kind && std::string(port->kind) == "twi") twi = reinterpret_cast<avr_twi_t*>(port);
  if (!twi) return;
  const avr_io_addr_t a = AVR_DATA_TO_IO(twi->r_twcr);
  twi_write = avr->io[a].w.c;
  twi_write_param = avr->io[a].w.param;
  avr->io[a].w.c = twcr_write;
  avr->io[a].w.param = this;
}

// While the bus is stuck, a write that enables the TWI only sets the register:
// a START, STOP or byte it asks for never completes, so TWINT stays clear
// (and the one such a write clears is cleared). Disabling the TWI (TWEN 0)
// goes through: it resets the interface, as on the chip.
void VirtualMega::Impl::twcr_write(avr_t* avr, avr_io_addr_t addr, uint8_t v, void* param) {
  Impl* self = static_cast<Impl*>(param);
  if (!self->bus_stuck || !(v & kTwen)) {
    self->twi_write(avr, addr, v, self->twi_write_param);
    return;
  }
  if (v & kTwint) avr_clear_interrupt(avr, &self->twi->twi);
  avr->data[addr] = uint8_t(v & ~kTwint);
}

// The bus is free again: a START or STOP the TWI is waiting for happens now.
void VirtualMega::Impl::release_bus() {
  bus_stuck = false;
  if (!twi) return;
  const avr_io_addr_t addr = twi->r_twcr;
  const uint8_t v = avr->data[addr];
  if (!(v & kTwen) || !(v & (kTwsta | kTwsto))) return;
  avr->data[addr] = uint8_t(v & ~(kTwsta | kTwsto));  // so that simavr sees the request
  twi_write(avr, addr, uint8_t(v | kTwint), twi_write_param);
}

void VirtualMega::set_board_power(int i, bool on) {
  Impl& s = *impl_;
  if (i < 0 || size_t(i) >= s.boards.size()) return;
  s.boards[size_t(i)].set_powered(on);
  if (s.avr) s.update_pulses();
}

void VirtualMega::set_board_attached(int i, bool attached) {
  if (i >= 0 && size_t(i) < impl_->attached.size()) impl_->attached[size_t(i)] = attached;
}

void VirtualMega::set_bus_stuck(bool stuck) {
  Impl& s = *impl_;
  if (stuck) s.bus_stuck = true;
  else if (s.bus_stuck && s.avr) s.release_bus();
  else s.bus_stuck = false;
}

bool VirtualMega::bus_stuck() const { return impl_->bus_stuck; }

}  // namespace strider_vmega
