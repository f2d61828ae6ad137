#include "commands.h"

#include <cmath>
#include <istream>
#include <ostream>

#include "args.h"
#include "json.h"
#include "kinematics/any_leg.h"
#include "robots/all_robots.h"

namespace strider_cli {

namespace {

using strider::AnyLeg;
using strider::Fixed;
using strider::IkStatus;
using strider::RobotModel;
using strider::Vec3;

// A coordinate farther than this from the frame origin is beyond every
// model's reach (and beyond Fixed's range): answered "unreachable" without
// calling a solver [mm].
constexpr double kFarLimitMm = 10000.0;

// Joint angles beyond this are rejected as a typo rather than wrapped [deg].
constexpr double kMaxJointDeg = 36000.0;

const RobotModel& robot_option(const Options& o) {
  const std::string& name = o.required("--robot");
  const RobotModel* m = strider::find_robot(name.c_str());
  if (m == nullptr) {
    std::string known;
    for (uint8_t i = 0; i < strider::kRobotCount; ++i) known += std::string(i ? ", " : "") + strider::kAllRobots[i]->name;
    throw UsageError("unknown robot '" + name + "' (known: " + known + ")");
  }
  return *m;
}

uint8_t leg_option(const Options& o, const RobotModel& m) {
  const std::string& text = o.required("--leg");
  const std::optional<unsigned> i = parse_index(text, m.leg_count);
  if (!i) {
    throw UsageError("--leg '" + text + "': " + m.name + " has legs 0 to " + std::to_string(m.leg_count - 1));
  }
  return uint8_t(*i);
}

bool body_frame_option(const Options& o) {
  const std::string f = o.get_or("--frame", "leg");
  if (f != "leg" && f != "body") throw UsageError("--frame '" + f + "': expected leg or body");
  return f == "body";
}

template <typename S>
AnyLeg<S> build_leg(const RobotModel& m, uint8_t index) {
  AnyLeg<S> leg;
  if (!AnyLeg<S>::from_model(m, index, leg)) throw UsageError("leg index out of range");
  return leg;
}

template <typename S>
std::vector<double> to_mm(const Vec3<S>& v) {
  return {strider::to_double(v.x), strider::to_double(v.y), strider::to_double(v.z)};
}

template <typename S>
std::vector<double> to_deg(const typename AnyLeg<S>::Joints& q, uint8_t dof) {
  std::vector<double> d;
  for (uint8_t j = 0; j < dof; ++j) d.push_back(strider::to_double(q[j]) * strider::kRadToDeg);
  return d;
}

std::string unreachable_line() {
  return JsonObject().add("status", "unreachable").add_null("joints_deg").add_null("foot_mm").str();
}

// Solves one target [mm] and formats the answer line (contract in docs/cli.md).
template <typename S>
std::string solve_line(const AnyLeg<S>& leg, const double p[3], bool body_frame) {
  for (int i = 0; i < 3; ++i)
    if (!(std::fabs(p[i]) <= kFarLimitMm)) return unreachable_line();
  const Vec3<S> target(strider::scalar<S>(p[0]), strider::scalar<S>(p[1]), strider::scalar<S>(p[2]));
  typename AnyLeg<S>::Joints q{};
  Vec3<S> reached;
  const IkStatus s = body_frame ? leg.ik_body(target, q, reached) : leg.ik(target, q, reached);
  if (s == IkStatus::kUnreachable) return unreachable_line();
  return JsonObject()
      .add("status", strider::to_string(s))
      .add("joints_deg", to_deg<S>(q, leg.dof()))
      .add("foot_mm", to_mm(reached))
      .str();
}

template <typename S>
int run_ik(const RobotModel& m, uint8_t index, const Options& o, bool body_frame, std::istream& in,
           std::ostream& out) {
  const AnyLeg<S> leg = build_leg<S>(m, index);
  if (!o.has("--stdin")) {
    const std::vector<double> p = parse_number_list(o.required("--foot"), "--foot");
    if (p.size() != 3) throw UsageError("--foot needs three numbers x,y,z [mm], got " + std::to_string(p.size()));
    out << solve_line(leg, p.data(), body_frame) << "\n";
    return 0;
  }
  std::string line;
  unsigned number = 0;
  while (std::getline(in, line)) {
    ++number;
    double p[3];
    const std::string error = parse_point_line(line, p);
    if (!error.empty()) {
      out << JsonObject().add("status", "error").add("line", number).add("error", error).str() << "\n";
    } else {
      out << solve_line(leg, p, body_frame) << "\n";
    }
    out.flush();  // answer each line as it comes (interactive pipes)
  }
  return 0;
}

}  // namespace

int cmd_robots(const Args& args, std::ostream& out) {
  Options::parse(args, OptionSpec{});
  for (uint8_t i = 0; i < strider::kRobotCount; ++i) {
    const RobotModel& m = *strider::kAllRobots[i];
    out << JsonObject().add("name", m.name).add("legs", unsigned(m.leg_count)).add("dof", unsigned(m.dof())).str()
        << "\n";
  }
  return 0;
}

int cmd_legs(const Args& args, std::ostream& out) {
  const Options o = Options::parse(args, OptionSpec{{"--robot"}, {}});
  const RobotModel& m = robot_option(o);
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    const strider::LegModel& lm = m.legs[i];
    std::string limits = "[", servos = "[";
    for (uint8_t j = 0; j < m.dof(); ++j) {
      limits += std::string(j ? "," : "") + json_array({lm.joint[j].min_deg, lm.joint[j].max_deg});
      servos += std::string(j ? "," : "") + json_string(strider::servo_spec(m.servo[j]).name);
    }
    const AnyLeg<float> leg = build_leg<float>(m, i);
    AnyLeg<float>::Joints q{};
    Vec3<float> reached;
    const IkStatus s = leg.ik_body(lm.stand_mm, q, reached);
    JsonObject line;
    line.add("leg", unsigned(i))
        .add("name", lm.name)
        .add("side", strider::to_string(lm.side))
        .add("kind", strider::to_string(m.kind))
        .add("mount_mm", to_mm(lm.mount_mm))
        .add("mount_yaw_deg", double(lm.mount_yaw_deg))
        .add_raw("limits_deg", limits + "]")
        .add_raw("servos", servos + "]")
        .add("stand_mm", to_mm(lm.stand_mm))
        .add("stand_status", strider::to_string(s));
    if (s == IkStatus::kUnreachable) {
      line.add_null("stand_joints_deg");
    } else {
      line.add("stand_joints_deg", to_deg<float>(q, m.dof()));
    }
    out << line.str() << "\n";
  }
  return 0;
}

int cmd_fk(const Args& args, std::ostream& out) {
  const Options o = Options::parse(args, OptionSpec{{"--robot", "--leg", "--joints", "--frame"}, {}});
  const RobotModel& m = robot_option(o);
  const uint8_t index = leg_option(o, m);
  const bool body_frame = body_frame_option(o);
  const std::vector<double> deg = parse_number_list(o.required("--joints"), "--joints");
  if (deg.size() != m.dof()) {
    throw UsageError("--joints: " + std::string(m.name) + " legs have " + std::to_string(m.dof()) +
                     " joints, got " + std::to_string(deg.size()) + " angles");
  }
  for (double d : deg)
    if (std::fabs(d) > kMaxJointDeg) throw UsageError("--joints: angles must lie within +-36000 deg");
  const AnyLeg<float> leg = build_leg<float>(m, index);
  AnyLeg<float>::Joints q{};
  for (size_t j = 0; j < deg.size(); ++j) q[uint8_t(j)] = float(deg[j] * strider::kDegToRad);
  const Vec3<float> foot = body_frame ? leg.fk_body(q) : leg.fk(q);
  out << JsonObject()
             .add("status", "ok")
             .add("foot_mm", to_mm(foot))
             .add("within_limits", leg.within_limits(q))
             .str()
      << "\n";
  return 0;
}

int cmd_ik(const Args& args, std::istream& in, std::ostream& out) {
  const Options o =
      Options::parse(args, OptionSpec{{"--robot", "--leg", "--foot", "--frame", "--scalar"}, {"--stdin"}});
  const RobotModel& m = robot_option(o);
  const uint8_t index = leg_option(o, m);
  const bool body_frame = body_frame_option(o);
  if (o.has("--stdin") == o.has("--foot")) throw UsageError("ik needs exactly one of --foot x,y,z and --stdin");
  const std::string scalar = o.get_or("--scalar", "float");
  if (scalar == "float") return run_ik<float>(m, index, o, body_frame, in, out);
  if (scalar == "fixed") return run_ik<Fixed>(m, index, o, body_frame, in, out);
  throw UsageError("--scalar '" + scalar + "': expected float or fixed");
}

}  // namespace strider_cli
