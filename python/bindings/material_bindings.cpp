// Materials and updates: a material from a file (with merge patches) or a JSON document, and the
// constitutive update of a batch of points (NumPy arrays, leading dimension N), done by the same
// UpdateBatch the MPM solver drives, so every point gets the bits ElasticPlastic::update gives.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <vector>

#include "models/kinematics/deformation_gradient.hpp"
#include "models/material/material.hpp"
#include "models/material/update_batch.hpp"
#include "python/bindings/bindings.hpp"

namespace impact::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The scalar history fields of PointState, by their names in a state dict.
struct ScalarField {
  const char* name;
  double PointState::*member;
};
constexpr std::array<ScalarField, 6> kScalars{
    {{"plastic_strain", &PointState::plastic_strain},
     {"plastic_strain_rate", &PointState::plastic_strain_rate},
     {"temperature", &PointState::temperature},
     {"internal_energy", &PointState::internal_energy},
     {"damage", &PointState::damage},
     {"porosity", &PointState::porosity}}};
struct TensorField {
  const char* name;
  Mat3 PointState::*member;
};
constexpr std::array<TensorField, 3> kTensors{
    {{"stress", &PointState::stress}, {"F", &PointState::F}, {"R", &PointState::R}}};
struct FlagField {
  const char* name;
  bool PointState::*member;
};
constexpr std::array<FlagField, 3> kFlags{{{"melted", &PointState::melted},
                                           {"failed", &PointState::failed},
                                           {"failed_in_tension", &PointState::failed_in_tension}}};

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

/// `a` as N 3x3 tensors; `what` names it in the error.
Array tensors(const py::handle& h, py::ssize_t n, const std::string& what) {
  Array a = Array::ensure(h);
  if (!a || a.ndim() != 3 || a.shape(0) != n || a.shape(1) != 3 || a.shape(2) != 3) {
    throw py::value_error(what + ": expected an array of shape (" + std::to_string(n) +
                          ", 3, 3), got " + (a ? shape_text(a) : std::string("no array")));
  }
  return a;
}

/// The N tensors of `a` (shape checked by tensors()).
std::vector<Mat3> tensor_list(const Array& a) {
  const auto v = a.unchecked<3>();
  std::vector<Mat3> out(static_cast<std::size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[i](r, c) = v(i, r, c);
  return out;
}

/// state[name] as N values; `name` is named in the error.
Array scalars(const py::dict& state, const char* name, py::ssize_t n) {
  Array a = Array::ensure(state[name]);
  if (!a || a.ndim() != 1 || a.shape(0) != n)
    throw py::value_error(std::string("state['") + name + "']: expected an array of shape (" +
                          std::to_string(n) + ",)");
  return a;
}

/// The N points of a state dict. A key not given keeps the material's initial state at its room
/// temperature (so {"temperature": T} alone is a batch at rest at T).
std::vector<PointState> read_states(const ElasticPlastic& model, const py::dict& state,
                                    py::ssize_t n) {
  std::vector<PointState> out(static_cast<std::size_t>(n),
                              model.initial_state(model.params().room_temperature));
  for (const auto& f : kTensors) {
    if (!state.contains(f.name)) continue;
    const auto t = tensor_list(tensors(state[f.name], n, std::string("state['") + f.name + "']"));
    for (py::ssize_t i = 0; i < n; ++i) out[i].*f.member = t[i];
  }
  for (const auto& f : kScalars) {
    if (!state.contains(f.name)) continue;
    const auto v = scalars(state, f.name, n).unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) out[i].*f.member = v(i);
  }
  for (const auto& f : kFlags) {
    if (!state.contains(f.name)) continue;
    const auto v = scalars(state, f.name, n).unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) out[i].*f.member = v(i) != 0.0;
  }
  if (state.contains("failure_cause")) {
    const auto v = scalars(state, "failure_cause", n).unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
      if (v(i) < 0.0 || v(i) > static_cast<double>(FailureCause::becker))
        throw py::value_error("state['failure_cause']: expected codes 0-4 (impact.failure_causes)");
      out[i].failure_cause = static_cast<FailureCause>(static_cast<int>(v(i)));
    }
  }
  if (state.contains("instability")) {
    const auto v = scalars(state, "instability", n).unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) out[i].instability = static_cast<std::uint8_t>(v(i));
  }
  return out;
}

py::dict write_states(const std::vector<PointState>& s) {
  const auto n = static_cast<py::ssize_t>(s.size());
  py::dict out;
  for (const auto& f : kTensors) {
    Array a({n, py::ssize_t{3}, py::ssize_t{3}});
    auto v = a.mutable_unchecked<3>();
    for (py::ssize_t i = 0; i < n; ++i)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) v(i, r, c) = (s[i].*f.member)(r, c);
    out[f.name] = a;
  }
  for (const auto& f : kScalars) {
    Array a(n);
    auto v = a.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) v(i) = s[i].*f.member;
    out[f.name] = a;
  }
  for (const auto& f : kFlags) {
    py::array_t<bool> a(n);
    for (py::ssize_t i = 0; i < n; ++i) a.mutable_at(i) = s[i].*f.member;
    out[f.name] = a;
  }
  py::array_t<std::uint8_t> cause(n), instability(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    cause.mutable_at(i) = static_cast<std::uint8_t>(s[i].failure_cause);
    instability.mutable_at(i) = s[i].instability;
  }
  out["failure_cause"] = cause;
  out["instability"] = instability;
  return out;
}

py::dict write_reports(const std::vector<StepReport>& r) {
  const auto n = static_cast<py::ssize_t>(r.size());
  py::array_t<std::uint8_t> status(n), failure(n);
  py::array_t<bool> plastic(n);
  py::array_t<int> iterations(n);
  Array wave(n), work(n), heating(n), eroded(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    status.mutable_at(i) = static_cast<std::uint8_t>(r[i].status);
    failure.mutable_at(i) = static_cast<std::uint8_t>(r[i].failure);
    plastic.mutable_at(i) = r[i].plastic;
    iterations.mutable_at(i) = r[i].return_iterations;
    wave.mutable_at(i) = r[i].wave_speed;
    work.mutable_at(i) = r[i].plastic_work;
    heating.mutable_at(i) = r[i].temperature_rise;
    eroded.mutable_at(i) = r[i].eroded_energy;
  }
  py::dict out;
  out["status"] = status;
  out["failure"] = failure;
  out["plastic"] = plastic;
  out["return_iterations"] = iterations;
  out["wave_speed"] = wave;
  out["plastic_work"] = work;
  out["temperature_rise"] = heating;
  out["eroded_energy"] = eroded;
  return out;
}

/// One step of N points: (new state, report). F1 defaults to exp(L dt) F0 per point.
py::tuple update(const Material& material, const py::dict& state, const py::handle& L_in, double dt,
                 const py::object& F1_in) {
  if (!(dt > 0.0)) throw py::value_error("dt: expected a time step > 0 [s]");
  const Array L0 = Array::ensure(L_in);
  if (!L0 || L0.ndim() != 3)
    throw py::value_error("L: expected velocity gradients of shape (N, 3, 3) [1/s]");
  const py::ssize_t n = L0.shape(0);
  const Array L = tensors(L0, n, "L");
  const ElasticPlastic& model = material.model;
  std::vector<PointState> s0 = read_states(model, state, n), s1 = s0;
  const std::vector<Mat3> Ls = tensor_list(L);
  std::vector<Mat3> F1s(n);
  if (F1_in.is_none()) {
    for (py::ssize_t i = 0; i < n; ++i)
      F1s[i] = advance_deformation_gradient(s0[i].F, Ls[i], dt, FIntegration::exponential);
  } else {
    F1s = tensor_list(tensors(F1_in, n, "F1"));
  }
  std::vector<StepReport> reports(n);
  {
    py::gil_scoped_release release;
    UpdateBatch batch;
    for (py::ssize_t first = 0; first < n; first += UpdateBatch::capacity) {
      batch.clear();
      const py::ssize_t last = std::min<py::ssize_t>(n, first + UpdateBatch::capacity);
      for (py::ssize_t i = first; i < last; ++i) batch.add(model, s0[i], Ls[i], F1s[i], s1[i]);
      batch.run(dt);
      for (py::ssize_t i = first; i < last; ++i)
        reports[i] = batch.finish(static_cast<int>(i - first), dt, s1[i]);
    }
  }
  return py::make_tuple(write_states(s1), write_reports(reports));
}

Material load(const std::string& file, const std::vector<std::string>& patches) {
  std::vector<Json> parsed;
  for (std::size_t k = 0; k < patches.size(); ++k)
    parsed.push_back(parse_json(patches[k], "patch " + std::to_string(k)));
  return load_material(file, parsed);
}

}  // namespace

void bind_material(py::module_& m) {
  py::class_<Material>(m, "Material")
      .def_readonly("name", &Material::name)
      .def_readonly("file", &Material::file)
      .def_readonly("warnings", &Material::warnings)
      .def("to_json", [](const Material& mat) { return to_json(mat).dump(); })
      .def(
          "initial_state",
          [](const Material& mat, double temperature, int n) {
            return write_states(std::vector<PointState>(static_cast<std::size_t>(n),
                                                        mat.model.initial_state(temperature)));
          },
          py::arg("temperature"), py::arg("n") = 1)
      .def_property_readonly(
          "room_temperature",
          [](const Material& mat) { return mat.model.params().room_temperature; })
      .def_property_readonly("density",
                             [](const Material& mat) { return mat.model.params().density; })
      .def("wave_speed",
           [](const Material& mat, double rho, double e) { return mat.model.wave_speed(rho, e); });
  m.def("load_material", &load, py::arg("file"), py::arg("patches") = std::vector<std::string>{});
  m.def(
      "read_material",
      [](const std::string& text, const std::string& label) {
        return read_material(parse_json(text, label), label);
      },
      py::arg("text"), py::arg("label"));
  m.def("update", &update, py::arg("material"), py::arg("state"), py::arg("L"), py::arg("dt"),
        py::arg("F1") = py::none());
  py::list status, causes;
  for (int k = 0; k <= static_cast<int>(UpdateStatus::non_finite_wave_speed); ++k)
    status.append(std::string(to_string(static_cast<UpdateStatus>(k))));
  for (int k = 0; k <= static_cast<int>(FailureCause::becker); ++k)
    causes.append(std::string(to_string(static_cast<FailureCause>(k))));
  m.attr("update_status_names") = status;
  m.attr("failure_cause_names") = causes;
}

}  // namespace impact::python
