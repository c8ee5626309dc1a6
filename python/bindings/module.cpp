// impact._impact: the extension module. Input errors surface as impact.InputError (a ValueError
// whose message names the file and the JSON key path, as on the command line).
#include <pybind11/pybind11.h>

#include "python/bindings/bindings.hpp"

namespace impact::python {

Json parse_json(const std::string& text, const std::string& what) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw InputError({what + ": invalid JSON: " + e.what()});
  }
}

}  // namespace impact::python

PYBIND11_MODULE(_impact, m) {
  namespace py = pybind11;
  m.doc() = "impact-mpm: material models, point driver, fitting and the MPM solver";
  py::register_exception<impact::InputError>(m, "InputError", PyExc_ValueError);
  impact::python::bind_material(m);
  impact::python::bind_path(m);
  impact::python::bind_fit(m);
  impact::python::bind_scene(m);
  m.def(
      "merge_patch",
      [](const std::string& target, const std::string& patch) {
        impact::Json document = impact::python::parse_json(target, "merge_patch target");
        document.merge_patch(impact::python::parse_json(patch, "merge_patch patch"));
        return document.dump();
      },
      py::arg("target"), py::arg("patch"));
#ifdef IMPACT_VERSION
  m.attr("__version__") = IMPACT_VERSION;
#endif
}
