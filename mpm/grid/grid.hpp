// The background grid: cells_d + 1 nodes per axis plus one ghost layer on each side (node index
// -1 and cells_d + 1), which uGIMP reaches from a particle next to a face. Node data are stored
// per thread for a race-free particles-to-grid scatter and then reduced in thread order, so
// results are deterministic for a given thread count. All per-node arrays are allocated once (no
// allocation in a step).
#pragma once

#include <array>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// What particles-to-grid accumulates at a node (64 bytes: one cache line).
struct NodeData {
  double mass = 0.0;        ///< m_I [kg]
  double momentum[3] = {};  ///< p_I [kg m/s]
  double force[3] = {};     ///< f_I = f_int [N]
  double pad = 0.0;
};

/// Momentum and energy that the face conditions exchanged in one step (the ledger's boundary
/// terms; docs/mpm.md#ledger).
struct BoundaryLoad {
  Vec3 impulse = Vec3::Zero();  ///< sum_I m_I (dv_I - dv_I^free) over constrained nodes [N s]
  double work = 0.0;            ///< v_face . impulse: 0 for stationary faces [J]
};

class Grid {
 public:
  Grid(const GridSpec& spec, int threads);

  const GridSpec& spec() const { return spec_; }
  const Vec3& lower() const { return spec_.lower; }
  const Vec3& spacing() const { return dx_; }
  const Vec3& inverse_spacing() const { return inv_dx_; }
  const std::array<int, 3>& cells() const { return spec_.cells; }
  /// Storage index of node (i, j, k), i in [-1, cells_0 + 1] etc.; k runs fastest.
  int index(int i, int j, int k) const { return ((i + 1) * ny_ + (j + 1)) * nz_ + (k + 1); }
  int node_count() const { return nx_ * ny_ * nz_; }
  int threads() const { return static_cast<int>(buffers_.size()); }

  /// Zeroes every thread buffer (start of particles-to-grid).
  void clear();
  /// The scatter target of thread t.
  NodeData* buffer(int t) { return buffers_[t].data(); }
  /// Sums thread buffers into buffer 0 in thread order (deterministic).
  void reduce();
  /// The reduced node data (valid after reduce()).
  std::vector<NodeData>& nodes() { return buffers_[0]; }
  const std::vector<NodeData>& nodes() const { return buffers_[0]; }

  /// MUSL re-map: per-thread momentum buffers, zeroed / reduced like the node buffers.
  Vec3* momentum_buffer(int t) { return remap_buffers_[t].data(); }
  void clear_momentum();
  void reduce_momentum();
  const std::vector<Vec3>& remapped_momentum() const { return remap_buffers_[0]; }

  std::vector<double> mass;        ///< m_I (copy of nodes()[I].mass, compact for gathers)
  std::vector<Vec3> velocity;      ///< v_I = p_I / m_I (ghost layer mirrored) [m/s]
  std::vector<Vec3> velocity_new;  ///< v*_I after the momentum update and face conditions
  std::vector<Vec3> increment;     ///< v*_I - v_I (FLIP increment)
  std::vector<Vec3> velocity_L;    ///< the nodal velocity L_p is built from (USL/MUSL)
  std::vector<Vec3> bc_increment;  ///< (v*_I - v_I) - (v*_I - v_I)_free: the faces' share
  double light_mass = 0.0;         ///< [kg] see kLightNodeMassFraction in step/step.hpp

  /// Nodes touched by a constrained (symmetric or fixed) face: face layers, ghost layers, once
  /// each (for the impulse / boundary bookkeeping).
  const std::vector<int>& boundary_nodes() const { return boundary_nodes_; }
  /// True if a stencil of n nodes per axis starting at `base` touches a constrained face layer
  /// or ghost layer (then the particle's energy exchange with the faces is measured).
  bool touches_boundary(const std::array<int, 3>& base, int n) const;

  /// The mirror condition on a nodal velocity field (grid/boundary.cpp): on every constrained
  /// face, `project_face` zeroes the constrained components on the face layer, and the ghost layer
  /// outside is set to the reflection of the first interior layer (`mirror_ghost`).
  void apply_mirror(std::vector<Vec3>& v, bool project_face, bool mirror_ghost = true) const;

  std::size_t bytes() const;

 private:
  GridSpec spec_;
  Vec3 dx_, inv_dx_;
  int nx_, ny_, nz_;
  std::vector<std::vector<NodeData>> buffers_;
  std::vector<std::vector<Vec3>> remap_buffers_;
  std::vector<int> boundary_nodes_;
  std::array<bool, 6> constrained_{};
};

}  // namespace impact::mpm
