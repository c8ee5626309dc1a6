// impact._impact: the extension module. Input errors surface as impact.InputError (a ValueError
// whose message names the file and the JSON key path, as on the command line), outputs that
// cannot be written as impact.OutputError (an OSError naming the file).
#include <pybind11/pybind11.h>

#include "python/bindings/bindings.hpp"
#include "support/atomic_file.hpp"

namespace impact::python {

Json parse_json(const std::string& text, const std::string& what) {
  return parse_json_text(text, what);
}

std::vector<Json> parse_patches(const std::vector<std::string>& texts) {
  std::vector<Json> out;
  for (std::size_t k = 0; k < texts.size(); ++k)
    out.push_back(parse_json(texts[k], "patches[" + std::to_string(k) + "]"));
  return out;
}

PatchOrigins patch_origins(const std::string& file, const std::vector<Json>& patches) {
  return PatchOrigins(file, patches,
                      [](std::size_t k) { return "patches[" + std::to_string(k) + "]"; });
}

}  // namespace impact::python

PYBIND11_MODULE(_impact, m) {
  namespace py = pybind11;
  m.doc() = "impact-mpm: material models, point driver, fitting and the MPM solver";
  py::register_exception<impact::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<impact::OutputError>(m, "OutputError", PyExc_OSError);
  impact::python::bind_material(m);
  impact::python::bind_path(m);
  impact::python::bind_fit(m);
  impact::python::bind_scene(m);
  m.def(
      "merge_patch",
      [](const std::string& target, const std::string& patch, const std::string& target_name,
         const std::string& patch_name) {
        impact::Json document = impact::python::parse_json(target, target_name);
        document.merge_patch(impact::python::parse_json(patch, patch_name));
        return document.dump();
      },
      py::arg("target"), py::arg("patch"), py::arg("target_name") = "merge_patch target",
      py::arg("patch_name") = "merge_patch patch");
#ifdef IMPACT_VERSION
  m.attr("__version__") = IMPACT_VERSION;
#endif
}
