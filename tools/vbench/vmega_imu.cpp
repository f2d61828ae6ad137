// VirtualMega: the MPU-6050 on TWI (present on demand; the register model is
// mpu6050.cpp, the bus routing vmega_twi.cpp) and the analog inputs A0..A7.
#include "virtual_mega_impl.h"

#include <cmath>

#include "avr_adc.h"

namespace strider_vmega {

void VirtualMega::set_imu_present(bool present, uint8_t address7) {
  Impl& s = *impl_;
  if (present && (!s.imu_present || s.imu.address() != address7)) {
    s.imu.set_address(address7);
    s.imu.power_on_reset();  // connected: its supply comes on
  }
  s.imu_present = present;
}

bool VirtualMega::imu_present() const { return impl_->imu_present; }
void VirtualMega::set_imu_accel_m_s2(double x, double y, double z) { impl_->imu.set_accel_m_s2(x, y, z); }
void VirtualMega::set_imu_gyro_rad_s(double x, double y, double z) { impl_->imu.set_gyro_rad_s(x, y, z); }
void VirtualMega::set_imu_temp_c(double c) { impl_->imu.set_temp_c(c); }
const Mpu6050& VirtualMega::imu() const { return impl_->imu; }

// --- ADC ---------------------------------------------------------------------

namespace {

uint32_t avcc_mv(const Options& o) { return uint32_t(std::lround(o.avcc_volts * 1000.0)); }

uint16_t code_for(double volts, double avcc_volts) {
  if (!(volts > 0) || !(avcc_volts > 0)) return 0;
  const double n = std::floor(volts * 1024.0 / avcc_volts);
  return n >= 1023.0 ? 1023 : uint16_t(n);
}

}  // namespace

void VirtualMega::Impl::hook_adc() {
  const uint32_t mv = avcc_mv(options);
  avr->vcc = mv;
  avr->avcc = mv;
  avr->aref = mv;
  avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_OUT_TRIGGER), on_adc_trigger, this);
  feed_adc();
}

// simavr converts as floor(mV x 1023 / AVCC_mV); the chip as floor(V x 1024 /
// AVCC). Hand simavr the millivolts that give the chip's code.
void VirtualMega::Impl::feed_adc() {
  const uint32_t vref = avcc_mv(options);
  if (vref == 0) return;
  for (int pin = 0; pin < kAdcPins; ++pin) {
    const uint32_t n = code_for(adc_volts[pin], options.avcc_volts);
    uint32_t mv = uint32_t(std::ceil(double(n) * double(vref) / 1023.0));
    while (mv > 0 && mv * 1023u / vref > n) --mv;
    while (mv * 1023u / vref < n) ++mv;
    avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0 + pin), mv);
  }
}

// A conversion starts: the pins' voltages as they are now.
void VirtualMega::Impl::on_adc_trigger(avr_irq_t*, uint32_t, void* param) { static_cast<Impl*>(param)->feed_adc(); }

void VirtualMega::set_adc_volts(int pin, double volts) {
  Impl& s = *impl_;
  if (pin < 0 || pin >= Impl::kAdcPins) return;
  s.adc_volts[pin] = std::isfinite(volts) ? volts : 0.0;
  if (s.avr) s.feed_adc();
}

double VirtualMega::adc_volts(int pin) const {
  return pin < 0 || pin >= Impl::kAdcPins ? 0.0 : impl_->adc_volts[pin];
}

uint16_t VirtualMega::adc_code(int pin) const {
  return pin < 0 || pin >= Impl::kAdcPins ? 0 : code_for(impl_->adc_volts[pin], impl_->options.avcc_volts);
}

}  // namespace strider_vmega
