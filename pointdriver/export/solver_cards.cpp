#include "pointdriver/export/solver_cards.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace impact::pointdriver {

namespace {

const std::array<UnitSystem, 4> kSystems{{{"SI", "Pa", 1.0, 1.0, 1.0},
                                          {"mm-s-tonne", "MPa", 1e-3, 1e3, 1.0},
                                          {"mm-ms-kg", "GPa", 1e-3, 1.0, 1e-3},
                                          {"mm-ms-g", "MPa", 1e-3, 1e-3, 1e-3}}};

// v in a 10-character LS-DYNA field: the most significant digits that fit in 9 characters (one
// blank always separates the fields), the exponent written compactly as Fortran reads it
// ("6.8995e10", "2.7e-6").
std::string field(double v) {
  std::string text;
  for (int digits = 8; digits > 0; --digits) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    text = buffer;
    for (const auto& [from, to] : {std::pair{"e+0", "e"}, {"e+", "e"}, {"e-0", "e-"}})
      if (const auto at = text.find(from); at != std::string::npos)
        text.replace(at, std::string_view(from).size(), to);
    if (text.size() <= 9) break;
  }
  return std::string(10 - std::min<std::size_t>(text.size(), 10), ' ') + text;
}

std::string row(const std::vector<double>& values) {
  std::string r;
  for (double v : values) r += field(v);
  return r + '\n';
}

// Abaqus data lines: comma-separated, full precision.
std::string data(const std::vector<double>& values) {
  std::ostringstream o;
  o.precision(10);
  for (std::size_t i = 0; i < values.size(); ++i) o << (i ? ", " : "") << values[i];
  return o.str() + '\n';
}

const JohnsonCookParams& johnson_cook(const Material& m) {
  const auto* jc = std::get_if<JohnsonCookParams>(&m.model.params().flow_stress);
  if (jc == nullptr) {
    throw std::invalid_argument(m.file + ": /constitutive_model/flow_stress/type: " +
                                std::string(law_type(m.model.params().flow_stress)) +
                                " has no LS-DYNA or Abaqus card; cards are written for " +
                                std::string(JohnsonCookParams::kType) + " only");
  }
  return *jc;
}

// The SI quantities of a card, converted.
struct Converted {
  double density, G, E, nu, K, A, B, reference_rate, cp;
};
Converted convert(const Material& m, const UnitSystem& u) {
  const ElasticPlasticParams& p = m.model.params();
  const JohnsonCookParams& jc = johnson_cook(m);
  const double s = u.stress_scale();
  const double K = p.bulk_modulus, G = p.shear_modulus;
  return {p.density / (u.mass / (u.length * u.length * u.length)),
          G / s,
          9.0 * K * G / (3.0 * K + G) / s,
          (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G)),
          K / s,
          jc.A / s,
          jc.B / s,
          jc.reference_strain_rate * u.time,
          p.specific_heat / (u.length * u.length / (u.time * u.time))};
}

}  // namespace

const UnitSystem& unit_system(std::string_view name) {
  for (const UnitSystem& u : kSystems)
    if (u.name == name) return u;
  std::string known;
  for (const std::string& n : unit_system_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown unit system '" + std::string(name) + "' (known: " + known +
                              ")");
}

std::vector<std::string> unit_system_names() {
  std::vector<std::string> names;
  for (const UnitSystem& u : kSystems) names.push_back(u.name);
  return names;
}

std::string ls_dyna_cards(const Material& material, const UnitSystem& u, int id) {
  const ElasticPlasticParams& p = material.model.params();
  const JohnsonCookParams& jc = johnson_cook(material);
  const Converted c = convert(material, u);
  const JohnsonCookDamageParams d = p.damage.value_or(JohnsonCookDamageParams{});
  std::ostringstream k;
  k << "$ " << material.name << " (" << material.file << "), units " << u.name << " (stress "
    << u.stress << ", temperature K)\n";
  k << "$ rate term 1 + C ln(max(rate / EPSO, 1))"
    << (jc.rate_form == JohnsonCookRateForm::clamped ? "" : " (the source uses another form)")
    << "; no tensile cutoff (PC, SPALL 1)"
    << (p.damage ? "" : "; the source has no damage model: D1..D5 are 0, set them before use")
    << '\n';
  k << "*MAT_JOHNSON_COOK\n";
  k << "$#     mid        ro         g         e        pr       dtf        vp    rateop\n";
  k << field(id) << row({c.density, c.G, c.E, c.nu, 0.0, 0.0, 0.0});
  k << "$#       a         b         n         c         m        tm        tr      epso\n";
  k << row({c.A, c.B, jc.n, jc.C, jc.m, p.melt_temperature, p.room_temperature, c.reference_rate});
  k << "$#      cp        pc     spall        it        d1        d2        d3        d4\n";
  k << row({c.cp, -1e20, 1.0, 1.0, d.D1, d.D2, d.D3, d.D4});  // PC: no cutoff in any unit
  k << "$#      d5\n" << row({d.D5});
  if (const auto* mg = std::get_if<MieGruneisenParams>(&p.equation_of_state)) {
    k << "*EOS_GRUNEISEN\n";
    k << "$#   eosid         c        s1        s2        s3    gamao         a        e0\n";
    k << field(id)
      << row({mg->C0 * u.time / u.length, mg->S_alpha, 0.0, 0.0, mg->Gamma0, 0.0, 0.0});
    k << "$#      v0\n" << row({1.0});
  } else {
    k << "*EOS_LINEAR_POLYNOMIAL\n";
    k << "$#   eosid        c0        c1        c2        c3        c4        c5        c6\n";
    k << field(id) << row({0.0, c.K, 0.0, 0.0, 0.0, 0.0, 0.0});
    k << "$#      e0        v0\n" << row({0.0, 1.0});
  }
  return k.str();
}

std::string abaqus_cards(const Material& material, const UnitSystem& u) {
  const ElasticPlasticParams& p = material.model.params();
  const JohnsonCookParams& jc = johnson_cook(material);
  const Converted c = convert(material, u);
  std::ostringstream a;
  a << "** " << material.name << " (" << material.file << "), units " << u.name << " (stress "
    << u.stress << ", temperature K)\n";
  a << "*MATERIAL, NAME=" << std::filesystem::path(material.file).stem().string() << '\n';
  a << "*DENSITY\n" << data({c.density});
  a << "*ELASTIC\n" << data({c.E, c.nu});
  a << "*PLASTIC, HARDENING=JOHNSON COOK\n"
    << data({c.A, c.B, jc.n, jc.m, p.melt_temperature, p.room_temperature});
  a << "*RATE DEPENDENT, TYPE=JOHNSON COOK\n" << data({jc.C, c.reference_rate});
  a << "*SPECIFIC HEAT\n" << data({c.cp});
  if (p.heating.enabled) a << "*INELASTIC HEAT FRACTION\n" << data({p.heating.taylor_quinney});
  return a.str();
}

}  // namespace impact::pointdriver
