// The virtual Mega's peripherals against the bare-metal probe firmware
// (probe_firmware.cpp): UART pacing and buffering, TWI addressing and the
// PCA9685 decode, HC-SR04 echo timing, EEPROM persistence, power cuts during
// EEPROM writes, resets, the LED, and the vbench executable with a script
// and with a pseudo-terminal.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "virtual_mega.h"

using strider_vmega::Options;
using strider_vmega::RunStatus;
using strider_vmega::VirtualMega;

namespace {

std::string temp_path(const std::string& name) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir ? dir : "/tmp") + "/strider_vbench_" + std::to_string(getpid()) + "_" + name;
}

class Probe : public ::testing::Test {
 protected:
  Options options() {
    Options o;
    o.elf_path = STRIDER_VBENCH_PROBE_ELF;
    return o;
  }
  void boot(const Options& o) {
    std::string err;
    ASSERT_TRUE(mega.load(o, &err)) << err;
    const std::string line = next_line(1, 200000);
    ASSERT_EQ(line.substr(0, 5), "boot ") << line;
  }
  void SetUp() override { boot(options()); }

  // Runs until UART `uart` completes a line (or timeout_us passes).
  std::string next_line(int uart, uint64_t timeout_us) {
    const uint64_t end = mega.now_us() + timeout_us;
    while (mega.now_us() < end) {
      buffer[uart] += mega.take_output(uart);
      const size_t nl = buffer[uart].find('\n');
      if (nl != std::string::npos) {
        std::string line = buffer[uart].substr(0, nl);
        buffer[uart].erase(0, nl + 1);
        return line;
      }
      if (mega.run_for_us(500) != RunStatus::kOk) return "<stopped>";
    }
    return "<timeout>";
  }
  std::string command(const std::string& line, uint64_t timeout_us = 500000) {
    mega.send(1, line + "\n");
    return next_line(1, timeout_us);
  }
  // Standard 50 Hz bring-up of a board over the bus.
  void bring_up(const std::string& addr) {
    ASSERT_EQ(command("w " + addr + " 00 10"), "ok");
    ASSERT_EQ(command("w " + addr + " FE 79"), "ok");  // prescale 121
    ASSERT_EQ(command("w " + addr + " 00 20"), "ok");
    ASSERT_EQ(command("w " + addr + " 00 A0"), "ok");
  }

  VirtualMega mega;
  std::string buffer[2];
};

TEST_F(Probe, BootsOnBothUartsAtTheProgrammedBaud) {
  EXPECT_EQ(next_line(0, 100000), "boot0");
  EXPECT_EQ(mega.baud(1), 9615u);    // UBRR 207, U2X
  EXPECT_EQ(mega.baud(0), 117647u);  // UBRR 16, U2X
  EXPECT_EQ(mega.unexpected_resets(), 0);
}

TEST(ProbeBoot, BytesSentBeforeTheReceiverIsOnWait) {
  VirtualMega mega;
  Options o;
  o.elf_path = STRIDER_VBENCH_PROBE_ELF;
  std::string err;
  ASSERT_TRUE(mega.load(o, &err)) << err;
  mega.send(1, "q 40\n");  // at t = 0, before the firmware set up UART1
  mega.run_until_us(200000);
  EXPECT_EQ(mega.take_output(1), "boot 01\nack\n");
}

TEST_F(Probe, LongLineArrivesIntactAtTheBaudRate) {
  std::string text;
  uint32_t sum = 0;
  for (int i = 0; i < 150; ++i) {
    text.push_back(char('!' + (i * 7) % 90));
    sum += uint8_t(text.back());
  }
  const uint64_t t0 = mega.now_us();
  EXPECT_EQ(command("n " + text), "len 150 sum " + std::to_string(sum));
  // 153 bytes at 9615 baud take 159 ms; nothing arrives faster than the wire.
  EXPECT_GE(mega.now_us() - t0, 153 * 1040u);
}

TEST_F(Probe, BytesWaitWhileTheFirmwareIsBusy) {
  // The firmware does not read for 300 ms: 100 bytes would overflow simavr's
  // 64-byte FIFO if they were pushed in regardless.
  mega.send(1, "b 300\n");
  std::string text(100, 'x');
  mega.send(1, "n " + text + "\n");
  EXPECT_EQ(next_line(1, 1000000), "done");
  EXPECT_EQ(next_line(1, 1000000), "len 100 sum " + std::to_string(100 * int('x')));
  EXPECT_EQ(mega.pending_input(1), 0u);
}

// Link floods (fault injection): a sender at a set rate, and one faster than
// the wire, which then goes out back to back at the baud rate.
TEST_F(Probe, FloodSendsItsRate) {
  strider_vmega::Flood f;
  f.units = {"n ab\n"};
  f.per_s = 20;
  f.duration_us = 1000000;
  mega.flood(1, f);
  int replies = 0;
  for (std::string l = next_line(1, 300000); l != "<timeout>"; l = next_line(1, 300000)) {
    EXPECT_EQ(l, "len 2 sum 195");
    ++replies;
  }
  EXPECT_EQ(mega.flood_stats(1).units, 20u);
  EXPECT_EQ(mega.flood_stats(1).bytes, 100u);
  EXPECT_FALSE(mega.flood_stats(1).active);
  EXPECT_EQ(replies, 20);
}

TEST_F(Probe, FloodFasterThanTheWireGoesBackToBack) {
  strider_vmega::Flood f;
  f.units = {"n " + std::string(40, 'x') + "\n", "n " + std::string(41, 'y') + "\n"};
  f.per_s = 1000;
  f.count = 100000;
  f.duration_us = 1000000;
  const uint64_t t0 = mega.now_us();
  mega.flood(1, f);
  size_t most_pending = 0;
  while (mega.now_us() < t0 + 1000000) {
    ASSERT_EQ(mega.run_for_us(500), RunStatus::kOk);
    most_pending = std::max(most_pending, mega.pending_input(1));
  }
  // 9615 baud: 961 bytes a second, 43.5 bytes a unit (the probe's shorter
  // replies keep up); the sender waits while the port holds its 64 bytes.
  const auto st = mega.flood_stats(1);
  EXPECT_FALSE(st.active);
  const double delivered = double(st.bytes - mega.pending_input(1));
  EXPECT_NEAR(delivered, 961.0, 961.0 * 0.03) << st.units << " units";
  EXPECT_LE(most_pending, strider_vmega::kFloodSenderBytes + 44);
  mega.stop_flood(1);
  int x = 0, yy = 0;
  for (std::string l = next_line(1, 200000); l != "<timeout>"; l = next_line(1, 200000)) {
    x += l == "len 40 sum 4800";
    yy += l == "len 41 sum 4961";
  }
  EXPECT_EQ(uint64_t(x + yy), st.units);
  EXPECT_LE(std::abs(x - yy), 1);
}

// The stack pointer changes a byte at a time (SPH, then SPL): the deepest
// stack is where it settled, not the halfway value (0x2002) in between.
TEST_F(Probe, StackPeakIgnoresTheHalfWrittenStackPointer) {
  EXPECT_LT(mega.stack_peak_bytes(), 200u);
  EXPECT_EQ(command("x"), "depth 256");
  EXPECT_EQ(mega.stack_peak_bytes(), 256u);
  EXPECT_EQ(mega.stack_overflow_us(), 0u);
}

TEST_F(Probe, TwiAddressesAckOrNack) {
  EXPECT_EQ(command("q 40"), "ack");
  EXPECT_EQ(command("q 41"), "ack");
  EXPECT_EQ(command("q 42"), "nack");
  EXPECT_EQ(command("q 70"), "ack");  // ALLCALL, on at power-on
  EXPECT_EQ(command("w 55 00 01"), "nack");
  const auto& log = mega.i2c_log();
  ASSERT_GE(log.size(), 5u);
  EXPECT_TRUE(log[0].acked);
  EXPECT_FALSE(log[2].acked);
  EXPECT_EQ(log[2].address7, 0x42);
}

TEST_F(Probe, RegisterWritesDecodeIntoPulses) {
  bring_up("40");
  bring_up("41");
  mega.clear_pulse_log();
  mega.clear_i2c_log();
  const uint64_t t0 = mega.now_us();
  ASSERT_EQ(command("w 40 0A 00 00 33 01"), "ok");  // ch1: OFF 307
  ASSERT_EQ(command("w 41 0E 00 00 90 01"), "ok");  // board 2 ch2: OFF 400
  EXPECT_NEAR(mega.pulse_us(1), 307 * 122 / 25.0, 1e-6);
  EXPECT_NEAR(mega.pulse_us(18), 400 * 122 / 25.0, 1e-6);
  EXPECT_EQ(mega.pulse_us(0), 0.0);
  const auto& log = mega.pulse_log();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0].channel, 1);
  EXPECT_GE(log[0].time_us, t0);
  EXPECT_EQ(log[1].channel, 18);
  // Address byte + pointer + 4 data bytes per write.
  ASSERT_EQ(mega.i2c_log().size(), 2u);
  EXPECT_EQ(mega.i2c_log()[0].bytes, 6);
  const auto frames = mega.i2c_frames(100000);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].bytes, 12);
  EXPECT_NEAR(frames[0].bus_time_us(), (12 * 9 + 4) * 2.5, 1e-9);
}

TEST_F(Probe, BoardOscillatorSetsTheWidth) {
  Options o = options();
  o.pca_osc_hz = 26e6;
  boot(o);
  bring_up("40");
  ASSERT_EQ(command("w 40 06 00 00 33 01"), "ok");
  EXPECT_NEAR(mega.pulse_us(0), 307 * 122 / 26.0, 1e-6);
}

TEST_F(Probe, PrescaleIgnoredWhileAwake) {
  bring_up("40");
  ASSERT_EQ(command("w 40 06 00 00 33 01"), "ok");
  const double w = mega.pulse_us(0);
  ASSERT_EQ(command("w 40 FE 03"), "ok");  // awake: no effect
  EXPECT_EQ(mega.board(0).prescale(), 121);
  EXPECT_EQ(mega.pulse_us(0), w);
  EXPECT_EQ(mega.board(0).reg(0x00), 0x20);
}

TEST_F(Probe, SoftwareResetByGeneralCall) {
  bring_up("40");
  ASSERT_EQ(command("w 40 06 00 00 33 01"), "ok");
  ASSERT_GT(mega.pulse_us(0), 0.0);
  ASSERT_EQ(command("w 00 06"), "ok");  // SWRST
  EXPECT_EQ(mega.pulse_us(0), 0.0);
  EXPECT_EQ(mega.board(0).reg(0x00), 0x11);
  EXPECT_EQ(mega.board(1).prescale(), 0x1E);
}

TEST_F(Probe, SonarEchoWidthFollowsTheRange) {
  mega.set_range_mm(1000);
  const std::string r = command("s", 200000);
  unsigned width = 0, delay = 0;
  ASSERT_EQ(std::sscanf(r.c_str(), "echo %u %u", &width, &delay), 2) << r;
  EXPECT_NEAR(double(width), 1000 * 2 / 0.343, 10.0);  // Timer1 counts 4 us
  EXPECT_NEAR(double(delay), 460.0, 10.0);
  mega.set_range_mm(150);
  ASSERT_EQ(std::sscanf(command("s", 200000).c_str(), "echo %u", &width), 1);
  EXPECT_NEAR(double(width), 150 * 2 / 0.343, 10.0);
  mega.set_range_mm(6000);  // out of range: the module's 38 ms time-out pulse
  ASSERT_EQ(std::sscanf(command("s", 200000).c_str(), "echo %u", &width), 1);
  EXPECT_NEAR(double(width), 38000.0, 10.0);
  EXPECT_EQ(mega.sonar_triggers(), 3);
}

TEST_F(Probe, SonarWithoutEchoOrShortTriggerStaysLow) {
  mega.set_no_echo();
  EXPECT_EQ(command("s", 200000), "none");
  mega.set_range_mm(500);
  EXPECT_EQ(command("s 4", 200000), "none");  // 4 us < 10 us
  EXPECT_EQ(mega.sonar_short_triggers(), 1);
  EXPECT_EQ(mega.sonar_triggers(), 1);
}

TEST_F(Probe, EepromSurvivesInAFile) {
  const std::string path = temp_path("eeprom.bin");
  std::remove(path.c_str());
  EXPECT_EQ(command("E 0010"), "ee FF");  // erased
  EXPECT_EQ(command("e 0010 5A"), "ok");
  EXPECT_EQ(command("e 0FFF 33"), "ok");
  std::string err;
  ASSERT_TRUE(mega.save_eeprom(path, &err)) << err;
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(bytes.size(), 4096u);
  EXPECT_EQ(uint8_t(bytes[0x10]), 0x5A);
  // A fresh Mega with the file sees the bytes.
  Options o = options();
  o.eeprom_path = path;
  boot(o);
  EXPECT_EQ(command("E 0010"), "ee 5A");
  EXPECT_EQ(command("E 0FFF"), "ee 33");
  std::remove(path.c_str());
}

TEST_F(Probe, PowerCutAtAnEepromWriteKeepsTheWritesBeforeIt) {
  EXPECT_EQ(command("e 0010 5A"), "ok");
  EXPECT_EQ(mega.eeprom_writes(), 1u);
  ASSERT_EQ(mega.eeprom_write_log().size(), 1u);
  EXPECT_EQ(mega.eeprom_write_log()[0].address, 0x10);
  EXPECT_EQ(mega.eeprom_write_log()[0].value, 0x5A);
  // The second write from now: the first is made, the power fails as the second begins.
  EXPECT_EQ(command("e 0030 11"), "ok");
  mega.cut_power_after_eeprom_writes(1);
  EXPECT_TRUE(mega.eeprom_cut_armed());
  EXPECT_EQ(command("e 0020 AA"), "ok");
  mega.send(1, "e 0021 BB\n");
  EXPECT_EQ(next_line(1, 200000), "boot 01");  // a power-on reset: MCUSR.PORF
  EXPECT_FALSE(mega.eeprom_cut_armed());
  ASSERT_EQ(mega.power_cut_log().size(), 1u);
  EXPECT_EQ(mega.power_cut_log()[0].eeprom_write, 3);
  EXPECT_EQ(mega.power_cut_log()[0].address, 0x21);
  EXPECT_EQ(mega.eeprom_writes(), 3u);
  EXPECT_EQ(command("E 0020"), "ee AA");
  EXPECT_EQ(command("E 0021"), "ee FF");  // never written
  // The byte being written erased (the erase of an erase-and-write done).
  mega.cut_power_after_eeprom_writes(0, strider_vmega::TornByte::kErased);
  mega.send(1, "e 0030 22\n");
  EXPECT_EQ(next_line(1, 200000), "boot 01");
  EXPECT_EQ(command("E 0030"), "ee FF");
  EXPECT_EQ(command("E 0010"), "ee 5A");
  // Disarmed, a write goes through.
  mega.cut_power_after_eeprom_writes(0);
  mega.cancel_eeprom_cut();
  EXPECT_EQ(command("e 0030 22"), "ok");
  EXPECT_EQ(command("E 0030"), "ee 22");
  EXPECT_EQ(mega.power_cut_log().size(), 2u);
  EXPECT_EQ(mega.unexpected_resets(), 0);
  EXPECT_EQ(mega.external_resets(), 0);
}

TEST_F(Probe, PowerCutRestartsTheBoardsToo) {
  bring_up("40");
  ASSERT_EQ(command("w 40 06 00 00 33 01"), "ok");
  EXPECT_GT(mega.pulse_us(0), 0.0);
  EXPECT_EQ(command("e 0040 77"), "ok");
  mega.power_cut();
  EXPECT_EQ(next_line(1, 200000), "boot 01");
  EXPECT_EQ(mega.pulse_us(0), 0.0);  // unlike a reset of the MCU alone
  EXPECT_TRUE(mega.board(0).sleeping());
  EXPECT_EQ(command("E 0040"), "ee 77");
  ASSERT_EQ(mega.power_cut_log().size(), 1u);
  EXPECT_EQ(mega.power_cut_log()[0].eeprom_write, -1);
}

TEST_F(Probe, WatchdogResetIsCounted) {
  mega.send(1, "d\n");
  EXPECT_EQ(next_line(1, 200000), "boot 08");  // MCUSR.WDRF
  EXPECT_EQ(mega.unexpected_resets(), 1);
  EXPECT_EQ(command("q 40"), "ack");  // the bus still works after the reset
  mega.reset();
  EXPECT_EQ(next_line(1, 200000).substr(0, 5), "boot ");
  EXPECT_EQ(mega.external_resets(), 1);
  EXPECT_EQ(mega.unexpected_resets(), 1);
}

TEST_F(Probe, PcaOutputsSurviveAnMcuReset) {
  bring_up("40");
  ASSERT_EQ(command("w 40 06 00 00 33 01"), "ok");
  const double w = mega.pulse_us(0);
  mega.reset();
  next_line(1, 200000);
  EXPECT_EQ(mega.pulse_us(0), w);  // the board is a separate chip
}

TEST_F(Probe, ResetPinSetsExtrf) {
  mega.reset();
  EXPECT_EQ(next_line(1, 200000), "boot 02");  // MCUSR.EXTRF
}

// Fault injection: a board without power answers nothing and drives
// nothing; powered again it is in its power-on state.
TEST_F(Probe, BoardPowerOffAndOn) {
  bring_up("41");
  ASSERT_EQ(command("w 41 06 00 00 33 01"), "ok");
  ASSERT_GT(mega.pulse_us(16), 0.0);
  mega.set_board_power(1, false);
  EXPECT_EQ(mega.pulse_us(16), 0.0);
  EXPECT_EQ(mega.pulse_log().back().channel, 16);
  EXPECT_EQ(mega.pulse_log().back().width_us, 0.0);
  EXPECT_EQ(command("q 41"), "nack");
  EXPECT_EQ(command("w 41 00 20"), "nack");
  EXPECT_EQ(command("q 40"), "ack");  // the other board is still there
  mega.set_board_power(1, true);
  EXPECT_EQ(command("q 41"), "ack");
  EXPECT_EQ(mega.board(1).reg(0x00), 0x11);  // asleep, ALLCALL
  EXPECT_EQ(mega.board(1).prescale(), 0x1E);
  EXPECT_EQ(mega.pulse_us(16), 0.0);
}

// A detached board (loose bus wire) answers nothing but keeps its outputs.
TEST_F(Probe, BoardDetachedKeepsItsOutputs) {
  bring_up("40");
  ASSERT_EQ(command("w 40 06 00 00 33 01"), "ok");
  const double w = mega.pulse_us(0);
  mega.set_board_attached(0, false);
  EXPECT_EQ(command("q 40"), "nack");
  EXPECT_EQ(command("w 40 06 00 00 90 01"), "nack");
  EXPECT_EQ(mega.pulse_us(0), w);
  EXPECT_EQ(command("q 70"), "ack");  // ALLCALL: board 1 still answers
  mega.set_board_attached(0, true);
  EXPECT_EQ(command("q 40"), "ack");
  EXPECT_EQ(mega.pulse_us(0), w);
  EXPECT_EQ(mega.board(0).reg(0x00), 0x20);
}

// The bus held low: no START completes (the probe gives up polling TWINT),
// nothing reaches the boards; released, transfers work again.
TEST_F(Probe, StuckBusCompletesNoStart) {
  mega.clear_i2c_log();
  mega.set_bus_stuck(true);
  EXPECT_TRUE(mega.bus_stuck());
  EXPECT_EQ(command("q 40", 2000000), "nack");
  EXPECT_TRUE(mega.i2c_log().empty());
  mega.set_bus_stuck(false);
  EXPECT_EQ(command("q 40"), "ack");
  EXPECT_EQ(command("q 41"), "ack");
  ASSERT_FALSE(mega.i2c_log().empty());
  EXPECT_EQ(mega.i2c_log().back().address7, 0x41);
}

TEST_F(Probe, StuckEchoStaysHighUntilTheRangeChanges) {
  mega.set_range_mm(500);
  mega.set_echo_stuck();
  EXPECT_EQ(command("s", 200000), "none");  // rose, never fell
  EXPECT_EQ(command("s", 200000), "none");  // the module ignores triggers meanwhile
  mega.set_range_mm(500);
  unsigned width = 0;
  ASSERT_EQ(std::sscanf(command("s", 200000).c_str(), "echo %u", &width), 1);
  EXPECT_NEAR(double(width), 500 * 2 / 0.343, 10.0);
}

// A hung MCU: nothing answers; a running watchdog resets it.
TEST_F(Probe, HangEndsInAWatchdogReset) {
  mega.hang();
  EXPECT_EQ(command("q 40", 300000), "<timeout>");
  EXPECT_EQ(mega.unexpected_resets(), 0);
  boot(options());
  EXPECT_EQ(command("W"), "ok");
  EXPECT_EQ(command("q 40"), "ack");  // fed by the main loop
  mega.hang();
  EXPECT_EQ(next_line(1, 200000), "boot 08");
  EXPECT_EQ(mega.unexpected_resets(), 1);
}

TEST_F(Probe, LedPin) {
  EXPECT_FALSE(mega.pin_output('B', 7));
  EXPECT_EQ(command("l 1"), "ok");
  EXPECT_TRUE(mega.pin_output('B', 7));
  EXPECT_EQ(command("l 0"), "ok");
  EXPECT_FALSE(mega.pin_output('B', 7));
  EXPECT_EQ(mega.led_toggles(), 2);
}

TEST(VbenchExe, RunsAScriptAndPrintsReplies) {
  const std::string script = temp_path("script.txt");
  {
    std::ofstream s(script);
    s << "# probe\nat 0.1 send q 40\\n\nat 0.2 range 300\nat 0.3 send s\\n\n";
  }
  const std::string cmd = std::string(STRIDER_VBENCH_EXE) + " --elf " + STRIDER_VBENCH_PROBE_ELF +
                          " --script " + script + " --duration 0.6 --log";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  EXPECT_EQ(pclose(p), 0);
  std::remove(script.c_str());
  EXPECT_NE(out.find(" uart1: boot 01"), std::string::npos) << out;
  EXPECT_NE(out.find(" uart0: boot0"), std::string::npos) << out;
  EXPECT_NE(out.find(" uart1: ack"), std::string::npos) << out;
  EXPECT_NE(out.find(" uart1: echo 17"), std::string::npos) << out;  // 300 mm: 1749 us
  EXPECT_NE(out.find("# sonar triggers 1"), std::string::npos) << out;
}

// The sonar by default sees open space (the module's 38 ms time-out pulse);
// --range sets an obstacle, --range none no echo at all.
TEST(VbenchExe, SonarSeesOpenSpaceUnlessToldOtherwise) {
  const std::string script = temp_path("sonar.txt");
  {
    std::ofstream s(script);
    s << "at 0.1 send s\\n\n";
  }
  int status = 0;
  auto run = [&](const std::string& option) {
    const std::string cmd = std::string(STRIDER_VBENCH_EXE) + " --elf " + STRIDER_VBENCH_PROBE_ELF + " --script " +
                            script + " --duration 0.3 " + option + " 2>/dev/null";
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    char buf[256];
    while (p != nullptr && std::fgets(buf, sizeof buf, p)) out += buf;
    status = p == nullptr ? -1 : pclose(p);
    return out;
  };
  EXPECT_NE(run("").find(" uart1: echo 38000 "), std::string::npos);
  EXPECT_EQ(status, 0);
  EXPECT_NE(run("--range 300").find(" uart1: echo 17"), std::string::npos);  // 1749 us
  EXPECT_NE(run("--range none").find(" uart1: none"), std::string::npos);
  EXPECT_EQ(run("--range far").find("uart1"), std::string::npos);
  EXPECT_EQ(WEXITSTATUS(status), 2);  // bad usage
  std::remove(script.c_str());
}

TEST(VbenchExe, EepromCutOptionAndDirective) {
  const std::string script = temp_path("cut.vb");
  {
    std::ofstream s(script);
    s << "at 0.1 send e 0010 5A\\n\nat 0.15 send e 0011 5B\\n\nat 0.3 send E 0010\\n\n"
         "at 0.35 eeprom_cut 0 erased\nat 0.35 send e 0010 00\\n\nat 0.5 send E 0010\\n\n"
         "at 0.6 power_cut\n";
  }
  const std::string cmd = std::string(STRIDER_VBENCH_EXE) + " --elf " + STRIDER_VBENCH_PROBE_ELF +
                          " --script " + script + " --duration 0.8 --log --eeprom-cut 1";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  EXPECT_EQ(pclose(p), 0);
  std::remove(script.c_str());
  // --eeprom-cut 1: the first write made, the second cut.
  EXPECT_NE(out.find("power cut: EEPROM write 1 (address 0x011) not made"), std::string::npos) << out;
  EXPECT_NE(out.find(" uart1: ee 5A"), std::string::npos) << out;
  // The directive: the next write cut, its byte erased.
  EXPECT_NE(out.find("power cut: EEPROM write 1 (address 0x010) not made"), std::string::npos) << out;
  EXPECT_NE(out.find(" uart1: ee FF"), std::string::npos) << out;
  EXPECT_NE(out.find("0.600 power cut\n"), std::string::npos) << out;
  EXPECT_NE(out.find("# eeprom writes 1, power cuts 3"), std::string::npos) << out;
}

TEST(VbenchExe, PseudoTerminalBridgesUart1) {
  const int probe = posix_openpt(O_RDWR | O_NOCTTY);
  if (probe < 0) GTEST_SKIP() << "no pseudo-terminals here";
  close(probe);
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(fds[1], 1);
    close(fds[0]);
    execl(STRIDER_VBENCH_EXE, "vbench", "--elf", STRIDER_VBENCH_PROBE_ELF, "--pty", "--duration", "10",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  // First stdout line: the pseudo-terminal's path.
  std::string path;
  char c;
  pollfd pf{fds[0], POLLIN, 0};
  while (poll(&pf, 1, 5000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n') path.push_back(c);
  ASSERT_EQ(path.substr(0, 5), "/dev/") << path;
  const int tty = open(path.c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(tty, 0);
  termios t;
  tcgetattr(tty, &t);
  cfmakeraw(&t);
  tcsetattr(tty, TCSANOW, &t);
  ASSERT_EQ(write(tty, "q 41\n", 5), 5);
  std::string got;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (got.find("ack\n") == std::string::npos && std::chrono::steady_clock::now() < deadline) {
    pollfd tp{tty, POLLIN, 0};
    if (poll(&tp, 1, 100) > 0) {
      char buf[64];
      const ssize_t n = read(tty, buf, sizeof buf);
      if (n > 0) got.append(buf, size_t(n));
    }
  }
  close(tty);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  close(fds[0]);
  EXPECT_NE(got.find("ack\n"), std::string::npos) << got;
}

}  // namespace
