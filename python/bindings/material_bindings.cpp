// Materials and updates: a material from a file (with merge patches) or a JSON document, and the
// constitutive update of a batch of points (NumPy arrays, leading dimension N), done by the same
// UpdateBatch the MPM solver drives, so every point gets the bits ElasticPlastic::update gives.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "models/core/point_state_fields.hpp"
#include "models/kinematics/deformation_gradient.hpp"
#include "models/material/material.hpp"
#include "models/material/update_batch.hpp"
#include "python/bindings/bindings.hpp"

namespace impact::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The values a state dict's members may hold beyond their type, by member name: a NaN
/// temperature or a negative plastic strain would not stop the update, it would return nonsense.
/// The members themselves, their order and their types: kPointStateMembers
/// (models/core/point_state_fields.hpp); a number this list does not name must be finite, a
/// tensor finite, a flag 0 or 1, a code in its enumeration's range.
struct ScalarCheck {
  const char* name;
  bool (*admissible)(double);
  const char* expected;
};
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::array<ScalarCheck, 7> kScalarChecks{
    {{"plastic_strain", [](double v) { return v >= 0.0 && v < kInf; }, "a plastic strain >= 0 [-]"},
     {"plastic_strain_rate", [](double v) { return v >= 0.0 && v < kInf; },
      "a plastic strain rate >= 0 [1/s]"},
     {"temperature", [](double v) { return v > 0.0 && v < kInf; }, "a temperature > 0 [K]"},
     {"internal_energy", [](double v) { return std::isfinite(v); },
      "a finite specific internal energy [J/kg]"},
     // Johnson-Cook's D goes on past 1 (failure at D >= 1): no upper bound.
     {"damage", [](double v) { return v >= 0.0 && v < kInf; }, "a damage >= 0 [-]"},
     // TEPLA's void fraction, kept below 1 by the library (1 - f divides).
     {"porosity", [](double v) { return v >= 0.0 && v < 1.0; }, "a porosity in [0, 1) [-]"},
     {"flow_internal", [](double v) { return std::isfinite(v); },
      "a finite internal variable of the flow-stress law [Pa]"}}};
struct TensorCheck {
  const char* name;
  bool (*admissible)(const Mat3&);
  const char* expected;
};
constexpr std::array<TensorCheck, 3> kTensorChecks{
    {{"stress", [](const Mat3& s) { return s.allFinite(); }, "a finite stress [Pa]"},
     {"F", [](const Mat3& F) { return F.allFinite() && F.determinant() > 0.0; },
      "a deformation gradient with det F > 0"},
     {"R",
      [](const Mat3& R) {
        return R.allFinite() &&
               (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
               R.determinant() > 0.0;
      },
      "a rotation (R^T R = I to 1e-6, det R = 1)"}}};
/// A code member's largest value and what its values mean.
struct CodeCheck {
  const char* name;
  int max;
  const char* expected;
};
constexpr std::array<CodeCheck, 2> kCodeChecks{
    {{"failure_cause", static_cast<int>(kLastFailureCause), "codes 0-4 (impact.failure_causes)"},
     {"instability", kDruckerFired | kBeckerFired, "bits 0-3 (1 Drucker fired, 2 Becker fired)"}}};

/// The entry of `checks` for member `name`, or nullptr.
template <class Checks>
const typename Checks::value_type* check_of(const Checks& checks, const char* name) {
  for (const auto& c : checks)
    if (std::string_view(c.name) == name) return &c;
  return nullptr;
}

/// Every key a state dict may have.
std::vector<std::string> state_keys() {
  std::vector<std::string> keys;
  for_each_state_member([&](const auto& m) { keys.emplace_back(m.name); });
  return keys;
}

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// Refuses `what` when points fail `admissible`: names the first of them, its value (`shown`)
/// and how many there are.
template <class Admissible, class Shown>
void refuse_inadmissible(const std::string& what, py::ssize_t n, const char* expected,
                         Admissible admissible, Shown shown) {
  py::ssize_t first = -1, count = 0;
  for (py::ssize_t i = 0; i < n; ++i) {
    if (admissible(i)) continue;
    if (first < 0) first = i;
    ++count;
  }
  if (first < 0) return;
  throw InputError({what + "[" + std::to_string(first) + "]: expected " + expected + ", got " +
                    shown(first) + " (" + std::to_string(count) + " of " + std::to_string(n) +
                    " points)"});
}

std::string tensor_text(const Mat3& t) {
  std::string s = "[";
  for (int r = 0; r < 3; ++r) {
    s += r ? ", [" : "[";
    for (int c = 0; c < 3; ++c) s += (c ? ", " : "") + number_text(t(r, c));
    s += "]";
  }
  return s + "]";
}

/// `a` as N 3x3 tensors; `what` names it in the error.
Array tensors(const py::handle& h, py::ssize_t n, const std::string& what) {
  Array a = Array::ensure(h);
  if (!a || a.ndim() != 3 || a.shape(0) != n || a.shape(1) != 3 || a.shape(2) != 3) {
    throw InputError({what + ": expected an array of shape (" + std::to_string(n) +
                      ", 3, 3), got " + (a ? shape_text(a) : std::string("no numeric array"))});
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
    throw InputError({std::string("state['") + name + "']: expected an array of shape (" +
                      std::to_string(n) + ",), got " +
                      (a ? shape_text(a) : std::string("no numeric array"))});
  return a;
}

/// state[name] as N whole numbers in [0, max]; `expected` says what they are.
std::vector<int> codes(const py::dict& state, const char* name, py::ssize_t n, int max,
                       const char* expected) {
  const auto v = scalars(state, name, n).unchecked<1>();
  refuse_inadmissible(
      std::string("state['") + name + "']", n, expected,
      [&](py::ssize_t i) { return v(i) >= 0.0 && v(i) <= max && v(i) == std::floor(v(i)); },
      [&](py::ssize_t i) { return number_text(v(i)); });
  std::vector<int> out(static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) out[i] = static_cast<int>(v(i));
  return out;
}

/// The N points of a state dict. A key not given keeps the material's initial state at its room
/// temperature (so {"temperature": T} alone is a batch at rest at T); an unknown key (a typo that
/// would silently leave its field at rest) and inadmissible values are refused.
std::vector<PointState> read_states(const ElasticPlastic& model, const py::dict& state,
                                    py::ssize_t n) {
  const std::vector<std::string> known = state_keys();
  for (const auto& item : state) {
    const std::string key = py::str(item.first);
    if (py::isinstance<py::str>(item.first) &&
        std::find(known.begin(), known.end(), key) != known.end())
      continue;
    std::string message = "state[" + std::string(py::repr(item.first)) + "]: unknown key";
    if (const auto near = nearest_name(key, known)) message += " (did you mean " + *near + "?)";
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError({message + "; known: " + list});
  }
  std::vector<PointState> out(static_cast<std::size_t>(n),
                              model.initial_state(model.params().room_temperature));
  for_each_state_member([&](const auto& m) {
    using T = typename std::decay_t<decltype(m)>::Type;
    if (!state.contains(m.name)) return;
    const std::string what = std::string("state['") + m.name + "']";
    if constexpr (std::is_same_v<T, Mat3>) {
      const auto t = tensor_list(tensors(state[m.name], n, what));
      const TensorCheck* check = check_of(kTensorChecks, m.name);
      refuse_inadmissible(
          what, n, check ? check->expected : "a finite tensor",
          [&](py::ssize_t i) { return check ? check->admissible(t[i]) : t[i].allFinite(); },
          [&](py::ssize_t i) { return tensor_text(t[i]); });
      for (py::ssize_t i = 0; i < n; ++i) out[i].*m.member = t[i];
    } else if constexpr (std::is_same_v<T, double>) {
      const auto v = scalars(state, m.name, n).template unchecked<1>();
      const ScalarCheck* check = check_of(kScalarChecks, m.name);
      refuse_inadmissible(
          what, n, check ? check->expected : "a finite number",
          [&](py::ssize_t i) { return check ? check->admissible(v(i)) : std::isfinite(v(i)); },
          [&](py::ssize_t i) { return number_text(v(i)); });
      for (py::ssize_t i = 0; i < n; ++i) out[i].*m.member = v(i);
    } else if constexpr (std::is_same_v<T, bool>) {
      const auto v = codes(state, m.name, n, 1, "0 or 1 (False or True)");
      for (py::ssize_t i = 0; i < n; ++i) out[i].*m.member = v[i] != 0;
    } else {  // a code: FailureCause or bits
      const CodeCheck* check = check_of(kCodeChecks, m.name);
      const auto v = codes(state, m.name, n, check ? check->max : 255,
                           check ? check->expected : "codes 0-255");
      for (py::ssize_t i = 0; i < n; ++i) out[i].*m.member = static_cast<T>(v[i]);
    }
  });
  return out;
}

py::dict write_states(const std::vector<PointState>& s) {
  const auto n = static_cast<py::ssize_t>(s.size());
  py::dict out;
  for_each_state_member([&](const auto& m) {
    using T = typename std::decay_t<decltype(m)>::Type;
    if constexpr (std::is_same_v<T, Mat3>) {
      Array a({n, py::ssize_t{3}, py::ssize_t{3}});
      auto v = a.template mutable_unchecked<3>();
      for (py::ssize_t i = 0; i < n; ++i)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) v(i, r, c) = (s[i].*m.member)(r, c);
      out[m.name] = a;
    } else if constexpr (std::is_same_v<T, double>) {
      Array a(n);
      auto v = a.template mutable_unchecked<1>();
      for (py::ssize_t i = 0; i < n; ++i) v(i) = s[i].*m.member;
      out[m.name] = a;
    } else if constexpr (std::is_same_v<T, bool>) {
      py::array_t<bool> a(n);
      for (py::ssize_t i = 0; i < n; ++i) a.mutable_at(i) = s[i].*m.member;
      out[m.name] = a;
    } else {  // a code
      py::array_t<std::uint8_t> a(n);
      for (py::ssize_t i = 0; i < n; ++i)
        a.mutable_at(i) = static_cast<std::uint8_t>(s[i].*m.member);
      out[m.name] = a;
    }
  });
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
  if (!(dt > 0.0 && dt < kInf))
    throw InputError({"dt: expected a time step > 0 [s], got " + number_text(dt)});
  const Array L0 = Array::ensure(L_in);
  if (!L0 || L0.ndim() != 3)
    throw InputError({"L: expected velocity gradients of shape (N, 3, 3) [1/s], got " +
                      (L0 ? shape_text(L0) : std::string("no numeric array"))});
  const py::ssize_t n = L0.shape(0);
  const Array L = tensors(L0, n, "L");
  const ElasticPlastic& model = material.model;
  std::vector<PointState> s0 = read_states(model, state, n), s1 = s0;
  const std::vector<Mat3> Ls = tensor_list(L);
  refuse_inadmissible(
      "L", n, "a finite velocity gradient [1/s]", [&](py::ssize_t i) { return Ls[i].allFinite(); },
      [&](py::ssize_t i) { return tensor_text(Ls[i]); });
  std::vector<Mat3> F1s(n);
  if (F1_in.is_none()) {
    for (py::ssize_t i = 0; i < n; ++i)
      F1s[i] = advance_deformation_gradient(s0[i].F, Ls[i], dt, FIntegration::exponential);
  } else {
    F1s = tensor_list(tensors(F1_in, n, "F1"));
    refuse_inadmissible(
        "F1", n, "a deformation gradient with det F1 > 0",
        [&](py::ssize_t i) { return F1s[i].allFinite() && F1s[i].determinant() > 0.0; },
        [&](py::ssize_t i) { return tensor_text(F1s[i]); });
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
  const std::vector<Json> parsed = parse_patches(patches);
  const PatchOrigins origins = patch_origins(file, parsed);
  try {
    Material material = load_material(file, parsed);
    material.warnings = origins.attribute(material.warnings);
    return material;
  } catch (const InputError& e) {
    throw origins.attribute(e);
  }
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
