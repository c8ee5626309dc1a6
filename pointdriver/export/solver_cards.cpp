#include "pointdriver/export/solver_cards.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "pointdriver/format/text_format.hpp"

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

// The laws with cards: Johnson-Cook (both codes' built-in Johnson-Cook) and Swift with
// Cowper-Symonds (LS-DYNA's power-law plasticity; Abaqus's tabulated hardening with its power-law
// rate dependence). Another law is refused with the file, the key path and the laws that have.
void refuse_other_laws(const Material& m) {
  if (m.model.hyperelastic())
    throw std::invalid_argument(m.file +
                                ": /constitutive_model/type: neo_hookean has no flow stress; cards "
                                "are written for elastic_plastic materials only");
  const FlowStressLaw& law = m.model.params().flow_stress;
  if (std::holds_alternative<JohnsonCookParams>(law) ||
      std::holds_alternative<CowperSymondsParams>(law))
    return;
  throw std::invalid_argument(
      m.file + ": /constitutive_model/flow_stress/type: " + std::string(law_type(law)) +
      " has no LS-DYNA or Abaqus card; cards are written for " +
      std::string(JohnsonCookParams::kType) + " and " + std::string(CowperSymondsParams::kType) +
      " only");
}

// The SI quantities of a card, converted.
struct Converted {
  double density, G, E, nu, K, cp;
};
Converted convert(const Material& m, const UnitSystem& u) {
  const ElasticPlasticParams& p = m.model.params();
  const double s = u.stress_scale();
  const double K = p.bulk_modulus, G = p.shear_modulus;
  return {p.density / (u.mass / (u.length * u.length * u.length)),
          G / s,
          9.0 * K * G / (3.0 * K + G) / s,
          (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G)),
          K / s,
          p.specific_heat / (u.length * u.length / (u.time * u.time))};
}

std::string header(const Material& m, const UnitSystem& u, const char* comment) {
  std::ostringstream o;
  o << comment << ' ' << m.name << " (" << m.file << "), units " << u.name << " (stress "
    << u.stress << ", temperature K)\n";
  return o.str();
}

std::string mat_johnson_cook(const Material& material, const JohnsonCookParams& jc,
                             const UnitSystem& u, int id) {
  const ElasticPlasticParams& p = material.model.params();
  const Converted c = convert(material, u);
  const double s = u.stress_scale();
  // The card has Johnson-Cook damage's D1..D5 (zero without it).
  const auto* jc_damage = std::get_if<JohnsonCookDamageParams>(&p.damage);
  const JohnsonCookDamageParams d = jc_damage ? *jc_damage : JohnsonCookDamageParams{};
  std::ostringstream k;
  k << "$ rate term 1 + C ln(max(rate / EPSO, 1))"
    << (jc.rate_form == JohnsonCookRateForm::clamped ? "" : " (the source uses another form)")
    << "; no tensile cutoff (PC, SPALL 1)"
    << (jc_damage ? "" : "; the source has no damage model: D1..D5 are 0, set them before use")
    << '\n';
  k << "*MAT_JOHNSON_COOK\n";
  k << "$#     mid        ro         g         e        pr       dtf        vp    rateop\n";
  k << field(id) << row({c.density, c.G, c.E, c.nu, 0.0, 0.0, 0.0});
  k << "$#       a         b         n         c         m        tm        tr      epso\n";
  k << row({jc.A / s, jc.B / s, jc.n, jc.C, jc.m, p.melt_temperature, p.room_temperature,
            jc.reference_strain_rate * u.time});
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

// The number a 10-column field holds, as LS-DYNA reads it back.
double as_read(double v) {
  return std::stod(field(v));
}

// *MAT_POWER_LAW_PLASTICITY (MAT_018): sigma_y = k (eps_yp + ep)^N [1 + (rate / SRC)^(1/SRP)],
// with eps_yp set by SIGY: below 0.02 it is eps_yp itself, from 0.02 up a yield stress, eps_yp =
// (SIGY / k)^(1/N). Swift's K (eps0 + ep)^n is this with k = K, N = n, eps_yp = eps0: SIGY = eps0
// when it reads back below 0.02, else K eps0^n (a stress, which must then read back at or above
// 0.02 in the card's unit for LS-DYNA to take it as one). Cowper-Symonds' D and q are SRC and
// SRP; VP = 1 (the viscoplastic formulation) scales with the plastic strain rate, as the law.
std::string mat_power_law(const Material& material, const CowperSymondsParams& cs,
                          const UnitSystem& u, int id) {
  const ElasticPlasticParams& p = material.model.params();
  const Converted c = convert(material, u);
  const double s = u.stress_scale();
  double sigy = 0.0;  // n = 0: no strain offset (k (eps_yp + ep)^0 = k whatever eps_yp)
  const bool as_strain = as_read(cs.eps0) < 0.02;
  if (cs.n > 0.0) {
    sigy = as_strain ? cs.eps0 : cs.K * std::pow(cs.eps0, cs.n) / s;
    if (!as_strain && as_read(sigy) < 0.02) {
      throw std::invalid_argument(
          material.file + ": /constitutive_model/flow_stress/eps0: " + std::to_string(cs.eps0) +
          " needs SIGY = K eps0^n = " + std::to_string(sigy) + " " + u.stress +
          ", below 0.02, which LS-DYNA reads as a strain: no exact *MAT_POWER_LAW_PLASTICITY "
          "in units " +
          u.name + "; use a system with a smaller stress unit (SI or mm-s-tonne)");
    }
  }
  std::ostringstream k;
  k << "$ Swift K (eps0 + ep)^n as k (eps_yp + ep)^N: k = K, N = n, eps_yp = eps0 through SIGY ("
    << (cs.n == 0.0 ? "n = 0: unused"
        : as_strain ? "below 0.02: eps0 itself"
                    : "0.02 or more: the yield K eps0^n")
    << ")\n";
  k << "$ Cowper-Symonds 1 + (rate / SRC)^(1 / SRP), SRC = D, SRP = q; VP 1: the plastic strain "
       "rate, as the source (below its minimum_strain_rate "
    << format_number(cs.minimum_strain_rate)
    << " /s the source holds the factor, LS-DYNA lets it fall to 1)\n";
  k << "$ no temperature dependence or melting, no EOS card (pressure from E and PR: bulk modulus "
       "K)"
    << (std::holds_alternative<MieGruneisenParams>(p.equation_of_state)
            ? ": the source's Mie-Gruneisen EOS is not written"
            : "")
    << (std::holds_alternative<JohnsonCookDamageParams>(p.damage)
            ? "; the source's Johnson-Cook damage is not written (EPSF left blank)"
            : "")
    << '\n';
  k << "*MAT_POWER_LAW_PLASTICITY\n";
  k << "$#     mid        ro         e        pr         k         n       src       srp\n";
  k << field(id) << row({c.density, c.E, c.nu, cs.K / s, cs.n, cs.D * u.time, cs.q});
  k << "$#    sigy        vp\n" << row({sigy, 1.0});
  return k.str();
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
  refuse_other_laws(material);
  const FlowStressLaw& law = material.model.params().flow_stress;
  const std::string cards =
      std::holds_alternative<JohnsonCookParams>(law)
          ? mat_johnson_cook(material, std::get<JohnsonCookParams>(law), u, id)
          : mat_power_law(material, std::get<CowperSymondsParams>(law), u, id);
  return header(material, u, "$") + cards;
}

std::vector<std::array<double, 2>> swift_table(const CowperSymondsParams& cs) {
  if (cs.n == 0.0) return {{cs.K, 0.0}};
  std::vector<std::array<double, 2>> table;
  for (double x = cs.eps0;; x *= kSwiftTableRatio) {
    const double ep = std::min(x - cs.eps0, kSwiftTableEnd);
    table.push_back({cs.K * std::pow(cs.eps0 + ep, cs.n), ep});
    if (ep >= kSwiftTableEnd) break;
  }
  return table;
}

std::string abaqus_cards(const Material& material, const UnitSystem& u) {
  refuse_other_laws(material);
  const ElasticPlasticParams& p = material.model.params();
  const Converted c = convert(material, u);
  const double s = u.stress_scale();
  std::ostringstream a;
  a << header(material, u, "**");
  a << "*MATERIAL, NAME=" << std::filesystem::path(material.file).stem().string() << '\n';
  a << "*DENSITY\n" << data({c.density});
  a << "*ELASTIC\n" << data({c.E, c.nu});
  if (const auto* jc = std::get_if<JohnsonCookParams>(&p.flow_stress)) {
    a << "*PLASTIC, HARDENING=JOHNSON COOK\n"
      << data({jc->A / s, jc->B / s, jc->n, jc->m, p.melt_temperature, p.room_temperature});
    a << "*RATE DEPENDENT, TYPE=JOHNSON COOK\n"
      << data({jc->C, jc->reference_strain_rate * u.time});
  } else {
    // Abaqus has no Swift hardening: K (eps0 + ep)^n tabulated (yield stress, plastic strain),
    // and Cowper-Symonds is its power-law rate dependence, rate_p = D (sigma / sigma_0 - 1)^q.
    const CowperSymondsParams& cs = std::get<CowperSymondsParams>(p.flow_stress);
    const auto table = swift_table(cs);
    a << "** Swift K (eps0 + ep)^n tabulated to plastic strain " << format_number(kSwiftTableEnd)
      << " (" << table.size() << " points, eps0 + ep in ratios of at most "
      << format_number(kSwiftTableRatio)
      << ": linear interpolation within 1e-3 of the law; held constant beyond the last)\n";
    a << "*PLASTIC\n";
    for (const auto& [stress, ep] : table) a << data({stress / s, ep});
    a << "** Cowper-Symonds: D, q (below minimum_strain_rate "
      << format_number(cs.minimum_strain_rate)
      << " /s the source holds the factor, Abaqus lets it fall to 1)\n";
    a << "*RATE DEPENDENT, TYPE=POWER LAW\n" << data({cs.D * u.time, cs.q});
  }
  a << "*SPECIFIC HEAT\n" << data({c.cp});
  if (p.heating.enabled) a << "*INELASTIC HEAT FRACTION\n" << data({p.heating.taylor_quinney});
  return a.str();
}

}  // namespace impact::pointdriver
