// `mpm study`: the report's Table 2 study of a folder, or --ladder: one scene at several
// resolutions (campaigns/study/).
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "campaigns/study/ladder_command.hpp"
#include "campaigns/study/study.hpp"
#include "commands/mpm/commands.hpp"

namespace impact::mpm::commands {

/// Comma-separated, no empty items.
bool parse_list(const std::string& text, std::vector<std::string>& items) {
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma - start);
    if (item.empty()) return false;
    items.push_back(item);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

namespace {

// What is wrong with `mpm study --ladder LEVELS` (empty: nothing): checked here, so that the
// message names --ladder; ladder.py, which names its own --levels, then refuses only two levels
// that give the same cells (it needs the scene for that).
std::string ladder_levels_problem(const std::string& text) {
  std::vector<std::string> items;
  std::vector<double> levels;
  if (!parse_list(text, items)) return "expected comma-separated levels, e.g. --ladder 1,1.5,2.25";
  for (const std::string& item : items) {
    char* end = nullptr;
    const double level = std::strtod(item.c_str(), &end);
    if (end != item.c_str() + item.size() || !std::isfinite(level) || !(level > 0.0))
      return "expected positive numbers (multipliers of the scene's cells per axis), got '" + item +
             "' in '" + text + "'";
    if (std::find(levels.begin(), levels.end(), level) != levels.end())
      return "the level '" + item + "' is repeated in '" + text + "'";
    levels.push_back(level);
  }
  return {};
}

}  // namespace

int study_command(const CommandLine& c, const std::vector<Json>& patches) {
  if (c.study->get_option("--ladder")->count() > 0) {
    if (const std::string problem = ladder_levels_problem(c.ladder_levels); !problem.empty())
      return usage_error("study", "--ladder: " + problem);
    if (!c.cases.empty()) return usage_error("study", "--ladder runs one scene: no --cases");
    LadderOptions ladder;
    ladder.scene_file = c.scene_file;
    ladder.out_dir = c.options.out_dir;
    ladder.levels = c.ladder_levels;
    ladder.threads = c.study_options.threads;
    ladder.ranks = c.ladder_ranks;
    ladder.set_texts = c.set_texts;
    ladder.plot = !c.no_plot;
    return run_ladder(ladder);
  }
  if (c.ladder_ranks != 1) return usage_error("study", "--ranks goes with --ladder");
  StudyOptions study = c.study_options;
  study.patches = patches;
  study.scene_dir = c.scene_file;
  study.out_dir = c.options.out_dir;
  study.progress = c.progress;
  return run_study(study);
}

}  // namespace impact::mpm::commands
