// The strider CLI's gait commands (docs/gaits.md, ARCHITECTURE.md "Gaits").
#ifndef STRIDER_TOOLS_CLI_CMD_GAIT_H
#define STRIDER_TOOLS_CLI_CMD_GAIT_H

#include <iosfwd>
#include <string>
#include <vector>

namespace strider_cli {

// strider gait --robot R --gait G [--vx MM_S] [--vy MM_S] [--wz DEG_S]
//              [--speed PCT] --duration S --dt S [--scalar float|fixed]
//              [--trajectory NAME]
// CSV on stdout: t, then per leg i contact_i,foot_i_x,foot_i_y,foot_i_z
// (body frame, mm), q_i_0..q_i_K-1 (deg), status_i; then margin_mm. A note
// on stderr when the command was limited to the robot's limits.
int cmd_gait(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// strider gaits --robot R: one JSON line per gait {"name","duty","offsets",
// "min_margin_mm"}: the lowest static stability margin over two cycles of
// walking forward at the model's preferred speed [mm]; negative: the CoM
// leaves the support polygon (a dynamic gait on this robot).
int cmd_gaits(const std::vector<std::string>& args, std::ostream& out);

// The usage lines of both commands, for the CLI's usage text.
std::string gait_usage_text();

}  // namespace strider_cli

#endif  // STRIDER_TOOLS_CLI_CMD_GAIT_H
