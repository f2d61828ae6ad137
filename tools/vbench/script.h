// vbench scripts: one directive per line, `#` starts a comment.
//   at T send TEXT     bytes to UART1 (the HC-05) at T seconds; \n \r \t \\ \xHH escapes
//   at T send0 TEXT    the same to UART0 (USB)
//   at T range MM      HC-SR04 sees an obstacle at MM millimetres
//   at T range none    no echo at all (the echo line stays low)
//   at T range stuck   the echo line rises after the next ping and stays high
//   at T reset         external reset (RESET pin)
//   at T power_cut     the power fails and comes back at once (EEPROM kept)
//   at T eeprom_cut N [erased]  the power fails as the firmware starts its
//                      (N+1)-th EEPROM byte write from T: N writes kept, that
//                      byte left as it was (or erased, 0xFF)
//   at T board A off|on|detach|attach
//                      PCA9685 at address A (0x40): supply off / on again
//                      (power-on state), bus wires loose / back (keeps its outputs)
//   at T bus stuck|free  SDA held low (no START or STOP completes) / released
//   at T hang          the MCU hangs (interrupts off, spinning) until a watchdog reset
//   at T flood R S TEXT   a link flood on UART1: TEXT R times a second (or
//                      R = max: back to back) for S seconds
//   at T flood0 R S TEXT  the same on UART0
//   at T imu on [ADDR] | off   an MPU-6050 at ADDR (0x68) connected (in its
//                      power-on state) / disconnected
//   at T imu accel X Y Z   what it measures, its own axes: specific force [m/s^2]
//   at T imu gyro X Y Z    rates [rad/s]
//   at T imu tilt R P      at rest tilted by roll R and pitch P [deg] (Z-Y-X)
//   at T imu temp C        die temperature [deg C]
//   at T adc PIN V     V volts on analog pin PIN (A0..A7)
// Without `at T` a directive applies at once (commands piped into vbench).
#ifndef STRIDER_TOOLS_VBENCH_SCRIPT_H
#define STRIDER_TOOLS_VBENCH_SCRIPT_H

#include <cstdint>
#include <string>
#include <vector>

namespace strider_vmega {

class VirtualMega;

struct ScriptEvent {
  enum class Kind { kSend, kRange, kReset, kPowerCut, kEepromCut, kEchoStuck, kBoard, kBus, kHang, kFlood, kImu, kAdc };
  enum class ImuAction { kOn, kOff, kAccel, kGyro, kTilt, kTemp };
  enum class BoardAction { kOff, kOn, kDetach, kAttach };
  bool immediate = false;  // no `at T`
  uint64_t time_us = 0;
  Kind kind = Kind::kSend;
  int uart = 1;
  std::string text;        // kSend: the bytes, escapes resolved
  double range_mm = -1;    // kRange: negative = no echo
  uint64_t eeprom_writes = 0;  // kEepromCut: writes kept before the cut
  bool torn_erased = false;    // kEepromCut: the interrupted byte erased (0xFF)
  int board_address = 0;   // kBoard: 7-bit I2C address
  BoardAction board_action = BoardAction::kOff;
  bool bus_stuck = false;  // kBus
  double per_s = 0;        // kFlood: repetitions of text a second, 0 = back to back
  double duration_s = 0;   // kFlood: how long
  ImuAction imu_action = ImuAction::kOn;  // kImu
  double values[3] = {0, 0, 0};  // kImu: accel, gyro, tilt (roll, pitch), temp; kAdc: volts in [0]
  int pin = 0;             // kAdc: analog pin 0..7
  int line = 0;            // source line, for messages
};

//! Resolves \n \r \t \\ and \xHH; false and *error on a bad escape.
bool unescape(const std::string& in, std::string* out, std::string* error);

//! Parses one line; false and *error on a syntax error. Blank and comment
//! lines give true with *has_event = false.
bool parse_script_line(const std::string& line, ScriptEvent* event, bool* has_event, std::string* error);

//! Parses a whole script; events keep their order of appearance and are
//! stable-sorted by time.
bool parse_script(const std::string& text, std::vector<ScriptEvent>* events, std::string* error);

//! Parses `N` or `N:erased` (an EEPROM cut: writes kept, the torn byte).
bool parse_eeprom_cut(const std::string& text, uint64_t* writes, bool* erased, std::string* error);

//! Applies an event to the Mega now.
void apply_event(const ScriptEvent& event, VirtualMega& mega);

}  // namespace strider_vmega

#endif  // STRIDER_TOOLS_VBENCH_SCRIPT_H
