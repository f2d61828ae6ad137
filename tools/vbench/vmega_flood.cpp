// VirtualMega: link floods (fault injection). A sender writes units of text
// into a UART at a set rate and blocks, as a program writing to a serial port
// does, while the port holds kFloodSenderBytes unsent bytes; the UART then
// delivers them at the baud rate the firmware programmed (vmega_uart.cpp).
#include "virtual_mega_impl.h"

namespace strider_vmega {

void VirtualMega::Impl::flood_step(int u, uint64_t generation) {
  FloodState& f = flood[u];
  if (generation != f.generation || !f.stats.active) return;  // stopped or replaced
  const uint64_t now = avr->cycle;
  const uint64_t per_s_cycles = options.f_cpu_hz;
  if (f.spec.duration_us != 0 && now >= f.start_cycle + f.spec.duration_us * cycles_per_us()) {
    f.stats.active = false;
    return;
  }
  if (now < f.next_cycle) {
    schedule(f.next_cycle, [this, u, generation] { flood_step(u, generation); });
    return;
  }
  if (uart[u].input.size() >= kFloodSenderBytes) {  // the sender waits for the port
    schedule(now + byte_cycles(u), [this, u, generation] { flood_step(u, generation); });
    return;
  }
  const std::string& unit = f.spec.units[size_t(f.stats.units % f.spec.units.size())];
  for (char c : unit) uart[u].input.push_back(uint8_t(c));
  ++f.stats.units;
  f.stats.bytes += unit.size();
  f.stats.last_us = now_us();
  start_feed(u);
  if (f.spec.count != 0 && f.stats.units >= f.spec.count) {
    f.stats.active = false;
    return;
  }
  // Due times from the start (no drift); a sender that fell behind sends
  // the next unit at once.
  f.next_cycle = f.spec.per_s > 0
                     ? f.start_cycle + uint64_t(double(f.stats.units) * double(per_s_cycles) / f.spec.per_s)
                     : now;
  schedule(std::max(f.next_cycle, now + 1), [this, u, generation] { flood_step(u, generation); });
}

void VirtualMega::flood(int uart, const Flood& f) {
  Impl& s = *impl_;
  if (!s.avr || uart < 0 || uart > 1) return;
  Impl::FloodState& st = s.flood[uart];
  ++st.generation;
  st.spec = f;
  st.stats = FloodStats();
  bool empty = true;
  for (const std::string& unit : f.units) empty = empty && unit.empty();
  if (empty || (f.duration_us == 0 && f.count == 0) || f.per_s < 0) return;
  st.stats.active = true;
  st.stats.start_us = s.now_us();
  st.start_cycle = s.avr->cycle;
  st.next_cycle = st.start_cycle;
  const uint64_t generation = st.generation;
  s.schedule(s.avr->cycle, [&s, uart, generation] { s.flood_step(uart, generation); });
}

void VirtualMega::stop_flood(int uart) {
  if (uart < 0 || uart > 1) return;
  ++impl_->flood[uart].generation;
  impl_->flood[uart].stats.active = false;
}

FloodStats VirtualMega::flood_stats(int uart) const {
  if (uart < 0 || uart > 1) return FloodStats();
  const Impl::FloodState& f = impl_->flood[uart];
  FloodStats st = f.stats;
  // Its time is up even if no step has looked yet.
  if (f.spec.duration_us != 0 && impl_->now_us() >= st.start_us + f.spec.duration_us) st.active = false;
  return st;
}

}  // namespace strider_vmega
