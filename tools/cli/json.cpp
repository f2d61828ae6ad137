#include "json.h"

#include <cmath>
#include <cstdio>

namespace strider_cli {

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", kJsonDecimals, v);
  std::string s(buf);
  const size_t dot = s.find('.');
  if (dot != std::string::npos) {
    size_t end = s.size();
    while (end > dot + 1 && s[end - 1] == '0') --end;
    if (end == dot + 1) --end;  // no fraction left: drop the point
    s.resize(end);
  }
  if (s == "-0") s = "0";
  return s;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += char(c);
        }
    }
  }
  return out + "\"";
}

std::string json_array(const std::vector<double>& v) {
  std::string out = "[";
  for (size_t i = 0; i < v.size(); ++i) {
    if (i) out += ",";
    out += json_number(v[i]);
  }
  return out + "]";
}

void JsonObject::key(const std::string& k) {
  if (!body_.empty()) body_ += ",";
  body_ += json_string(k) + ":";
}

JsonObject& JsonObject::add(const std::string& k, const std::string& text) {
  key(k);
  body_ += json_string(text);
  return *this;
}
JsonObject& JsonObject::add(const std::string& k, const char* text) { return add(k, std::string(text)); }
JsonObject& JsonObject::add(const std::string& k, double v) {
  key(k);
  body_ += json_number(v);
  return *this;
}
JsonObject& JsonObject::add(const std::string& k, int v) {
  key(k);
  body_ += std::to_string(v);
  return *this;
}
JsonObject& JsonObject::add(const std::string& k, unsigned v) {
  key(k);
  body_ += std::to_string(v);
  return *this;
}
JsonObject& JsonObject::add(const std::string& k, bool v) {
  key(k);
  body_ += v ? "true" : "false";
  return *this;
}
JsonObject& JsonObject::add(const std::string& k, const std::vector<double>& v) {
  key(k);
  body_ += json_array(v);
  return *this;
}
JsonObject& JsonObject::add_null(const std::string& k) {
  key(k);
  body_ += "null";
  return *this;
}
JsonObject& JsonObject::add_raw(const std::string& k, const std::string& json) {
  key(k);
  body_ += json;
  return *this;
}

}  // namespace strider_cli
