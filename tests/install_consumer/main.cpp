// Outside consumer of the installed library: loads a material and checks one elastic
// uniaxial-strain step against sigma_xx = (K + 4 mu / 3) eps. Exit 0 on agreement to 1e-10.
#include <cmath>
#include <iostream>

#include "models/material/material.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: install_consumer MATERIAL.json\n";
    return 1;
  }
  const impact::Material m = impact::load_material(argv[1]);
  const auto& p = m.model.params();
  const double rate = 1.0, dt = 1e-6;  // eps = 1e-6, far below yield
  impact::Mat3 L = impact::Mat3::Zero();
  L(0, 0) = rate;
  impact::Mat3 F1 = impact::Mat3::Identity();
  F1(0, 0) = std::exp(rate * dt);
  impact::PointState s1;
  m.model.update(m.model.initial_state(294.0), L, F1, dt, s1);
  const double expected = (p.bulk_modulus + 4.0 * p.shear_modulus / 3.0) * rate * dt;
  const double error = std::abs(s1.stress(0, 0) - expected) / expected;
  std::cout << "sigma_xx = " << s1.stress(0, 0) << " Pa, expected " << expected
            << " Pa, relative error " << error << '\n';
  return error < 1e-10 ? 0 : 3;
}
