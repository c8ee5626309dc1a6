#include "mpm/run/output_directory.hpp"

#include <fstream>
#include <regex>
#include <set>
#include <system_error>

#include "models/core/input.hpp"
#include "mpm/run/checkpoint.hpp"

namespace impact::mpm {

namespace fs = std::filesystem;

namespace {

// What the run writes under these names (and, while writing, under the name + ".tmp").
const std::regex kTopFile(
    R"((history\.csv|summary\.json|status\.json|scene\.json|particles\.pvd|checkpoint(\.rank[0-9]+)?\.bin)(\.tmp)?)");
// particles/step_NNNNNN.vtu, step_NNNNNN_rankR.vtu (several ranks), step_NNNNNN.pvtu.
const std::regex kSnapshot(R"((step_[0-9]+)(_rank[0-9]+)?\.(vtu|pvtu)(\.tmp)?)");

// The JSON of `file`, or null when it is missing or not JSON (a run killed while writing it).
Json read_json_or_null(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  return Json::parse(in, nullptr, false);
}

bool remove_file(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(file, ec) && fs::remove(file, ec);
}

// Removes the files of `sub` (a directory of dir) whose names `doomed` accepts, then `sub`
// itself if that left it empty.
template <class Doomed>
std::size_t clear_in(const fs::path& sub, Doomed&& doomed) {
  std::error_code ec;
  if (!fs::is_directory(sub, ec)) return 0;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(sub, ec))
    if (entry.is_regular_file(ec) && doomed(entry.path().filename().string()))
      files.push_back(entry.path());
  std::size_t n = 0;
  for (const fs::path& f : files) n += remove_file(f) ? 1 : 0;
  if (fs::is_empty(sub, ec)) fs::remove(sub, ec);
  return n;
}

}  // namespace

std::string unfinished_run(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir / kCheckpointFile, ec)) return "";
  const Json status = read_json_or_null(dir / "status.json");
  const std::string state =
      status.is_object() && status.contains("status") && status["status"].is_string()
          ? status["status"].get<std::string>()
          : "";
  if (state == "completed" || state == "failed") return "";  // nothing left to continue
  // A status.json cut short by a kill reads as no JSON: say so, not "missing".
  const std::string status_text = !state.empty()                         ? "\"" + state + "\""
                                  : !fs::exists(dir / "status.json", ec) ? "missing"
                                  : status.is_object()                   ? "no \"status\""
                                                                         : "not JSON (cut short?)";
  std::string why = (dir / kCheckpointFile).string() + ": the checkpoint of a run that has not " +
                    "finished (status.json: " + status_text;
  if (status.is_object() && status.contains("checkpoint") && status["checkpoint"].is_object() &&
      status["checkpoint"].contains("step"))
    why += ", checkpoint at step " + status["checkpoint"]["step"].dump();
  return why + "): continue it with 'mpm run --restart " + dir.string() +
         "', or start a new run over it with --overwrite";
}

std::string completed_run(const fs::path& dir) {
  const Json status = read_json_or_null(dir / "status.json");
  if (!status.is_object() || status.value("status", Json()) != "completed") return "";
  return dir.string() + ": the run completed (status.json: \"completed\"); --restart continues " +
         "a run that stopped before its end. Run the scene again with 'mpm run " +
         (dir / "scene.json").string() + " --out NEW_DIR'";
}

std::size_t clear_previous_run(const fs::path& dir) {
  // Only where a run was: status.json as mpm writes it (a directory of the user's own files, one
  // named summary.json among them, is left alone).
  const Json status = read_json_or_null(dir / "status.json");
  if (!status.is_object() || !status.contains("status") || !status["status"].is_string()) return 0;
  // The particle paths are named by the previous run's scene: only those files go.
  std::set<std::string> paths;
  const Json scene = read_json_or_null(dir / "scene.json");
  if (scene.is_object() && scene.contains("output") && scene["output"].is_object() &&
      scene["output"].contains("particle_paths") && scene["output"]["particle_paths"].is_object())
    for (const auto& item : scene["output"]["particle_paths"].items())
      for (const char* suffix : {".json", ".material.json", ".csv"})
        for (const char* tmp : {"", ".tmp"}) paths.insert(item.key() + suffix + tmp);
  std::size_t n = 0;
  n += clear_in(dir / "particles",
                [](const std::string& name) { return std::regex_match(name, kSnapshot); });
  n += clear_in(dir / "paths", [&](const std::string& name) { return paths.count(name) > 0; });
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return n;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && std::regex_match(entry.path().filename().string(), kTopFile))
      files.push_back(entry.path());
  for (const fs::path& f : files) n += remove_file(f) ? 1 : 0;
  return n;
}

std::size_t remove_unlisted_snapshots(const fs::path& dir,
                                      const std::vector<std::pair<double, std::string>>& entries) {
  std::set<std::string> listed;  // the steps' stems, step_NNNNNN
  for (const auto& entry : entries) {
    std::smatch m;
    const std::string name = fs::path(entry.second).filename().string();
    if (std::regex_match(name, m, kSnapshot)) listed.insert(m[1]);
  }
  return clear_in(dir / "particles", [&](const std::string& name) {
    std::smatch m;
    return std::regex_match(name, m, kSnapshot) && listed.count(m[1]) == 0;
  });
}

}  // namespace impact::mpm
