#include "args.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace strider_cli {

namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Matches [+-]digits[.digits][(e|E)[+-]digits] or [+-].digits[...]: the
// grammar strtod accepts minus hex, inf and nan.
bool is_decimal(const std::string& t) {
  size_t i = 0;
  const size_t n = t.size();
  if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
  size_t digits = 0;
  while (i < n && is_digit(t[i])) ++i, ++digits;
  if (i < n && t[i] == '.') {
    ++i;
    while (i < n && is_digit(t[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < n && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < n && is_digit(t[i])) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == n;
}

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

}  // namespace

Options Options::parse(const std::vector<std::string>& args, const OptionSpec& spec) {
  Options o;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string name = args[i];
    std::optional<std::string> inline_value;
    if (name.rfind("--", 0) != 0) throw UsageError("unexpected argument '" + name + "'");
    const size_t eq = name.find('=');
    if (eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    if (o.has(name)) throw UsageError("option " + name + " given twice");
    if (contains(spec.flags, name)) {
      if (inline_value) throw UsageError("option " + name + " takes no value");
      o.values_[name] = "";
    } else if (contains(spec.with_value, name)) {
      if (inline_value) {
        o.values_[name] = *inline_value;
      } else {
        if (i + 1 >= args.size()) throw UsageError("option " + name + " needs a value");
        o.values_[name] = args[++i];
      }
    } else {
      throw UsageError("unknown option '" + name + "'");
    }
  }
  return o;
}

const std::string& Options::required(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw UsageError("missing required option " + name);
  return it->second;
}

std::string Options::get_or(const std::string& name, const std::string& fallback) const {
  const auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

std::optional<double> parse_number(const std::string& text) {
  if (!is_decimal(text)) return std::nullopt;
  // The CLI never calls setlocale, so strtod reads '.' as the decimal point.
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<unsigned> parse_index(const std::string& text, unsigned limit) {
  if (text.empty() || text.size() > 6) return std::nullopt;
  unsigned v = 0;
  for (char c : text) {
    if (!is_digit(c)) return std::nullopt;
    v = v * 10u + unsigned(c - '0');
  }
  if (v >= limit) return std::nullopt;
  return v;
}

std::vector<double> parse_number_list(const std::string& text, const std::string& what) {
  std::vector<double> out;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item = trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    const std::optional<double> v = parse_number(item);
    if (!v) {
      throw UsageError(what + ": '" + item + "' is not a finite number (expected comma-separated numbers, e.g. 1.5,-2,3)");
    }
    out.push_back(*v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string parse_point_line(const std::string& line, double out[3]) {
  std::vector<std::string> items;
  std::string cur;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
      if (!cur.empty()) items.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) items.push_back(cur);
  if (items.size() != 3) {
    return "expected three numbers 'x y z', got " + std::to_string(items.size()) + " field" +
           (items.size() == 1 ? "" : "s");
  }
  for (int i = 0; i < 3; ++i) {
    const std::optional<double> v = parse_number(items[size_t(i)]);
    if (!v) return "'" + items[size_t(i)] + "' is not a finite number";
    out[i] = *v;
  }
  return "";
}

}  // namespace strider_cli
