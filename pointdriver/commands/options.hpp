// A small command-line option parser: declared options only (unknown ones are an error), values
// that may repeat (--y a --y b) or take several words (--paths a.json b.json), positionals.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace impact::pointdriver {

struct OptionSpec {
  std::string name;  ///< e.g. "--out"; aliases separated by '|': "-o|--output"
  int arity = 1;     ///< 0: a flag; 1: one value; -1: every following word up to the next option
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Options {
  std::map<std::string, std::vector<std::string>> values;  ///< by the first alias
  std::vector<std::string> positional;
  bool help = false;

  bool has(const std::string& name) const { return values.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback) const;
  const std::vector<std::string>& all(const std::string& name) const;
};

/// Parses `args`; throws UsageError naming an unknown option or a missing value.
Options parse_options(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                      std::size_t max_positional);

/// The start of every command: parses into `out`; on a usage error prints it with `help` to
/// stderr and returns 1, on --help prints `help` and returns 0, otherwise returns nothing.
std::optional<int> parse_command(std::string_view command, const char* help, Options& out,
                                 const std::vector<std::string>& args,
                                 const std::vector<OptionSpec>& specs, std::size_t max_positional);

}  // namespace impact::pointdriver
