// Command-line parsing for the strider CLI: options, strict numbers, lists.
#ifndef STRIDER_TOOLS_CLI_ARGS_H
#define STRIDER_TOOLS_CLI_ARGS_H

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace strider_cli {

// Bad usage: main prints the message and the usage text to stderr, exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a command accepts: options that take a value, and flags that do not.
struct OptionSpec {
  std::vector<std::string> with_value;  // e.g. "--robot"
  std::vector<std::string> flags;       // e.g. "--stdin"
};

// The parsed options of one command ("--robot R" and "--robot=R" both work).
class Options {
 public:
  // Throws UsageError on an unknown option, a missing value, a repeated
  // option or a positional argument.
  static Options parse(const std::vector<std::string>& args, const OptionSpec& spec);

  bool has(const std::string& name) const { return values_.count(name) != 0; }
  // The value of an option the command requires; throws UsageError if absent.
  const std::string& required(const std::string& name) const;
  // The value, or `fallback` when the option was not given.
  std::string get_or(const std::string& name, const std::string& fallback) const;

 private:
  std::map<std::string, std::string> values_;  // flags map to ""
};

// A finite decimal number: [+-]digits[.digits][(e|E)[+-]digits]. Rejects
// hex, inf, nan, empty text, trailing characters and overflow.
std::optional<double> parse_number(const std::string& text);

// A non-negative decimal integer without sign, below `limit`.
std::optional<unsigned> parse_index(const std::string& text, unsigned limit);

// "a,b,c": numbers separated by commas (spaces around them allowed).
// Throws UsageError naming `what` on any bad item.
std::vector<double> parse_number_list(const std::string& text, const std::string& what);

// One stdin line "x y z" (spaces, tabs or commas between the numbers, a
// trailing CR ignored). Returns an error message, or empty when `out` is set.
std::string parse_point_line(const std::string& line, double out[3]);

}  // namespace strider_cli

#endif  // STRIDER_TOOLS_CLI_ARGS_H
