//! The hardware seams of the control layer, as compile-time concepts
//! (template parameters, no vtables on the AVR); firmware binds them to
//! drivers, tests to fakes, the simulator to physics. Members required:
//!
//! ServoOutput   void write_ticks(uint8_t channel, uint16_t off_ticks);
//!               void set_prescale(uint8_t prescale);   // board sleeps, writes, restarts
//!               void relax(uint8_t channel);           // full-off: no pulse, servo limp
//! RangeSensor   bool poll(EchoSample* out);            // true when a new sample is ready (sonar_echo.h)
//!               void trigger(uint32_t now_us);         // start one ping (non-blocking)
//! ByteStream    int16_t read();                        // next byte 0-255, or -1 if none
//!               void write(const char* text, uint8_t len);
//! Clock         uint32_t now_us();                     // wraps every 71.6 min: compare by subtraction
//! ByteStore     uint16_t size() const;                 // bytes (EEPROM: 4096 on the Mega)
//!               uint8_t read(uint16_t addr) const;
//!               bool write(uint16_t addr, uint8_t v);  // false on a failed write
#ifndef STRIDER_CONTROL_HAL_INTERFACES_H
#define STRIDER_CONTROL_HAL_INTERFACES_H

#include <stdint.h>

namespace strider {

//! What a range sensor driver reports for one ping.
enum class EchoKind : uint8_t {
  kEcho = 0,     //!< an echo pulse of width_us was measured
  kNoEdge = 1,   //!< no echo edge at all before the driver's deadline (missing echo)
};

struct EchoSample {
  EchoKind kind;      //!< echo or missing echo
  uint16_t width_us;  //!< echo pulse width [us] (kEcho only)
  uint32_t at_us;     //!< when the ping was triggered [us]
};

//! Elapsed time between two wrapping microsecond (or millisecond) stamps.
constexpr uint32_t elapsed(uint32_t now, uint32_t since) { return now - since; }

//! A ByteStore over a plain array (the EEPROM of tests and the simulator).
template <uint16_t kSize>
struct ArrayByteStore {
  uint8_t bytes[kSize];
  uint16_t size() const { return kSize; }
  uint8_t read(uint16_t addr) const { return addr < kSize ? bytes[addr] : uint8_t(0xFF); }
  bool write(uint16_t addr, uint8_t v) {
    if (addr >= kSize) return false;
    bytes[addr] = v;
    return true;
  }
  void erase() { for (uint16_t i = 0; i < kSize; ++i) bytes[i] = 0xFF; }  //!< like a new EEPROM
};

}  // namespace strider

#endif  // STRIDER_CONTROL_HAL_INTERFACES_H
