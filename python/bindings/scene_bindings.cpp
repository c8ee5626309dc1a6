// MPM scenes: a scene file (extends resolved, merge patches applied) or document, checked or run
// to its end time. A run writes what `mpm run` writes (history.csv, summary.json, snapshots) into
// its output directory; the Python side reads them back.
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "mpm/run/memory.hpp"
#include "mpm/run/run.hpp"
#include "mpm/run/summary.hpp"
#include "mpm/scene/scene.hpp"
#include "python/bindings/bindings.hpp"

namespace impact::python {

namespace {

namespace mpm = impact::mpm;

/// The scene of a file with patches, or of a document (`file` empty) with patches.
mpm::Scene scene_of(const std::string& file, const std::string& text, const std::string& label,
                    const std::vector<std::string>& patches) {
  Json document = file.empty() ? parse_json(text, label) : mpm::load_scene_document(file);
  for (std::size_t k = 0; k < patches.size(); ++k)
    document.merge_patch(parse_json(patches[k], "patch " + std::to_string(k)));
  return mpm::read_scene(document, file.empty() ? label : file);
}

}  // namespace

void bind_scene(py::module_& m) {
  m.def(
      "scene_document",
      [](const std::string& file) { return mpm::load_scene_document(file).dump(); },
      py::arg("file"));
  m.def(
      "check_scene",
      [](const std::string& file, const std::string& text, const std::string& label,
         const std::vector<std::string>& patches, int threads) {
        const mpm::Scene scene = scene_of(file, text, label, patches);
        Json out = {{"resolved", scene.resolved}, {"warnings", scene.warnings}};
        out["refusal"] = mpm::memory_refusal(scene);
        if (out["refusal"].get<std::string>().empty())
          out["report"] = mpm::check_report(scene, mpm::run_threads(threads));
        return out.dump();
      },
      py::arg("file"), py::arg("text"), py::arg("label"), py::arg("patches"), py::arg("threads"));
  m.def(
      "run_scene",
      [](const std::string& file, const std::string& text, const std::string& label,
         const std::vector<std::string>& patches, const std::string& out_dir, int threads,
         bool progress) {
        const mpm::Scene scene = scene_of(file, text, label, patches);
        mpm::RunOptions options;
        options.out_dir = out_dir;
        options.threads = threads;
        options.progress = progress;
        int code = 0;
        {
          py::gil_scoped_release release;
          code = mpm::run(scene, options);
        }
        const std::string dir = out_dir.empty() ? scene.output.directory : out_dir;
        return py::make_tuple(code, dir, scene.warnings);
      },
      py::arg("file"), py::arg("text"), py::arg("label"), py::arg("patches"), py::arg("out_dir"),
      py::arg("threads"), py::arg("progress"));
  m.attr("exit_run_failed") = mpm::kExitRunFailed;
  m.attr("exit_memory") = mpm::kExitMemory;
}

}  // namespace impact::python
