// Runs the benchmark firmware on a simulated ATmega2560 (libsimavr) and
// collects what it reports through GPIOR0/1/2 (see bench_protocol.h): cycles
// per timed call, raw bit-exact records, and the stack high-water mark.
// Shared by the avr_cycles runner and the host bit-exact test.
#ifndef STRIDER_TOOLS_BENCH_AVR_SIM_H
#define STRIDER_TOOLS_BENCH_AVR_SIM_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace strider_sim {

struct BenchEntry {
  std::string name;
  uint64_t calls = 0;
  uint64_t total_cycles = 0;  // raw, marker overhead included
  uint64_t min_cycles = UINT64_MAX;
  uint64_t max_cycles = 0;
  double average() const { return calls ? double(total_cycles) / double(calls) : 0.0; }
};

struct ExactSection {
  std::string name;
  std::vector<std::vector<int32_t>> records;
};

struct RunOptions {
  std::string elf_path;
  uint8_t mode = 0;                          // STRIDER_BENCH_MODE_* bits
  uint32_t f_cpu = 16000000;                 // [Hz]
  uint64_t max_cycles = 4000000000ull;       // about 50 s of simulation
  std::string profile_entry;                 // when set: cycles per PC inside its timed calls
};

struct RunResult {
  bool ok = false;          // loaded, ran to "E" and stopped by cli; sleep
  std::string error;        // why not, when !ok
  uint64_t cycles = 0;      // simulated cycles of the whole run
  double wall_seconds = 0;  // host time the simulation took [s]
  uint32_t stack_peak_bytes = 0;  // RAMEND - lowest stack pointer seen
  std::vector<std::string> info;  // "I" lines
  std::vector<BenchEntry> entries;
  //! With RunOptions::profile_entry: (byte address, cycles) of every
  //! instruction executed inside that entry's timed calls, by address.
  std::vector<std::pair<uint32_t, uint64_t>> profile;
  std::vector<ExactSection> sections;

  const BenchEntry* find_entry(const std::string& name) const;
  const ExactSection* find_section(const std::string& name) const;
};

//! Loads the ELF into a fresh simulated ATmega2560 and runs it to the end.
RunResult run_firmware(const RunOptions& options);

}  // namespace strider_sim

#endif  // STRIDER_TOOLS_BENCH_AVR_SIM_H
