// The strider CLI as scripts see it: the built binary run through popen,
// its stdout parsed as JSON lines, its exit status and stderr checked
// (host contracts of docs/cli.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "mini_json.h"

namespace {

using Result = strider_test::CliResult;
using strider_test::run_cli;

mini_json::Value only_line(const Result& r) {
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.lines.size(), 1u);
  return mini_json::parse(r.lines.empty() ? "null" : r.lines[0]);
}

void expect_near(const std::vector<double>& got, const std::vector<double>& want, double tol, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << what << " [" << i << "]";
}

double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s);
}

TEST(Cli, RobotsListsEveryModel) {
  const Result r = run_cli("robots");
  ASSERT_EQ(r.status, 0);
  ASSERT_EQ(r.lines.size(), 5u);
  const char* names[] = {"sprawl8", "mammal8", "dog12", "hexapod18", "spider12"};
  const int legs[] = {4, 4, 4, 6, 4};
  const int dof[] = {2, 2, 3, 3, 3};
  for (size_t i = 0; i < 5; ++i) {
    const mini_json::Value v = mini_json::parse(r.lines[i]);
    EXPECT_EQ(v.keys(), (std::vector<std::string>{"name", "legs", "dof"}));
    EXPECT_EQ(v["name"].str, names[i]);
    EXPECT_EQ(v["legs"].num, legs[i]);
    EXPECT_EQ(v["dof"].num, dof[i]);
  }
  EXPECT_TRUE(r.err.empty());
}

TEST(Cli, LegsDescribesEveryLegStandingOk) {
  const char* names[] = {"sprawl8", "mammal8", "dog12", "hexapod18", "spider12"};
  const size_t counts[] = {4, 4, 4, 6, 4};
  for (size_t i = 0; i < 5; ++i) {
    const Result r = run_cli(std::string("legs --robot ") + names[i]);
    ASSERT_EQ(r.status, 0);
    ASSERT_EQ(r.lines.size(), counts[i]);
    for (size_t k = 0; k < counts[i]; ++k) {
      const mini_json::Value v = mini_json::parse(r.lines[k]);
      EXPECT_EQ(v["leg"].num, double(k));
      EXPECT_EQ(v["stand_status"].str, "ok") << names[i];
      EXPECT_EQ(v["limits_deg"].arr.size(), v["stand_joints_deg"].arr.size());
    }
  }
}

TEST(Cli, FkKnownAnswers) {
  // Hexapod leg stretched out (seed 002 eqs 5-7 at zero): (l1 + l2 + l3, 0, d1).
  mini_json::Value v = only_line(run_cli("fk --robot hexapod18 --leg 0 --joints 0,0,0"));
  EXPECT_EQ(v["status"].str, "ok");
  expect_near(v["foot_mm"].numbers(), {240, 0, 32}, 1e-3, "hexapod leg frame");
  EXPECT_FALSE(v["within_limits"].b);  // t3 = 0 is outside [-150, -20]
  // Same in the body frame: mount (87.5, 77.5, -20), yaw 45 deg.
  v = only_line(run_cli("fk --robot hexapod18 --leg 0 --joints 0,0,0 --frame body"));
  const double c = std::sqrt(0.5) * 240;
  expect_near(v["foot_mm"].numbers(), {87.5 + c, 77.5 + c, 12}, 1e-3, "hexapod body frame");
  // Sprawl (seed 000 eqs 4-6): t1 = 90, t2 = -90: (0, a1, -a2).
  v = only_line(run_cli("fk --robot sprawl8 --leg 1 --joints=90,-90"));
  expect_near(v["foot_mm"].numbers(), {0, 55, -90}, 1e-3, "sprawl");
  EXPECT_FALSE(v["within_limits"].b);
  // Planar (seed 003 eq 3): hanging straight down.
  v = only_line(run_cli("fk --robot mammal8 --leg 2 --joints -90,0 --frame body"));
  expect_near(v["foot_mm"].numbers(), {-75, -45, -140}, 1e-3, "planar");
  // Abduction: standing joints of the right front leg land on its stance.
  v = only_line(run_cli("fk --robot dog12 --leg 3 --joints 180,39.3107,102.1427 --frame body"));
  expect_near(v["foot_mm"].numbers(), {300, -184, -350}, 0.01, "dog12");
  EXPECT_TRUE(v["within_limits"].b);
}

TEST(Cli, IkStatusesAndTheirFields) {
  mini_json::Value v = only_line(run_cli("ik --robot hexapod18 --leg 0 --foot 120,0,-90"));
  EXPECT_EQ(v.keys(), (std::vector<std::string>{"status", "joints_deg", "foot_mm"}));
  EXPECT_EQ(v["status"].str, "ok");
  expect_near(v["joints_deg"].numbers(), {0, 1.9538, -89.6387}, 2e-4, "hexapod stand");
  expect_near(v["foot_mm"].numbers(), {120, 0, -90}, 1e-4, "hexapod stand");

  // Off the sprawl leg's torus by a few mm: clamped onto it.
  v = only_line(run_cli("ik --robot sprawl8 --leg 0 --foot 80,80,-60"));
  EXPECT_EQ(v["status"].str, "clamped");
  EXPECT_EQ(v["joints_deg"].arr.size(), 2u);
  const std::vector<double> at = v["foot_mm"].numbers();
  const double rho = std::hypot(at[0], at[1]);
  EXPECT_NEAR(std::hypot(rho - 55, at[2]), 90, 1e-3);  // on the torus

  // Reachable only past a limit: joint_limit, foot_mm where the clamped joints are.
  v = only_line(run_cli("ik --robot sprawl8 --leg 0 --foot 94,94,60"));
  EXPECT_EQ(v["status"].str, "joint_limit");
  EXPECT_NEAR(v["joints_deg"].numbers()[1], 30, 1e-3);
  const mini_json::Value f = only_line(run_cli("fk --robot sprawl8 --leg 0 --joints 45,30"));
  expect_near(v["foot_mm"].numbers(), f["foot_mm"].numbers(), 1e-3, "joint_limit foot");

  // Far away: unreachable, exit 0, nulls.
  for (const char* args : {"ik --robot dog12 --leg 1 --foot 2000,0,0", "ik --robot dog12 --leg 1 --foot 1e7,0,0",
                           "ik --robot dog12 --leg 1 --foot 5000,0,0 --scalar fixed",
                           "ik --robot spider12 --leg 3 --foot 0,0,-900 --frame body --scalar fixed"}) {
    v = only_line(run_cli(args));
    EXPECT_EQ(v["status"].str, "unreachable") << args;
    EXPECT_TRUE(v["joints_deg"].is_null());
    EXPECT_TRUE(v["foot_mm"].is_null());
  }
}

// Every leg of every model: IK of the standing foot in the body frame is ok,
// and FK of the joints it returns comes back to the same foot.
TEST(Cli, IkThenFkRoundTripsOnEveryLeg) {
  const char* names[] = {"sprawl8", "mammal8", "dog12", "hexapod18", "spider12"};
  for (const char* name : names) {
    const Result legs = run_cli(std::string("legs --robot ") + name);
    for (const std::string& line : legs.lines) {
      const mini_json::Value leg = mini_json::parse(line);
      const std::vector<double> stand = leg["stand_mm"].numbers();
      std::ostringstream args;
      args.precision(10);
      args << "ik --robot " << name << " --leg " << int(leg["leg"].num) << " --frame body --foot " << stand[0] << ","
           << stand[1] << "," << stand[2];
      const mini_json::Value ik = only_line(run_cli(args.str()));
      ASSERT_EQ(ik["status"].str, "ok") << args.str();
      std::ostringstream fk;
      fk.precision(10);
      fk << "fk --robot " << name << " --leg " << int(leg["leg"].num) << " --frame body --joints ";
      const std::vector<double> q = ik["joints_deg"].numbers();
      for (size_t j = 0; j < q.size(); ++j) fk << (j ? "," : "") << q[j];
      const mini_json::Value back = only_line(run_cli(fk.str()));
      EXPECT_LT(distance(back["foot_mm"].numbers(), stand), 0.01) << fk.str();  // 4 printed decimals
      EXPECT_TRUE(back["within_limits"].b);
    }
  }
}

TEST(Cli, StdinAnswersEveryLineInOrder) {
  const std::string input =
      "120 0 -90\n"
      "120,10,-80\r\n"
      "\n"
      "1 2\n"
      "abc 1 2\n"
      "nan 0 0\n"
      "1 2 3 4\n"
      "  130\t 5   -70  \n"
      "4000 0 0\n"
      "110 0 -95";  // no final newline
  const Result r = run_cli("ik --robot hexapod18 --leg 4 --stdin", input);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(r.lines.size(), 10u);
  const char* want[] = {"ok", "ok", "error", "error", "error", "error", "error", "ok", "unreachable", "ok"};
  for (size_t i = 0; i < 10; ++i) {
    const mini_json::Value v = mini_json::parse(r.lines[i]);
    EXPECT_EQ(v["status"].str, want[i]) << "line " << i + 1;
    if (v["status"].str == "error") {
      EXPECT_EQ(v["line"].num, double(i + 1));
      EXPECT_FALSE(v["error"].str.empty());
    }
  }
  // Good lines give exactly what --foot gives.
  const Result single = run_cli("ik --robot hexapod18 --leg 4 --foot 130,5,-70");
  ASSERT_EQ(single.lines.size(), 1u);
  EXPECT_EQ(r.lines[7], single.lines[0]);
  // Empty input: no output, exit 0.
  const Result empty = run_cli("ik --robot dog12 --leg 0 --stdin", "");
  EXPECT_EQ(empty.status, 0);
  EXPECT_TRUE(empty.lines.empty());
}

// Fixed point agrees with float within the fixed solver's bounds (0.05 deg,
// 0.1 mm) over a grid of targets around every standing foot of every model.
TEST(Cli, FixedAgreesWithFloat) {
  const char* names[] = {"sprawl8", "mammal8", "dog12", "hexapod18", "spider12"};
  double worst_deg = 0, worst_mm = 0;
  for (const char* name : names) {
    const Result legs = run_cli(std::string("legs --robot ") + name);
    for (const std::string& line : legs.lines) {
      const mini_json::Value leg = mini_json::parse(line);
      const std::vector<double> s = leg["stand_mm"].numbers();
      std::ostringstream in;
      in.precision(10);
      for (double dx : {-20.0, 0.0, 20.0})
        for (double dy : {-15.0, 0.0, 15.0})
          for (double dz : {-20.0, 0.0, 20.0}) in << s[0] + dx << " " << s[1] + dy << " " << s[2] + dz << "\n";
      const std::string base = std::string("ik --robot ") + name + " --leg " + std::to_string(int(leg["leg"].num)) +
                               " --frame body --stdin --scalar ";
      const Result f = run_cli(base + "float", in.str());
      const Result x = run_cli(base + "fixed", in.str());
      ASSERT_EQ(f.lines.size(), 27u);
      ASSERT_EQ(x.lines.size(), 27u);
      for (size_t i = 0; i < 27; ++i) {
        const mini_json::Value a = mini_json::parse(f.lines[i]);
        const mini_json::Value b = mini_json::parse(x.lines[i]);
        ASSERT_EQ(a["status"].str, b["status"].str) << name << " point " << i;
        if (a["status"].str == "unreachable") continue;
        const std::vector<double> qa = a["joints_deg"].numbers(), qb = b["joints_deg"].numbers();
        for (size_t j = 0; j < qa.size(); ++j) {
          double d = std::fmod(std::fabs(qa[j] - qb[j]), 360.0);
          d = std::min(d, 360.0 - d);
          worst_deg = std::max(worst_deg, d);
        }
        worst_mm = std::max(worst_mm, distance(a["foot_mm"].numbers(), b["foot_mm"].numbers()));
      }
    }
  }
  EXPECT_LT(worst_deg, 0.05);
  EXPECT_LT(worst_mm, 0.1);
  std::printf("[ measured ] CLI fixed vs float: worst joint %.4f deg, worst foot %.4f mm\n", worst_deg, worst_mm);
}

// A seeded random stream of stdin lines, well formed and not: every line gets
// exactly one valid JSON answer, an error object exactly for the bad ones.
TEST(Cli, RandomStdinLinesEachGetOneAnswer) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> coord(-400.0, 400.0);
  const char* junk[] = {"x", "nan", "inf", "-", "1e", "1.2.3", "0x1p3", "+", "--5", "1e999", "", "e5", "."};
  const char* seps[] = {" ", "\t", ",", " , ", "  "};
  std::ostringstream in;
  std::vector<bool> good;
  const int n = std::min(STRIDER_RANDOM_CASES, 5000);
  for (int i = 0; i < n; ++i) {
    const int kind = int(rng() % 4);
    const int fields = kind == 0 ? int(rng() % 5) : 3;  // kind 0: wrong field count (maybe 3 by chance)
    const bool with_junk = kind == 1;
    const int junk_at = int(rng() % 3);
    std::ostringstream line;
    line.precision(7);
    for (int f = 0; f < fields; ++f) {
      if (f) line << seps[rng() % 5];
      if (with_junk && f == junk_at) {
        line << junk[rng() % 13];
      } else {
        line << coord(rng);
      }
    }
    std::string text = line.str();
    // Every junk token is malformed (an empty one leaves too few fields).
    const bool ok = (kind != 0 || fields == 3) && !with_junk;
    if (rng() % 7 == 0) text += "\r";
    in << text << "\n";
    good.push_back(ok);
  }
  const Result r = run_cli("ik --robot spider12 --leg 2 --frame body --stdin --scalar fixed", in.str());
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(r.lines.size(), size_t(n));
  for (int i = 0; i < n; ++i) {
    const mini_json::Value v = mini_json::parse(r.lines[size_t(i)]);
    EXPECT_EQ(v["status"].str == "error", !good[size_t(i)]) << "line " << i + 1 << ": " << r.lines[size_t(i)];
    if (!good[size_t(i)]) {
      EXPECT_EQ(v["line"].num, double(i + 1));
    }
  }
}

TEST(Cli, BadUsageExitsTwoWithAMessage) {
  const char* bad[] = {
      "",
      "walk",
      "robots --robot dog12",
      "legs",
      "legs --robot cat4",
      "fk --robot dog12 --leg 0",
      "fk --robot dog12 --leg 0 --joints 1,2",
      "fk --robot sprawl8 --leg 0 --joints 1,2,3",
      "fk --robot dog12 --leg 0 --joints 1,x,3",
      "fk --robot dog12 --leg 0 --joints 1,,3",
      "fk --robot dog12 --leg 0 --joints 1,2,inf",
      "fk --robot dog12 --leg 0 --joints 1,2,1e999",
      "fk --robot dog12 --leg 0 --joints 1,2,0x10",
      "fk --robot dog12 --leg 0 --joints 1,2,3 --frame world",
      "fk --robot dog12 --leg 0 --joints 1,2,3 --scalar fixed",
      "ik --robot dog12 --leg 0",
      "ik --robot dog12 --leg 0 --foot 1,2,3 --stdin",
      "ik --robot dog12 --leg 0 --foot 1,2",
      "ik --robot dog12 --leg 0 --foot 1,2,3,4",
      "ik --robot dog12 --leg 0 --foot 1,nan,3",
      "ik --robot dog12 --leg 0 --foot 1,2,3 --scalar double",
      "ik --robot dog12 --leg 4 --foot 1,2,3",
      "ik --robot hexapod18 --leg 6 --foot 1,2,3",
      "ik --robot dog12 --leg -1 --foot 1,2,3",
      "ik --robot dog12 --leg 1.0 --foot 1,2,3",
      "ik --robot dog12 --leg x --foot 1,2,3",
      "ik --robot dog12 --foot 1,2,3",
      "ik --leg 0 --foot 1,2,3",
      "ik --robot dog12 --robot dog12 --leg 0 --foot 1,2,3",
      "ik --robot dog12 --leg 0 --foot 1,2,3 extra",
      "ik --robot dog12 --leg 0 --foot 1,2,3 --verbose",
      "ik --robot dog12 --leg 0 --foot",
      "ik --robot dog12 --leg 0 --stdin=yes",
  };
  for (const char* args : bad) {
    const Result r = run_cli(args);
    EXPECT_EQ(r.status, 2) << "'" << args << "'";
    EXPECT_TRUE(r.lines.empty()) << "'" << args << "'";
    EXPECT_EQ(r.err.rfind("strider: ", 0), 0u) << "'" << args << "': " << r.err;
    EXPECT_NE(r.err.find("usage: strider"), std::string::npos) << "'" << args << "'";
  }
}

TEST(Cli, HelpGoesToStdout) {
  for (const char* args : {"help", "--help", "ik --help"}) {
    const Result r = run_cli(args);
    EXPECT_EQ(r.status, 0) << args;
    ASSERT_FALSE(r.lines.empty());
    EXPECT_EQ(r.lines[0].rfind("usage: strider", 0), 0u);
    EXPECT_TRUE(r.err.empty());
  }
}

}  // namespace
