// Outside consumer of find_package(Impact): runs a point-driver path (uniaxial stress, elastic:
// sigma_xx = E eps_xx with E = 9 K mu / (3 K + mu)) and validates an MPM scene (a 20 mm cube of
// density 2700 kg/m^3: 0.0216 kg). Exit 0 when both agree to 1e-6.
#include <cmath>
#include <iostream>

#include "mpm/input/scene_reader.hpp"
#include "mpm/run/summary.hpp"
#include "mpm/scene/scene.hpp"
#include "pointdriver/driver/driver.hpp"
#include "pointdriver/path/path.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: install_consumer_all MATERIAL.json SCENE.json\n";
    return 1;
  }
  const impact::Json document = {{"material", argv[1]},
                                 {"temperature", 294.0},
                                 {"legs",
                                  {{{"duration", 1e-6},
                                    {"steps", 10},
                                    {"velocity_gradient", {{"xx", 1.0}}},
                                    {"stress", {{"yy", 0.0}, {"zz", 0.0}}}}}}};
  const auto path = impact::pointdriver::read_path(document, "consumer path");
  double stress = 0.0, strain = 0.0;
  impact::pointdriver::run_path(path, [&](const impact::pointdriver::Row& row) {
    stress = row.state.stress(0, 0);
    strain = std::log(row.F(0, 0));
  });
  const auto& p = path.material.model.params();
  const double E =
      9.0 * p.bulk_modulus * p.shear_modulus / (3.0 * p.bulk_modulus + p.shear_modulus);
  const double path_error = std::abs(stress / strain - E) / E;

  const impact::mpm::Scene scene = impact::mpm::load_scene(argv[2]);
  const double mass = impact::mpm::check_report(scene, 1)["mass [kg]"].get<double>();
  const double mass_error = std::abs(mass - 2700.0 * 0.02 * 0.02 * 0.02) / mass;
  std::cout << "E from the path " << stress / strain << " Pa (relative error " << path_error
            << "), scene mass " << mass << " kg (relative error " << mass_error << ")\n";
  return path_error < 1e-6 && mass_error < 1e-6 ? 0 : 3;
}
