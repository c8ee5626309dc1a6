// The C++ side of the Python module `impact` (python/impact/__init__.py is the public face). Each
// bind_* adds one concept's functions to the extension module `impact._impact`. JSON crosses the
// boundary as text (the Python side converts with its json module), arrays as NumPy arrays.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "models/core/input.hpp"

namespace impact::python {

namespace py = pybind11;

void bind_material(py::module_& m);  ///< material loading, one-point and batch updates
void bind_path(py::module_& m);      ///< point-driver paths
void bind_fit(py::module_& m);       ///< fit and check
void bind_scene(py::module_& m);     ///< MPM scenes

/// A JSON text from Python, parsed; a syntax error is an InputError naming `what`.
Json parse_json(const std::string& text, const std::string& what);

}  // namespace impact::python
