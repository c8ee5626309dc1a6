// `mpm run` (and --restart), `mpm check` and `mpm study`: the commands that read a scene. The
// usage checks first (each names its command), then the scene with its --set patches, then the
// command; an input error names the file and key path (or the patch that set it): exit 2.
#include <filesystem>
#include <iostream>

#include "commands/mpm/commands.hpp"
#include "mpm/input/scene_reader.hpp"
#include "mpm/run/scene_fingerprint.hpp"
#include "mpm/simulation/fault_injection.hpp"

namespace impact::mpm::commands {

namespace {

// A run writes its resolved scene to DIR/scene.json: a scene file that is that file would be
// overwritten (the user's extends and comments lost). Why, or empty.
std::string overwritten_scene(const Scene& scene, const std::string& out_dir) {
  namespace fs = std::filesystem;
  const fs::path dir = out_dir.empty() ? fs::path(scene.output.directory) : fs::path(out_dir);
  std::error_code ec;
  if (!fs::equivalent(dir / "scene.json", scene.file, ec)) return {};
  return scene.file + ": is " + (dir / "scene.json").string() + ", which the run replaces with " +
         "the resolved scene (" + (out_dir.empty() ? "/output/directory" : "--out") + " " +
         dir.string() + "): give the scene another name or the run another directory";
}

/// The usage errors of run, check and study that need no file (0: none).
int usage_problem(CommandLine& c) {
  for (const auto& text : c.fault_texts) {
    const auto fault = parse_fault_injection(text);
    if (!fault) {
      return usage_error(
          "run",
          "--inject-fault: expected nan|nan_velocity|outside|jacobian:STEP:PARTICLE or "
          "sigterm|sigint:STEP (STEP >= 1), got '" +
              text + "'");
    }
    c.options.faults.push_back(*fault);
  }
  if (!c.cases.empty() && !parse_list(c.cases, c.study_options.cases))
    return usage_error("study",
                       "--cases needs a comma-separated list of case names, e.g. case01,case04");
  if (c.options.threads > 0) c.study_options.threads = c.options.threads;
  c.study_options.plot = !c.no_plot;
  if (!c.restart_dir.empty()) {
    if (!c.scene_file.empty())
      return usage_error("run", "--restart takes the scene from DIR/scene.json: no SCENE.json");
    if (!c.options.out_dir.empty())
      return usage_error("run", "--restart writes into DIR: no --out");
    if (!c.set_texts.empty())
      return usage_error("run", "--restart continues DIR/scene.json as it is: no --set");
    if (c.options.overwrite) return usage_error("run", "--restart continues DIR: no --overwrite");
  } else if (c.scene_file.empty()) {
    return usage_error("run", "missing SCENE.json (or --restart DIR)");
  }
  return 0;
}

/// `mpm run SCENE.json` and `mpm check`: the scene read with its patches, then run or checked.
int run_or_check(CommandLine& c, const std::vector<Json>& patches, ExtendsChain& chain) {
  Json document = load_scene_document(c.scene_file, &chain);
  for (const Json& patch : patches) document.merge_patch(patch);
  const Scene scene = read_scene(document, c.scene_file);
  const std::vector<std::string> warnings = extends_origins(chain).attribute(
      cli::set_origins(c.scene_file, patches).attribute(scene.warnings));
  for (const std::string& w : warnings) std::cerr << "mpm: warning: " << w << '\n';
  // The warnings found after seeding (the seeded volume) name their source likewise.
  c.options.attribute_warning = [&](const std::string& w) {
    return extends_origins(chain).attribute(cli::set_origins(c.scene_file, patches).attribute(w));
  };
  if (c.verbosity.verbose) std::cerr << scene.resolved.dump(2) << '\n';
  if (c.check->parsed() && c.fingerprint_only) {
    std::cout << scene_fingerprint(scene.resolved) << '\n';
    return 0;
  }
  if (c.check->parsed())
    return check_scene(scene, warnings, c.options.threads, c.plan_ranks,
                       c.options.attribute_warning);
  if (const std::string clash = overwritten_scene(scene, c.options.out_dir); !clash.empty())
    throw InputError({clash});
  return run(scene, c.options);
}

}  // namespace

// A usage error of one command: named, with that command's help to read (not mpm --help's list
// of commands).
int usage_error(const std::string& command, const std::string& message) {
  std::cerr << "mpm " << command << ": " << message << "\nRun 'mpm " << command
            << " --help' for the options.\n";
  return cli::kExitUsage;
}

int scene_command(CommandLine& c) {
  if (const int code = usage_problem(c)) return code;
  std::vector<Json> patches;
  ExtendsChain chain;  // the scene file's, for messages
  try {
    patches = cli::patches_of(c.set_texts);
    for (Json& patch : patches) resolve_patch_material_paths(patch);
    if (c.study->parsed()) return study_command(c, patches);
    c.options.progress = c.progress;
    c.options.handle_signals = true;
    c.options.report = c.options.comm.get().root();  // one rank prints the outcome
    if (!c.restart_dir.empty()) return restart(c.restart_dir, c.options);
    return run_or_check(c, patches, chain);
  } catch (const InputError& e) {
    // A key a --set patch set names the patch; one a base scene set, the base.
    std::cerr << extends_origins(chain)
                     .attribute(cli::set_origins(c.scene_file, patches).attribute(e))
                     .what()
              << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mpm: " << e.what() << '\n';
    return 3;
  }
}

}  // namespace impact::mpm::commands
