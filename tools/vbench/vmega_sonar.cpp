// VirtualMega: the HC-SR04 (trigger watched, echo timed from the range) and the
// heartbeat LED pin.
#include "virtual_mega_impl.h"

#include "avr_extint.h"

namespace strider_vmega {

using namespace regs;

void VirtualMega::Impl::on_trigger(avr_irq_t*, uint32_t value, void* param) {
  static_cast<Impl*>(param)->trigger_edge(value != 0);
}

void VirtualMega::Impl::trigger_edge(bool high) {
  if (high == trig_high) return;
  trig_high = high;
  if (high) {
    trig_rise_cycle = avr->cycle;
    return;
  }
  const uint64_t width = avr->cycle - trig_rise_cycle;
  if (min_trigger_width_cycles == 0 || width < min_trigger_width_cycles) min_trigger_width_cycles = width;
  if (width < kMinTriggerUs * cycles_per_us()) {
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
  const uint64_t rise = avr->cycle + uint64_t(options.sonar_echo_delay_us) * cycles_per_us();
  if (echo_stuck) {  // rises and stays high; the module ignores triggers meanwhile
    sonar_busy = true;
    schedule(rise, [this] { if (echo_stuck) set_echo(true); });
    return;
  }
  if (range_mm < 0) return;  // no sensor / no echo: the line stays low
  const uint64_t width_us =
      range_mm > kMaxRangeMm ? kTimeoutEchoUs : uint64_t(range_mm * 2.0 / kSoundMmPerUs + 0.5);
  sonar_busy = true;
  schedule(rise, [this] { set_echo(true); });
  schedule(rise + width_us * cycles_per_us(), [this] {
    set_echo(false);
    sonar_busy = false;
  });
}

void VirtualMega::Impl::set_echo(bool high) {
  echo_high = high;
  avr_raise_irq(echo_irq, high ? 1 : 0);
}

void VirtualMega::Impl::unstick_echo() {
  if (!echo_stuck) return;
  echo_stuck = false;
  if (avr && echo_high) set_echo(false);
  sonar_busy = false;
}

void VirtualMega::Impl::on_led(avr_irq_t*, uint32_t value, void* param) {
  // The pin IRQ also fires when the port is set up: count level changes only.
  Impl* self = static_cast<Impl*>(param);
  if ((value != 0) != self->led_level) {
    self->led_level = value != 0;
    ++self->led_toggles;
  }
}

void VirtualMega::Impl::relax_level_interrupts() {
  for (uint8_t i = 0; i < 8; ++i) avr_extint_set_strict_lvl_trig(avr, i, 0);
}

}  // namespace strider_vmega
