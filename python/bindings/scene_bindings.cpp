// MPM scenes: a scene file (extends resolved, merge patches applied) or document, checked or run
// to its end time. A run writes what `mpm run` writes (history.csv, summary.json, snapshots) into
// its output directory; the Python side reads them back and turns a failed, refused or
// interrupted run into an exception.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "mpm/input/scene_reader.hpp"
#include "mpm/run/interrupt.hpp"
#include "mpm/run/memory.hpp"
#include "mpm/run/run.hpp"
#include "mpm/run/step_estimate.hpp"
#include "mpm/run/summary.hpp"
#include "mpm/scene/scene.hpp"
#include "python/bindings/bindings.hpp"
#include "support/atomic_file.hpp"

namespace impact::python {

namespace {

namespace mpm = impact::mpm;

/// The scene of a file with patches, or of a document (`file` empty) with patches.
mpm::Scene scene_of(const std::string& file, const std::string& text, const std::string& label,
                    const std::vector<std::string>& patches) {
  Json document = file.empty() ? parse_json(text, label) : mpm::load_scene_document(file);
  const std::vector<Json> parsed = parse_patches(patches);
  for (const Json& patch : parsed) document.merge_patch(patch);
  const PatchOrigins origins = patch_origins(file.empty() ? label : file, parsed);
  try {
    mpm::Scene scene = mpm::read_scene(document, file.empty() ? label : file);
    scene.warnings = origins.attribute(scene.warnings);
    return scene;
  } catch (const InputError& e) {
    throw origins.attribute(e);
  }
}

/// Ctrl-C while a run has released the GIL: Python's C-level handler only flags the signal, so
/// every 50 ms the run takes the GIL and lets Python run its handlers. An exception they raise
/// (KeyboardInterrupt) stops the run as SIGINT stops `mpm run` (a checkpoint, status
/// "interrupted") and is kept for the Python side to re-raise.
class PythonSignals {
 public:
  int poll() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(50)) return 0;
    last_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return 0;
    error_ = std::make_unique<py::error_already_set>();  // takes the raised exception
    return mpm::sigint_number();
  }
  /// The exception a handler raised, or None.
  py::object exception() const { return error_ ? py::object(error_->value()) : py::none(); }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  std::unique_ptr<py::error_already_set> error_;
};

/// Runs `start` (run or restart) without the GIL, polling Python's signals. Returns (exit code,
/// message, exception raised by a signal handler or None); the message is set when the run
/// stopped on an error it threw: `mpm run` prints it and exits 3. Bad input and an output that
/// cannot be written (a full disk) go on as impact.InputError and impact.OutputError.
py::tuple run_polled(const std::function<int(const mpm::RunOptions&)>& start,
                     mpm::RunOptions options) {
  PythonSignals signals;
  options.poll_interrupt = [&signals] { return signals.poll(); };
  int code = 0;
  std::string message;
  try {
    py::gil_scoped_release release;
    code = start(options);
  } catch (const InputError&) {
    throw;
  } catch (const OutputError&) {  // a full disk is impact.OutputError (an OSError), not RunError
    throw;
  } catch (const std::exception& e) {
    code = mpm::kExitRunFailed;
    message = e.what();
  }
  return py::make_tuple(code, message, signals.exception());
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
        out["refusal"] = mpm::start_refusal(scene);
        if (out["refusal"].get<std::string>().empty())
          out["report"] = mpm::check_report(scene, mpm::run_threads(threads));
        return out.dump();
      },
      py::arg("file"), py::arg("text"), py::arg("label"), py::arg("patches"), py::arg("threads"));
  // (exit code, directory, warnings, message, exception): `warn` gets the scene's warnings
  // before the run starts; a scene the memory or step estimate refuses is not started (exit 4, the
  // refusal as message).
  m.def(
      "run_scene",
      [](const std::string& file, const std::string& text, const std::string& label,
         const std::vector<std::string>& patches, const std::string& out_dir, int threads,
         bool progress, bool overwrite,
         const std::function<void(const std::vector<std::string>&)>& warn) {
        const mpm::Scene scene = scene_of(file, text, label, patches);
        warn(scene.warnings);
        const std::string dir = out_dir.empty() ? scene.output.directory : out_dir;
        if (const std::string refusal = mpm::start_refusal(scene); !refusal.empty())
          return py::make_tuple(mpm::kExitMemory, dir, scene.warnings, refusal, py::none());
        mpm::RunOptions options;
        options.out_dir = out_dir;
        options.threads = threads;
        options.progress = progress;
        options.overwrite = overwrite;
        const py::tuple r =
            run_polled([&scene](const mpm::RunOptions& o) { return mpm::run(scene, o); }, options);
        return py::make_tuple(r[0], dir, scene.warnings, r[1], r[2]);
      },
      py::arg("file"), py::arg("text"), py::arg("label"), py::arg("patches"), py::arg("out_dir"),
      py::arg("threads"), py::arg("progress"), py::arg("overwrite"), py::arg("warn"));
  // (exit code, message, exception) of `mpm run --restart DIR`.
  m.def(
      "resume_scene",
      [](const std::string& dir, int threads, bool progress) {
        mpm::RunOptions options;
        options.threads = threads;
        options.progress = progress;
        return run_polled([&dir](const mpm::RunOptions& o) { return mpm::restart(dir, o); },
                          options);
      },
      py::arg("directory"), py::arg("threads"), py::arg("progress"));
  m.attr("exit_run_failed") = mpm::kExitRunFailed;
  m.attr("exit_memory") = mpm::kExitMemory;
  m.attr("exit_signal_base") = mpm::kExitSignalBase;
}

}  // namespace impact::python
