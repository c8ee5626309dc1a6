// The units of a plane-strain run's totals (mpm/ledger/extensive_units.hpp, docs/mpm.md#ledger):
// a plane-strain run books a slice of unit thickness, so its energies, masses, momenta, impulses
// and volumes are per metre of thickness and every label says so (issue 52: they were labelled J,
// kg, kg m/s and m^3). A block [0.02, 0.04]^2 m of elastic aluminium (rho0 2700 kg/m^3) at
// (30, -20) m/s: its mass is rho0 x 0.02^2 x 1 m = 1.08 kg per metre and its kinetic energy
// 1/2 x 1.08 x 1300 = 702 J per metre, under the labels `[kg/m]` and `[J/m]` in history.csv,
// summary.json (objects, observables, initial energy and momentum, units) and `mpm check`'s
// report; its 3D twin (the same block 1 m deep) keeps `[kg]` and `[J]`.
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>

#include "../verification_helpers.hpp"
#include "mpm/run/run.hpp"
#include "mpm/run/summary.hpp"

using namespace impact;
using namespace impact::mpm;
namespace fs = std::filesystem;
namespace tt = boost::test_tools;

namespace {

Json block(bool planar) {
  Json grid =
      planar ? Json{{"geometry", "plane_strain"},
                    {"lower", {0.0, 0.0}},
                    {"upper", {0.06, 0.06}},
                    {"cells", {12, 12}},
                    {"boundary", {{"x-", "free"}, {"x+", "free"}, {"y-", "free"}, {"y+", "free"}}}}
             : Json{{"lower", {0.0, 0.0, -0.5}},
                    {"upper", {0.06, 0.06, 0.5}},
                    {"cells", {12, 12, 1}},
                    {"boundary",
                     {{"x-", "free"},
                      {"x+", "free"},
                      {"y-", "free"},
                      {"y+", "free"},
                      {"z-", "symmetric"},
                      {"z+", "symmetric"}}}};
  return {{"grid", grid},
          {"objects",
           {{"block",
             {{"material", "elastic_al"},
              {"geometry",
               {{"type", "box"}, {"lower", {0.02, 0.02, -0.5}}, {"upper", {0.04, 0.04, 0.5}}}},
              {"velocity", {30.0, -20.0, 0.0}},
              {"particles_per_cell", planar ? Json{2, 2} : Json{2, 2, 1}}}}}},
          {"time", {{"max_time", 2.0e-6}}}};
}

Json run_summary_of(bool planar, const fs::path& dir, std::string& header) {
  RunOptions options;
  options.threads = 1;
  options.out_dir = dir.string();
  BOOST_REQUIRE(run(test::verification_scene("elastic_base.json", block(planar)), options) == 0);
  std::ifstream history(dir / "history.csv");
  std::getline(history, header);
  std::ifstream in(dir / "summary.json");
  return Json::parse(in);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_planar_units)

BOOST_AUTO_TEST_CASE(plane_strain_totals_are_per_metre_of_thickness_and_labelled_so) {
  const fs::path dir = fs::temp_directory_path() / ("mpm_units_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const double mass = 2700.0 * 0.02 * 0.02, energy = 0.5 * mass * (30.0 * 30.0 + 20.0 * 20.0);
  std::string header;
  const Json s = run_summary_of(true, dir / "planar", header);
  BOOST_TEST_MESSAGE(header);
  for (const char* column : {"kinetic_energy [J/m]", "strain_energy [J/m]", "total_energy [J/m]",
                             "momentum_x [(kg m/s)/m]", "boundary_impulse_x [(N s)/m]"})
    BOOST_TEST(header.find(column) != std::string::npos, column);
  BOOST_TEST(header.find("[J]") == std::string::npos);
  BOOST_TEST(s.at("units").at("energy") == "J/m");
  BOOST_TEST(s.at("units").at("mass") == "kg/m");
  BOOST_TEST(s.at("units").at("volume") == "m^3/m");
  BOOST_TEST(s.at("initial_energy [J/m]").get<double>() == energy, tt::tolerance(1e-12));
  BOOST_TEST(s.contains("initial_momentum [(kg m/s)/m]"));
  BOOST_TEST(s.at("mass [kg/m]").get<double>() == mass, tt::tolerance(1e-12));
  const Json& o = s.at("objects").at("block");
  BOOST_TEST(o.at("mass [kg/m]").get<double>() == mass, tt::tolerance(1e-12));
  BOOST_TEST(o.at("particle_volume [m^3/m]").get<double>() == 0.02 * 0.02, tt::tolerance(1e-12));
  BOOST_TEST(s.at("observables").at("objects").at("block").contains("kinetic_energy [J/m]"));
  const Json check = check_report(test::verification_scene("elastic_base.json", block(true)), 1);
  BOOST_TEST(check.at("objects").at("block").at("geometric_mass [kg/m]").get<double>() == mass,
             tt::tolerance(1e-12));

  const Json t = run_summary_of(false, dir / "twin", header);
  BOOST_TEST(header.find("kinetic_energy [J]") != std::string::npos, header);
  BOOST_TEST(t.at("units").at("energy") == "J");
  BOOST_TEST(t.at("objects").at("block").at("mass [kg]").get<double>() == mass,
             tt::tolerance(1e-12));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
