// The background grid: cells_d + 1 nodes per axis plus one ghost layer on each side (node index
// -1 and cells_d + 1), which uGIMP reaches from a particle next to a face. Node data are stored
// per thread for a race-free particles-to-grid scatter and then reduced in thread order, so
// results are deterministic for a given thread count. All per-node arrays are allocated once (no
// allocation in a step).
// Velocity fields (multi-material contact): every per-node array holds `fields` consecutive
// copies of the node set; field f of node I is entry f * node_count() + I. With one field (the
// default, and single_velocity contact) this is the ordinary single-field grid.
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

/// Nodal stress sum_p S_Ip sigma_p (xx, yy, zz, xy, yz, zx): only its normal component's sign is
/// used, by friction contact's compression test (reference_code_notes.md sec. 14).
struct NodeStress {
  double s[6] = {};
};

/// Momentum and energy that the face conditions exchanged in one step (the ledger's boundary
/// terms; docs/mpm.md#ledger).
struct BoundaryLoad {
  Vec3 impulse = Vec3::Zero();  ///< sum_I m_I (dv_I - dv_I^free) over constrained nodes [N s]
  double work = 0.0;            ///< v_face . impulse: 0 for stationary faces [J]
  double dissipation = 0.0;     ///< kinetic energy the face projection took from the grid [J]
};

class Grid {
 public:
  /// `fields` velocity fields; `nodal_stress`: also scatter the stress (friction contact).
  Grid(const GridSpec& spec, int threads, int fields = 1, bool nodal_stress = false);

  const GridSpec& spec() const { return spec_; }
  const Vec3& lower() const { return spec_.lower; }
  const Vec3& spacing() const { return dx_; }
  const Vec3& inverse_spacing() const { return inv_dx_; }
  const std::array<int, 3>& cells() const { return spec_.cells; }
  /// Storage index of node (i, j, k), i in [-1, cells_0 + 1] etc.; k runs fastest.
  int index(int i, int j, int k) const { return ((i + 1) * ny_ + (j + 1)) * nz_ + (k + 1); }
  int node_count() const { return nx_ * ny_ * nz_; }
  /// (i, j, k) of a storage index (inverse of index()).
  std::array<int, 3> ijk(int index) const {
    return {index / (ny_ * nz_) - 1, (index / nz_) % ny_ - 1, index % nz_ - 1};
  }
  int threads() const { return static_cast<int>(buffers_.size()); }
  int fields() const { return fields_; }
  /// Entries of every per-node array: fields() * node_count().
  int entry_count() const { return fields_ * node_count(); }

  /// Zeroes every thread buffer (start of particles-to-grid).
  void clear();
  /// The scatter target of thread t.
  NodeData* buffer(int t) { return buffers_[t].data(); }
  /// Sums thread buffers into buffer 0 in thread order (deterministic).
  void reduce();
  /// Nodal stress scatter target of thread t (empty unless constructed with nodal_stress).
  NodeStress* stress_buffer(int t) { return stress_buffers_[t].data(); }
  bool has_nodal_stress() const { return !stress_buffers_.empty(); }
  const std::vector<NodeStress>& nodal_stress() const { return stress_buffers_[0]; }
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
  std::vector<double> heat;        ///< friction heat of the step per entry [J] (friction only)
  /// v*_I - v_I before the face conditions at the boundary nodes (field-major, boundary_nodes()
  /// order): the faces' impulse is what they changed in it.
  std::vector<Vec3> free_increment;
  double light_mass = 0.0;  ///< [kg] see kLightNodeMassFraction in step/step.hpp

  /// Nodes touched by a constrained (symmetric or fixed) face: face layers, ghost layers, once
  /// each (for the impulse / boundary bookkeeping); indices within one field.
  const std::vector<int>& boundary_nodes() const { return boundary_nodes_; }

  /// The mirror condition on every field of a nodal velocity array (grid/boundary.cpp): on every
  /// constrained face the constrained components on the face layer are zeroed, and the ghost
  /// layer outside is set to the reflection of the first interior layer.
  void apply_mirror(std::vector<Vec3>& v) const;

  std::size_t bytes() const;

 private:
  GridSpec spec_;
  Vec3 dx_, inv_dx_;
  int nx_, ny_, nz_;
  int fields_;
  std::vector<std::vector<NodeData>> buffers_;
  std::vector<std::vector<NodeStress>> stress_buffers_;
  std::vector<std::vector<Vec3>> remap_buffers_;
  std::vector<int> boundary_nodes_;
  std::array<bool, 6> constrained_{};
};

}  // namespace impact::mpm
