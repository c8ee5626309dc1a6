// The shear modulus models (models/elasticity/shear_modulus.hpp) against values computed from the
// papers' equations in Python (the expressions written out again, test constants of the order of
// copper's and tantalum's), the reader, and the modulus in the elastic update: an elastic shear
// step under pressure and temperature gives the deviator 2 mu(p, T) gamma and the wave speed
// sqrt((K + 4 mu / 3) / rho) of that mu.
#include "models/elasticity/shear_modulus.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "models/material/material.hpp"

using namespace impact;

namespace {

bool close(double a, double b) {
  return std::abs(a - b) <= 1e-12 * std::abs(b);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(elasticity_shear_modulus)

// Python: mu0 - D / expm1(T0 / T); mu0 + G'_p p / eta^(1/3) + G'_T (T - 300);
// ((mu0 + G'_p p / eta^(1/3))(1 - t) + rho k_B T / (C M / N_A)) / (1 + exp(-(1 + 1/zeta) /
// (1 + zeta / (1 - t)))), t = T / T_m.
BOOST_AUTO_TEST_CASE(every_form_equals_its_papers_equation) {
  BOOST_TEST(shear_modulus(ConstantShearModulus{}, 26e9, {900.0, 5e9, 1.2, 3000.0, 925.0}) == 26e9);
  const VarshniShearModulus varshni{3.0e9, 180.0};
  BOOST_TEST(
      close(shear_modulus(varshni, 47.7e9, {600.0, 0.0, 1.0, 8960.0, 1356.0}), 39125112259.46975));
  BOOST_TEST(
      close(shear_modulus(varshni, 47.7e9, {294.0, 0.0, 1.0, 8960.0, 1356.0}), 44147886554.70808));
  const SteinbergShearModulus scg{1.45e-11 * 69e9, -1.3e-4 * 69e9};
  BOOST_TEST(
      close(shear_modulus(scg, 69e9, {800.0, 20e9, 1.1, 18000.0, 3290.0}), 83899273416.09079));
  BOOST_TEST(shear_modulus(scg, 69e9, {1e5, 0.0, 1.0, 16600.0, 3290.0}) == 0.0);  // floored
  const NadalLePoacShearModulus np{1.5, 0.04, 0.057, 63.546e-3};
  BOOST_TEST(
      close(shear_modulus(np, 50e9, {700.0, 10e9, 1.05, 9400.0, 1356.0}), 46432539574.56053));
  BOOST_TEST(close(shear_modulus(np, 50e9, {300.0, 0.0, 1.0, 8960.0, 1356.0}), 45108269206.74808));
  BOOST_TEST(shear_modulus(np, 50e9, {1500.0, 0.0, 1.0, 8960.0, 1356.0}) == 0.0);  // T^ > 1 + zeta
}

// shear_modulus_with_slope: mu is shear_modulus()'s, bit for bit, and d mu / d T its central
// difference at fixed p and rho (the MTS law's d sigma / d T uses it); 0 where mu is floored.
BOOST_AUTO_TEST_CASE(the_slope_is_the_temperature_derivative_of_the_same_expression) {
  const std::vector<ShearModulusLaw> laws = {ConstantShearModulus{},
                                             VarshniShearModulus{3.0e9, 180.0},
                                             SteinbergShearModulus{1.45e-11 * 69e9, -1.3e-4 * 69e9},
                                             NadalLePoacShearModulus{1.8, 0.04, 0.080, 55.947e-3}};
  for (const ShearModulusLaw& law : laws)
    for (const double T : {150.0, 294.0, 700.0, 1500.0}) {
      const ModulusConditions c{T, 2e9, 1.01, 7900.0, 1793.0};
      const ModulusWithSlope m = shear_modulus_with_slope(law, 90e9, c);
      const double h = 1e-3 * T;
      ModulusConditions up = c, down = c;
      up.temperature += h;
      down.temperature -= h;
      const double fd = (shear_modulus(law, 90e9, up) - shear_modulus(law, 90e9, down)) / (2 * h);
      BOOST_TEST_CONTEXT(model_type(law) << " at " << T << " K") {
        BOOST_TEST(m.mu == shear_modulus(law, 90e9, c));
        BOOST_TEST(std::abs(m.d_T - fd) <= 1e-5 * std::max(std::abs(fd), 1e3));
      }
    }
  // Floored (Nadal-Le Poac above T_m (1 + zeta)): mu 0, slope 0.
  const ModulusWithSlope hot =
      shear_modulus_with_slope(NadalLePoacShearModulus{1.8, 0.04, 0.080, 55.947e-3}, 90e9,
                               {1900.0, 0.0, 1.0, 7810.0, 1793.0});
  BOOST_TEST(hot.mu == 0.0);
  BOOST_TEST(hot.d_T == 0.0);
}

BOOST_AUTO_TEST_CASE(the_reader_defaults_to_constant_and_names_missing_constants) {
  InputProblems problems("mat.json");
  const Json empty = Json::object();
  JsonReader r0(empty, "/constitutive_model/shear_modulus", problems);
  BOOST_TEST(is_constant(read_shear_modulus(r0)));
  const Json varshni = {{"type", "varshni"}, {"D", 3e9}};
  JsonReader r1(varshni, "/constitutive_model/shear_modulus", problems);
  read_shear_modulus(r1);
  BOOST_REQUIRE(problems.count() == 1u);
  try {
    problems.throw_if_any();
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("mat.json: /constitutive_model/shear_modulus/T0: "
                                          "missing required number") != std::string::npos);
  }
  const Json scg = {{"type", "steinberg_cochran_guinan"}, {"dG_dp", 1.8}, {"dG_dT", -1.7e7}};
  InputProblems fine("mat.json");
  JsonReader r2(scg, "/constitutive_model/shear_modulus", fine);
  const ShearModulusLaw law = read_shear_modulus(r2);
  BOOST_TEST(fine.empty());
  BOOST_TEST(to_json(law) ==
             Json({{"type", "steinberg_cochran_guinan"}, {"dG_dp", 1.8}, {"dG_dT", -1.7e7}}));
}

// 6061-T6 with the SCG modulus (Steinberg 1996: G'_p = 65.0e-12 /Pa x 27.6 GPa, G'_T = -0.62e-3
// /K x 27.6 GPa, here on the file's mu0 = 26 GPa): a point at 400 K under 2 GPa of pressure takes
// a shear step far below yield. Its shear stress is 2 mu gamma_xy with mu of the model at the
// step's start, and its wave speed uses that mu.
BOOST_AUTO_TEST_CASE(
    an_elastic_shear_step_uses_the_modulus_at_the_points_pressure_and_temperature) {
  const Json patch = {{"constitutive_model",
                       {{"shear_modulus",
                         {{"type", "steinberg_cochran_guinan"},
                          {"dG_dp", 65.0e-12 * 27.6e9},
                          {"dG_dT", -0.62e-3 * 27.6e9}}},
                        {"damage", {{"type", "none"}}},
                        {"erosion", {{"algorithm", "none"}}}}}};
  const Material m =
      load_material(std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json", patch);
  const ElasticPlasticParams& p = m.model.params();
  PointState s0 = m.model.initial_state(400.0);
  s0.stress = -2e9 * Mat3::Identity();  // 2 GPa of pressure, at rest in volume
  const double dt = 1e-9, gamma_rate = 1e3;
  Mat3 L = Mat3::Zero();
  L(0, 1) = L(1, 0) = gamma_rate;  // pure shear D_xy = 1e3 /s, no spin
  const Mat3 F1 = Mat3::Identity() + L * dt;
  PointState s1;
  const StepReport r = m.model.update(s0, L, F1, dt, s1);
  BOOST_REQUIRE(r.status == UpdateStatus::ok);
  BOOST_TEST(!r.plastic);
  const double mu = p.shear_modulus + 65.0e-12 * 27.6e9 * 2e9 - 0.62e-3 * 27.6e9 * (400.0 - 300.0);
  BOOST_TEST(std::abs(s1.stress(0, 1) - 2.0 * mu * gamma_rate * dt) <=
             1e-6 * 2.0 * mu * gamma_rate * dt);
  BOOST_TEST(std::abs(m.model.shear_modulus_of(s0) - mu) <= 1e-12 * mu);
  // Against mu0: the model's modulus differs by 7 % here, far beyond the tolerance.
  BOOST_TEST(std::abs(mu - p.shear_modulus) > 0.05 * p.shear_modulus);
}

BOOST_AUTO_TEST_SUITE_END()
