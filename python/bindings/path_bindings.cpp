// Point-driver paths: a path file (with merge patches) or document run through the driver; the
// rows come back as the CSV's columns (`name [unit]`, docs/pointdriver.md), one NumPy array each.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "pointdriver/driver/driver.hpp"
#include "pointdriver/output/csv_writer.hpp"
#include "pointdriver/path/path.hpp"
#include "python/bindings/bindings.hpp"

namespace impact::python {

namespace {

namespace pd = impact::pointdriver;

py::dict run(const pd::Path& path) {
  const auto& names = pd::csv_columns();
  std::vector<std::vector<double>> columns(names.size());
  pd::RunResult result;
  {
    py::gil_scoped_release release;
    const ElasticPlasticParams& params = path.material.model.params();
    result = pd::run_path(path, [&](const pd::Row& row) {
      const std::vector<double> v = pd::csv_values(row, params);
      for (std::size_t c = 0; c < v.size(); ++c) columns[c].push_back(v[c]);
    });
  }
  py::dict cols;
  for (std::size_t c = 0; c < names.size(); ++c)
    cols[py::str(names[c])] =
        py::array_t<double>(static_cast<py::ssize_t>(columns[c].size()), columns[c].data());
  py::dict out;
  out["columns"] = cols;
  out["completed"] = result.completed;
  out["steps"] = result.steps;
  out["end_time"] = result.end_time;
  out["failure"] = std::string(to_string(result.failure));
  out["failure_time"] = result.failure_time;
  out["error"] = result.error;
  out["replay"] = result.replay ? result.replay->dump() : std::string();  // repeats a failed step
  out["warnings"] = path.warnings;
  return out;
}

}  // namespace

void bind_path(py::module_& m) {
  m.def(
      "run_path_file",
      [](const std::string& file, const std::vector<std::string>& patches) {
        const std::vector<Json> parsed = parse_patches(patches);
        const PatchOrigins origins = patch_origins(file, parsed);
        pd::Path path;
        try {
          path = pd::load_path(file, parsed);
        } catch (const InputError& e) {
          throw origins.attribute(e);
        }
        path.warnings = origins.attribute(path.warnings);
        return run(path);
      },
      py::arg("file"), py::arg("patches") = std::vector<std::string>{});
  m.def(
      "run_path_document",
      [](const std::string& text, const std::string& label) {
        return run(pd::read_path(parse_json(text, label), label));
      },
      py::arg("text"), py::arg("label"));
}

}  // namespace impact::python
