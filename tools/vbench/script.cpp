// vbench script parsing (see script.h).
#include "script.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "virtual_mega.h"

namespace strider_vmega {

namespace {

bool parse_number(const std::string& s, double* v) {
  if (s.empty()) return false;
  char* end = nullptr;
  *v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(*v);
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Splits off the first whitespace-delimited word of *rest.
std::string take_word(std::string* rest) {
  size_t b = rest->find_first_not_of(" \t");
  if (b == std::string::npos) {
    rest->clear();
    return std::string();
  }
  size_t e = rest->find_first_of(" \t", b);
  std::string word = rest->substr(b, e == std::string::npos ? std::string::npos : e - b);
  *rest = e == std::string::npos ? std::string() : rest->substr(e + 1);
  return word;
}

}  // namespace

bool unescape(const std::string& in, std::string* out, std::string* error) {
  out->clear();
  for (size_t i = 0; i < in.size(); ++i) {
    if (in[i] != '\\') {
      out->push_back(in[i]);
      continue;
    }
    if (++i >= in.size()) {
      *error = "backslash at end of text";
      return false;
    }
    switch (in[i]) {
      case 'n': out->push_back('\n'); break;
      case 'r': out->push_back('\r'); break;
      case 't': out->push_back('\t'); break;
      case '\\': out->push_back('\\'); break;
      case 'x': {
        const int hi = i + 1 < in.size() ? hex_digit(in[i + 1]) : -1;
        const int lo = i + 2 < in.size() ? hex_digit(in[i + 2]) : -1;
        if (hi < 0 || lo < 0) {
          *error = "\\x needs two hex digits";
          return false;
        }
        out->push_back(char(hi * 16 + lo));
        i += 2;
        break;
      }
      default:
        *error = std::string("unknown escape \\") + in[i];
        return false;
    }
  }
  return true;
}

bool parse_script_line(const std::string& raw, ScriptEvent* event, bool* has_event, std::string* error) {
  *has_event = false;
  std::string line = raw;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::string rest = line;
  std::string word = take_word(&rest);
  if (word.empty() || word[0] == '#') return true;
  ScriptEvent ev;
  ev.immediate = true;
  if (word == "at") {
    double t = 0;
    if (!parse_number(take_word(&rest), &t) || t < 0) {
      *error = "`at` needs a time in seconds >= 0";
      return false;
    }
    ev.immediate = false;
    ev.time_us = uint64_t(std::llround(t * 1e6));
    word = take_word(&rest);
  }
  if (word == "send" || word == "send0" || word == "send1") {
    ev.kind = ScriptEvent::Kind::kSend;
    ev.uart = word == "send0" ? 0 : 1;
    // The text is everything after one separating space, kept verbatim.
    if (!unescape(rest, &ev.text, error)) return false;
    if (ev.text.empty()) {
      *error = "send needs text";
      return false;
    }
  } else if (word == "flood" || word == "flood0" || word == "flood1") {
    ev.kind = ScriptEvent::Kind::kFlood;
    ev.uart = word == "flood0" ? 0 : 1;
    const std::string rate = take_word(&rest);
    if (rate == "max") {
      ev.per_s = 0;
    } else if (!parse_number(rate, &ev.per_s) || ev.per_s <= 0) {
      *error = "flood needs a rate (a number > 0 a second, or `max`)";
      return false;
    }
    if (!parse_number(take_word(&rest), &ev.duration_s) || ev.duration_s <= 0) {
      *error = "flood needs a duration in seconds > 0 after the rate";
      return false;
    }
    if (!unescape(rest, &ev.text, error)) return false;
    if (ev.text.empty()) {
      *error = "flood needs text";
      return false;
    }
  } else if (word == "range") {
    ev.kind = ScriptEvent::Kind::kRange;
    const std::string v = take_word(&rest);
    if (v == "none") {
      ev.range_mm = -1;
    } else if (v == "stuck") {
      ev.kind = ScriptEvent::Kind::kEchoStuck;
    } else if (!parse_number(v, &ev.range_mm) || ev.range_mm < 0) {
      *error = "range needs millimetres >= 0, `none` or `stuck`";
      return false;
    }
  } else if (word == "reset") {
    ev.kind = ScriptEvent::Kind::kReset;
  } else if (word == "power_cut") {
    ev.kind = ScriptEvent::Kind::kPowerCut;
  } else if (word == "eeprom_cut") {
    ev.kind = ScriptEvent::Kind::kEepromCut;
    std::string n = take_word(&rest);
    const std::string mode = take_word(&rest);
    if (mode == "erased") n += ":erased";
    else if (!mode.empty()) n += ":" + mode;
    if (!parse_eeprom_cut(n, &ev.eeprom_writes, &ev.torn_erased, error)) return false;
  } else if (word == "hang") {
    ev.kind = ScriptEvent::Kind::kHang;
  } else if (word == "board") {
    ev.kind = ScriptEvent::Kind::kBoard;
    const std::string a = take_word(&rest);
    char* end = nullptr;
    const long addr = std::strtol(a.c_str(), &end, 0);
    if (a.empty() || *end != 0 || addr < 0 || addr > 0x7F) {
      *error = "board needs a 7-bit I2C address (0x40)";
      return false;
    }
    ev.board_address = int(addr);
    const std::string action = take_word(&rest);
    if (action == "off") ev.board_action = ScriptEvent::BoardAction::kOff;
    else if (action == "on") ev.board_action = ScriptEvent::BoardAction::kOn;
    else if (action == "detach") ev.board_action = ScriptEvent::BoardAction::kDetach;
    else if (action == "attach") ev.board_action = ScriptEvent::BoardAction::kAttach;
    else {
      *error = "board needs off, on, detach or attach";
      return false;
    }
  } else if (word == "imu") {
    ev.kind = ScriptEvent::Kind::kImu;
    const std::string action = take_word(&rest);
    int count = 0;
    if (action == "on") {
      ev.imu_action = ScriptEvent::ImuAction::kOn;
      ev.board_address = 0x68;
      const std::string a = take_word(&rest);
      if (!a.empty()) {
        char* end = nullptr;
        const long addr = std::strtol(a.c_str(), &end, 0);
        if (*end != 0 || (addr != 0x68 && addr != 0x69)) {
          *error = "imu on takes the address 0x68 or 0x69";
          return false;
        }
        ev.board_address = int(addr);
      }
    } else if (action == "off") {
      ev.imu_action = ScriptEvent::ImuAction::kOff;
    } else if (action == "accel" || action == "gyro") {
      ev.imu_action = action == "accel" ? ScriptEvent::ImuAction::kAccel : ScriptEvent::ImuAction::kGyro;
      count = 3;
    } else if (action == "tilt") {
      ev.imu_action = ScriptEvent::ImuAction::kTilt;
      count = 2;
    } else if (action == "temp") {
      ev.imu_action = ScriptEvent::ImuAction::kTemp;
      count = 1;
    } else {
      *error = "imu needs on, off, accel X Y Z, gyro X Y Z, tilt ROLL PITCH or temp C";
      return false;
    }
    for (int i = 0; i < count; ++i)
      if (!parse_number(take_word(&rest), &ev.values[i])) {
        *error = "imu " + action + " needs " + std::to_string(count) + (count == 1 ? " number" : " numbers");
        return false;
      }
  } else if (word == "adc") {
    ev.kind = ScriptEvent::Kind::kAdc;
    std::string p = take_word(&rest);
    if (!p.empty() && (p[0] == 'A' || p[0] == 'a')) p = p.substr(1);
    double pin = -1;
    if (!parse_number(p, &pin) || pin < 0 || pin > 7 || pin != std::floor(pin)) {
      *error = "adc needs an analog pin A0..A7";
      return false;
    }
    ev.pin = int(pin);
    if (!parse_number(take_word(&rest), &ev.values[0]) || ev.values[0] < 0) {
      *error = "adc needs volts >= 0 after the pin";
      return false;
    }
  } else if (word == "bus") {
    ev.kind = ScriptEvent::Kind::kBus;
    const std::string state = take_word(&rest);
    if (state != "stuck" && state != "free") {
      *error = "bus needs stuck or free";
      return false;
    }
    ev.bus_stuck = state == "stuck";
  } else {
    *error = "unknown directive `" + word + "`";
    return false;
  }
  if (ev.kind != ScriptEvent::Kind::kSend && ev.kind != ScriptEvent::Kind::kFlood && !take_word(&rest).empty()) {
    *error = "extra words after `" + word + "`";
    return false;
  }
  *event = ev;
  *has_event = true;
  return true;
}

bool parse_script(const std::string& text, std::vector<ScriptEvent>* events, std::string* error) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    ScriptEvent ev;
    bool has = false;
    std::string why;
    if (!parse_script_line(line, &ev, &has, &why)) {
      *error = "line " + std::to_string(n) + ": " + why;
      return false;
    }
    if (!has) continue;
    ev.line = n;
    events->push_back(ev);
  }
  std::stable_sort(events->begin(), events->end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.time_us < b.time_us; });
  return true;
}

bool parse_eeprom_cut(const std::string& text, uint64_t* writes, bool* erased, std::string* error) {
  const size_t colon = text.find(':');
  const std::string n = text.substr(0, colon);
  const std::string mode = colon == std::string::npos ? std::string() : text.substr(colon + 1);
  double v = -1;
  if (!parse_number(n, &v) || v < 0 || v != std::floor(v) || v > 1e15) {
    *error = "eeprom_cut needs a whole number of EEPROM writes >= 0";
    return false;
  }
  if (!mode.empty() && mode != "erased") {
    *error = "eeprom_cut: `erased` or nothing after the number";
    return false;
  }
  *writes = uint64_t(v);
  *erased = mode == "erased";
  return true;
}

void apply_event(const ScriptEvent& event, VirtualMega& mega) {
  switch (event.kind) {
    case ScriptEvent::Kind::kSend: mega.send(event.uart, event.text); break;
    case ScriptEvent::Kind::kRange: mega.set_range_mm(event.range_mm); break;
    case ScriptEvent::Kind::kReset: mega.reset(); break;
    case ScriptEvent::Kind::kPowerCut: mega.power_cut(); break;
    case ScriptEvent::Kind::kEepromCut:
      mega.cut_power_after_eeprom_writes(event.eeprom_writes, event.torn_erased ? TornByte::kErased : TornByte::kOld);
      break;
    case ScriptEvent::Kind::kEchoStuck: mega.set_echo_stuck(); break;
    case ScriptEvent::Kind::kHang: mega.hang(); break;
    case ScriptEvent::Kind::kBus: mega.set_bus_stuck(event.bus_stuck); break;
    case ScriptEvent::Kind::kBoard:
      for (int i = 0; i < mega.board_count(); ++i) {
        if (mega.board(i).address() != event.board_address) continue;
        switch (event.board_action) {
          case ScriptEvent::BoardAction::kOff: mega.set_board_power(i, false); break;
          case ScriptEvent::BoardAction::kOn: mega.set_board_power(i, true); break;
          case ScriptEvent::BoardAction::kDetach: mega.set_board_attached(i, false); break;
          case ScriptEvent::BoardAction::kAttach: mega.set_board_attached(i, true); break;
        }
      }
      break;
    case ScriptEvent::Kind::kImu: {
      const double* v = event.values;
      switch (event.imu_action) {
        case ScriptEvent::ImuAction::kOn: mega.set_imu_present(true, uint8_t(event.board_address)); break;
        case ScriptEvent::ImuAction::kOff: mega.set_imu_present(false); break;
        case ScriptEvent::ImuAction::kAccel: mega.set_imu_accel_m_s2(v[0], v[1], v[2]); break;
        case ScriptEvent::ImuAction::kGyro: mega.set_imu_gyro_rad_s(v[0], v[1], v[2]); break;
        case ScriptEvent::ImuAction::kTemp: mega.set_imu_temp_c(v[0]); break;
        case ScriptEvent::ImuAction::kTilt: {
          // Gravity's "up" in the body frame of Z-Y-X roll and pitch, at rest.
          const double r = v[0] * M_PI / 180.0, p = v[1] * M_PI / 180.0, g = Mpu6050::kG;
          mega.set_imu_accel_m_s2(-g * std::sin(p), g * std::sin(r) * std::cos(p), g * std::cos(r) * std::cos(p));
          mega.set_imu_gyro_rad_s(0, 0, 0);
          break;
        }
      }
      break;
    }
    case ScriptEvent::Kind::kAdc: mega.set_adc_volts(event.pin, event.values[0]); break;
    case ScriptEvent::Kind::kFlood: {
      Flood f;
      f.units.push_back(event.text);
      f.per_s = event.per_s;
      f.duration_us = uint64_t(std::llround(event.duration_s * 1e6));
      mega.flood(event.uart, f);
      break;
    }
  }
}

}  // namespace strider_vmega
