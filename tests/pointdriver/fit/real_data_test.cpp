// The fit against real 6061-T6 curves (data/experiments/al6061_t6/, converted from the digitized
// collection): fitting B, n, C (A held at the curves' 0.2 % offset yield, 293.5 MPa; m fixed) to
// the room-temperature curves from 1e-3 to 29000 /s through the driver must give a lower RMS
// stress error than the report's published set (data/materials/al6061_t6.json: C = 0.002
// under-predicts rate hardening). Measured with the shipped configuration
// data/fits/al6061_t6_room_temperature.json (60 steps per test): 25.9 MPa against 41.7 MPa. Here
// with 40 steps per test to keep the test short; the assertion is that the fitted RMS is at least
// 25 % lower, that the fitted C exceeds the published 0.002, and that no free parameter ended on
// a bound (with A free, A ran to its 1 MPa lower bound: docs/fitting.md, worked example 2).
#include <boost/test/unit_test.hpp>

#include "pointdriver/fit/fit_config.hpp"
#include "pointdriver/fit/strength_fit.hpp"

using namespace impact;
using namespace impact::pointdriver::fit;

BOOST_AUTO_TEST_CASE(room_temperature_fit_beats_the_published_set) {
  FitConfig config = read_fit_config(std::string(IMPACT_SOURCE_DIR) +
                                     "/data/fits/al6061_t6_room_temperature.json");
  config.curves.steps = 40;
  const StrengthFit fit = fit_strength(config);
  BOOST_TEST_MESSAGE("fitted RMS " << fit.overall_fitted.rms / 1e6 << " MPa, published "
                                   << fit.overall_material.rms / 1e6 << " MPa; C = "
                                   << fit.fitted[3] << ", " << fit.lsq.wall_time << " s");
  BOOST_TEST(fit.experiments.size() >= 15u);
  BOOST_TEST(fit.overall_fitted.rms < 0.75 * fit.overall_material.rms);
  BOOST_TEST(fit.fitted[3] > 0.002);
  BOOST_TEST(fit.fitted[4] == 1.34);     // fixed
  BOOST_TEST(fit.fitted[0] == 293.5e6);  // held
  BOOST_TEST(fit.at_bound_messages().empty());
}
