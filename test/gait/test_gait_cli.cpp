// `strider gait` and `strider gaits` as scripts see them (ARCHITECTURE.md
// "Gaits"): the built binary run through popen; the CSV's header names,
// column count, row count, value formats and status values; the JSON lines
// of `gaits`; bad usage exits 2; float and fixed agree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "gait/gait_library.h"
#include "gait/gait_params.h"
#include "robots/all_robots.h"

namespace {

using Result = strider_test::CliResult;
using strider_test::run_cli;

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> v;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep)) v.push_back(item);
  if (!s.empty() && s.back() == sep) v.push_back("");
  return v;
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v);
}

// The expected header of a model (ARCHITECTURE.md).
std::vector<std::string> expected_header(const strider::RobotModel& m) {
  std::vector<std::string> h = {"t"};
  for (int i = 0; i < m.leg_count; ++i) {
    const std::string n = std::to_string(i);
    h.push_back("contact_" + n);
    h.push_back("foot_" + n + "_x");
    h.push_back("foot_" + n + "_y");
    h.push_back("foot_" + n + "_z");
    for (int j = 0; j < m.dof(); ++j) h.push_back("q_" + n + "_" + std::to_string(j));
    h.push_back("status_" + n);
  }
  h.push_back("margin_mm");
  return h;
}

const std::set<std::string> kStatuses = {"ok", "clamped", "joint_limit", "unreachable"};

TEST(GaitCli, CsvFormatForEveryModelAndGait) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    const strider::GaitList list = strider::gaits_for(*m);
    for (uint8_t g = 0; g < list.count; ++g) {
      SCOPED_TRACE(std::string(m->name) + "/" + list.items[g]->name);
      const Result r = run_cli(std::string("gait --robot ") + m->name + " --gait " + list.items[g]->name +
                               " --vx 40 --wz 5 --duration 2 --dt 0.02");
      ASSERT_EQ(r.status, 0) << r.err;
      ASSERT_EQ(r.lines.size(), 1u + 101u);  // header, t = 0 .. 2 s
      const std::vector<std::string> header = expected_header(*m);
      EXPECT_EQ(split(r.lines[0], ','), header);
      const size_t cols = header.size();
      EXPECT_EQ(cols, 1u + m->leg_count * (4u + m->dof() + 1u) + 1u);
      std::set<std::string> contacts_seen;
      for (size_t k = 1; k < r.lines.size(); ++k) {
        const std::vector<std::string> c = split(r.lines[k], ',');
        ASSERT_EQ(c.size(), cols) << r.lines[k];
        EXPECT_NEAR(std::stod(c[0]), 0.02 * double(k - 1), 1e-9);
        size_t at = 1;
        for (int i = 0; i < m->leg_count; ++i) {
          ASSERT_TRUE(c[at] == "0" || c[at] == "1") << c[at];
          contacts_seen.insert(c[at]);
          ++at;
          for (int v = 0; v < 3 + m->dof(); ++v, ++at) ASSERT_TRUE(is_number(c[at])) << c[at];
          ASSERT_TRUE(kStatuses.count(c[at])) << c[at];
          if (m->dof() == 3) {
            EXPECT_EQ(c[at], "ok");
          }
          ++at;
        }
        ASSERT_TRUE(is_number(c[at])) << c[at];
      }
      EXPECT_EQ(contacts_seen.size(), 2u);  // the feet step
    }
  }
}

TEST(GaitCli, StandingRowAndMarginMatchTheModel) {
  // The first row is the standing pose: feet at the model's stand_mm, margin
  // the CoM's distance to the nearest support edge plus the pad radius.
  const Result r = run_cli("gait --robot hexapod18 --gait tripod --vx 50 --duration 0.04 --dt 0.02");
  ASSERT_EQ(r.status, 0);
  const std::vector<std::string> c = split(r.lines[1], ',');
  for (int i = 0; i < 6; ++i) {
    const strider::Vec3<float>& s = strider::kHexapod18.legs[i].stand_mm;
    EXPECT_EQ(c[size_t(1 + i * 8)], "1");
    EXPECT_NEAR(std::stod(c[size_t(2 + i * 8)]), s.x, 1e-3);
    EXPECT_NEAR(std::stod(c[size_t(3 + i * 8)]), s.y, 1e-3);
    EXPECT_NEAR(std::stod(c[size_t(4 + i * 8)]), s.z, 1e-3);
  }
  EXPECT_GT(std::stod(c.back()), 0.0);
}

TEST(GaitCli, GaitsListsEachGaitOfAModel) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    const Result r = run_cli(std::string("gaits --robot ") + m->name);
    ASSERT_EQ(r.status, 0);
    const strider::GaitList list = strider::gaits_for(*m);
    ASSERT_EQ(r.lines.size(), size_t(list.count));
    for (uint8_t g = 0; g < list.count; ++g) {
      const std::string& l = r.lines[g];
      EXPECT_EQ(l.rfind(std::string("{\"name\":\"") + list.items[g]->name + "\",\"duty\":", 0), 0u) << l;
      EXPECT_NE(l.find(",\"offsets\":["), std::string::npos) << l;
      const size_t open = l.find('['), close = l.find(']');
      EXPECT_EQ(split(l.substr(open + 1, close - open - 1), ',').size(), size_t(m->leg_count)) << l;
      EXPECT_EQ(l.back(), '}');
    }
  }
  const Result walk = run_cli("gaits --robot mammal8");
  EXPECT_EQ(walk.lines[0], "{\"name\":\"walk\",\"duty\":0.85,\"offsets\":[0.25,0.75,0,0.5],\"min_margin_mm\":11}");
}

// min_margin_mm of `gaits`: the value after "min_margin_mm": in line l.
double min_margin_of(const std::string& l) {
  const std::string key = "\"min_margin_mm\":";
  const size_t at = l.find(key);
  if (at == std::string::npos) return NAN;
  return std::strtod(l.c_str() + at + key.size(), nullptr);
}

// The lowest static margin tells static gaits from dynamic ones. Known
// answers: a pace keeps the two feet of one side down, so its support is the
// line through them; on mammal8's planar legs (seed 003) the feet stay at the
// hips' y = +-45 mm, the CoM at y = 0, and the 5 mm pads reach 5 mm toward
// it: -40 mm, whatever the stride. A trot's diagonal passes through the CoM:
// within a pad radius of 0. The walk keeps its configured margin
// (gait_params.h), a hexapod's tripod three feet around the CoM.
TEST(GaitCli, GaitsMinMarginSeparatesStaticFromDynamicGaits) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    SCOPED_TRACE(m->name);
    const Result r = run_cli(std::string("gaits --robot ") + m->name);
    ASSERT_EQ(r.status, 0);
    const strider::GaitParams& params = *strider::gait_params_for(*m);
    for (const std::string& l : r.lines) {
      const double margin = min_margin_of(l);
      ASSERT_TRUE(std::isfinite(margin)) << l;
      if (l.find("\"name\":\"walk\"") != std::string::npos) {
        EXPECT_GE(margin, params.margin_mm - 0.05) << l;
      }
      if (l.find("\"name\":\"pace\"") != std::string::npos) {
        EXPECT_LT(margin, -30.0) << l;
      }
      if (m->leg_count == 6) {
        EXPECT_GT(margin, 50.0) << l;
      }
    }
  }
  const Result mammal8 = run_cli("gaits --robot mammal8");
  ASSERT_EQ(mammal8.lines.size(), 4u);
  const double half_width = strider::kMammal8.legs[0].mount_mm.y;
  const double pad = strider::gait_params_for(strider::kMammal8)->foot_radius_mm;
  EXPECT_NEAR(min_margin_of(mammal8.lines[2]), -(half_width - pad), 0.05) << mammal8.lines[2];  // pace
  EXPECT_NEAR(min_margin_of(mammal8.lines[1]), 0.0, pad) << mammal8.lines[1];                   // trot
}

TEST(GaitCli, BadUsageExits2) {
  for (const char* args :
       {"gait", "gait --robot nosuch --gait walk --duration 1 --dt 0.02",
        "gait --robot sprawl8 --gait tripod --duration 1 --dt 0.02",
        "gait --robot sprawl8 --gait walk --dt 0.02", "gait --robot sprawl8 --gait walk --duration 1",
        "gait --robot sprawl8 --gait walk --duration 1 --dt 0", "gait --robot sprawl8 --gait walk --duration -1 --dt 0.02",
        "gait --robot sprawl8 --gait walk --duration 1 --dt 0.02 --speed 150",
        "gait --robot sprawl8 --gait walk --duration 1 --dt 0.02 --vx fast",
        "gait --robot sprawl8 --gait walk --duration 1 --dt 0.02 --vx nan",
        "gait --robot sprawl8 --gait walk --duration 1 --dt 0.02 --scalar double",
        "gait --robot sprawl8 --gait walk --duration 1 --dt 0.02 --trajectory circle",
        "gait --robot sprawl8 --gait walk --duration 1 --dt 0.02 --bogus 1", "gaits", "gaits --robot nosuch",
        "gaits --robot sprawl8 --gait walk"}) {
    const Result r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(r.lines.empty()) << args;
    EXPECT_NE(r.err.find("strider: "), std::string::npos) << args;
  }
}

TEST(GaitCli, LimitedCommandIsReported) {
  const Result r = run_cli("gait --robot spider12 --gait walk --vx 5000 --duration 0.1 --dt 0.02");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("command limited"), std::string::npos) << r.err;
  const Result ok = run_cli("gait --robot spider12 --gait walk --vx 5 --duration 0.1 --dt 0.02");
  EXPECT_EQ(ok.err, "");
}

TEST(GaitCli, FloatAndFixedAgree) {
  // Same run in both scalars, each with its own configuration (Fixed builds
  // its velocity limits with Fixed IK): a lift-off may fall one tick apart,
  // so contacts agree on at least 97 % of the rows and feet within one tick
  // of travel (the largest row-to-row move in the float run) plus 0.5 mm.
  const std::string args = "gait --robot hexapod18 --gait ripple --vx 60 --vy 20 --wz 5 --duration 6 --dt 0.02";
  const Result a = run_cli(args + " --scalar float");
  const Result b = run_cli(args + " --scalar fixed");
  ASSERT_EQ(a.status, 0);
  ASSERT_EQ(b.status, 0);
  ASSERT_EQ(a.lines.size(), b.lines.size());
  EXPECT_EQ(a.lines[0], b.lines[0]);
  // How far apart leg i's foot is in rows r and s (its x, y, z: columns 2-4 of its 8).
  auto feet_apart = [](const std::vector<std::string>& r, const std::vector<std::string>& s, int i) {
    auto foot = [i](const std::vector<std::string>& c, int v) { return std::stod(c[size_t(v + i * 8)]); };
    return std::hypot(std::hypot(foot(r, 2) - foot(s, 2), foot(r, 3) - foot(s, 3)), foot(r, 4) - foot(s, 4));
  };
  double tick = 0.0;
  for (size_t k = 2; k < a.lines.size(); ++k) {
    const std::vector<std::string> x = split(a.lines[k], ','), p = split(a.lines[k - 1], ',');
    for (int i = 0; i < 6; ++i) tick = std::max(tick, feet_apart(x, p, i));
  }
  size_t same = 0;
  double worst = 0.0;
  for (size_t k = 1; k < a.lines.size(); ++k) {
    const std::vector<std::string> x = split(a.lines[k], ','), y = split(b.lines[k], ',');
    bool contacts = true;
    for (int i = 0; i < 6; ++i) contacts = contacts && x[size_t(1 + i * 8)] == y[size_t(1 + i * 8)];
    if (!contacts) continue;
    ++same;
    for (int i = 0; i < 6; ++i) worst = std::max(worst, feet_apart(x, y, i));
  }
  EXPECT_GE(double(same) / double(a.lines.size() - 1), 0.97);
  EXPECT_LT(worst, tick + 0.5);
  std::printf("[ measured ] CLI float vs fixed: %zu of %zu rows same contacts, feet within %.3f mm (a tick: %.3f)\n",
              same, a.lines.size() - 1, worst, tick);
}

TEST(GaitCli, TrajectoryOptionChangesTheSwing) {
  const std::string base = "gait --robot dog12 --gait trot --vx 100 --duration 1.5 --dt 0.02 --trajectory ";
  const Result rect = run_cli(base + "rectangle");
  const Result bez = run_cli(base + "bezier");
  ASSERT_EQ(rect.status, 0);
  ASSERT_EQ(bez.status, 0);
  ASSERT_EQ(rect.lines.size(), bez.lines.size());
  int differ = 0;
  for (size_t k = 1; k < rect.lines.size(); ++k) differ += rect.lines[k] != bez.lines[k] ? 1 : 0;
  EXPECT_GT(differ, 10);
}

}  // namespace
