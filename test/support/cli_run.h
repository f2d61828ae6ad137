// The built strider CLI run as a script runs it: `strider <args>` through
// popen with a given stdin, its stdout split into lines, its exit status and
// its stderr. The test target defines STRIDER_CLI_PATH.
#ifndef STRIDER_TEST_SUPPORT_CLI_RUN_H
#define STRIDER_TEST_SUPPORT_CLI_RUN_H

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef STRIDER_CLI_PATH
#error "STRIDER_CLI_PATH must name the strider executable"
#endif

namespace strider_test {

struct CliResult {
  int status = -1;                 // exit status, -1 when not exited normally
  std::vector<std::string> lines;  // stdout
  std::string err;                 // stderr
};

// Runs `strider <args>` with `input` on stdin (through a temporary file, as
// is stderr on the way out).
inline CliResult run_cli(const std::string& args, const std::string& input = "") {
  const std::string dir = std::filesystem::temp_directory_path().string();
  std::string in_name = dir + "/strider_cli_in_XXXXXX", err_name = dir + "/strider_cli_err_XXXXXX";
  char* in_path = in_name.data();
  char* err_path = err_name.data();
  const int in_fd = mkstemp(in_path);
  const int err_fd = mkstemp(err_path);
  EXPECT_GE(in_fd, 0);
  EXPECT_GE(err_fd, 0);
  EXPECT_EQ(write(in_fd, input.data(), input.size()), ssize_t(input.size()));
  close(in_fd);
  close(err_fd);
  const std::string cmd = std::string("'") + STRIDER_CLI_PATH + "' " + args + " < " + in_path + " 2> " + err_path;
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  EXPECT_NE(p, nullptr);
  std::string out;
  char buf[8192];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int raw = pclose(p);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::stringstream ss(out);
  std::string line;
  while (std::getline(ss, line)) r.lines.push_back(line);
  {
    std::ifstream f(err_path);
    std::stringstream es;
    es << f.rdbuf();
    r.err = es.str();
  }
  unlink(in_path);
  unlink(err_path);
  return r;
}

}  // namespace strider_test

#endif  // STRIDER_TEST_SUPPORT_CLI_RUN_H
