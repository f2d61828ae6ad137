// The protocol lines that README.md and docs/*.md show work on the robots
// they name: each example runs on RobotApp (the firmware's whole loop, the
// simulator's library mode) of each of those models, standing, and must be
// answered `ok ...`, or exactly the reply the doc shows after `->`.
//
// What counts as an example:
// - an inline code span that the parser takes as a text command (`walk 100`,
//   `gait trot`; not `walk V`, not an RC byte, not a line the parser refuses
//   such as `deadman 0`), unless the words right after it say it is refused
//   (`err`, `refused`);
// - in a code block, a line `COMMAND -> REPLY` (the reply compared exactly
//   unless it has `...`), and the commands after `send` on a robotctl line.
// Which models: those named (sprawl8, hexapod18, sim:dog12 ...) in the
// example's paragraph (a table: its row; a code block: the block and the
// paragraph before it); `hexapods` or `quadrupeds` (or the singular) just
// before a span narrows it to those legs; none named: every model, as a
// user may have any of them.
// Each example runs on a robot of its own that has just stood up (a `cal`
// step after `cal start`), as a user who reads one example tries it.
// Beside the protocol lines: host-tool command lines name gaits their model
// has and scenario files that exist, every scenario's commands are taken by
// its robot, and links between the docs reach a file and heading.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fakes/app_rig.h"
#include "robots/all_robots.h"

namespace {

struct Example {
  std::string where;   // file:line
  std::string line;    // what is sent
  std::string expect;  // "" = any `ok`; otherwise the reply (a prefix when it ended in `...`)
  bool hexapods_only = false, quadrupeds_only = false;
};

struct Group {
  std::vector<std::string> models;  // empty: every model
  std::vector<Example> examples;
};

std::vector<std::string> model_names() {
  std::vector<std::string> out;
  for (const strider::RobotModel* m : strider::kAllRobots) out.push_back(m->name);
  return out;
}

std::vector<std::string> models_in(const std::string& text) {
  std::vector<std::string> out;
  for (const std::string& name : model_names()) {
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
      const bool word_end = at + name.size() >= text.size() || !std::isalnum(uint8_t(text[at + name.size()]));
      const bool word_start = at == 0 || !std::isalnum(uint8_t(text[at - 1]));
      if (word_end && word_start) {
        out.push_back(name);
        break;
      }
    }
  }
  return out;
}

// True when the parser takes `text` as one text command (not an RC byte or light).
bool is_command(const std::string& text) {
  if (text.empty() || text.size() > strider::kMaxLineBytes) return false;
  strider::CommandParser p;
  int commands = 0, errors = 0;
  strider::Command c;
  for (unsigned char b : text + "\n") {
    const strider::ParseResult r = p.feed(b, &c);
    if (r == strider::ParseResult::kError) ++errors;
    if (r == strider::ParseResult::kCommand) {
      if (c.source == strider::CommandSource::kBareByte || c.kind == strider::CommandKind::kLight ||
          c.kind == strider::CommandKind::kRcEcho)
        return false;
      ++commands;
    }
  }
  return commands == 1 && errors == 0;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// Words of a shell line (quotes removed).
std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  char quote = 0;
  bool any = false;
  for (char ch : line) {
    if (quote != 0) {
      if (ch == quote) quote = 0; else cur += ch;
    } else if (ch == '"' || ch == '\'') {
      quote = ch;
      any = true;
    } else if (ch == ' ' || ch == '\t') {
      if (any || !cur.empty()) out.push_back(cur);
      cur.clear();
      any = false;
    } else if (ch == '#') {
      break;
    } else {
      cur += ch;
    }
  }
  if (any || !cur.empty()) out.push_back(cur);
  return out;
}

void add_spans(const std::string& file, int line_no, const std::string& line, Group* g) {
  for (size_t a = line.find('`'); a != std::string::npos; a = line.find('`', a + 1)) {
    const size_t b = line.find('`', a + 1);
    if (b == std::string::npos) break;
    const std::string span = line.substr(a + 1, b - a - 1);
    const std::string before = line.substr(a >= 12 ? a - 12 : 0, a >= 12 ? 12 : a);
    const size_t next = line.find('`', b + 1);  // the words after it, up to the next span
    const std::string after = line.substr(b + 1, std::min<size_t>(30, next == std::string::npos ? 30 : next - b - 1));
    a = b;
    if (!is_command(span)) continue;
    if (after.find("err") != std::string::npos || after.find("refused") != std::string::npos) continue;
    Example e{file + ":" + std::to_string(line_no), span, ""};
    e.hexapods_only = before.find("hexapod") != std::string::npos;
    e.quadrupeds_only = before.find("quadruped") != std::string::npos;
    g->examples.push_back(e);
  }
}

std::vector<Group> examples_of(const std::string& path, const std::string& file) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  std::vector<Group> groups;
  std::string paragraph;  // the text of the paragraph so far
  std::string last;       // the last paragraph (before a code block)
  Group cur;
  auto flush = [&] {
    if (!cur.examples.empty()) {
      cur.models = models_in(paragraph);
      groups.push_back(cur);
    }
    cur = Group();
  };
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.rfind("```", 0) == 0) {  // a code block: with the paragraph before it
      std::string block = paragraph.empty() ? last : paragraph;
      Group g;
      size_t j = i + 1;
      for (; j < lines.size() && lines[j].rfind("```", 0) != 0; ++j) {
        const std::string& c = lines[j];
        block += "\n" + c;
        const size_t arrow = c.find("->");
        const std::vector<std::string> words = shell_words(c);
        if (arrow != std::string::npos) {
          const std::string cmd = trim(c.substr(0, arrow));
          std::string reply = trim(c.substr(arrow + 2));
          if (cmd.empty() || (!is_command(cmd) && cmd[0] != '$')) continue;
          g.examples.push_back(Example{file + ":" + std::to_string(j + 1), cmd, reply});
        } else if (!words.empty() && words[0] == "robotctl") {
          bool after_send = false;
          for (size_t k = 1; k < words.size(); ++k) {
            if (words[k] == "send") { after_send = true; continue; }
            if (after_send && words[k][0] != '-' && is_command(words[k]))
              g.examples.push_back(Example{file + ":" + std::to_string(j + 1), words[k], ""});
          }
        }
      }
      flush();
      if (!g.examples.empty()) {
        g.models = models_in(block);
        groups.push_back(g);
      }
      paragraph.clear();
      last.clear();
      i = j;
      continue;
    }
    if (trim(l).empty() || l[0] == '|' || l[0] == '#') {  // a table row is a paragraph of its own
      flush();
      if (!paragraph.empty()) last = paragraph;
      paragraph.clear();
      if (l[0] == '|') {
        paragraph = l;
        add_spans(file, int(i + 1), l, &cur);
        flush();
        paragraph.clear();
      }
      continue;
    }
    paragraph += "\n" + l;
    add_spans(file, int(i + 1), l, &cur);
  }
  flush();
  return groups;
}

// A level MPU-6050 at rest: gravity up, no rotation.
const strider::ImuSample<float> kLevelImu{{0.0f, 0.0f, 9.81f}, {0.0f, 0.0f, 0.0f}, 25.0f};

// A robot that has stood up (with an MPU-6050 when with_imu); each reply
// after 100 ms of ticks (`cal level`'s after the second it measures).
struct Robot : strider_test::AppRig {
  explicit Robot(const strider::RobotModel& m, bool with_imu = false) : AppRig(m) {
    EXPECT_TRUE(began);
    if (with_imu) {
      app.set_imu_present(true);
      imu = &kLevelImu;
    }
    run_ms(3000);
  }
  std::string reply(const std::string& line) { return AppRig::reply(line, line == "cal level" ? 1100 : 100); }
};

// `err 34 no imu`: the command needs the optional MPU-6050, which the
// robot of a doc example or scenario has unless said otherwise.
bool needs_imu(const std::string& reply) { return reply.rfind("err 34 ", 0) == 0; }

// README.md and every page in docs/: a new page is checked without being listed.
std::vector<std::string> doc_files() {
  std::vector<std::string> out{"README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(std::string(STRIDER_SOURCE_DIR) + "/docs"))
    if (entry.path().extension() == ".md") out.push_back("docs/" + entry.path().filename().string());
  std::sort(out.begin() + 1, out.end());
  return out;
}

TEST(DocExamples, WorkOnTheModelsTheyName) {
  int run = 0;
  const std::vector<std::string> files = doc_files();
  EXPECT_GT(files.size(), 15u);
  for (const std::string& file : files) {
    for (const Group& g : examples_of(std::string(STRIDER_SOURCE_DIR) + "/" + file, file)) {
      for (const strider::RobotModel* m : strider::kAllRobots) {
        bool named = g.models.empty();
        for (const std::string& n : g.models) named = named || n == m->name;
        if (!named) continue;
        for (const Example& e : g.examples) {
          if ((e.hexapods_only && m->leg_count != 6) || (e.quadrupeds_only && m->leg_count != 4)) continue;
          // (`cal level` is no step of `cal start`: the robot stands for it.)
          const bool cal_step = e.line.rfind("cal ", 0) == 0 && e.line != "cal start" && e.line != "cal show" &&
                                e.line != "cal level";
          std::string got;
          for (bool with_imu : {false, true}) {
            Robot r(*m, with_imu);
            if (cal_step) {
              EXPECT_EQ(r.reply("cal start"), "ok cal start");
            }
            got = r.reply(e.line);
            if (!needs_imu(got)) break;  // else once more, the part fitted
          }
          ++run;
          const size_t dots = e.expect.find("...");
          if (e.expect.empty()) {
            EXPECT_EQ(got.rfind("ok", 0), 0u) << e.where << " `" << e.line << "` on " << m->name << ": " << got;
          } else if (dots != std::string::npos) {
            EXPECT_EQ(got.rfind(trim(e.expect.substr(0, dots)), 0), 0u)
                << e.where << " `" << e.line << "` on " << m->name << ": " << got;
          } else {
            EXPECT_EQ(got, e.expect) << e.where << " `" << e.line << "` on " << m->name;
          }
        }
      }
    }
  }
  std::printf("%d doc examples run\n", run);
  EXPECT_GT(run, 100);
}

// The extraction itself: what it finds in a small doc, so that the test
// above cannot pass by finding nothing.
TEST(DocExamples, FindsSpansBlocksAndModels) {
  const std::string path = testing::TempDir() + "doc_examples_probe.md";
  {
    std::ofstream out(path);
    out << "On hexapod18: `walk 100`, `gait ripple`, `walk V` and `deadman 0` (refused).\n\n"
           "Any robot: `stop`, `gait trot` (hexapods: `gait tripod`). `height 120` is refused on sprawl8.\n\n"
           "| `speed 40` | row |\n\n"
           "Examples, sprawl8:\n\n```\ngait ripple    ->  err 23 unknown gait: walk trot pace crawl\n"
           "robotctl --port sim:dog12 send \"walk 80\" status\n```\n";
  }
  const auto groups = examples_of(path, "probe");
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_EQ(groups[0].models, std::vector<std::string>{"hexapod18"});
  ASSERT_EQ(groups[0].examples.size(), 2u);
  EXPECT_EQ(groups[0].examples[1].line, "gait ripple");
  EXPECT_EQ(groups[1].models, std::vector<std::string>{"sprawl8"});  // named in the paragraph
  ASSERT_EQ(groups[1].examples.size(), 3u);                          // not `height 120`: refused
  EXPECT_TRUE(groups[1].examples[2].hexapods_only);
  EXPECT_TRUE(groups[2].models.empty());
  ASSERT_EQ(groups[3].examples.size(), 3u);
  EXPECT_EQ(groups[3].examples[0].expect, "err 23 unknown gait: walk trot pace crawl");
  EXPECT_EQ(groups[3].models, (std::vector<std::string>{"sprawl8", "dog12"}));
  Robot r(strider::kSprawl8);
  EXPECT_EQ(r.reply("gait ripple"), groups[3].examples[0].expect);
  EXPECT_EQ(r.reply("height 120").rfind("err 24 height refused: ", 0), 0u);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The gaits `help` lists on model `name` ("" if there is no such model).
std::string gaits_of(const std::string& name) {
  for (const strider::RobotModel* m : strider::kAllRobots) {
    if (name != m->name) continue;
    Robot r(*m);
    const std::string help = r.reply("help");
    const size_t at = help.find("; gaits ");
    return at == std::string::npos ? "" : help.substr(at + 8, help.find(';', at + 8) - at - 8);
  }
  return "";
}

bool has_word(const std::string& words, const std::string& w) {
  std::istringstream in(words);
  for (std::string x; in >> x;)
    if (x == w) return true;
  return false;
}

// Host-tool command lines in the docs (the strider CLI, sweep_gait.py,
// tools/dev tune, strider-sim): a `--gait G` with `--robot R` or `--model R`
// on the same line names a gait that model has, and a scenario file named
// exists.
TEST(DocExamples, ToolCommandLinesNameGaitsTheModelHas) {
  int gait_lines = 0, scenario_paths = 0;
  for (const std::string& file : doc_files()) {
    std::istringstream in(read_file(std::string(STRIDER_SOURCE_DIR) + "/" + file));
    int line_no = 0;
    for (std::string l; std::getline(in, l);) {
      ++line_no;
      const std::vector<std::string> w = shell_words(l);
      std::string model, gait;
      for (size_t k = 0; k + 1 < w.size(); ++k) {
        if (w[k] == "--robot" || w[k] == "--model") model = w[k + 1];
        if (w[k] == "--gait") gait = w[k + 1];
      }
      if (!model.empty() && !gait.empty() && model != "R" && model != "M" && gait != "G") {
        const std::string gaits = gaits_of(model);
        EXPECT_FALSE(gaits.empty()) << file << ":" << line_no << ": no model " << model;
        EXPECT_TRUE(has_word(gaits, gait)) << file << ":" << line_no << ": " << model << " has no gait " << gait
                                           << " (it has " << gaits << ")";
        ++gait_lines;
      }
      for (size_t at = l.find("tools/sim/scenarios/"); at != std::string::npos;
           at = l.find("tools/sim/scenarios/", at + 1)) {
        size_t end = at;
        while (end < l.size() && (std::isalnum(uint8_t(l[end])) || std::strchr("/._-", l[end]) != nullptr)) ++end;
        const std::string path = l.substr(at, end - at);
        if (path.size() < 9 || path.compare(path.size() - 9, 9, ".scenario") != 0) continue;
        EXPECT_TRUE(std::filesystem::exists(std::string(STRIDER_SOURCE_DIR) + "/" + path))
            << file << ":" << line_no << ": " << path;
        ++scenario_paths;
      }
    }
  }
  std::printf("%d tool lines with a model and gait, %d scenario paths\n", gait_lines, scenario_paths);
  EXPECT_GT(gait_lines, 5);
  EXPECT_GT(scenario_paths, 2);
}

// A scenario's TEXT as sent (strider-sim's escapes: \n \r \t \\ \s \xHH).
std::string unescape(const std::string& t) {
  std::string out;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] != '\\' || i + 1 >= t.size()) {
      out += t[i];
      continue;
    }
    const char c = t[++i];
    if (c == 'n') out += '\n';
    else if (c == 'r') out += '\r';
    else if (c == 't') out += '\t';
    else if (c == 's') out += ' ';
    else if (c == 'x' && i + 2 < t.size()) out += char(std::stoi(t.substr(i + 1, 2), nullptr, 16)), i += 2;
    else out += c;
  }
  return out;
}

// Every scenario in tools/sim/scenarios (the examples the simulator's docs
// and the demo run): what it sends, in time order, is taken by the robot it
// names, on RobotApp: no `err` reply, and the robot is a known model.
TEST(DocExamples, ScenarioCommandsWorkOnTheirRobot) {
  int scenarios = 0, sends = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(STRIDER_SOURCE_DIR) + "/tools/sim/scenarios")) {
    if (entry.path().extension() != ".scenario") continue;
    const std::string name = entry.path().filename().string();
    std::istringstream in(read_file(entry.path().string()));
    std::string robot;
    bool imu = false;  // the scenario fits an MPU-6050
    std::vector<std::pair<double, std::string>> timed;
    for (std::string l; std::getline(in, l);) {
      const size_t hash = l.find('#');
      if (hash != std::string::npos) l.erase(hash);
      l = trim(l);
      std::istringstream words(l);
      std::string key;
      words >> key;
      if (key == "robot") words >> robot;
      if (key == "imu") {
        std::string v;
        words >> v;
        imu = v == "on";
      }
      if (key != "at") continue;
      double t = 0;
      std::string send;
      words >> t >> send;
      if (send == "shove" || send == "upright" || send == "ramp") continue;  // the simulator's hand, not the link
      ASSERT_EQ(send, "send") << name << ": " << l;
      timed.emplace_back(t, unescape(trim(l.substr(l.find(" send ") + 6))));
    }
    std::stable_sort(timed.begin(), timed.end(),
                     [](const std::pair<double, std::string>& a, const std::pair<double, std::string>& b) { return a.first < b.first; });
    const strider::RobotModel* model = nullptr;
    for (const strider::RobotModel* m : strider::kAllRobots)
      if (robot == m->name) model = m;
    ASSERT_NE(model, nullptr) << name << ": robot " << robot;
    Robot r(*model, imu);  // stands during its first 3 s, as the scenario's robot boots
    const double start_s = 3.0;
    double now_s = start_s;
    for (const auto& s : timed) {
      if (s.first > now_s) {
        r.run_ms(uint32_t((s.first - now_s) * 1000.0));
        now_s = s.first;
      }
      for (unsigned char b : s.second) r.app.on_byte(1, b, r.now_us, r.lines);
      ++sends;
    }
    r.run_ms(500);
    int replies = 0;
    for (const std::string& l : r.lines.sent) {
      EXPECT_NE(l.rfind("err", 0), 0u) << name << " on " << robot << ": " << l;
      replies += l.rfind("ok", 0) == 0;
    }
    EXPECT_GT(replies, 0) << name;
    ++scenarios;
  }
  std::printf("%d scenarios, %d sends\n", scenarios, sends);
  EXPECT_GE(scenarios, 20);
}

// GitHub's anchor for a heading: lower case, spaces to '-', other
// punctuation but '-' and '_' dropped.
std::string anchor_of(const std::string& heading) {
  std::string out;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_') out += char(std::tolower(c));
    else if (c == ' ') out += '-';
  }
  return out;
}

std::vector<std::string> anchors_in(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  bool code = false;
  for (std::string l; std::getline(in, l);) {
    if (l.rfind("```", 0) == 0) code = !code;
    if (code || l.empty() || l[0] != '#') continue;
    const size_t a = l.find_first_not_of('#');
    out.push_back(anchor_of(trim(l.substr(a))));
  }
  return out;
}

// Links between the docs: every relative link names a file that exists, and
// an anchor (`file.md#section`, `#section`) a heading it has.
TEST(DocExamples, LinksPointAtFilesAndHeadingsThatExist) {
  int links = 0;
  for (const std::string& file : doc_files()) {
    const std::string text = read_file(std::string(STRIDER_SOURCE_DIR) + "/" + file);
    const std::string dir = file.find('/') == std::string::npos ? "" : file.substr(0, file.rfind('/') + 1);
    bool code = false;
    std::istringstream in(text);
    int line_no = 0;
    for (std::string l; std::getline(in, l);) {
      ++line_no;
      if (l.rfind("```", 0) == 0) code = !code;
      if (code) continue;
      for (size_t at = l.find("]("); at != std::string::npos; at = l.find("](", at + 2)) {
        const size_t end = l.find(')', at + 2);
        if (end == std::string::npos) break;
        const std::string target = l.substr(at + 2, end - at - 2);
        if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
        const size_t hash = target.find('#');
        const std::string path = target.substr(0, hash);
        const std::string full = path.empty() ? std::string(STRIDER_SOURCE_DIR) + "/" + file
                                              : std::string(STRIDER_SOURCE_DIR) + "/" + dir + path;
        ++links;
        EXPECT_TRUE(std::filesystem::exists(full)) << file << ":" << line_no << ": " << target;
        if (hash == std::string::npos || !std::filesystem::exists(full)) continue;
        const std::vector<std::string> anchors = anchors_in(read_file(full));
        EXPECT_NE(std::find(anchors.begin(), anchors.end(), target.substr(hash + 1)), anchors.end())
            << file << ":" << line_no << ": " << target << ": no such heading";
      }
    }
  }
  std::printf("%d links\n", links);
  EXPECT_GT(links, 50);
  EXPECT_EQ(anchor_of("Constraint solver (WorldConfig::solver)"), "constraint-solver-worldconfigsolver");
}

}  // namespace
