// A minimal JSON writer for the CLI: one object per output line.
#ifndef STRIDER_TOOLS_CLI_JSON_H
#define STRIDER_TOOLS_CLI_JSON_H

#include <string>
#include <vector>

namespace strider_cli {

// Decimal places of every number the CLI writes: 0.1 um and 0.0001 deg,
// finer than the fixed-point resolution of the solvers' results.
constexpr int kJsonDecimals = 4;

// A number rounded to kJsonDecimals, trailing zeros dropped, never "-0".
// Non-finite values (which the library never returns) become null.
std::string json_number(double v);

// A string literal with JSON escapes.
std::string json_string(const std::string& s);

// Builds {"k":v,...} in insertion order.
class JsonObject {
 public:
  JsonObject& add(const std::string& key, const std::string& text);  // a string value
  JsonObject& add(const std::string& key, const char* text);
  JsonObject& add(const std::string& key, double v);
  JsonObject& add(const std::string& key, int v);
  JsonObject& add(const std::string& key, unsigned v);
  JsonObject& add(const std::string& key, bool v);
  JsonObject& add(const std::string& key, const std::vector<double>& v);  // an array of numbers
  JsonObject& add_null(const std::string& key);
  JsonObject& add_raw(const std::string& key, const std::string& json);  // already-encoded JSON
  std::string str() const { return "{" + body_ + "}"; }

 private:
  void key(const std::string& k);
  std::string body_;
};

// [a,b,c] of numbers.
std::string json_array(const std::vector<double>& v);

}  // namespace strider_cli

#endif  // STRIDER_TOOLS_CLI_JSON_H
