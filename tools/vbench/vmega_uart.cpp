// VirtualMega: the two UARTs (Serial to the host, Serial1 to the HC-05): bytes fed at the
// baud rate the firmware set, replies captured.
#include "virtual_mega_impl.h"

#include "avr_uart.h"
#include "sim_io.h"

namespace strider_vmega {

using namespace regs;

uint64_t VirtualMega::Impl::byte_cycles(int u) const {
  const uint32_t ubrr = uint32_t(avr->data[kUbrrL[u]] | ((avr->data[kUbrrH[u]] & 0x0F) << 8));
  const uint32_t div = (avr->data[kUcsrA[u]] & kU2x) ? 8 : 16;
  return uint64_t(ubrr + 1) * div * 10;  // start + 8 data + stop
}

uint32_t VirtualMega::Impl::baud(int u) const {
  if (!avr || !(avr->data[kUcsrB[u]] & kRxen)) return 0;
  return uint32_t(uint64_t(options.f_cpu_hz) * 10 / byte_cycles(u));
}

void VirtualMega::Impl::start_feed(int u) {
  if (uart[u].feeding || uart[u].input.empty()) return;
  uart[u].feeding = true;
  // Receiver off (not yet set up, or after a reset): look again in 1 ms.
  const bool rx_on = (avr->data[kUcsrB[u]] & kRxen) != 0;
  schedule(avr->cycle + (rx_on ? byte_cycles(u) : 1000 * cycles_per_us()), [this, u] { feed(u); });
}

void VirtualMega::Impl::feed(int u) {
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

void VirtualMega::Impl::on_uart_out(avr_irq_t* irq, uint32_t value, void* param) {
  Impl* self = static_cast<Impl*>(param);
  const int u = irq == self->uart_out_irq[1] ? 1 : 0;
  const UartByte b{self->now_us(), uint8_t(value)};
  self->uart[u].output.push_back(char(b.value));
  if (self->output_cb) self->output_cb(u, b);
}

void VirtualMega::Impl::on_xoff(avr_irq_t* irq, uint32_t value, void* param) {
  Impl* self = static_cast<Impl*>(param);
  const int u = irq == self->uart_xoff_irq[1] ? 1 : 0;
  if (value) self->uart[u].xoff = true;
}

void VirtualMega::Impl::on_xon(avr_irq_t* irq, uint32_t, void* param) {
  Impl* self = static_cast<Impl*>(param);
  const int u = irq == self->uart_xon_irq[1] ? 1 : 0;
  self->uart[u].xoff = false;
}

}  // namespace strider_vmega
