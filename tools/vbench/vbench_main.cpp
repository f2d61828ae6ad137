// vbench: runs a firmware ELF on the virtual Mega (see docs/vbench.md).
//   vbench --elf F [--eeprom FILE] [--script FILE] [--duration S] [--pty]
//          [--realtime] [--stdin] [--osc HZ] [--boards LIST] [--pulses CSV] [--log]
//          [--eeprom-cut N[:erased]] [--imu[=ADDR]] [--avcc V]
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "pty.h"
#include "script.h"
#include "virtual_mega.h"

using strider_vmega::Pty;
using strider_vmega::RunStatus;
using strider_vmega::ScriptEvent;
using strider_vmega::VirtualMega;

namespace {

volatile sig_atomic_t g_stop = 0;
//! The default sonar range [mm]: beyond the HC-SR04's 4 m, so every ping gets
//! the module's time-out pulse (no obstacle), as in an open room.
constexpr double kOpenSpaceMm = 10000.0;
void on_signal(int) { g_stop = 1; }

void usage() {
  std::fprintf(stderr,
               "usage: vbench --elf FIRMWARE.elf [--eeprom FILE] [--script FILE] [--duration S]\n"
               "              [--pty] [--realtime] [--stdin] [--osc HZ] [--boards LIST] [--pulses CSV] [--log] [--i2c]\n"
               "              [--eeprom-cut N[:erased]] [--range MM|none] [--imu[=ADDR]] [--avcc V]\n"
               "  --eeprom FILE  EEPROM image loaded at start (if present) and saved at the end\n"
               "  --script FILE  timed directives: at T send TEXT | at T range MM|none|stuck | at T reset |\n"
               "                 at T board ADDR off|on|detach|attach | at T bus stuck|free | at T hang |\n"
               "                 at T power_cut | at T eeprom_cut N [erased] |\n"
               "                 at T flood RATE|max SECONDS TEXT (send0, flood0: UART0) |\n"
               "                 at T imu on [ADDR]|off | at T imu accel X Y Z (m/s^2) | at T imu gyro X Y Z (rad/s) |\n"
               "                 at T imu tilt ROLL PITCH (deg) | at T imu temp C | at T adc A0..A7 VOLTS\n"
               "  --duration S   simulated seconds (default 10; with --pty or --stdin: until stopped)\n"
               "  --pty          bridge UART1 to a new pseudo-terminal (path on the first stdout line)\n"
               "  --realtime     pace simulated time to the wall clock (implied by --pty)\n"
               "  --stdin        read directives from stdin as they come (automatic for a pipe; implies --realtime)\n"
               "  --osc HZ       PCA9685 oscillator frequency (default 25e6)\n"
               "  --range MM|none  what the sonar sees at start: an obstacle MM ahead, or no echo at all\n"
               "                 (a missing sensor); default open space (nothing within 4 m)\n"
               "  --boards LIST  PCA9685 boards on the bus: addresses, comma-separated (default 0x40,0x41), or none\n"
               "  --pulses CSV   write every pulse-width change: time_us,channel,width_us\n"
               "  --log          print pulse changes, resets and an I2C summary\n"
               "  --i2c          print every I2C transaction\n"
               "  --eeprom-cut N[:erased]  the power fails as the firmware starts its (N+1)-th EEPROM\n"
               "                 byte write (N kept; that byte as it was, or erased) and comes back\n"
               "  --imu[=ADDR]   an MPU-6050 on the bus at 0x68 (or ADDR: 0x69), lying flat at rest;\n"
               "                 without it nothing answers there\n"
               "  --avcc V       the ADC's reference, AVCC (default 5.0)\n");
}

std::string seconds(uint64_t us) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", double(us) * 1e-6);
  return buf;
}

// Collects a UART's bytes into lines printed as `T uartN: line`.
struct LinePrinter {
  std::string line[2];
  void add(int uart, const strider_vmega::UartByte& b) {
    if (b.value == '\n') {
      std::string& l = line[uart];
      if (!l.empty() && l.back() == '\r') l.pop_back();
      std::printf("%s uart%d: %s\n", seconds(b.time_us).c_str(), uart, l.c_str());
      std::fflush(stdout);
      l.clear();
    } else {
      line[uart].push_back(char(b.value));
    }
  }
  void flush(uint64_t t_us) {
    for (int u = 0; u < 2; ++u)
      if (!line[u].empty()) {
        std::printf("%s uart%d: %s\n", seconds(t_us).c_str(), u, line[u].c_str());
        line[u].clear();
      }
  }
};

// "0x40,0x41", "0x40" or "none" -> 7-bit addresses; false on anything else.
bool parse_boards(const std::string& list, std::vector<uint8_t>* out) {
  out->clear();
  if (list == "none") return true;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const long a = std::strtol(item.c_str(), &end, 0);
    if (item.empty() || *end != 0 || a < 0 || a > 0x7F) return false;
    out->push_back(uint8_t(a));
  }
  return !out->empty();
}

bool read_file(const std::string& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  *text = ss.str();
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  strider_vmega::Options options;
  options.sonar_range_mm = kOpenSpaceMm;  // a robot on a desk in an open room: nothing in range
  std::string script_path, pulses_path;
  double duration_s = -1;
  bool use_pty = false, realtime = false, use_stdin = false, log = false, log_i2c = false;
  bool eeprom_cut = false, eeprom_cut_erased = false;
  uint64_t eeprom_cut_writes = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "vbench: %s needs a value\n", name);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--elf") options.elf_path = value("--elf");
    else if (a == "--eeprom") options.eeprom_path = value("--eeprom");
    else if (a == "--script") script_path = value("--script");
    else if (a == "--duration") duration_s = std::atof(value("--duration").c_str());
    else if (a == "--pty") use_pty = true;
    else if (a == "--realtime") realtime = true;
    else if (a == "--stdin") use_stdin = true;
    else if (a == "--osc") options.pca_osc_hz = std::atof(value("--osc").c_str());
    else if (a == "--range") {
      const std::string r = value("--range");
      char* end = nullptr;
      const double mm = std::strtod(r.c_str(), &end);
      if (r == "none") {
        options.sonar_range_mm = -1;
      } else if (!r.empty() && *end == 0 && mm >= 0) {
        options.sonar_range_mm = mm;
      } else {
        std::fprintf(stderr, "vbench: --range takes millimetres >= 0 or none\n");
        return 2;
      }
    }
    else if (a == "--boards") {
      if (!parse_boards(value("--boards"), &options.pca_addresses)) {
        std::fprintf(stderr, "vbench: --boards takes addresses like 0x40,0x41 or none\n");
        return 2;
      }
    }
    else if (a == "--pulses") pulses_path = value("--pulses");
    else if (a == "--log") log = true;
    else if (a == "--i2c") log_i2c = true;
    else if (a == "--eeprom-cut") {
      std::string why;
      if (!strider_vmega::parse_eeprom_cut(value("--eeprom-cut"), &eeprom_cut_writes, &eeprom_cut_erased, &why)) {
        std::fprintf(stderr, "vbench: --eeprom-cut: %s\n", why.c_str());
        return 2;
      }
      eeprom_cut = true;
    }
    else if (a == "--imu" || a.rfind("--imu=", 0) == 0) {
      options.imu_address = 0x68;
      if (a.size() > 6) {
        char* end = nullptr;
        const long addr = std::strtol(a.c_str() + 6, &end, 0);
        if (*end != 0 || (addr != 0x68 && addr != 0x69)) {
          std::fprintf(stderr, "vbench: --imu takes the address 0x68 or 0x69\n");
          return 2;
        }
        options.imu_address = uint8_t(addr);
      }
    }
    else if (a == "--avcc") {
      options.avcc_volts = std::atof(value("--avcc").c_str());
      if (!(options.avcc_volts >= 1.0 && options.avcc_volts <= 5.5)) {
        std::fprintf(stderr, "vbench: --avcc out of range (1..5.5 V)\n");
        return 2;
      }
    }
    else if (a == "-h" || a == "--help") {
      usage();
      return 0;
    } else {
      std::fprintf(stderr, "vbench: unknown option %s\n", a.c_str());
      usage();
      return 2;
    }
  }
  if (options.elf_path.empty()) {
    usage();
    return 2;
  }
  if (options.pca_osc_hz < 1e6 || options.pca_osc_hz > 50e6) {
    std::fprintf(stderr, "vbench: --osc out of range (1e6..50e6)\n");
    return 2;
  }
  struct stat st;
  if (!use_stdin && fstat(STDIN_FILENO, &st) == 0 && S_ISFIFO(st.st_mode)) use_stdin = true;
  // Directives typed or piped in arrive in wall-clock time: pace to it.
  if (use_pty || use_stdin) realtime = true;
  const bool open_ended = duration_s < 0 && (use_pty || use_stdin);
  if (duration_s < 0) duration_s = 10.0;

  std::vector<ScriptEvent> events;
  if (!script_path.empty()) {
    std::string text, error;
    if (!read_file(script_path, &text)) {
      std::fprintf(stderr, "vbench: cannot read %s\n", script_path.c_str());
      return 2;
    }
    if (!strider_vmega::parse_script(text, &events, &error)) {
      std::fprintf(stderr, "vbench: %s: %s\n", script_path.c_str(), error.c_str());
      return 2;
    }
  }

  VirtualMega mega;
  std::string error;
  if (!mega.load(options, &error)) {
    std::fprintf(stderr, "vbench: %s\n", error.c_str());
    return 1;
  }
  Pty pty;
  if (use_pty) {
    if (!pty.open_pty(&error)) {
      std::fprintf(stderr, "vbench: %s\n", error.c_str());
      return 1;
    }
    std::printf("%s\n", pty.path.c_str());
    std::fflush(stdout);
  }
  if (eeprom_cut)
    mega.cut_power_after_eeprom_writes(eeprom_cut_writes, eeprom_cut_erased ? strider_vmega::TornByte::kErased
                                                                             : strider_vmega::TornByte::kOld);
  LinePrinter printer;
  mega.set_output_callback([&](int uart, const strider_vmega::UartByte& b) {
    printer.add(uart, b);
    if (use_pty && uart == 1) pty.write_bytes(std::string(1, char(b.value)));
  });
  if (use_stdin) fcntl(STDIN_FILENO, F_SETFL, fcntl(STDIN_FILENO, F_GETFL) | O_NONBLOCK);
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  signal(SIGPIPE, SIG_IGN);

  std::ofstream pulses;
  if (!pulses_path.empty()) {
    pulses.open(pulses_path);
    pulses << "time_us,channel,width_us\n";
  }
  size_t pulses_written = 0;
  size_t i2c_printed = 0;
  size_t next_event = 0;
  std::string stdin_buf;
  bool stdin_open = use_stdin;
  int resets_seen = 0;
  size_t cuts_printed = 0;
  const uint64_t end_us = uint64_t(duration_s * 1e6);
  const uint64_t step_us = 1000;
  const auto wall0 = std::chrono::steady_clock::now();
  RunStatus status = RunStatus::kOk;

  while (!g_stop && (open_ended || mega.now_us() < end_us)) {
    // Directives due now (scripted) or arriving (stdin, pty).
    while (next_event < events.size() && events[next_event].time_us <= mega.now_us())
      strider_vmega::apply_event(events[next_event++], mega);
    if (stdin_open) {
      char buf[512];
      ssize_t n;
      while ((n = ::read(STDIN_FILENO, buf, sizeof buf)) > 0) stdin_buf.append(buf, size_t(n));
      if (n == 0) stdin_open = false;
      size_t nl;
      while ((nl = stdin_buf.find('\n')) != std::string::npos) {
        ScriptEvent ev;
        bool has = false;
        if (!strider_vmega::parse_script_line(stdin_buf.substr(0, nl), &ev, &has, &error)) {
          std::fprintf(stderr, "vbench: stdin: %s\n", error.c_str());
        } else if (has && ev.immediate) {
          strider_vmega::apply_event(ev, mega);
        } else if (has) {
          auto it = events.begin() + long(next_event);
          while (it != events.end() && it->time_us <= ev.time_us) ++it;
          events.insert(it, ev);
        }
        stdin_buf.erase(0, nl + 1);
      }
      if (!stdin_open && !use_pty && open_ended) break;  // the pipe closed
    }
    if (use_pty) {
      const std::string in = pty.read_available();
      if (!in.empty()) mega.send(1, in);
    }

    uint64_t next = mega.now_us() + step_us;
    if (!open_ended && next > end_us) next = end_us;
    if (next_event < events.size() && events[next_event].time_us < next)
      next = std::max(events[next_event].time_us, mega.now_us() + 1);
    status = mega.run_until_us(next);
    if (status != RunStatus::kOk) break;

    const int resets = mega.unexpected_resets() + mega.external_resets();
    if (log && resets != resets_seen)
      std::printf("%s reset (%d unexpected, %d external)\n", seconds(mega.now_us()).c_str(),
                  mega.unexpected_resets(), mega.external_resets());
    resets_seen = resets;
    for (; cuts_printed < mega.power_cut_log().size(); ++cuts_printed) {
      const auto& c = mega.power_cut_log()[cuts_printed];
      printer.flush(c.time_us);  // a line cut short by the power
      if (c.eeprom_write >= 0)
        std::printf("%s power cut: EEPROM write %lld (address 0x%03x) not made\n", seconds(c.time_us).c_str(),
                    static_cast<long long>(c.eeprom_write), c.address);
      else
        std::printf("%s power cut\n", seconds(c.time_us).c_str());
      std::fflush(stdout);
    }
    const auto& plog = mega.pulse_log();
    for (; pulses_written < plog.size(); ++pulses_written) {
      const auto& c = plog[pulses_written];
      if (pulses.is_open()) pulses << c.time_us << ',' << c.channel << ',' << c.width_us << '\n';
      if (log) std::printf("%s pwm ch%d: %.1f\n", seconds(c.time_us).c_str(), c.channel, c.width_us);
    }
    if (plog.size() > 100000 && pulses_written == plog.size()) {
      mega.clear_pulse_log();
      pulses_written = 0;
    }
    const auto& ilog = mega.i2c_log();
    for (; log_i2c && i2c_printed < ilog.size(); ++i2c_printed) {
      const auto& t = ilog[i2c_printed];
      std::printf("%s i2c 0x%02x %s %d bytes %s\n", seconds(t.start_us).c_str(), t.address7, t.read ? "read" : "write",
                  t.bytes, t.acked ? "ack" : "nack");
    }
    if (ilog.size() > 100000 && !log) {
      mega.clear_i2c_log();
      i2c_printed = 0;
    }
    if (realtime) {
      const auto due = wall0 + std::chrono::microseconds(mega.now_us());
      if (due > std::chrono::steady_clock::now()) std::this_thread::sleep_until(due);
    }
  }
  printer.flush(mega.now_us());

  if (log) {
    int max_bytes = 0;
    double max_time = 0;
    const auto frames = mega.i2c_frames();
    for (const auto& f : frames) {
      if (f.bytes > max_bytes) max_bytes = f.bytes;
      if (f.bus_time_us() > max_time) max_time = f.bus_time_us();
    }
    std::printf("# i2c frames %zu, max %d bytes/frame, max %.0f us/frame at 400 kHz\n", frames.size(), max_bytes,
                max_time);
    std::printf("# sonar triggers %d, resets %d unexpected %d external, led toggles %d, stack peak %u bytes\n",
                mega.sonar_triggers(), mega.unexpected_resets(), mega.external_resets(), mega.led_toggles(),
                mega.stack_peak_bytes());
    std::printf("# eeprom writes %llu, power cuts %zu\n", static_cast<unsigned long long>(mega.eeprom_writes()),
                mega.power_cut_log().size());
    for (int u = 0; u < 2; ++u) {
      const strider_vmega::FloodStats f = mega.flood_stats(u);
      if (f.units != 0)
        std::printf("# flood uart%d: %llu units, %llu bytes, %s-%s s\n", u, (unsigned long long)f.units,
                    (unsigned long long)f.bytes, seconds(f.start_us).c_str(), seconds(f.last_us).c_str());
    }
    if (mega.stack_overflow_us() != 0)
      std::printf("# STACK OVERFLOW: the stack reached .bss (%u bytes static) at %s s\n", mega.static_ram_bytes(),
                  seconds(mega.stack_overflow_us()).c_str());
  }
  if (!options.eeprom_path.empty() && !mega.save_eeprom(options.eeprom_path, &error))
    std::fprintf(stderr, "vbench: %s\n", error.c_str());
  if (status != RunStatus::kOk) {
    std::fprintf(stderr, "vbench: firmware %s at %s s\n", strider_vmega::to_string(status),
                 seconds(mega.now_us()).c_str());
    return status == RunStatus::kStopped ? 0 : 1;
  }
  return 0;
}
