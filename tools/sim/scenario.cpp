#include "scenario.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "robots/all_robots.h"

namespace strider_sim {

namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

bool to_number(const std::string& word, double* v) {
  if (word.empty()) return false;
  char* end = nullptr;
  *v = std::strtod(word.c_str(), &end);
  return end != nullptr && *end == '\0';
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

bool decode_escapes(const std::string& in, std::string* out) {
  out->clear();
  for (size_t i = 0; i < in.size(); ++i) {
    if (in[i] != '\\') {
      out->push_back(in[i]);
      continue;
    }
    if (++i >= in.size()) return false;
    switch (in[i]) {
      case 'n': out->push_back('\n'); break;
      case 'r': out->push_back('\r'); break;
      case 't': out->push_back('\t'); break;
      case '\\': out->push_back('\\'); break;
      case 's': out->push_back(' '); break;  // a trailing space survives trimming
      case 'x': {
        if (i + 2 >= in.size()) return false;
        const int hi = hex_digit(in[i + 1]), lo = hex_digit(in[i + 2]);
        if (hi < 0 || lo < 0) return false;
        out->push_back(char(hi * 16 + lo));
        i += 2;
        break;
      }
      default: return false;
    }
  }
  return true;
}

bool parse_scenario(const std::string& text, Scenario* out, std::string* error) {
  Scenario s;
  std::istringstream in(text);
  std::string raw;
  int line_no = 0;
  auto fail = [&](const std::string& why) {
    *error = "line " + std::to_string(line_no) + ": " + why;
    return false;
  };
  while (std::getline(in, raw)) {
    ++line_no;
    const size_t hash = raw.find('#');
    const std::string line = trim(hash == std::string::npos ? raw : raw.substr(0, hash));
    if (line.empty()) continue;
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "robot") {
      words >> s.robot;
      std::string extra;
      if (s.robot.empty() || (words >> extra)) return fail("robot takes one name");
      if (strider::find_robot(s.robot.c_str()) == nullptr) return fail("unknown robot '" + s.robot + "'");
    } else if (word == "duration") {
      std::string v, extra;
      words >> v;
      if (!to_number(v, &s.duration_s) || s.duration_s <= 0 || (words >> extra)) return fail("duration takes seconds > 0");
    } else if (word == "obstacle") {
      std::string kind;
      words >> kind;
      if (kind != "box") return fail("only 'obstacle box X Y SX SY SZ' is known");
      double v[5];
      for (double& x : v) {
        std::string w;
        words >> w;
        if (!to_number(w, &x)) return fail("obstacle box takes X Y SX SY SZ [mm]");
      }
      std::string extra;
      if (words >> extra) return fail("obstacle box takes X Y SX SY SZ [mm]");
      if (v[2] <= 0 || v[3] <= 0 || v[4] <= 0) return fail("obstacle sizes must be > 0");
      s.obstacles.push_back(ObstacleBox{v[0], v[1], v[2], v[3], v[4]});
    } else if (word == "feet") {
      std::string kind, mm, extra;
      words >> kind >> mm;
      if (kind != "pad" || !to_number(mm, &s.foot_pad_half_mm) ||
          !(s.foot_pad_half_mm > 0 && s.foot_pad_half_mm <= 50) || (words >> extra))
        return fail("feet takes pad and its half-length 0..50 [mm]");
    } else if (word == "imu") {
      std::string v, extra;
      words >> v;
      if ((v != "on" && v != "off") || (words >> extra)) return fail("imu takes on or off");
      s.imu = v == "on";
    } else if (word == "ramp") {
      std::string a, b, extra;
      words >> a >> b;
      if (!to_number(a, &s.ramp_deg) || !(s.ramp_deg >= 0 && s.ramp_deg <= 45) ||
          (!b.empty() && !to_number(b, &s.ramp_uphill_deg)) || (words >> extra))
        return fail("ramp takes a slope 0..45 [deg] and the direction it rises toward [deg]");
    } else if (word == "battery") {
      const std::string form = "battery takes cells 1..12, mah > 0, ohm >= 0, soc 0..1";
      std::string key, v;
      int keys = 0;
      while (words >> key) {
        double x = 0;
        if (!(words >> v) || !to_number(v, &x)) return fail(form);
        if (key == "cells" && x >= 1 && x <= 12 && x == std::floor(x)) s.battery.cells = int(x);
        else if (key == "mah" && x > 0) s.battery.capacity_mah = x;
        else if (key == "ohm" && x >= 0) s.battery.internal_ohm = x;
        else if (key == "soc" && x >= 0 && x <= 1) s.battery.soc = x;
        else return fail(form);
        ++keys;
      }
      if (keys == 0) return fail(form);
    } else if (word == "at") {
      std::string t, verb;
      words >> t >> verb;
      TimedSend send;
      if (!to_number(t, &send.at_s) || send.at_s < 0) return fail("at takes a time [s] >= 0");
      if (verb == "ramp") {
        TimedEvent e;
        e.at_s = send.at_s;
        e.kind = TimedEvent::kRamp;
        std::string a, b, extra;
        words >> a >> b;
        if (!to_number(a, &e.ramp_deg) || !(e.ramp_deg >= 0 && e.ramp_deg <= 45) ||
            (!b.empty() && !to_number(b, &e.ramp_uphill_deg)) || (words >> extra))
          return fail("ramp takes a slope 0..45 [deg] and the direction it rises toward [deg]");
        s.events.push_back(e);
        continue;
      }
      if (verb == "shove" || verb == "upright") {
        TimedEvent e;
        e.at_s = send.at_s;
        e.kind = verb == "shove" ? TimedEvent::kShove : TimedEvent::kUpright;
        std::string x, y, z, extra;
        if (verb == "shove") {
          words >> x >> y >> z;
          if (!to_number(x, &e.impulse_ns.x) || !to_number(y, &e.impulse_ns.y) || !to_number(z, &e.impulse_ns.z))
            return fail("shove takes an impulse X Y Z [N s]");
        }
        if (words >> extra) return fail(verb + " takes " + (verb == "shove" ? "X Y Z only" : "nothing"));
        s.events.push_back(e);
        continue;
      }
      if (verb != "send")
        return fail("expected 'at T send TEXT', 'at T shove X Y Z', 'at T upright' or 'at T ramp DEG [UPHILL_DEG]'");
      std::string rest;
      std::getline(words, rest);
      rest = trim(rest);
      if (rest.empty()) return fail("send needs text");
      if (!decode_escapes(rest, &send.bytes)) return fail("bad escape in send text");
      s.sends.push_back(send);
    } else {
      return fail("unknown directive '" + word + "'");
    }
  }
  line_no = 0;
  if (s.robot.empty()) return fail("no robot");
  if (s.duration_s <= 0) return fail("no duration");
  std::stable_sort(s.sends.begin(), s.sends.end(), [](const TimedSend& a, const TimedSend& b) { return a.at_s < b.at_s; });
  std::stable_sort(s.events.begin(), s.events.end(), [](const TimedEvent& a, const TimedEvent& b) { return a.at_s < b.at_s; });
  *out = s;
  return true;
}

bool load_scenario(const std::string& path, Scenario* out, std::string* error) {
  std::ifstream f(path);
  if (!f) {
    *error = "cannot read " + path;
    return false;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_scenario(ss.str(), out, error);
}

}  // namespace strider_sim
