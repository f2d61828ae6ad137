// strider: kinematics of the built-in robots on the command line (docs/cli.md).
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  const std::vector<std::string> args(argv + 1, argv + argc);
  const int status = strider_cli::run(args, std::cin, std::cout, std::cerr);
  std::cout.flush();
  return status;
}
