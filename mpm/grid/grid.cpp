#include "mpm/grid/grid.hpp"

#include <omp.h>

#include <algorithm>
#include <utility>

namespace impact::mpm {

Grid::Grid(const GridSpec& spec, GridSettings settings, std::optional<NodeBox> box)
    : spec_(spec),
      settings_(std::move(settings)),
      dx_(spec.spacing()),
      inv_dx_(dx_.cwiseInverse()),
      // A 2D grid stores its one node plane along z, k = 0 (scene/grid_geometry.hpp).
      first_{box ? std::max(box->first[0], -1) : -1, box ? std::max(box->first[1], -1) : -1,
             spec.planar() ? 0 : (box ? std::max(box->first[2], -1) : -1)},
      nx_((box ? std::min(box->last[0], spec.cells[0] + 1) : spec.cells[0] + 1) - first_[0] + 1),
      ny_((box ? std::min(box->last[1], spec.cells[1] + 1) : spec.cells[1] + 1) - first_[1] + 1),
      nz_(spec.planar() ? 1
                        : (box ? std::min(box->last[2], spec.cells[2] + 1) : spec.cells[2] + 1) -
                              first_[2] + 1),
      fields_(std::max(settings_.fields, 1)),
      threads_(std::max(settings_.threads, 1)),
      nodes_(entry_count()) {
  const int e = entry_count();
  mass.assign(e, 0.0);
  velocity.assign(e, Vec3::Zero());
  velocity_new.assign(e, Vec3::Zero());
  increment.assign(e, Vec3::Zero());
  velocity_L.assign(e, Vec3::Zero());
  if (settings_.friction_heat || spec.has_wall_friction()) heat.assign(e, 0.0);
  const int n = node_count();
  if (fields_ > 1) contact_held.assign(e, 0);
  const bool has_wall = spec.has_walls();
  find_boundary_nodes();
  build_face_writes();
  if (has_wall) {
    wall_touch.assign(e, 0);
    wall_held.assign(e, 0);
  }
  bx_ = (nx_ + kBlock - 1) / kBlock;
  by_ = (ny_ + kBlock - 1) / kBlock;
  bz_ = (nz_ + kBlock - 1) / kBlock;
  if (dense()) {
    active_.resize(n);
    for (int i = 0; i < n; ++i) active_[i] = i;
    active_boundary_.resize(boundary_nodes_.size());
    for (std::size_t k = 0; k < boundary_nodes_.size(); ++k) active_boundary_[k] = int(k);
    mirror_active_ = mirror_all_;
    mirror_after_walls_active_ = mirror_after_walls_all_;
    wall_active_ = wall_all_;
  } else {
    marks_.assign(std::size_t(bx_) * by_ * bz_, 0);
    active_.reserve(n);  // no allocation in a step
    active_boundary_.reserve(boundary_nodes_.size());
    mirror_active_.reserve(mirror_all_.size());
    mirror_after_walls_active_.reserve(mirror_after_walls_all_.size());
    wall_active_.reserve(wall_all_.size());
  }
}

// The nodes of every constrained face's layer and ghost layer that this grid stores, ascending.
void Grid::find_boundary_nodes() {
  const int n = node_count();
  // The stored node range per axis: the faces' layers and rows are visited only where stored.
  const NodeBox x = stored();
  const std::array<int, 3>& lowest = x.first;
  const std::array<int, 3>& highest = x.last;
  const auto stored = [&](int axis, int i) { return i >= lowest[axis] && i <= highest[axis]; };
  std::vector<char> mark(n, 0);
  for (int face = 0; face < 6; ++face) {
    constrained_[face] = spec_.faces[face] != FaceCondition::free;
    if (!constrained_[face]) continue;
    const int axis = face / 2;
    const int c[3] = {spec_.cells[0], spec_.cells[1], spec_.cells[2]};
    const int layers[2] = {face % 2 == 0 ? 0 : c[axis], face % 2 == 0 ? -1 : c[axis] + 1};
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int layer : layers)
      for (int u = lowest[a]; u <= highest[a]; ++u)
        for (int w = lowest[b]; w <= highest[b]; ++w) {
          if (!stored(axis, layer)) continue;
          int ijk[3];
          ijk[axis] = layer;
          ijk[a] = u;
          ijk[b] = w;
          mark[index(ijk[0], ijk[1], ijk[2])] = 1;
        }
  }
  for (int i = 0; i < n; ++i)
    if (mark[i]) boundary_nodes_.push_back(i);
  free_increment.assign(boundary_nodes_.size() * fields_, Vec3::Zero());
}

// The mirror's writes (symmetric and fixed faces), the wall nodes with their faces, ghosts and
// images, and the walls' planes for the touch test.
void Grid::build_face_writes() {
  const int n = node_count();
  const bool has_wall = spec_.has_walls();
  // The stored node range per axis: the faces' layers and rows are visited only where stored.
  const NodeBox x = stored();
  const std::array<int, 3>& lowest = x.first;
  const std::array<int, 3>& highest = x.last;
  const auto stored = [&](int axis, int i) { return i >= lowest[axis] && i <= highest[axis]; };
  // The mirror's writes in its order: every face layer first (all faces), then the ghost layers
  // in face order, so that a ghost corner node is the reflection in both planes of an interior
  // node (grid/boundary.cpp). A wall's face layer and ghost layer are its own condition
  // (grid/wall.cpp); a mirror write whose source lies on a wall's layers is applied again after
  // the walls.
  const int c[3] = {spec_.cells[0], spec_.cells[1], spec_.cells[2]};
  const auto on_wall_layer = [&](int i, int j, int k) {
    const int ijk[3] = {i, j, k};
    for (int face = 0; face < 6; ++face) {
      if (spec_.faces[face] != FaceCondition::wall) continue;
      const int axis = face / 2;
      if (face % 2 == 0 ? ijk[axis] <= 0 : ijk[axis] >= c[axis]) return true;
    }
    return false;
  };
  std::vector<int> wall_slot(has_wall ? n : 0, -1);
  for (int pass = 0; pass < 2; ++pass)
    for (int face = 0; face < 6; ++face) {
      if (!constrained_[face]) continue;
      const bool fixed = spec_.faces[face] == FaceCondition::fixed;
      const int axis = face / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
      const int layer = face % 2 == 0 ? 0 : c[axis];
      const int ghost = face % 2 == 0 ? -1 : c[axis] + 1;
      const int inner = face % 2 == 0 ? 1 : c[axis] - 1;
      // A face whose layers this grid does not store is another rank's.
      if (!stored(axis, layer) || !stored(axis, ghost) || !stored(axis, inner)) continue;
      const bool wall = spec_.faces[face] == FaceCondition::wall;
      if (wall && pass == 1) continue;  // set with the face layer (below)
      for (int u = lowest[a]; u <= highest[a]; ++u)
        for (int w = lowest[b]; w <= highest[b]; ++w) {
          int ijk[3];
          ijk[a] = u;
          ijk[b] = w;
          ijk[axis] = pass == 0 ? layer : ghost;
          const int target = index(ijk[0], ijk[1], ijk[2]);
          ijk[axis] = inner;
          const int source = index(ijk[0], ijk[1], ijk[2]);
          if (wall) {
            ijk[axis] = ghost;
            const int outside = index(ijk[0], ijk[1], ijk[2]);
            int& slot = wall_slot[target];
            if (slot < 0) {
              slot = int(wall_all_.size());
              wall_all_.push_back({target, 0, {}, 0, {}});
            }
            WallNode& node = wall_all_[slot];
            node.face[node.count++] = {axis,
                                       face % 2 == 0 ? 1.0 : -1.0,
                                       spec_.wall_friction[face],
                                       std::uint8_t(1u << face),
                                       outside,
                                       source};
            continue;
          }
          const MirrorWrite m{target, pass == 0 ? -1 : source, axis, fixed, std::int8_t(face)};
          mirror_all_.push_back(m);
          ijk[axis] = inner;
          if (has_wall && pass == 1 && on_wall_layer(ijk[0], ijk[1], ijk[2]))
            mirror_after_walls_all_.push_back(m);
        }
    }
  // Wall nodes in ascending storage order: the heat sum runs in the same order on any grid.
  std::sort(wall_all_.begin(), wall_all_.end(),
            [](const WallNode& x, const WallNode& y) { return x.node < y.node; });
  // A wall node in another wall's ghost layer: that wall's image sets one of its components.
  std::fill(wall_slot.begin(), wall_slot.end(), -1);
  for (std::size_t k = 0; k < wall_all_.size(); ++k) wall_slot[wall_all_[k].node] = int(k);
  for (const WallNode& w : wall_all_)
    for (int i = 0; i < w.count; ++i) {
      const int slot = wall_slot[w.face[i].ghost];
      if (slot < 0) continue;
      WallNode& g = wall_all_[std::size_t(slot)];
      g.image[g.images++] = {w.face[i].axis, w.node, w.face[i].bit};
    }
  for (int face = 0; face < 6; ++face) {
    if (spec_.faces[face] != FaceCondition::wall) continue;
    const int axis = face / 2;
    wall_planes_.push_back({axis, face % 2 == 0 ? 1.0 : -1.0,
                            face % 2 == 0 ? spec_.lower(axis) : spec_.upper(axis),
                            std::uint8_t(1u << face)});
  }
}

void Grid::activate() {
  if (dense()) return;
  std::vector<char>& m = marks_;
  // Ascending storage order (i, then j, then k): the serial sums over nodes (gravity, faces) run
  // in the same order as on the dense grid, so both give the same bits.
  active_.clear();
  for (int a = 0; a < bx_; ++a)
    for (int i = a * kBlock; i < std::min(nx_, (a + 1) * kBlock); ++i)
      for (int b = 0; b < by_; ++b) {
        const char* row = m.data() + std::size_t(a * by_ + b) * bz_;
        if (std::find(row, row + bz_, 1) == row + bz_) continue;
        for (int j = b * kBlock; j < std::min(ny_, (b + 1) * kBlock); ++j)
          for (int c = 0; c < bz_; ++c) {
            if (!row[c]) continue;
            const int first = (i * ny_ + j) * nz_;
            for (int k = c * kBlock; k < std::min(nz_, (c + 1) * kBlock); ++k)
              active_.push_back(first + k);
          }
      }
  // The face conditions follow the particles too: a face node outside the marked blocks has no
  // mass and is in no particle's stencil this step, so neither its mirror value nor its impulse
  // term is read (both are skipped in the same order as on the dense grid: same bits).
  const auto in_marked_block = [&](int node) {
    const int i = node / (ny_ * nz_), j = (node / nz_) % ny_, k = node % nz_;
    return m[std::size_t((i / kBlock) * by_ + j / kBlock) * bz_ + k / kBlock] != 0;
  };
  active_boundary_.clear();
  for (std::size_t k = 0; k < boundary_nodes_.size(); ++k)
    if (in_marked_block(boundary_nodes_[k])) active_boundary_.push_back(int(k));
  mirror_active_.clear();
  for (const MirrorWrite& w : mirror_all_)
    if (in_marked_block(w.target)) mirror_active_.push_back(w);
  mirror_after_walls_active_.clear();
  for (const MirrorWrite& w : mirror_after_walls_all_)
    if (in_marked_block(w.target)) mirror_after_walls_active_.push_back(w);
  wall_active_.clear();
  for (const WallNode& w : wall_all_)
    if (in_marked_block(w.node)) wall_active_.push_back(w);
  std::fill(m.begin(), m.end(), 0);
}

void Grid::clear() {
  const bool touch = !wall_touch.empty();
  for_active_entries([&](int i) {
    nodes_[i] = NodeData{};
    if (touch) {
      wall_touch[i] = 0;
      wall_held[i] = 0;
    }
    mass[i] = 0.0;
  });
}

void Grid::collect_mass() {
  for_active_entries([&](int i) { mass[i] = nodes_[i].mass; });
}

// The re-map buffer is written at this step's stencil nodes only and read at active nodes:
// zeroing the active nodes suffices (stale values elsewhere are never read).
void Grid::clear_momentum() {
  if (remap_.empty()) remap_.assign(entry_count(), Vec3::Zero());
  for_active_entries([&](int i) { remap_[i].setZero(); });
}

std::size_t Grid::bytes() const {
  std::size_t b = nodes_.size() * sizeof(NodeData) + remap_.size() * sizeof(Vec3);
  b +=
      (mass.size() + heat.size()) * sizeof(double) +
      (velocity.size() + velocity_new.size() + increment.size() + velocity_L.size()) * sizeof(Vec3);
  b += active_.capacity() * sizeof(int);
  b += marks_.size() + contact_held.size();
  b += (boundary_nodes_.capacity() + active_boundary_.capacity()) * sizeof(int) +
       free_increment.capacity() * sizeof(Vec3) +
       (mirror_all_.capacity() + mirror_active_.capacity()) * sizeof(MirrorWrite) +
       (mirror_after_walls_all_.capacity() + mirror_after_walls_active_.capacity()) *
           sizeof(MirrorWrite) +
       (wall_all_.capacity() + wall_active_.capacity()) * sizeof(WallNode) + wall_touch.size() +
       wall_held.size();
  return b;
}

}  // namespace impact::mpm
