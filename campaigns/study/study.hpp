// `mpm study`: the report's Table 2 study. Runs every case*.json (and recommended.json) of a scene
// directory one after another into OUT/<case>/, then hands OUT to study_plot.py, which writes the
// per-case energy/momentum figures and the summary table (OUT/summary.csv, OUT/summary.md).
#pragma once

#include <string>
#include <vector>

#include "models/core/input.hpp"

namespace impact::mpm {

struct StudyOptions {
  std::string scene_dir;           ///< holds case01.json ... (+ recommended.json)
  std::string out_dir;             ///< OUT: one sub-directory per case, plus the table
  int threads = 2;                 ///< OpenMP threads per case, capped at the processors available
  std::vector<std::string> cases;  ///< case names (file stems) to run; empty: all
  bool plot = true;                ///< draw the figures (the table is written either way)
  bool progress = false;           ///< the solver's progress line on stderr
  std::vector<Json> patches;       ///< merge patches over every case (after its extends)
};

/// The scene files a study runs: case*.json sorted by name, then recommended.json if present;
/// restricted to `selected` (stems, ".json" optional) when not empty. Throws InputError naming the
/// directory when it is missing, holds no case, or a selected case does not exist.
std::vector<std::string> study_scene_files(const std::string& scene_dir,
                                           const std::vector<std::string>& selected = {});

/// Validates every selected scene first (InputError with all problems, nothing run), then runs the
/// cases in order. A case that fails is recorded (OUT/<case>/summary.json "status": "failed") and
/// the study goes on. Writes OUT/study.json, then runs study_plot.py once. Returns 0 when every
/// case completed, 3 when any failed.
int run_study(const StudyOptions& options);

}  // namespace impact::mpm
