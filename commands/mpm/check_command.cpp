// `mpm check`: the scene validated, its particles, mass, memory and steps, as one JSON document.
#include <iostream>

#include "commands/mpm/commands.hpp"
#include "mpm/run/memory.hpp"
#include "mpm/run/run.hpp"
#include "mpm/run/step_estimate.hpp"
#include "mpm/run/summary.hpp"

namespace impact::mpm::commands {

// `mpm check`: one JSON document on stdout, the keys of Python's impact.check_scene: the resolved
// scene, its warnings, why mpm run would refuse it ("" when it would not) and, unless the memory
// estimate refuses it (then nothing is seeded), the report: particles, mass, memory, steps.
int check_scene(const Scene& scene, const std::vector<std::string>& warnings, int threads,
                int plan_ranks, const std::function<std::string(const std::string&)>& attribute) {
  Json out = {{"resolved", scene.resolved}, {"warnings", warnings}};
  const std::string memory = memory_refusal(scene);
  const std::string refusal = memory.empty() ? step_refusal(scene) : memory;
  out["refusal"] = refusal;
  if (memory.empty()) {
    std::vector<std::string> seeding;
    out["report"] = check_report(scene, run_threads(threads), plan_ranks, &seeding);
    for (std::string& w : seeding) {
      w = attribute(w);
      std::cerr << "mpm: warning: " << w << '\n';
      out["warnings"].push_back(w);
    }
  }
  std::cout << out.dump(2) << '\n';
  if (refusal.empty()) return 0;
  std::cerr << "mpm: check: mpm run would refuse this scene: " << refusal << '\n';
  return kExitMemory;
}

}  // namespace impact::mpm::commands
