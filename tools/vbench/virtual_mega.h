// VirtualMega: an ATmega2560 at 16 MHz on libsimavr with what a Strider robot
// wires to it: PCA9685 boards on TWI, the HC-05 on a UART, the HC-SR04 on
// PE5 (trigger) / PE4 (echo, INT4), EEPROM kept in a file, a reset
// counter, and power cuts (at once or at the N-th EEPROM write); on demand
// an MPU-6050 on TWI and voltages on the analog pins (a battery divider). Time only
// moves inside run_until_us()/run_for_us(), so a physics simulator can
// advance the firmware in lock-step with its own steps.
#ifndef STRIDER_TOOLS_VBENCH_VIRTUAL_MEGA_H
#define STRIDER_TOOLS_VBENCH_VIRTUAL_MEGA_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mpu6050.h"
#include "pca9685.h"

namespace strider_vmega {

struct Options {
  std::string elf_path;
  uint32_t f_cpu_hz = 16000000;
  //! 7-bit addresses of the PCA9685 boards; board i drives global channels 16i..16i+15.
  std::vector<uint8_t> pca_addresses = {0x40, 0x41};
  //! Oscillator of every board [Hz] (a real board: 23-27 MHz).
  double pca_osc_hz = 25e6;
  //! Per-board oscillators [Hz], overriding pca_osc_hz where given.
  std::vector<double> pca_osc_per_board_hz;
  //! EEPROM image loaded at load() when the file exists (missing = erased, 0xFF).
  std::string eeprom_path;
  //! Sonar: HC-SR04 echo rises this long after the trigger's falling edge [us].
  uint32_t sonar_echo_delay_us = 460;
  //! Initial sonar range [mm]; negative = no echo (the line stays low).
  double sonar_range_mm = -1;
  //! An MPU-6050 on the bus at this 7-bit address (0x68, or 0x69 with AD0
  //! high); 0 = none, the default: nothing answers there.
  uint8_t imu_address = 0;
  //! AVCC [V]: the ADC's reference under analogReference(DEFAULT).
  double avcc_volts = 5.0;
  //! The pulse and I2C logs drop their older half beyond this many entries
  //! (long lock-step runs); clear them after reading to keep everything.
  size_t log_limit = 1000000;
};

//! A pulse-width change on a PCA9685 output.
struct PulseChange {
  uint64_t time_us;
  int channel;      // global: 16 * board + channel
  double width_us;  // 0 = off
};

//! One I2C transaction, START to STOP (a repeated START starts a new one).
struct I2cTransaction {
  uint64_t start_us = 0;
  uint8_t address7 = 0;
  bool read = false;
  bool acked = false;
  int bytes = 0;  // address byte included
};

//! I2C traffic of one servo frame: transactions closer than the frame gap.
struct I2cFrame {
  uint64_t start_us = 0;
  int transactions = 0;
  int bytes = 0;
  //! Bus time at bus_hz: 9 clocks per byte plus START and STOP [us].
  double bus_time_us(double bus_hz = 400e3) const {
    return (9.0 * bytes + 2.0 * transactions) * 1e6 / bus_hz;
  }
};

//! A link flood (fault injection): a sender that writes `units` in turn
//! (after the last, the first again), `per_s` of them a second, into a UART.
//! Like a program writing to a serial port, it blocks while the port still
//! holds kFloodSenderBytes unsent bytes: a flood faster than the baud rate
//! goes out back to back at the baud rate.
struct Flood {
  std::vector<std::string> units;  //!< e.g. {"F"} (RC bytes) or {"status\n"} (lines)
  double per_s = 0;                //!< units a second; 0 = back to back
  uint64_t duration_us = 0;        //!< stop after this long; 0 = only after `count` units
  uint64_t count = 0;              //!< stop after this many units; 0 = only after `duration_us`
};
constexpr size_t kFloodSenderBytes = 64;  //!< the sender's queue: it waits beyond this

//! What a flood has sent so far.
struct FloodStats {
  bool active = false;
  uint64_t units = 0;  //!< units handed to the UART (whole)
  uint64_t bytes = 0;
  uint64_t start_us = 0;
  uint64_t last_us = 0;  //!< when the last unit was handed over
};

//! A byte the firmware wrote to a UART.
struct UartByte {
  uint64_t time_us;
  uint8_t value;
};

//! An EEPROM byte the firmware programmed (a write operation: avr-libc's
//! eeprom_update_byte() skips a byte that already holds its value).
struct EepromWrite {
  uint64_t time_us;
  uint16_t address;
  uint8_t value;
};

//! What the byte whose write a power cut interrupts holds afterwards.
enum class TornByte {
  kOld,     //!< its old value: the power failed before the write began
  kErased,  //!< 0xFF: the power failed between the erase and the write of an erase-and-write
};

//! A power cut: when, and the EEPROM write it interrupted.
struct PowerCut {
  uint64_t time_us;
  int64_t eeprom_write;  //!< index of the interrupted write (as eeprom_writes() counts), -1 = none
  uint16_t address;      //!< its address
};

enum class RunStatus {
  kOk,          // reached the requested time
  kStopped,     // the firmware stopped the CPU (cli; sleep)
  kCrashed,     // simavr reported a crash
  kNotLoaded,
};

const char* to_string(RunStatus s);

class VirtualMega {
 public:
  VirtualMega();
  ~VirtualMega();
  VirtualMega(const VirtualMega&) = delete;
  VirtualMega& operator=(const VirtualMega&) = delete;

  //! Loads the ELF into a fresh ATmega2560; false and *error on failure.
  bool load(const Options& options, std::string* error);
  bool loaded() const;

  //! Advances simulated time to t_us: stops at the first instruction boundary
  //! at or after it (a sleeping CPU wakes there too); never hangs.
  RunStatus run_until_us(uint64_t t_us);
  RunStatus run_for_us(uint64_t dt_us) { return run_until_us(now_us() + dt_us); }
  uint64_t now_us() const;
  uint64_t cycles() const;

  // UARTs (0 = USB, 1 = HC-05). Queued bytes go in at the baud the firmware
  // programmed, never more than simavr's 64-byte receive FIFO holds; they
  // wait while the receiver is disabled.
  void send(int uart, const std::string& bytes);
  size_t pending_input(int uart) const;
  //! Bytes the firmware wrote since the last call.
  std::string take_output(int uart);
  //! Called for every byte the firmware writes (in addition to take_output).
  void set_output_callback(std::function<void(int uart, const UartByte&)> cb);
  //! Baud rate the firmware programmed (0 before it did).
  uint32_t baud(int uart) const;
  //! Starts a flood on `uart` now (replacing one that runs there); a flood
  //! with neither duration nor count, or without units, does nothing.
  void flood(int uart, const Flood& f);
  void stop_flood(int uart);
  FloodStats flood_stats(int uart) const;

  // PCA9685 boards.
  int board_count() const;
  const Pca9685& board(int i) const;
  //! Pulse width of a global channel [us], 0 = off/full-off/asleep.
  double pulse_us(int channel) const;
  std::vector<double> pulses_us() const;
  // Servo-board faults (docs/vbench.md, "Fault injection").
  //! Board i's supply: off, it drives no output and answers nothing; on
  //! again, it answers in its power-on state (asleep, every output off).
  void set_board_power(int i, bool on);
  //! Board i's bus wires: detached, it answers nothing (a loose SDA or SCL
  //! wire) but keeps driving its outputs from its registers.
  void set_board_attached(int i, bool attached);
  //! The bus held low (a slave holding SDA): no START or STOP the TWI asks
  //! for completes, TWINT stays clear. Released, a pending one completes.
  void set_bus_stuck(bool stuck);
  bool bus_stuck() const;
  const std::vector<PulseChange>& pulse_log() const;
  void clear_pulse_log();
  const std::vector<I2cTransaction>& i2c_log() const;
  void clear_i2c_log();
  //! Groups the logged transactions into frames separated by > gap_us of silence.
  std::vector<I2cFrame> i2c_frames(uint64_t gap_us = 5000) const;

  // HC-SR04.
  void set_range_mm(double mm);
  void set_no_echo();
  //! ECHO stuck high: it rises after the next trigger and never falls (until
  //! set_range_mm() or set_no_echo()).
  void set_echo_stuck();
  int sonar_triggers() const;       // accepted trigger pulses (>= 10 us)
  int sonar_short_triggers() const;  // pulses too short to trigger
  //! Shortest TRIG high time seen, accepted or not [us] (0 before the first).
  double sonar_min_trigger_width_us() const;
  //! Shortest time between two accepted triggers [us] (0 before two).
  uint64_t sonar_min_trigger_interval_us() const;

  // MPU-6050 (absent unless Options::imu_address or set_imu_present()).
  //! Connects the IMU at address7 (0x68 or 0x69) in its power-on state, or
  //! disconnects it (nothing answers at its address).
  void set_imu_present(bool present, uint8_t address7 = 0x68);
  bool imu_present() const;
  //! What it measures, in its own axes: specific force [m/s^2] (+9.81 on z
  //! lying flat), rates [rad/s], die temperature [deg C]. Kept while absent.
  void set_imu_accel_m_s2(double x, double y, double z);
  void set_imu_gyro_rad_s(double x, double y, double z);
  void set_imu_temp_c(double c);
  //! Register-level view.
  const Mpu6050& imu() const;

  // Analog inputs A0..A7 (libsimavr converts only those eight).
  //! The voltage on analog pin `pin` [V] from now on (0 at load).
  void set_adc_volts(int pin, double volts);
  double adc_volts(int pin) const;
  //! The code a conversion of `pin` gives against AVCC, as the chip
  //! computes it: floor(V x 1024 / AVCC), 0..1023.
  uint16_t adc_code(int pin) const;

  // EEPROM (4 KiB).
  std::vector<uint8_t> eeprom() const;
  void set_eeprom(const std::vector<uint8_t>& bytes);
  bool load_eeprom(const std::string& path, std::string* error);
  bool save_eeprom(const std::string& path, std::string* error) const;

  // EEPROM writes and power cuts.
  //! EEPROM byte writes since load (the first has index 0).
  uint64_t eeprom_writes() const;
  //! Every EEPROM write since load (or the last clear).
  const std::vector<EepromWrite>& eeprom_write_log() const;
  void clear_eeprom_write_log();
  //! Arms a power cut during an EEPROM write: the power fails when the
  //! firmware starts its (n+1)-th EEPROM byte write from now (n = 0: the
  //! next one). The n writes before it are kept, that byte holds what
  //! `torn` says, and the Mega powers up again at once, as power_cut() does.
  void cut_power_after_eeprom_writes(uint64_t n, TornByte torn = TornByte::kOld);
  //! Disarms an armed cut (none fired yet).
  void cancel_eeprom_cut();
  bool eeprom_cut_armed() const;
  //! The power fails and comes back at once: the MCU starts from its
  //! power-on reset (MCUSR = PORF, SRAM garbage), the PCA9685 boards from
  //! their power-on state (asleep, outputs off), bytes queued for the UARTs
  //! are lost; the EEPROM keeps what was written.
  void power_cut();
  //! Power cuts so far (armed or immediate).
  const std::vector<PowerCut>& power_cut_log() const;

  // Resets.
  //! External reset (the RESET pin, MCUSR.EXTRF): counted separately from
  //! the others.
  void reset();
  //! The MCU hangs: interrupts off, spinning in place (a loop at the top of
  //! the flash, the unused boot section) until a running watchdog resets it.
  void hang();
  //! Resets the host did not cause: watchdog, a jump to the reset vector.
  int unexpected_resets() const;
  int external_resets() const;

  // GPIO.
  //! Level an output pin drives (port 'A'..'L', bit 0..7); false for inputs.
  bool pin_output(char port, int bit) const;
  //! Level changes of the LED on D13 (PB7) since load.
  int led_toggles() const;
  //! Data-space bytes (registers, I/O, SRAM) for inspection, e.g. a
  //! variable at an address from avr-nm.
  std::vector<uint8_t> read_ram(uint16_t address, uint16_t count) const;
  //! Deepest stack seen since load: RAMEND - lowest SP [bytes].
  uint32_t stack_peak_bytes() const;
  //! .data + .bss of the firmware [bytes].
  uint32_t static_ram_bytes() const;
  //! When the stack first grew into .bss [us]; 0 = never.
  uint64_t stack_overflow_us() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strider_vmega

#endif  // STRIDER_TOOLS_VBENCH_VIRTUAL_MEGA_H
