// Command dispatch and the usage text of the strider CLI.
#include <ostream>

#include "args.h"
#include "cmd_gait.h"
#include "commands.h"

namespace strider_cli {

std::string usage_text() {
  return "usage: strider <command> [options]\n"
         "\n"
         "commands:\n"
         "  robots\n"
         "      list the robot models: {\"name\",\"legs\",\"dof\"} per line\n"
         "  legs --robot R\n"
         "      every leg of a model: mount, joint limits, servos, standing pose\n"
         "  fk --robot R --leg I --joints a,b[,c] [--frame leg|body]\n"
         "      foot position [mm] for joint angles [deg]\n"
         "  ik --robot R --leg I (--foot x,y,z | --stdin) [--frame leg|body] [--scalar float|fixed]\n"
         "      joint angles [deg] for a foot position [mm]; --stdin answers one 'x y z' per line\n" +
         gait_usage_text() +
         "  help\n"
         "      this text\n"
         "\n"
         "Legs are numbered from 0, counter-clockwise seen from above, starting front left.\n"
         "Joint angles are in the leg type's seed convention (docs/kinematics.md), not servo\n"
         "angles. --frame defaults to leg, --scalar to float.\n"
         "Output: one JSON object per line on stdout (gait: CSV). Exit status 0, also for an unreachable\n"
         "point; 2 for bad usage, with a message on stderr.\n";
}

int run(const Args& args, std::istream& in, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty()) throw UsageError("no command given");
    const std::string& command = args[0];
    const Args rest(args.begin() + 1, args.end());
    if (command == "help" || command == "--help" || command == "-h") {
      out << usage_text();
      return 0;
    }
    for (const std::string& a : rest) {
      if (a == "--help" || a == "-h") {
        out << usage_text();
        return 0;
      }
    }
    if (command == "robots") return cmd_robots(rest, out);
    if (command == "legs") return cmd_legs(rest, out);
    if (command == "fk") return cmd_fk(rest, out);
    if (command == "ik") return cmd_ik(rest, in, out);
    if (command == "gait") return cmd_gait(rest, out, err);
    if (command == "gaits") return cmd_gaits(rest, out);
    throw UsageError("unknown command '" + command + "'");
  } catch (const UsageError& e) {
    out.flush();
    err << "strider: " << e.what() << "\n\n" << usage_text();
    return 2;
  }
}

}  // namespace strider_cli
