// The strider CLI's commands. Each takes the arguments after its name,
// writes JSON lines to `out` and returns the exit status; bad usage throws
// UsageError (args.h).
#ifndef STRIDER_TOOLS_CLI_COMMANDS_H
#define STRIDER_TOOLS_CLI_COMMANDS_H

#include <iosfwd>
#include <string>
#include <vector>

namespace strider_cli {

using Args = std::vector<std::string>;

// strider robots: one line per model {"name","legs","dof"}.
int cmd_robots(const Args& args, std::ostream& out);

// strider legs --robot R: one line per leg (mount, limits, servos, stance).
int cmd_legs(const Args& args, std::ostream& out);

// strider fk --robot R --leg I --joints a,b[,c] [--frame leg|body].
int cmd_fk(const Args& args, std::ostream& out);

// strider ik --robot R --leg I (--foot x,y,z | --stdin) [--frame leg|body]
//            [--scalar float|fixed].
int cmd_ik(const Args& args, std::istream& in, std::ostream& out);

// The usage text (stdout for `help`, stderr after a usage error).
std::string usage_text();

// Runs the CLI on argv[1..]: the whole program but the process plumbing.
int run(const Args& args, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace strider_cli

#endif  // STRIDER_TOOLS_CLI_COMMANDS_H
