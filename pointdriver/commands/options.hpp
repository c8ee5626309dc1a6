// The point driver's commands on the programs' one command-line convention
// (support/command_line.hpp, CLI11): each command declares its options with a line of help, and
// --help, --version, --quiet and --verbose come with every command. Values may repeat
// (--y a --y b) or take several words (--paths a.json b.json); --out=DIR works as --out DIR.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "support/command_line.hpp"

namespace impact::pointdriver {

struct OptionSpec {
  std::string name;  ///< e.g. "--out"; aliases separated by '|': "-o|--output"
  int arity = 1;     ///< 0: a flag; 1: one value (repeatable); -1: every following word
  std::string help;  ///< one line for --help
  std::string value_name = "VALUE";  ///< how --help names the value (DIR, FILE, JSON, ...)
};

struct CommandSpec {
  std::string name;         ///< "run"
  std::string description;  ///< what the command does (the start of --help)
  std::string positional;   ///< how --help names the positional arguments ("" for none)
  std::size_t max_positional = 0;
  std::string footer;  ///< exit codes and notes (the end of --help)
};

struct Options {
  std::map<std::string, std::vector<std::string>> values;  ///< by the last alias
  std::vector<std::string> positional;
  cli::Verbosity verbosity;  ///< --quiet silences stdout while this lives

  bool has(const std::string& name) const { return values.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback) const;
  const std::vector<std::string>& all(const std::string& name) const;
};

/// The start of every command: parses `args` into `out`. On a usage error prints it to stderr and
/// returns 1; on --help or --version prints it and returns 0; otherwise returns nothing.
std::optional<int> parse_command(const CommandSpec& command, Options& out,
                                 const std::vector<std::string>& args,
                                 const std::vector<OptionSpec>& specs);

/// A JSON file with --set patches (cli::patches_of) applied in order (throws InputError naming the
/// file when it cannot be read or parsed).
Json patched_json_file(const std::string& file, const std::vector<Json>& patches);

}  // namespace impact::pointdriver
