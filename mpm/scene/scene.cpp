#include "mpm/scene/scene.hpp"

namespace impact::mpm {

void GridSpec::grade() {
  base_cells = cells;
  if (refine.empty()) return;
  for (int d = 0; d < 3; ++d) {
    const std::size_t a = std::size_t(d);
    std::vector<RefinedSpan> spans;
    for (const GridRefinement& box : refine)  // a 2D grid's one cell of 1 m along z stays one
      spans.push_back(
          {box.lower(d), box.upper(d), planar() && d == 2 ? 1.0 : box.factor, box.growth});
    axes[a] = spans.size() == 1 ? graded_axis(lower(d), upper(d), base_cells[a], spans.front())
                                : graded_axis(lower(d), upper(d), base_cells[a], spans);
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
