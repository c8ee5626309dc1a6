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

void GridSpec::ungrade() {
  refine.clear();
  axes = {};
  cells = base_cells;
}

std::string GridSpec::refinement_advice() const {
  if (!graded()) return "";
  if (refine.size() == 1) return ", lower grid.refine.factor or narrow the refined box,";
  const auto cell_count = [&](const GridSpec& g) {
    return double(g.cells[0]) * double(g.cells[1]) * double(g.cells[2]);
  };
  std::size_t costliest = 0;
  double most = -1.0;
  for (std::size_t i = 0; i < refine.size(); ++i) {
    GridSpec without = *this;
    without.refine.erase(without.refine.begin() + static_cast<std::ptrdiff_t>(i));
    without.cells = base_cells;
    without.axes = {};
    without.grade();
    if (const double saved = cell_count(*this) - cell_count(without); saved > most) {
      most = saved;
      costliest = i;
    }
  }
  return ", lower a factor of grid.refine or narrow its boxes (/grid/refine/" +
         std::to_string(costliest) +
         " adds the most cells: " + std::to_string(static_cast<long long>(most)) + " of " +
         std::to_string(static_cast<long long>(cell_count(*this))) + "),";
}

int Scene::field_count() const {
  if (physics.contact.type == ContactType::single_velocity) return 1;
  const int n = static_cast<int>(materials.size());
  return physics.create_new_particles ? 2 * n : n;
}

std::vector<std::optional<Vec3>> Scene::rigid_field_velocities() const {
  if (!has_rigid_objects()) return {};
  std::vector<std::optional<Vec3>> v(static_cast<std::size_t>(field_count()));
  for (const SceneObject& o : objects)
    if (o.rigid) v[std::size_t(parent_field(o.material))] = o.velocity;
  return v;
}

std::vector<double> Scene::rigid_field_friction() const {
  if (!has_rigid_objects()) return {};
  std::vector<double> mu(static_cast<std::size_t>(field_count()), physics.contact.mu);
  for (const SceneObject& o : objects)
    if (o.rigid) mu[std::size_t(parent_field(o.material))] = friction_of(o);
  return mu;
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
