#include "mpm/scene/scene.hpp"

namespace impact::mpm {

void GridSpec::grade() {
  base_cells = cells;
  if (!refine) return;
  for (int d = 0; d < 3; ++d) {
    const std::size_t a = std::size_t(d);
    // A 2D grid's one cell along z is not a mesh axis: it stays one cell of 1 m.
    const RefinedSpan span{refine->lower(d), refine->upper(d),
                           planar() && d == 2 ? 1.0 : refine->factor, refine->growth};
    axes[a] = graded_axis(lower(d), upper(d), base_cells[a], span);
    cells[a] = axes[a].cells();
  }
}

int Scene::field_count() const {
  if (physics.contact.type == ContactType::single_velocity) return 1;
  const int n = static_cast<int>(materials.size());
  return physics.create_new_particles ? 2 * n : n;
}

int Scene::parent_field(int material) const {
  return field_count() == 1 ? 0 : material;
}

int Scene::companion_field(int material) const {
  return field_count() > static_cast<int>(materials.size())
             ? material + static_cast<int>(materials.size())
             : parent_field(material);
}

}  // namespace impact::mpm
