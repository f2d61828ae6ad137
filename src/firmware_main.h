// Strider firmware for the Arduino Mega 2560: binds the portable robot
// (lib/strider/control/robot_app.h) to the board: PCA9685 servo boards on
// I2C, the HC-05 on Serial1 and USB on Serial, the HC-SR04 on D2/D3, the
// EEPROM, the watchdog, and a 50 Hz tick.
//
// Included once per build, last, by the file of src/models/ that PlatformIO
// (build_src_filter) or CMake (per target) picks, which first includes
// control/firmware_profile.h and names its profile: `using Firmware =
// strider::FirmwareProfile<strider::robot_index(strider::kSprawl8)>;` (control/firmware_profile.h):
// the model is a compile-time constant here, and the profile sizes the
// walker, the servo stage and the RobotApp to it.
#ifndef STRIDER_FIRMWARE_MAIN_H
#define STRIDER_FIRMWARE_MAIN_H

// Library headers before Arduino.h, which defines min, max, abs and
// constrain as macros that would rewrite the library's own names.
#include "control/robot_app.h"
#include "control/rx_overflow.h"
#include "eeprom_store.h"
#include "hcsr04_sonar.h"
#include "mpu6050_imu.h"
#include "pca9685_output.h"
#include "serial_link.h"

#include <Arduino.h>
#include <avr/sleep.h>
#include <avr/wdt.h>

#include "board_pins.h"

namespace {

using Scalar = Firmware::Scalar;
// The model in flash: the RobotApp copies it to the stack for its start-up
// configuration, and no RAM holds it.
constexpr strider::RobotModel kModelInFlash PROGMEM = strider::without_leg_names(Firmware::kModel);
constexpr uint8_t kBoards = strider::pca_board_count(kModelInFlash);  // for constant expressions only
using App = strider::RobotApp<Scalar, Pca9685Output, EepromStore, Firmware>;

uint16_t g_servo_shadow[kBoards * strider::kPcaChannelsPerBoard];  // the boards this model uses
Pca9685Output g_servos(g_servo_shadow, uint8_t(sizeof g_servo_shadow / sizeof g_servo_shadow[0]));
EepromStore g_eeprom;
SerialLink g_link;
// The RobotApp, built in setup() once the watchdog is on: its constructor
// reads the settings from EEPROM.
App* g_app = nullptr;
uint32_t g_next_tick_us = 0;
uint32_t g_last_tick_us = 0;  // the last tick's scheduled time
// The servo boards' check runs once per period, this long after the frame:
// the frame's transfers are sent at their time, in one burst, and do not
// share the bus with it (unless a tick ran past 14 ms: then it runs late).
constexpr uint32_t kBoardsAfterFrameUs = 6000;
bool g_boards_due = false;
bool g_imu = false;  // an MPU-6050 answered at start-up
uint32_t g_boards_at_us = 0;
uint32_t g_led_ms = 0;

// Before anything else runs (.init3: the stack pointer and the zero register
// are set, no constructor has run yet):
// - the reset cause is saved; a watchdog reset leaves the watchdog running
//   with its shortest timeout, so it is disabled at once or the board would
//   reset again during start-up;
// - the free RAM between the static data and the stack is painted, so that
//   `status` can tell how deep the stack has ever reached (stack_peak).
constexpr uint8_t kStackPaint = 0xC5;
extern "C" uint8_t __heap_start;  // avr-libc: first byte after .data, .bss and .noinit
extern "C" char* __brkval;        // avr-libc: end of the heap, 0 until malloc() first runs
uint8_t g_reset_flags __attribute__((section(".noinit")));
void early_init() __attribute__((naked, used, section(".init3")));
void early_init() {
  g_reset_flags = MCUSR;
  MCUSR = 0;
  wdt_disable();
  for (uint8_t* p = &__heap_start; p < reinterpret_cast<uint8_t*>(SP) - 2; ++p) *p = kStackPaint;
}

// Deepest stack use since power-up [bytes]: RAMEND down to the lowest byte
// that lost its paint, searched from the top of the heap up (a library that
// allocates, as Arduino libraries may in begin(), overwrites the paint
// below it: those bytes are heap, not stack).
uint16_t stack_peak() {
  const uint8_t* p = __brkval != nullptr ? reinterpret_cast<const uint8_t*>(__brkval) : &__heap_start;
  while (p <= reinterpret_cast<const uint8_t*>(RAMEND) && *p == kStackPaint) ++p;
  return uint16_t(RAMEND + 1 - reinterpret_cast<uintptr_t>(p));
}

constexpr char kInfoWatchdog[] PROGMEM = "info reset watchdog";
constexpr char kInfoBrownOut[] PROGMEM = "info reset brown-out";
constexpr char kInfoExternal[] PROGMEM = "info reset external";

void notice(const char* flash_text) {
  char buf[32];
  strncpy_P(buf, flash_text, sizeof buf - 1);
  buf[sizeof buf - 1] = 0;
  g_link.send_line(strider::kAllPorts, buf);
}

// The reset's cause, once, from the flags early_init() saved: the most
// telling one when several are set. Nothing for a power-up, nor when a
// bootloader cleared MCUSR before the firmware ran (docs/reliability.md).
void report_reset_cause() {
  const uint8_t f = g_reset_flags;
  if (f & _BV(WDRF)) notice(kInfoWatchdog);
  else if (f & _BV(BORF)) notice(kInfoBrownOut);
  else if ((f & _BV(EXTRF)) && !(f & _BV(PORF))) notice(kInfoExternal);
}

// The prescale the servo stage will set (configure_servo_pwm() with the
// loaded settings): boards found running at it after an MCU reset keep
// their pulses. 0 after a power-up: the boards' registers are not trusted,
// every output starts off.
uint8_t warm_prescale() {
  if (g_reset_flags & _BV(PORF)) return 0;
  strider::Pca9685Timing timing;  // 25 MHz, 50 Hz unless the settings' oscillator is accepted
  const strider::Settings& s = g_app->controller().settings();
  timing.configure(s.pca_osc_hz, s.pwm_hz);
  return timing.prescale();
}

// The links. Bytes arrive faster than some commands run (at 115200 baud one
// every 87 us), so each loop pass reads a port for at most kLinkReadUs and
// not past the tick's time (at least one byte a pass), and only while a
// reply would not wait for the UART (SerialLink::can_reply()): the loop
// comes round to the watchdog, the tick and the sonar whatever arrives.
// What is not read yet waits in the core's receive buffer, 256 bytes per
// port (SERIAL_RX_BUFFER_SIZE in platformio.ini's build_flags): 22 ms at
// 115200 baud, longer than the longest tick. When it was full all the same,
// the core dropped bytes without a word; RxOverflowWatch finds where, and
// the line they fell into is answered `err 10` and never runs.
static_assert(SERIAL_RX_BUFFER_SIZE >= 256, "platformio.ini's build_flags: -DSERIAL_RX_BUFFER_SIZE=256");
constexpr uint16_t kRxCapacity = SERIAL_RX_BUFFER_SIZE - 1;  // HardwareSerial keeps one slot free
constexpr uint32_t kLinkReadUs = 2000;
strider::RxOverflowWatch g_rx_watch[strider::kLinkPorts];

// One function for both ports, inlined into loop(): its locals share the
// loop's frame instead of adding one of their own under the deepest call
// chain (a line whose command plans a new walking speed).
void read_links(uint32_t now_us) {
  for (uint8_t port = 0; port < strider::kLinkPorts; ++port) {
    HardwareSerial& s = port == 0 ? Serial : Serial1;
    const uint32_t start_us = micros();
    for (bool first = true;; first = false) {
      const int waiting = s.available();
      if (waiting <= 0 || !g_link.can_reply(port)) break;
      if (!first) {
        const uint32_t t = micros();
        if (t - start_us >= kLinkReadUs || int32_t(t - g_next_tick_us) >= 0) break;
      }
      if (g_rx_watch[port].gap_before_next(uint16_t(waiting), kRxCapacity)) g_app->on_bytes_lost(port, now_us, g_link);
      g_app->on_byte(port, uint8_t(s.read()), now_us, g_link);
    }
  }
}

// A fresh time stamp, not the loop's: the 60 ms between pings must hold for
// the TRIG pulses themselves, and the echo interrupt may have stamped an
// edge since the loop began.
void run_sonar() {
  const uint32_t now_us = micros();
  strider::EchoSample sample;
  if (hcsr04::poll(now_us, &sample)) g_app->sonar().add(sample, now_us);
  if (!hcsr04::busy() && g_app->sonar().ping_due(now_us)) hcsr04::trigger(now_us);
}

}  // namespace

// The IMU and the battery divider, once a tick before it. Not inlined into
// loop(): their locals (the burst, the sample, the filter's) would otherwise
// stay in loop()'s frame under the deepest call chain (a command that plans
// a new walking speed).
static __attribute__((noinline)) void read_sensors() {
  if (g_imu) {  // one burst a tick (14 bytes: 0.4 ms at 400 kHz)
    uint8_t burst[strider::kMpu6050BurstBytes];
    const bool read = mpu6050_imu::read(burst);
    const strider::ImuSample<Scalar> s =
        strider::mpu6050_sample<Scalar>(burst, mpu6050_imu::kAccelRange, mpu6050_imu::kGyroRange);
    g_app->imu(read ? &s : nullptr, g_link);
  }
  g_app->battery(uint16_t(analogRead(pins::kBatteryAdcChannel)), g_link);  // 0.11 ms
}

// The heartbeat LED through its port's registers (no pinMode(), digitalRead()).
static_assert(pins::kHeartbeatLed == 13, "the LED on D13 = PB7 (the port bits below)");

// The core's loop hook calls serialEvent() callbacks when a port has bytes;
// the firmware reads its ports in loop() and has none: a hook that does nothing.
void serialEventRun() {}

void setup() {
  // The watchdog before anything can hang: a bus held low (before Wire's
  // time-out is set), a library that blocks. Start-up takes about 20 ms
  // (the velocity limits come from the stored table, FirmwareProfile); a
  // reply that waits for a full ring feeds it (serial_link.h).
  wdt_enable(WDTO_500MS);
  static App app(kModelInFlash, g_servos, g_eeprom, strider::ModelMemory::kFlash);  // reads the settings from EEPROM
  g_app = &app;
  DDRB |= _BV(PB7);
  Serial.begin(pins::kUsbBaud);
  Serial1.begin(g_app->controller().settings().baud);
  hcsr04::begin();
  report_reset_cause();
  // After an MCU reset the boards may still run the last frame (the robot
  // stands on it): held() outputs keep their pulses and the robot stands up
  // from them. After a power-up, every output starts off.
  g_servos.begin(kBoards, warm_prescale());
  g_app->set_stack_probe(stack_peak);
  strider::BatteryConfig battery;
  battery.adc_ref_mv = pins::kAdcReferenceMv;
  battery.divider_x100 = pins::kBatteryDividerX100;
  g_app->set_battery_config(battery);
  g_imu = mpu6050_imu::begin();  // after the boards: the bus is up
  g_app->set_imu_present(g_imu);
  wdt_reset();
  g_app->begin(micros(), g_link, g_servos.held() != 0 ? g_servos.outputs() : nullptr, g_servos.channels());
  wdt_reset();
  g_next_tick_us = micros();
  g_last_tick_us = g_next_tick_us - strider::kTickPeriodUs;
}

void loop() {
  wdt_reset();
  const uint32_t now_us = micros();
  read_links(now_us);
  g_link.poll();
  run_sonar();
  if (int32_t(now_us - g_next_tick_us) >= 0) {
    read_sensors();
    const uint32_t start_us = micros();
    // The gait advances by the scheduled time since the last tick (a period,
    // more after skipped ones), not by the measured one: the loop wakes on
    // Timer0's overflow every 1.024 ms, and that jitter of the start would
    // otherwise move the feet by a different amount every tick.
    g_app->tick(start_us, g_link, g_next_tick_us - g_last_tick_us);
    g_last_tick_us = g_next_tick_us;
    const uint32_t took = micros() - start_us;
    g_app->record_tick_time(took);
    g_next_tick_us += strider::kTickPeriodUs;
    const int32_t late = int32_t(micros() - g_next_tick_us);
    if (late > int32_t(strider::kTickPeriodUs)) {  // fell behind by whole ticks: skip them
      const uint32_t missed = uint32_t(late) / strider::kTickPeriodUs;
      g_app->record_missed_ticks(uint16_t(missed > 0xFFFF ? 0xFFFF : missed));
      g_next_tick_us += missed * strider::kTickPeriodUs;
    }
    if (!g_boards_due) {
      g_boards_due = true;
      g_boards_at_us = micros() + kBoardsAfterFrameUs;
    }
  }
  // The servo boards between frames: working boards read, a faulted one
  // probed, one that answers taken back; RobotApp hears of it.
  if (g_boards_due && int32_t(now_us - g_boards_at_us) >= 0) {
    g_boards_due = false;
    g_servos.service(now_us / 1000u);
    g_app->servo_boards(g_servos.report(), now_us, g_link);
  }
  const uint32_t now_ms = now_us / 1000u;
  if (now_ms - g_led_ms >= 500u) {  // heartbeat: the loop is alive
    g_led_ms = now_ms;
    PORTB ^= _BV(PB7);
  }
  // Idle until the next interrupt instead of spinning: Timer0's millis
  // overflow (every 1.024 ms), a received byte, a sonar echo edge or a UART
  // ready for more wakes the CPU, so the loop still runs at least once a
  // millisecond (the tick starts within 1.024 ms of its time; the watchdog is
  // fed). Idle mode keeps the timers, UARTs and TWI running and saves about
  // half the MCU's current between ticks.
  set_sleep_mode(SLEEP_MODE_IDLE);
  sleep_mode();
}

#endif  // STRIDER_FIRMWARE_MAIN_H
