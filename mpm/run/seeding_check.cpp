#include "mpm/run/seeding_check.hpp"

#include <cmath>
#include <sstream>

#include "mpm/scene/grid_coverage.hpp"
#include "mpm/scene/grid_geometry.hpp"
#include "mpm/scene/object_overlap.hpp"

namespace impact::mpm {

std::vector<std::string> seeding_warnings(const Scene& scene, const Particles& P,
                                          const Communicator& comm) {
  std::vector<double> seeded(scene.objects.size(), 0.0);
  for (std::size_t p = 0; p < P.size(); ++p) seeded[P.object[p]] += P.volume0[p];
  seeded = comm.sum(seeded);
  std::vector<std::string> warnings;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    // The revolved body's volume (axisymmetric), or per metre of thickness (plane strain): the
    // particle volumes' measure.
    const double whole = visit_geometry(scene.grid.geometry, [&](auto geometry) {
      return decltype(geometry)::modelled_volume(object.geometry);
    });
    const double share =
        grid_coverage(object.geometry, scene.grid).inside - object_overlap(scene, o).claimed;
    const double expected = whole * share;
    if (!(expected > 0.0) || seeded[o] == 0.0) continue;  // refused or warned of when read
    const double ratio = seeded[o] / expected;
    if (std::abs(ratio - 1.0) <= kSeedingVolumeTolerance) continue;
    const Vec3 h = scene.grid.largest_cell();
    std::ostringstream m;
    m.precision(3);
    m << scene.file << ": /objects/" << object.name << "/geometry: its particles hold " << ratio
      << " of the volume they should fill (" << seeded[o] << " of " << expected
      << (scene.grid.per_metre_of_thickness() ? " m^3 per m" : " m^3")
      << ", its part inside the grid and outside earlier objects): seeded at the sub-cell centres ("
      << object.particles_per_cell[0] << " x " << object.particles_per_cell[1] << " x "
      << object.particles_per_cell[2] << " per cell; cells up to [" << h(0) << ", " << h(1) << ", "
      << h(2) << "] m), its faces cut the cells; the mass is " << ratio
      << " of the body's: align its faces with the cells, or raise particles_per_cell";
    warnings.push_back(m.str());
  }
  return warnings;
}

}  // namespace impact::mpm
