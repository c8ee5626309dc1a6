// The background grid: cells_d + 1 nodes per axis plus one ghost layer on each side (node index
// -1 and cells_d + 1), which uGIMP reaches from a particle next to a face; on a rank of a domain
// decomposition, only the nodes of its box and halo (NodeBox). Node data are
// stored once; the scatters write them race-free by coloured slabs (mpm/step/scatter_order.hpp), in
// an order that does not depend on the thread count. All per-node arrays are allocated once (no
// allocation in a step).
// Velocity fields (multi-material contact): every per-node array holds `fields` consecutive
// copies of the node set; field f of node I is entry f * node_count() + I. With one field (the
// default, and single_velocity contact) this is the ordinary single-field grid.
// Active blocks (GridSpec::active_blocks): the node set is tiled into blocks of kBlock^3 = 8 nodes;
// each step the blocks touched by a particle's stencil are marked and every grid loop runs over
// the nodes of the marked blocks only (active_nodes(), ascending), so the grid work follows the
// particles, not the box (a hollow cylinder's interior, empty space around the bodies). Storage
// stays dense (one index per node: no hashing in the particle loops). Invariant: the mass-carrying
// arrays (thread buffers, nodal stress, mass) are zero outside the active nodes; the velocity
// arrays are read only at active nodes or weighted by their mass. Dense mode: every node active.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace impact::mpm {

/// What particles-to-grid accumulates at a node (64 bytes, aligned to one cache line: in a 16-byte
/// aligned array three records in four straddle two lines, and the scatter is bound by moving node
/// lines, docs/performance.md).
struct alignas(64) NodeData {
  double mass = 0.0;        ///< m_I [kg]
  double momentum[3] = {};  ///< p_I [kg m/s]
  double force[3] = {};     ///< f_I = f_int [N]
  double pad = 0.0;
};

/// Nodal stress sum_p S_Ip sigma_p (xx, yy, zz, xy, yz, zx): only its normal component's sign is
/// used, by friction contact's compression test (docs/report_code.md sec. 14).
struct NodeStress {
  double s[6] = {};
};

/// One write of the face mirror (Grid::apply_mirror): `target` is a face-layer node (its
/// constrained components zeroed) or a ghost node (the reflection of `source`, the first interior
/// node); storage indices within one field.
struct MirrorWrite {
  int target;
  int source;  ///< -1 on the face layer
  int axis;
  bool fixed;
};

/// One face-layer node of a `wall` face (Grid::apply_walls): `inward` is +1 on a lower face and
/// -1 on an upper one (the direction the wall pushes), `mu` the face's Coulomb coefficient.
struct WallNode {
  int node;
  int axis;
  double inward;
  double mu;
};

/// Which velocity a wall acts on: `step` on the step's end velocity v* (contact, friction and its
/// heat), `projection` on the MUSL re-map (normal contact only).
enum class WallPass { step, projection };

/// The nodes a grid stores per axis, first[d] to last[d] inclusive (node indices, -1 being the
/// ghost layer): the whole grid [-1, cells_d + 1] on one rank, a rank's box and its halo in a
/// domain decomposition (mpm/parallel/halo_exchange.hpp), so that no rank allocates the whole
/// grid.
struct NodeBox {
  std::array<int, 3> first;
  std::array<int, 3> last;
  bool operator==(const NodeBox&) const = default;
};

class Grid {
 public:
  /// `fields` velocity fields; `nodal_stress`: also scatter the stress (friction contact);
  /// `box`: the nodes to store (all of them when absent; clipped to the grid and its ghost
  /// layers). Node indices stay those of the whole grid; a face condition applies where its layer
  /// is stored.
  Grid(const GridSpec& spec, int threads, int fields = 1, bool nodal_stress = false,
       std::optional<NodeBox> box = std::nullopt);

  const GridSpec& spec() const { return spec_; }
  const Vec3& lower() const { return spec_.lower; }
  const Vec3& spacing() const { return dx_; }
  const Vec3& inverse_spacing() const { return inv_dx_; }
  const std::array<int, 3>& cells() const { return spec_.cells; }
  /// Storage index of node (i, j, k) within stored(); k runs fastest.
  int index(int i, int j, int k) const {
    return ((i - first_[0]) * ny_ + (j - first_[1])) * nz_ + (k - first_[2]);
  }
  int node_count() const { return nx_ * ny_ * nz_; }
  /// index(i + 1, j, k) - index(i, j, k) and index(i, j + 1, k) - index(i, j, k): the hot loops
  /// step through a stencil with these, held in registers, from index() of its base node.
  int stride_x() const { return ny_ * nz_; }
  int stride_y() const { return nz_; }
  /// (i, j, k) of a storage index (inverse of index()).
  std::array<int, 3> ijk(int index) const {
    return {index / (ny_ * nz_) + first_[0], (index / nz_) % ny_ + first_[1],
            index % nz_ + first_[2]};
  }
  /// The nodes stored.
  NodeBox stored() const {
    return {first_, {first_[0] + nx_ - 1, first_[1] + ny_ - 1, first_[2] + nz_ - 1}};
  }
  /// Storage coordinate along x of node plane i (0 for the first stored plane).
  int storage_x(int i) const { return i - first_[0]; }
  int threads() const { return threads_; }
  int fields() const { return fields_; }

  /// The nodes whose ledger terms this grid books (all of them on one rank; a rank's own box in
  /// a domain decomposition, mpm/parallel/halo_exchange.hpp, so that a node several ranks share
  /// is booked once). `node`: storage index within one field.
  void set_owned(const NodeBox& owned) { owned_ = owned; }
  bool owns(int node) const {
    const std::array<int, 3> n = ijk(node);
    for (int d = 0; d < 3; ++d)
      if (n[d] < owned_.first[d] || n[d] > owned_.last[d]) return false;
    return true;
  }
  /// Entries of every per-node array: fields() * node_count().
  int entry_count() const { return fields_ * node_count(); }

  /// Nodes per block edge (active blocks).
  static constexpr int kBlock = 2;
  /// The nodes the grid loops visit this step, ascending storage indices within one field.
  const std::vector<int>& active_nodes() const { return active_; }
  bool dense() const { return !spec_.active_blocks; }
  /// The block marks (active blocks only): mark_stencil() sets them during the scatter (threads
  /// mark disjoint blocks, mpm/step/scatter_order.hpp), activate() reads and resets them.
  char* block_marks() { return marks_.data(); }
  /// Marks the blocks holding nodes base..base+n-1 per axis (a particle's stencil).
  void mark_stencil(char* marks, const std::array<int, 3>& base, int n) const {
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {  // storage coordinate = node index - first
      lo[d] = (base[d] - first_[d]) / kBlock;
      hi[d] = (base[d] - first_[d] + n - 1) / kBlock;
    }
    for (int a = lo[0]; a <= hi[0]; ++a)
      for (int b = lo[1]; b <= hi[1]; ++b)
        for (int c = lo[2]; c <= hi[2]; ++c) marks[(a * by_ + b) * bz_ + c] = 1;
  }
  /// Rebuilds active_nodes() from the marks (active blocks; no-op when dense).
  void activate();
  /// body(e) for every entry e = f * node_count() + I of every field f and active node I, in
  /// parallel over the nodes of each field.
  template <class Body>
  void for_active_entries(Body&& body) const {
    const int na = static_cast<int>(active_.size());
    const int nn = node_count();
    for (int f = 0; f < fields_; ++f) {
      const int* const nodes = active_.data();
      const int offset = f * nn;
#pragma omp parallel for schedule(static) num_threads(threads())
      for (int a = 0; a < na; ++a) body(offset + nodes[a]);
    }
  }

  /// Zeroes the mass-carrying arrays at the nodes active so far (start of particles-to-grid,
  /// before the new blocks are marked): then they are zero everywhere.
  void clear();
  /// The scatter target: one buffer for all threads, which write disjoint nodes at any one time
  /// (mpm/step/scatter_order.hpp), so the memory does not grow with the thread count.
  NodeData* node_buffer() {
    return nodes_.data();
  }
  /// Copies the scattered masses into `mass` at the active nodes (after the scatter).
  void collect_mass();
  /// Nodal stress scatter target (empty unless constructed with nodal_stress).
  NodeStress* stress_buffer() {
    return stress_.data();
  }
  bool has_nodal_stress() const {
    return !stress_.empty();
  }
  const std::vector<NodeStress>& nodal_stress() const {
    return stress_;
  }
  /// The scattered node data.
  std::vector<NodeData>& nodes() {
    return nodes_;
  }
  const std::vector<NodeData>& nodes() const {
    return nodes_;
  }

  /// MUSL re-map: the momentum scatter target, zeroed at the active nodes by clear_momentum.
  Vec3* momentum_buffer() {
    return remap_.data();
  }
  void clear_momentum();
  const std::vector<Vec3>& remapped_momentum() const {
    return remap_;
  }

  std::vector<double> mass;        ///< m_I (copy of nodes()[I].mass, compact for gathers)
  std::vector<Vec3> velocity;      ///< v_I = p_I / m_I (ghost layer mirrored) [m/s]
  std::vector<Vec3> velocity_new;  ///< v*_I after the momentum update and face conditions
  std::vector<Vec3> increment;     ///< v*_I - v_I (FLIP increment)
  std::vector<Vec3> velocity_L;    ///< the nodal velocity L_p is built from (USL/MUSL)
  std::vector<double> heat;  ///< friction heat of the step per entry [J] (contact or wall friction)
  /// v*_I - v_I before the face conditions at the boundary nodes (field-major, boundary_nodes()
  /// order): the faces' impulse is what they changed in it.
  std::vector<Vec3> free_increment;
  double light_mass = 0.0;  ///< [kg] see kLightNodeMassFraction in step/step.hpp
  /// Contact body of each velocity field (its material: a material's parent and companion fields
  /// are one body against the others, contact/contact.hpp); empty: every field its own body.
  std::vector<int> field_body;

  /// Nodes touched by a constrained (symmetric or fixed) face: face layers, ghost layers, once
  /// each (for the impulse / boundary bookkeeping); indices within one field.
  const std::vector<int>& boundary_nodes() const {
    return boundary_nodes_;
  }
  /// Positions k in boundary_nodes() of the nodes in active blocks, ascending (all with a dense
  /// grid): the only boundary nodes that can carry mass this step.
  const std::vector<int>& active_boundary() const {
    return active_boundary_;
  }

  /// The mirror condition on every field of a nodal velocity array (grid/boundary.cpp): on every
  /// constrained face the constrained components on the face layer are zeroed, and the ghost
  /// layer outside is set to the reflection of the first interior layer.
  void apply_mirror(std::vector<Vec3>& v) const;
  /// The `wall` faces' face layers (grid/wall.cpp), on every field of the end velocity `end`: a
  /// node moving into the wall has its normal component zeroed and, in the step pass, friction
  /// takes up to mu times that normal velocity off its tangential one; any other node is left
  /// free (the wall never pulls). Step pass: adds the Coulomb heat to `heat` (if allocated) and
  /// returns its sum [J].
  double apply_walls(std::vector<Vec3>& end, WallPass pass);
  bool has_walls() const {
    return !wall_all_.empty();
  }

  std::size_t bytes() const;

 private:
  GridSpec spec_;
  Vec3 dx_, inv_dx_;
  std::array<int, 3> first_;  ///< node index of the first stored node per axis
  int nx_, ny_, nz_;
  int fields_;
  int threads_;
  std::vector<NodeData> nodes_;
  std::vector<NodeStress> stress_;
  std::vector<Vec3> remap_;
  std::vector<int> boundary_nodes_;
  std::vector<int> active_boundary_;
  std::vector<MirrorWrite> mirror_all_;     ///< every face node, in the order of the mirror
  std::vector<MirrorWrite> mirror_active_;  ///< those whose target is in an active block
  std::vector<WallNode> wall_all_;          ///< face layers of the wall faces
  std::vector<WallNode> wall_active_;       ///< those in an active block
  std::array<bool, 6> constrained_{};
  int bx_ = 0, by_ = 0, bz_ = 0;  ///< blocks per axis
  std::vector<int> active_;       ///< active nodes, ascending
  std::vector<char> marks_;       ///< per block (active blocks only)
  NodeBox owned_{{-1, -1, -1}, {1 << 30, 1 << 30, 1 << 30}};
};

}  // namespace impact::mpm
