// The C++ side of the Python module `impact` (python/impact/__init__.py is the public face). Each
// bind_* adds one concept's functions to the extension module `impact._impact`. JSON crosses the
// boundary as text (the Python side converts with its json module), arrays as NumPy arrays. Bad
// input raises impact.InputError (a ValueError), an output that cannot be written
// impact.OutputError (an OSError).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "models/core/input.hpp"
#include "support/patch_origins.hpp"

namespace impact::python {

namespace py = pybind11;

void bind_material(py::module_& m);  ///< material loading, one-point and batch updates
void bind_path(py::module_& m);      ///< point-driver paths
void bind_fit(py::module_& m);       ///< fit and check
void bind_scene(py::module_& m);     ///< MPM scenes

/// A JSON text from Python, parsed; a syntax error or a number no double holds (an int of 400
/// digits) is an InputError naming `what` (and the key).
Json parse_json(const std::string& text, const std::string& what);

/// Python's `patches` (JSON texts), parsed; messages call them patches[0], patches[1], ...
std::vector<Json> parse_patches(const std::vector<std::string>& texts);

/// Problems and warnings of `file` read with `patches` merged in, attributed to the patch that
/// set the key: "patches[0] (over FILE): /key: ...".
PatchOrigins patch_origins(const std::string& file, const std::vector<Json>& patches);

}  // namespace impact::python
