// The strider command lines that docs/*.md and README.md show with their
// output (`$ strider ...` in a code block, then what it prints) give that
// output: run through the built CLI, every line as the doc has it (up to a
// line `...`). Understood around the command: `printf '...' |` before it
// (its stdin), `| cut -c1-N` after it, `; echo "exit $?"` (the exit status
// is the line `exit N`), and lines `strider: ...` (stderr, in order). So the
// examples cannot drift from what the tool prints.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"

namespace {

struct CliExample {
  std::string where, args, input;
  size_t cut = 0;  // keep only the first `cut` characters of each line (0: all)
  std::vector<std::string> out, err;
  int exit_status = 0;
  bool partial = false;  // ended with `...`
};

// printf's argument with its escapes (\n \t \\) read.
std::string printf_text(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      const char c = s[++i];
      out += c == 'n' ? '\n' : c == 't' ? '\t' : c;
    } else {
      out += s[i];
    }
  }
  return out;
}

// `$ ...` -> the example's command, or false if it is not one this test runs.
bool parse_command(const std::string& line, CliExample* e) {
  std::string cmd = line.substr(2);
  if (cmd.rfind("printf '", 0) == 0) {
    const size_t close = cmd.find("' | ", 8);
    if (close == std::string::npos) return false;
    e->input = printf_text(cmd.substr(8, close - 8));
    cmd = cmd.substr(close + 4);
  }
  if (cmd.rfind("strider ", 0) != 0) return false;
  cmd = cmd.substr(8);
  const size_t echo = cmd.find("; echo \"exit $?\"");
  if (echo != std::string::npos) cmd.erase(echo);
  const size_t cut = cmd.find(" | cut -c1-");
  if (cut != std::string::npos) {
    e->cut = size_t(std::stoul(cmd.substr(cut + 11)));
    cmd.erase(cut);
  }
  if (cmd.find_first_of("|;>&`$") != std::string::npos) return false;
  e->args = cmd;
  return true;
}

std::vector<CliExample> examples_in(const std::string& path, const std::string& file) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::vector<CliExample> out;
  bool block = false, taking = false;
  int line_no = 0;
  for (std::string l; std::getline(in, l);) {
    ++line_no;
    if (l.rfind("```", 0) == 0) {
      block = !block;
      taking = false;
      continue;
    }
    if (!block) continue;
    if (l.rfind("$ ", 0) == 0) {
      CliExample e;
      e.where = file + ":" + std::to_string(line_no);
      taking = parse_command(l, &e);
      if (taking) out.push_back(e);
      continue;
    }
    if (!taking) continue;
    CliExample& e = out.back();
    if (l.rfind("exit ", 0) == 0) e.exit_status = std::stoi(l.substr(5));
    else if (e.partial) continue;
    else if (l == "...") e.partial = true;
    else if (l.rfind("strider: ", 0) == 0) e.err.push_back(l);
    else if (!e.err.empty() && (l.empty() || l.rfind("usage: ", 0) == 0)) e.partial = true;  // the usage text
    else e.out.push_back(l);
  }
  return out;
}

TEST(CliDocExamples, PrintWhatTheDocsShow) {
  std::vector<std::string> files{"README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(std::string(STRIDER_SOURCE_DIR) + "/docs"))
    if (entry.path().extension() == ".md") files.push_back("docs/" + entry.path().filename().string());
  std::sort(files.begin(), files.end());
  int run = 0;
  for (const std::string& file : files) {
    for (const CliExample& e : examples_in(std::string(STRIDER_SOURCE_DIR) + "/" + file, file)) {
      SCOPED_TRACE(e.where + ": strider " + e.args);
      const strider_test::CliResult r = strider_test::run_cli(e.args, e.input);
      ++run;
      EXPECT_EQ(r.status, e.exit_status) << r.err;
      std::vector<std::string> got = r.lines;
      if (e.cut != 0)
        for (std::string& l : got) l = l.substr(0, e.cut);
      if (e.partial && got.size() > e.out.size()) got.resize(e.out.size());
      EXPECT_EQ(got, e.out);
      for (const std::string& want : e.err) EXPECT_NE(r.err.find(want), std::string::npos) << r.err;
    }
  }
  std::printf("%d documented strider command lines run\n", run);
  EXPECT_GE(run, 15);
}

// The reading of an example block, on a small doc of known content.
TEST(CliDocExamples, ReadsCommandsOutputAndItsForms) {
  const std::string path = testing::TempDir() + "cli_doc_probe.md";
  {
    std::ofstream out(path);
    out << "```\n$ strider robots\n{\"a\":1}\n...\n"
           "$ printf '1 2 3\\n' | strider ik --stdin | cut -c1-10\nx\n"
           "$ strider fk; echo \"exit $?\"\nstrider: bad\n\nusage: more\n...\nexit 2\n"
           "$ strider gait > out.csv\n```\n";
  }
  const auto ex = examples_in(path, "probe");
  ASSERT_EQ(ex.size(), 3u);  // not the one redirected to a file
  EXPECT_EQ(ex[0].args, "robots");
  EXPECT_EQ(ex[0].out, std::vector<std::string>{"{\"a\":1}"});
  EXPECT_TRUE(ex[0].partial);
  EXPECT_EQ(ex[1].input, "1 2 3\n");
  EXPECT_EQ(ex[1].cut, 10u);
  EXPECT_EQ(ex[1].args, "ik --stdin");
  EXPECT_EQ(ex[2].err, std::vector<std::string>{"strider: bad"});
  EXPECT_TRUE(ex[2].out.empty());
  EXPECT_EQ(ex[2].exit_status, 2);
}

}  // namespace
