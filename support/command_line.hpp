// The one command-line convention of the programs (material_check, pointdriver, mpm), on CLI11:
//   --out DIR and --out=DIR (-o where a program writes one file or folder), --set PATCH wherever a
//   JSON file is read (an RFC 7396 merge patch, repeatable, applied in order), --version,
//   --quiet (nothing on stdout: results go to files, warnings and errors still to stderr),
//   --verbose (the resolved input and timings on stderr), --help generated from the options.
// Exit codes are the programs' own; a usage error (unknown option, missing or malformed value)
// is always 1, --help and --version exit 0. A --set number no double holds (1e999) is an input
// error (2) naming "--set patch N" and the key; problems at keys a patch set name the patch.
#pragma once

#include <fcntl.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/input.hpp"
#include "support/patch_origins.hpp"

namespace impact::cli {

inline constexpr int kExitUsage = 1;
inline constexpr int kExitInput = 2;
inline constexpr int kExitFailed = 3;   ///< a failed run or check, an output that cannot be written
inline constexpr int kExitRefused = 4;  ///< a run that would not fit (memory, output); not started

#ifndef IMPACT_VERSION
#define IMPACT_VERSION "unknown"
#endif

/// --quiet and --verbose of one program run. While `quiet` holds after parse(), std::cout is
/// silenced (restored when this object goes).
class Verbosity {
 public:
  Verbosity() = default;
  Verbosity(const Verbosity&) = delete;
  Verbosity& operator=(const Verbosity&) = delete;
  ~Verbosity() {
    if (saved_ != nullptr) std::cout.rdbuf(saved_);
    if (saved_fd_ >= 0) {
      std::fflush(stdout);
      ::dup2(saved_fd_, STDOUT_FILENO);
      ::close(saved_fd_);
    }
  }

  bool quiet = false;
  bool verbose = false;

  /// Called by parse(): silences std::cout when quiet, and the file descriptor 1 too, so that
  /// a child process (the Python that draws the figures) inherits the silence.
  void apply() {
    if (!quiet || saved_ != nullptr) return;
    saved_ = std::cout.rdbuf(&null_);
    std::fflush(stdout);
    const int null_fd = ::open("/dev/null", O_WRONLY);
    if (null_fd < 0) return;  // no /dev/null: the child keeps stdout, std::cout stays silent
    saved_fd_ = ::dup(STDOUT_FILENO);
    if (saved_fd_ >= 0) ::dup2(null_fd, STDOUT_FILENO);
    ::close(null_fd);
  }

 private:
  struct NullBuffer : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
  };
  NullBuffer null_;
  std::streambuf* saved_ = nullptr;
  int saved_fd_ = -1;  ///< the original descriptor 1 while quiet
};

/// A program or command: its description, the exit codes in the help's footer, and the flags
/// every program takes (--version, --quiet, --verbose).
inline void describe(CLI::App& app, const std::string& footer, Verbosity& verbosity) {
  app.footer(footer);
  const CLI::App* program = &app;  // a command's version is its program's
  while (program->get_parent() != nullptr) program = program->get_parent();
  std::string name = program->get_name();
  name = name.substr(0, name.find(' '));  // "pointdriver run" -> pointdriver
  app.set_version_flag("--version", name + " " + IMPACT_VERSION);
  app.add_flag("-q,--quiet", verbosity.quiet, "nothing on stdout (files, stderr as usual)");
  app.add_flag("-v,--verbose", verbosity.verbose, "the resolved input on stderr");
  app.get_formatter()->column_width(34);
}

/// `text` with every number no double holds (1e999) replaced by 0 and spaces, the strings left
/// alone: its syntax can then be checked apart from the range of its numbers.
inline std::string with_huge_numbers_zeroed(const std::string& text) {
  const std::string_view number_chars = "0123456789+-.eE";
  std::string out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (in_string || c == '"') {
      out += c;
      if (in_string && c == '\\' && i + 1 < text.size()) out += text[++i];
      in_string = c == '"' ? !in_string : in_string;
      ++i;
      continue;
    }
    if (c != '-' && !std::isdigit(static_cast<unsigned char>(c))) {
      out += c;
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    while (end < text.size() && number_chars.find(text[end]) != std::string_view::npos) ++end;
    const std::string token = text.substr(i, end - i);
    // 0 padded to the token's length: a syntax error keeps its byte position
    out += std::isinf(std::strtod(token.c_str(), nullptr))
               ? "0" + std::string(token.size() - 1, ' ')
               : token;
    i = end;
  }
  return out;
}

/// Accepts the text of a JSON object (a merge patch), else says why: a CLI11 check, so that a
/// malformed --set is a usage error (exit 1), a truncated one holding 1e999 too. A number no
/// double holds in a patch that is otherwise valid is an input error of patches_of (exit 2).
inline std::string set_patch_error(const std::string& text) {
  Json parsed;
  try {
    try {
      parsed = Json::parse(text);
    } catch (const Json::out_of_range&) {  // 1e999: is the rest valid?
      parsed = Json::parse(with_huge_numbers_zeroed(text));
    }
  } catch (const Json::exception& e) {
    return std::string("invalid JSON: ") + e.what();
  }
  if (!parsed.is_object()) {
    std::string shown = parsed.dump();
    if (shown.size() > 40) shown = shown.substr(0, 37) + "...";
    return std::string("expected a JSON object, a merge patch such as '{\"key\": value}', got ") +
           parsed.type_name() + " " + shown;
  }
  return "";
}

/// --set PATCH (repeatable): JSON merge patches over `what`, checked as JSON when parsed.
inline CLI::Option* add_set(CLI::App& app, std::vector<std::string>& patches,
                            const std::string& what) {
  return app.add_option("--set", patches, "JSON merge patch over " + what + " (repeatable)")
      ->type_name("JSON")
      ->check(set_patch_error, "")
      ->allow_extra_args(false);  // one patch per --set: "--set P SCENE.json" keeps the scene
}

/// What messages call the k-th --set patch (from 0): "--set patch 1".
inline std::string set_patch_name(std::size_t k) {
  return "--set patch " + std::to_string(k + 1);
}

/// The patches of add_set, parsed. Throws InputError for a number no double holds, naming the
/// patch and the key ("--set patch 2: /density: the number 1e999 is beyond ...": exit 2).
inline std::vector<Json> patches_of(const std::vector<std::string>& texts) {
  std::vector<Json> out;
  for (std::size_t k = 0; k < texts.size(); ++k)
    out.push_back(parse_json_text(texts[k], set_patch_name(k)));
  return out;
}

/// Problems and warnings of `file` read with `patches` merged in, attributed to the --set patch
/// that set the key ("--set patch 1 (over FILE): /key: ...").
inline PatchOrigins set_origins(const std::string& file, const std::vector<Json>& patches) {
  return PatchOrigins(file, patches, set_patch_name);
}

/// Parses `args` (in order, without the program name). Returns nothing to go on; 0 after --help
/// or --version (printed on stdout); kExitUsage after a usage error, printed on stderr as
/// "<program>: <what>" with a pointer to --help.
inline std::optional<int> parse(CLI::App& app, std::vector<std::string> args,
                                Verbosity& verbosity) {
  const std::string first = args.empty() ? std::string() : args.front();
  std::reverse(args.begin(), args.end());  // CLI11 takes a vector last argument first
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << '\n';
    return 0;
  } catch (const CLI::ParseError& e) {
    // A command's own error points to the command's help ("mpm run --help"); a first word that
    // names no command says so (CLI11 reports "A subcommand is required").
    std::string where = app.get_name();
    const std::vector<CLI::App*> reached = app.get_subcommands();
    if (!reached.empty()) where += " " + reached.back()->get_name();
    std::string what = e.what();
    if (reached.empty() && !app.get_subcommands({}).empty() && !first.empty()) {
      if (first[0] != '-') {
        what = "unknown command '" + first + "'";
      } else if (app.get_option_no_throw(first.substr(0, first.find('='))) == nullptr) {
        what = "unknown option '" + first + "'; a command comes first (" + app.get_name() +
               " COMMAND --help)";
      }
    }
    std::cerr << where << ": " << what << "\nRun '" << where << " --help' for the options.\n";
    return kExitUsage;
  }
  verbosity.apply();
  return std::nullopt;
}

inline std::optional<int> parse(CLI::App& app, int argc, char** argv, Verbosity& verbosity) {
  return parse(app, std::vector<std::string>(argv + 1, argv + argc), verbosity);
}

/// Call first in main. Under a file-size limit (`ulimit -f`) the write that passes it raises
/// SIGXFSZ, which kills the program with no word and leaves a .tmp behind; ignored, the write
/// fails with EFBIG and the checked writers report it (exit 3, the file named).
inline void report_file_size_limits() {
  std::signal(SIGXFSZ, SIG_IGN);
}

/// `code`, after making sure that what was printed on stdout reached it: when it did not (a full
/// disk, /dev/full), says so on stderr and turns a success into kExitFailed.
inline int stdout_checked(int code, const std::string& program) {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (!failed) return code;
  const int error = errno;
  std::cerr << program << ": cannot write the standard output"
            << (error != 0 ? std::string(" (") + std::strerror(error) + ")" : std::string())
            << '\n';
  return code == 0 ? kExitFailed : code;
}

}  // namespace impact::cli
