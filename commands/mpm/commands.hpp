// The mpm program's commands: main.cpp declares the command line (command_line.cpp), CLI11
// parses it, and one function per command runs it and returns the process exit code. This layer
// sits above mpm/ and campaigns/ (it is the only code that includes both).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "campaigns/study/study.hpp"
#include "models/core/input.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/run/run.hpp"
#include "mpm/scene/scene.hpp"
#include "support/command_line.hpp"

namespace impact::mpm::commands {

/// Every option of every command, as CLI11 fills them, and the commands themselves.
struct CommandLine {
  CLI::App app{"The explicit MPM solver.", "mpm"};
  CLI::App* run = nullptr;
  CLI::App* check = nullptr;
  CLI::App* study = nullptr;
  CLI::App* plot = nullptr;
  CLI::App* keys = nullptr;
  cli::Verbosity verbosity;
  RunOptions options;
  StudyOptions study_options;
  std::string scene_file, restart_dir, cases;
  std::vector<std::string> set_texts, fault_texts;
  bool progress = false;
  std::string keys_format = "md";
  std::string plot_run, plot_figure;
  int plan_ranks = 0;
  bool fingerprint_only = false;
  std::string ladder_levels;
  int ladder_ranks = 1;
  bool no_plot = false;
};

/// Declares every command and option on `c.app` (command_line.cpp); `c` must not move after.
void declare(CommandLine& c);

/// `mpm run`, `mpm check` and `mpm study`: the commands that read a scene (scene_commands.cpp).
int scene_command(CommandLine& c);
/// `mpm study`, after the scene patches are read (study_command.cpp).
int study_command(const CommandLine& c, const std::vector<Json>& patches);
/// `mpm check` of a read scene: one JSON document on stdout (check_command.cpp); `attribute`
/// names the source of a warning found after seeding (RunOptions::attribute_warning).
int check_scene(const Scene& scene, const std::vector<std::string>& warnings, int threads,
                int plan_ranks, const std::function<std::string(const std::string&)>& attribute);
/// `mpm keys` (keys_command.cpp).
int keys_command(const std::string& format);

/// Comma-separated, no empty items (study_command.cpp).
bool parse_list(const std::string& text, std::vector<std::string>& items);
/// A usage error of one command: named, with that command's help to read (scene_commands.cpp).
int usage_error(const std::string& command, const std::string& message);

/// The end of each command's --help: what it writes and its exit codes (help_text.cpp).
extern const char* const kFooter;
extern const char* const kRunFooter;
extern const char* const kCheckFooter;
extern const char* const kStudyFooter;
extern const char* const kPlotFooter;
extern const char* const kKeysFooter;

}  // namespace impact::mpm::commands
