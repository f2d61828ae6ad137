// Simulated ATmega2560 run of the benchmark firmware (see avr_sim.h).
#include "avr_sim.h"

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "bench_protocol.h"
#include "sim_avr.h"
#include "sim_elf.h"
#include "sim_io.h"

namespace strider_sim {

const BenchEntry* RunResult::find_entry(const std::string& name) const {
  for (const BenchEntry& e : entries)
    if (e.name == name) return &e;
  return nullptr;
}

const ExactSection* RunResult::find_section(const std::string& name) const {
  for (const ExactSection& s : sections)
    if (s.name == name) return &s;
  return nullptr;
}

namespace {

// State shared by the register hooks during one run.
struct Monitor {
  RunResult* result = nullptr;
  std::string line;
  bool in_call = false;
  const std::string* profile_entry = nullptr;  // entry to profile, or null
  bool profiling = false;                      // inside a timed call of it
  avr_cycle_count_t call_start = 0;
  bool done = false;
  std::string protocol_error;

  void on_start(avr_cycle_count_t now) {
    if (result->entries.empty()) protocol_error = "timed call before any entry name";
    in_call = true;
    call_start = now;
    profiling = profile_entry && !result->entries.empty() && result->entries.back().name == *profile_entry;
  }
  void on_end(avr_cycle_count_t now) {
    if (!in_call || result->entries.empty()) {
      protocol_error = "end marker without start marker";
      return;
    }
    in_call = false;
    profiling = false;
    BenchEntry& e = result->entries.back();
    const uint64_t d = now - call_start;
    ++e.calls;
    e.total_cycles += d;
    if (d < e.min_cycles) e.min_cycles = d;
    if (d > e.max_cycles) e.max_cycles = d;
  }
  void on_char(char c) {
    if (c != '\n') {
      line.push_back(c);
      return;
    }
    parse_line();
    line.clear();
  }
  void parse_line() {
    if (line.empty()) return;
    const char tag = line[0];
    const std::string rest = line.size() > 2 ? line.substr(2) : std::string();
    switch (tag) {
      case 'N': {
        BenchEntry e;
        e.name = rest;
        result->entries.push_back(e);
        break;
      }
      case 'S': {
        ExactSection s;
        s.name = rest;
        result->sections.push_back(s);
        break;
      }
      case 'R': {
        if (result->sections.empty()) {
          protocol_error = "record before any section";
          return;
        }
        std::vector<int32_t> values;
        const char* p = rest.c_str();
        while (*p != '\0') {
          char* end = nullptr;
          const unsigned long v = std::strtoul(p, &end, 16);
          if (end == p) {
            protocol_error = "bad record: " + line;
            return;
          }
          values.push_back(int32_t(uint32_t(v)));
          p = end;
          while (*p == ' ') ++p;
        }
        result->sections.back().records.push_back(values);
        break;
      }
      case 'I': result->info.push_back(rest); break;
      case 'E': done = true; break;
      default: protocol_error = "unknown line: " + line; break;
    }
  }
};

void hook_start(avr_t* avr, avr_io_addr_t addr, uint8_t v, void* param) {
  avr->data[addr] = v;
  static_cast<Monitor*>(param)->on_start(avr->cycle);
}
void hook_end(avr_t* avr, avr_io_addr_t addr, uint8_t v, void* param) {
  avr->data[addr] = v;
  static_cast<Monitor*>(param)->on_end(avr->cycle);
}
void hook_text(avr_t* avr, avr_io_addr_t addr, uint8_t v, void* param) {
  avr->data[addr] = v;
  static_cast<Monitor*>(param)->on_char(char(v));
}

// simavr logs ELF loading on stdout; keep stdout for the caller and pass
// only errors on, to stderr.
void quiet_logger(avr_t*, const int level, const char* format, va_list ap) {
  if (level > LOG_ERROR) return;
  std::vfprintf(stderr, format, ap);
}

struct FirmwareDeleter {
  void operator()(elf_firmware_t* fw) const {
    std::free(fw->flash);
    std::free(fw->eeprom);
    delete fw;
  }
};

struct AvrDeleter {
  void operator()(avr_t* avr) const {
    avr_terminate(avr);
    std::free(avr);
  }
};

}  // namespace

RunResult run_firmware(const RunOptions& options) {
  RunResult result;
  avr_global_logger_set(quiet_logger);
  // elf_firmware_t is large and must start zeroed.
  std::unique_ptr<elf_firmware_t, FirmwareDeleter> fw(new elf_firmware_t());
  std::memset(fw.get(), 0, sizeof(elf_firmware_t));
  if (elf_read_firmware(options.elf_path.c_str(), fw.get()) != 0) {
    result.error = "cannot read ELF " + options.elf_path;
    return result;
  }
  std::unique_ptr<avr_t, AvrDeleter> avr(avr_make_mcu_by_name("atmega2560"));
  if (!avr) {
    result.error = "simavr has no atmega2560 core";
    return result;
  }
  avr_init(avr.get());
  avr->log = LOG_ERROR;
  avr_load_firmware(avr.get(), fw.get());
  avr->frequency = options.f_cpu;  // the ELF carries no .mmcu section

  Monitor monitor;
  monitor.result = &result;
  if (!options.profile_entry.empty()) monitor.profile_entry = &options.profile_entry;
  avr_register_io_write(avr.get(), STRIDER_BENCH_ADDR_START, hook_start, &monitor);
  avr_register_io_write(avr.get(), STRIDER_BENCH_ADDR_END, hook_end, &monitor);
  avr_register_io_write(avr.get(), STRIDER_BENCH_ADDR_TEXT, hook_text, &monitor);
  avr->data[STRIDER_BENCH_ADDR_TEXT] = options.mode;

  const uint16_t ramend = avr->ramend;
  uint16_t lowest_sp = ramend;
  const auto t0 = std::chrono::steady_clock::now();
  int state = cpu_Running;
  // avr_run() executes one instruction: the cycles it advances belong to
  // the PC it started at. Indexed by word address (256 KB of flash).
  std::vector<uint64_t> pc_cycles(monitor.profile_entry ? 0x20000 : 0, 0);
  while (state != cpu_Done && state != cpu_Crashed && avr->cycle < options.max_cycles) {
    const bool sample = monitor.profiling;
    const uint32_t pc = avr->pc;
    const avr_cycle_count_t c0 = avr->cycle;
    state = avr_run(avr.get());
    if (sample) pc_cycles[(pc >> 1) & 0x1FFFF] += avr->cycle - c0;
    const uint16_t sp = uint16_t(avr->data[R_SPL] | (avr->data[R_SPH] << 8));
    if (sp < lowest_sp) lowest_sp = sp;
  }
  const auto t1 = std::chrono::steady_clock::now();
  for (uint32_t w = 0; w < pc_cycles.size(); ++w)
    if (pc_cycles[w]) result.profile.emplace_back(w * 2, pc_cycles[w]);
  if (!monitor.line.empty()) monitor.parse_line();

  result.cycles = avr->cycle;
  result.wall_seconds = std::chrono::duration<double>(t1 - t0).count();
  result.stack_peak_bytes = uint32_t(ramend - lowest_sp);
  if (state == cpu_Crashed) {
    result.error = "firmware crashed at cycle " + std::to_string(avr->cycle);
  } else if (state != cpu_Done) {
    result.error = "cycle limit reached (" + std::to_string(options.max_cycles) + ")";
  } else if (!monitor.protocol_error.empty()) {
    result.error = "protocol: " + monitor.protocol_error;
  } else if (!monitor.done) {
    result.error = "firmware stopped before its end line";
  } else if (monitor.in_call) {
    result.error = "timed call left open";
  } else {
    result.ok = true;
  }
  return result;
}

}  // namespace strider_sim
