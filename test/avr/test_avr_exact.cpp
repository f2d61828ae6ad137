// Bit-exactness of Fixed on the ATmega2560: the benchmark firmware computes
// the cases of tools/bench/exact_cases.h on the simulated Mega (avr-gcc 5.4,
// -Os, 16-bit int, 32-bit double) and the host computes the same cases from
// the same source; every raw int32 result must be identical.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "avr_sim.h"
#include "bench_protocol.h"
#include "exact_cases.h"

namespace {

using strider_sim::ExactSection;
using strider_sim::RunResult;

// Collects the host results in the same shape the firmware reports them.
struct HostSink {
  std::vector<ExactSection> sections;
  void section(const char* name) {
    ExactSection s;
    s.name = name;
    sections.push_back(s);
  }
  void record(const int32_t* v, uint8_t n) { sections.back().records.emplace_back(v, v + n); }
};

const std::vector<ExactSection>& host_sections() {
  static const std::vector<ExactSection> sections = [] {
    HostSink sink;
    strider_bench::run_exact_cases(sink);
    return sink.sections;
  }();
  return sections;
}

// One simulated run per test process, shared by all tests.
const RunResult& avr_run() {
  static const RunResult result = [] {
    strider_sim::RunOptions opt;
    opt.elf_path = STRIDER_BENCH_ELF;
    opt.mode = STRIDER_BENCH_MODE_NO_BENCH;
    opt.max_cycles = 2000000000ull;  // ~25 s: far above a normal run
    return strider_sim::run_firmware(opt);
  }();
  return result;
}

std::vector<std::string> host_section_names() {
  std::vector<std::string> names;
  for (const ExactSection& s : host_sections()) names.push_back(s.name);
  return names;
}

std::string format_record(const std::vector<int32_t>& r) {
  std::string out;
  char buf[32];
  for (int32_t v : r) {
    std::snprintf(buf, sizeof buf, "%s%ld", out.empty() ? "" : " ", static_cast<long>(v));
    out += buf;
  }
  return out;
}

TEST(AvrExact, FirmwareRunsToCompletion) {
  const RunResult& r = avr_run();
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.entries.empty()) << "bench entries ran in exact-only mode";
}

TEST(AvrExact, SameSectionsInSameOrder) {
  const RunResult& r = avr_run();
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.sections.size(), host_sections().size());
  for (size_t i = 0; i < r.sections.size(); ++i) {
    EXPECT_EQ(r.sections[i].name, host_sections()[i].name);
    EXPECT_EQ(r.sections[i].records.size(), host_sections()[i].records.size()) << r.sections[i].name;
  }
}

// The list the project requires: arithmetic, every elementary function and
// at least one leg solver.
TEST(AvrExact, CoversTheRequiredOperations) {
  const char* required[] = {"fixed_mul", "fixed_div", "fixed_sqrt", "fixed_sin", "fixed_cos",
                            "fixed_atan2", "fixed_asin", "fixed_acos", "sprawl_ik", "sprawl_fk"};
  for (const char* name : required) {
    bool found = false;
    for (const ExactSection& s : host_sections()) found = found || (s.name == name && !s.records.empty());
    EXPECT_TRUE(found) << name;
  }
}

class AvrExactSection : public ::testing::TestWithParam<std::string> {};

TEST_P(AvrExactSection, BitIdenticalToHost) {
  const RunResult& r = avr_run();
  ASSERT_TRUE(r.ok) << r.error;
  const ExactSection* avr = r.find_section(GetParam());
  ASSERT_NE(avr, nullptr) << "firmware did not report " << GetParam();
  const ExactSection* host = nullptr;
  for (const ExactSection& s : host_sections())
    if (s.name == GetParam()) host = &s;
  ASSERT_NE(host, nullptr);
  ASSERT_EQ(avr->records.size(), host->records.size());
  ASSERT_FALSE(host->records.empty());
  size_t mismatches = 0;
  for (size_t i = 0; i < host->records.size(); ++i) {
    if (avr->records[i] == host->records[i]) continue;
    if (++mismatches <= 8)
      ADD_FAILURE() << GetParam() << " case " << i << "\n  host: " << format_record(host->records[i])
                    << "\n  avr:  " << format_record(avr->records[i]);
  }
  EXPECT_EQ(mismatches, 0u) << "of " << host->records.size() << " cases differ";
}

INSTANTIATE_TEST_SUITE_P(Sections, AvrExactSection, ::testing::ValuesIn(host_section_names()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
