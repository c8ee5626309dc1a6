#include "mpm/scene/scene.hpp"

namespace impact::mpm {

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
