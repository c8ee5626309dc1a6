// `mpm study --ladder LEVELS SCENE.json --out DIR`: a grid-convergence ladder of one scene
// (docs/accuracy.md#grid-convergence-ladders). The ladder itself (levels, runs, resumption, the
// Celik et al. 2008 GCI per observable) is campaigns/study/ladder.py; this hands it the options
// and this very mpm binary, so `mpm study --ladder` and the script are one command.
#pragma once

#include <string>
#include <vector>

namespace impact::mpm {

struct LadderOptions {
  std::string scene_file;              ///< the scene whose cells the levels multiply
  std::string out_dir;                 ///< tables and figures (runs in OUT/runs/)
  std::string levels;                  ///< "1,1.5,2.25": multipliers of the cells per axis
  int threads = 2;                     ///< OpenMP threads per run
  int ranks = 1;                       ///< > 1: every level under mpirun -np ranks
  std::vector<std::string> set_texts;  ///< --set merge patches, passed on as given
  bool plot = true;                    ///< the figures (the tables are written either way)
};

/// Runs ladder.py with python3 (matplotlib for the figures: without it, tables only). Returns the
/// script's exit code (0 done, 1 usage, 2 input error, 3 a level failed, 130 interrupted), or 1
/// when no python3 or no script is found.
int run_ladder(const LadderOptions& options);

}  // namespace impact::mpm
