// strider gait / strider gaits: walk a robot model through a gait and write
// the CSV of ARCHITECTURE.md's "Gaits" contract; list the gaits of a model.
#include "cmd_gait.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "args.h"
#include "gait/gait_library.h"
#include "gait/walker.h"
#include "json.h"

namespace strider_cli {

namespace {

using strider::Fixed;
using strider::GaitParams;
using strider::GaitTable;
using strider::RobotModel;
using strider::SwingShape;

// Bounds that catch typos before they become a run of hours.
constexpr double kMaxDurationS = 3600.0;
constexpr double kMaxRows = 2e6;
constexpr double kMaxSpeedMmS = 5000.0;
constexpr double kMaxYawDegS = 3600.0;

const RobotModel& robot_of(const Options& o) {
  const std::string& name = o.required("--robot");
  const RobotModel* m = strider::find_robot(name.c_str());
  if (m == nullptr) {
    std::string known;
    for (uint8_t i = 0; i < strider::kRobotCount; ++i)
      known += std::string(i ? ", " : "") + strider::kAllRobots[i]->name;
    throw UsageError("unknown robot '" + name + "' (known: " + known + ")");
  }
  return *m;
}

const GaitTable& gait_of(const Options& o, const RobotModel& m) {
  const std::string& name = o.required("--gait");
  const GaitTable* g = strider::find_gait(m, name.c_str());
  if (g == nullptr) {
    const strider::GaitList list = strider::gaits_for(m);
    std::string known;
    for (uint8_t i = 0; i < list.count; ++i) known += std::string(i ? ", " : "") + list.items[i]->name;
    throw UsageError("--gait '" + name + "': " + m.name + " walks " + known);
  }
  return *g;
}

double number_of(const Options& o, const std::string& name, double fallback, double lo, double hi,
                 bool required = false) {
  if (!o.has(name)) {
    if (required) o.required(name);  // throws
    return fallback;
  }
  const std::string& text = o.required(name);
  const std::optional<double> v = parse_number(text);
  if (!v) throw UsageError(name + " '" + text + "': not a number");
  if (!(*v >= lo && *v <= hi)) {
    char range[96];
    std::snprintf(range, sizeof range, " is outside [%g, %g]", lo, hi);
    throw UsageError(name + " " + text + range);
  }
  return *v;
}

// A number for the CSV: fixed decimals, never "-0.000".
std::string csv_number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s(buf);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string header(const RobotModel& m) {
  std::string h = "t";
  for (uint8_t i = 0; i < m.leg_count; ++i) {
    const std::string n = std::to_string(i);
    h += ",contact_" + n + ",foot_" + n + "_x,foot_" + n + "_y,foot_" + n + "_z";
    for (uint8_t j = 0; j < m.dof(); ++j) h += ",q_" + n + "_" + std::to_string(j);
    h += ",status_" + n;
  }
  return h + ",margin_mm";
}

struct Run {
  const RobotModel* model;
  const GaitTable* gait;
  SwingShape shape;
  double vx, vy, wz_deg, speed, duration, dt;
};

template <typename S>
int walk(const Run& r, std::ostream& out, std::ostream& err) {
  using strider::scalar;
  using strider::to_double;
  static strider::Walker<S> w;  // a few kB: keep it off the stack
  const GaitParams& params = *strider::gait_params_for(*r.model);
  if (!w.configure(*r.model, *r.gait, params, r.shape)) throw UsageError("gait does not fit the robot");
  strider::GaitEngine<S>& e = w.engine();
  const bool still = r.vx == 0.0 && r.vy == 0.0 && r.wz_deg == 0.0;
  e.set_step_in_place(still);  // no velocity: show the gait stepping in place
  e.set_command(scalar<S>(r.vx), scalar<S>(r.vy), scalar<S>(r.wz_deg * strider::kDegToRad), scalar<S>(r.speed));
  const strider::VelocityPlan<S>& plan = e.target_plan();
  if (plan.limited) {
    char note[200];
    std::snprintf(note, sizeof note,
                  "strider: note: command limited to vx=%.1f mm/s vy=%.1f mm/s wz=%.1f deg/s "
                  "(workspace and servo speed of %s)\n",
                  to_double(plan.vx_mm_s), to_double(plan.vy_mm_s), to_double(plan.wz_rad_s) * strider::kRadToDeg,
                  r.model->name);
    err << note;
  }
  out << header(*r.model) << "\n";
  const S dt = scalar<S>(r.dt);
  const long rows = long(std::floor(r.duration / r.dt + 1e-9));
  const uint8_t dof = r.model->dof();
  std::string line;
  for (long k = 0; k <= rows; ++k) {
    if (k > 0) w.tick(dt);
    line = csv_number(double(k) * r.dt, 6);
    for (uint8_t i = 0; i < r.model->leg_count; ++i) {
      const strider::LegResult<S>& leg = w.leg(i);
      line += leg.contact ? ",1" : ",0";
      line += "," + csv_number(to_double(leg.foot_mm.x), 3) + "," + csv_number(to_double(leg.foot_mm.y), 3) + "," +
              csv_number(to_double(leg.foot_mm.z), 3);
      for (uint8_t j = 0; j < dof; ++j) line += "," + csv_number(to_double(leg.q[j]) * strider::kRadToDeg, 3);
      line += ",";
      line += strider::to_string(leg.status);
    }
    line += "," + csv_number(to_double(w.margin_mm()), 3);
    out << line << "\n";
  }
  return 0;
}

// The smallest static stability margin [mm] of `g` on `m`: the CoM's ground
// projection to the edge of the feet's support region (stability.h; negative:
// outside), over two cycles of walking straight ahead at the model's
// preferred speed (step length / cycle time, gait_params.h), after three
// cycles to settle. A gait with a negative margin cannot stand still on the
// feet it keeps down: only its motion keeps it up (a pace on legs that cannot
// move the body sideways; docs/gaits.md).
double steady_min_margin_mm(const RobotModel& m, const GaitTable& g) {
  static strider::Walker<float> w;  // a few kB: keep it off the stack
  const GaitParams& params = *strider::gait_params_for(m);
  if (!w.configure(m, g, params, params.shape)) return 0.0;
  strider::GaitEngine<float>& e = w.engine();
  e.set_command(params.step_length_mm / params.cycle_s, 0.0f, 0.0f, 100.0f);
  constexpr float kDt = 0.01f;
  const long settle = long(3.0f * params.cycle_s / kDt);
  const long measure = long(2.0f * params.cycle_s / kDt);
  double lowest = 1e9;
  for (long k = 0; k < settle + measure; ++k) {
    w.tick(kDt);
    if (k >= settle && e.state() == strider::GaitState::kWalking) lowest = std::min(lowest, double(w.margin_mm()));
  }
  return lowest;
}

}  // namespace

std::string gait_usage_text() {
  return "  gait --robot R --gait G [--vx MM_S] [--vy MM_S] [--wz DEG_S] [--speed PCT]\n"
         "       --duration S --dt S [--scalar float|fixed] [--trajectory SHAPE]\n"
         "      walk a gait; CSV on stdout: t, per leg contact, foot x,y,z [mm, body\n"
         "      frame], joints [deg], IK status, then margin_mm. No velocity: steps in place.\n"
         "      SHAPE: rectangle, semicircle, ellipse, cycloid, parabola, bezier\n"
         "  gaits --robot R\n"
         "      the gaits of a model, one JSON line each: name, duty, offsets, and\n"
         "      min_margin_mm (lowest static stability margin walking; < 0: only\n"
         "      the motion keeps the robot up)\n";
}

int cmd_gaits(const std::vector<std::string>& args, std::ostream& out) {
  const Options o = Options::parse(args, OptionSpec{{"--robot"}, {}});
  const RobotModel& m = robot_of(o);
  const strider::GaitList list = strider::gaits_for(m);
  for (uint8_t i = 0; i < list.count; ++i) {
    const GaitTable& g = *list.items[i];
    std::vector<double> offsets;
    for (uint8_t k = 0; k < g.leg_count; ++k) offsets.push_back(double(g.offset[k]));
    const double margin = std::round(steady_min_margin_mm(m, g) * 10.0) / 10.0;
    out << JsonObject()
               .add("name", g.name)
               .add("duty", double(g.duty))
               .add("offsets", offsets)
               .add("min_margin_mm", margin)
               .str()
        << "\n";
  }
  return 0;
}

int cmd_gait(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Options o = Options::parse(
      args, OptionSpec{{"--robot", "--gait", "--vx", "--vy", "--wz", "--speed", "--duration", "--dt", "--scalar",
                        "--trajectory"},
                       {}});
  Run r{};
  r.model = &robot_of(o);
  r.gait = &gait_of(o, *r.model);
  r.shape = strider::gait_params_for(*r.model)->shape;
  if (o.has("--trajectory")) {
    const std::string& t = o.required("--trajectory");
    if (!strider::parse_swing_shape(t.c_str(), r.shape))
      throw UsageError("--trajectory '" + t + "': expected rectangle, semicircle, ellipse, cycloid, parabola or bezier");
  }
  r.vx = number_of(o, "--vx", 0.0, -kMaxSpeedMmS, kMaxSpeedMmS);
  r.vy = number_of(o, "--vy", 0.0, -kMaxSpeedMmS, kMaxSpeedMmS);
  r.wz_deg = number_of(o, "--wz", 0.0, -kMaxYawDegS, kMaxYawDegS);
  r.speed = number_of(o, "--speed", 100.0, 0.0, 100.0);
  r.duration = number_of(o, "--duration", 0.0, 0.0, kMaxDurationS, true);
  r.dt = number_of(o, "--dt", 0.0, 1e-4, 0.5, true);
  if (r.duration / r.dt > kMaxRows) throw UsageError("--duration / --dt: more than 2000000 rows");
  const std::string scalar = o.get_or("--scalar", "float");
  if (scalar == "float") return walk<float>(r, out, err);
  if (scalar == "fixed") return walk<Fixed>(r, out, err);
  throw UsageError("--scalar '" + scalar + "': expected float or fixed");
}

}  // namespace strider_cli
