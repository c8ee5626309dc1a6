// The background grid: cells_d + 1 nodes per axis plus one ghost layer on each side (node index
// -1 and cells_d + 1), which uGIMP reaches from a particle next to a face; on a rank of a domain
// decomposition, only the nodes of its box and halo (NodeBox). Node data are
// stored once; the scatters write them race-free by coloured bands (mpm/step/scatter_order.hpp), in
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

#include <algorithm>
#include <array>
#include <cstdint>
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
  /// sum_p S_Ip m_p^2 [kg^2] on a graded grid (zero on a uniform one): over `mass`, the nodal
  /// mean particle mass that USL's light-node rule scales (step/grid_update.cpp).
  double mass_moment = 0.0;
};

/// One write of the face mirror (Grid::apply_mirror): `target` is a face-layer node (its
/// constrained components zeroed) or a ghost node (the reflection of `source`, the first interior
/// node); storage indices within one field.
struct MirrorWrite {
  int target;
  int source;  ///< -1 on the face layer
  int axis;
  bool fixed;
  std::int8_t face;  ///< kFaceNames order: its velocity (grid.face_velocity) moves the plane
};

/// Which of a moving face's velocities a mirror applies: the step's start (the start-of-step grid
/// velocity) or its end (v*, the gradient velocities).
enum class MirrorTime { start, end };

/// One `wall` face a face-layer node lies on (grid/wall.cpp): `inward` is +1 on a lower face and
/// -1 on an upper one (the direction the wall pushes), `mu` its Coulomb coefficient, `bit` the
/// face's bit in Grid::wall_touch (1 << face), `ghost` and `inner` the storage indices of the node
/// outside it and of the first interior node (-1 where not stored).
struct WallFace {
  int axis;
  double inward;
  double mu;
  std::uint8_t bit;
  int ghost;
  int inner;
};

/// A component of a wall node that another wall's ghost image sets (the node lies in that wall's
/// ghost layer): `axis`, and the face node (storage index) and face bit whose touch decides it.
struct WallImage {
  int axis;
  int face_node;
  std::uint8_t bit;
};

/// A face-layer node of the `wall` faces: on one face, two on an edge, three at a corner; its
/// faces are projected together (Grid::apply_walls). `image`: the components other walls' ghost
/// images set (up to two, beyond a corner of three walls).
struct WallNode {
  int node;
  int count = 0;
  std::array<WallFace, 3> face;
  int images = 0;
  std::array<WallImage, 2> image;
};

/// A `wall` face's plane for the touch test (Grid::wall_touch): the particles whose domain reaches
/// `plane` along `axis` within the step.
struct WallPlane {
  int axis;
  double inward;
  double plane;  ///< [m]
  std::uint8_t bit;
};

/// Which velocity a wall acts on: `step` on the step's start and end velocities (contact, friction
/// and its heat), `projection` on the MUSL re-map (normal contact only).
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

/// What a grid is given besides its geometry and its box: made once by the solver
/// (Simulation::grid_settings) and kept whole, so that a grid rebuilt for another box (a
/// re-balance, a restart on several ranks) is given the same.
struct GridSettings {
  int threads = 1;
  int fields = 1;  ///< velocity fields
  /// A heat array for friction contact's Coulomb work (a wall face with friction allocates it too).
  bool friction_heat = false;
  double light_mass = 0.0;  ///< [kg] see kLightNodeMassFraction in step/step.hpp
  /// A graded grid under USL: the light-node rule takes each node's mean particle mass
  /// (NodeData::mass_moment, scattered only then).
  bool node_mean_mass = false;
  /// Axisymmetric: the radius light_mass holds at [m]; a node at r_I > light_radius is light
  /// below light_mass r_I / light_radius (rings weigh in proportion to their radius). 0: off.
  double light_radius = 0.0;
  /// Contact body of each velocity field (its material: a material's parent and companion fields
  /// are one body against the others, contact/contact.hpp); empty: every field its own body.
  std::vector<int> field_body;
  /// Reference density of each velocity field's material [kg/m^3] (contact's nodal volumes).
  std::vector<double> field_density;
  /// Per velocity field, 1 where it carries a rigid object (SceneObject::rigid), and that
  /// object's velocity [m/s] (Grid::hold_rigid_fields); both empty when no object is rigid.
  std::vector<std::uint8_t> rigid_field;
  std::vector<Vec3> rigid_velocity;
  /// Per velocity field, the Coulomb coefficient of its rigid object against the bodies it meets
  /// [-] (Scene::rigid_field_friction); empty when no object is rigid.
  std::vector<double> rigid_friction;
  /// Per velocity field, the rigid object's surface at t = 0 (scene/rigid_surface.hpp), absent
  /// where its mass gradient serves; empty when no object is rigid.
  std::vector<std::optional<Geometry>> rigid_surface;
  /// Per scene object: the particles' half-widths [m] (uGIMP's l times the spacing), the extent
  /// of a particle's domain for the touch test of the wall faces and for the bodies' separation
  /// (`contact.detection = "separation"`); empty without either.
  std::vector<Vec3> particle_half_width;
};

class Grid {
 public:
  /// `box`: the nodes to store (all of them when absent; clipped to the grid and its ghost
  /// layers). Node indices stay those of the whole grid; a face condition applies where its layer
  /// is stored.
  Grid(const GridSpec& spec, GridSettings settings, std::optional<NodeBox> box = std::nullopt);

  const GridSpec& spec() const { return spec_; }
  const Vec3& lower() const { return spec_.lower; }
  /// The cell edges [m]; on a graded grid the base cells' (GridSpec::spacing).
  const Vec3& spacing() const { return dx_; }
  /// Node i's coordinate along axis d [m], ghost nodes included (graded or uniform).
  double node_coordinate(int d, int i) const {
    return spec_.graded() ? spec_.axes[std::size_t(d)].node(i) : spec_.lower(d) + i * dx_(d);
  }
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
  const GridSettings& settings() const { return settings_; }

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
  /// Marks the blocks holding nodes base..base+n-1 along x and y and base..base+nz-1 along z (a
  /// particle's stencil; nz = 1 on a 2D grid).
  void mark_stencil(char* marks, const std::array<int, 3>& base, int n, int nz) const {
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {  // storage coordinate = node index - first
      lo[d] = (base[d] - first_[d]) / kBlock;
      hi[d] = (base[d] - first_[d] + (d == 2 ? nz : n) - 1) / kBlock;
    }
    for (int a = lo[0]; a <= hi[0]; ++a)
      for (int b = lo[1]; b <= hi[1]; ++b)
        for (int c = lo[2]; c <= hi[2]; ++c) marks[(a * by_ + b) * bz_ + c] = 1;
  }
  /// Rebuilds active_nodes() from the marks (active blocks; no-op when dense).
  void activate();
  /// Below this many active nodes a node loop runs on one thread: waking the team costs more
  /// than it saves (about 30 us per parallel region with passive waiting on the project VM,
  /// against ~5 ns per node; docs/performance.md#threads). Above it the team shares the loop
  /// even where waking it costs more than the loop: a node loop on one thread pulls every node
  /// into that core's cache, and the other threads' particles then read them from it (16 384
  /// -> 4096: the recommended scene, 22 491 nodes, on 2 threads 1.03-1.05x; a 672-particle rod
  /// always on the team 0.80x).
  static constexpr int kMinParallelNodes = 4096;
  /// body(e) for every entry e = f * node_count() + I of every field f and active node I, in
  /// parallel over the nodes of each field (on one thread when there are few: the bodies are
  /// independent per entry, so the bits are the same either way).
  template <class Body>
  void for_active_entries(Body&& body) const {
    const int na = static_cast<int>(active_.size());
    const int nn = node_count();
    const bool team = threads() > 1 && na >= kMinParallelNodes;
    for (int f = 0; f < fields_; ++f) {
      const int* const nodes = active_.data();
      const int offset = f * nn;
#pragma omp parallel for schedule(static) num_threads(threads()) if (team)
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
  /// Per entry, with two or more velocity fields: what the step's contact pass decided for the
  /// field (bit 1: its body held against the others, bit 2: within its body); the strain pass
  /// holds the strain velocity (MUSL's re-map, USL's v^L) there too (contact/contact.hpp).
  std::vector<unsigned char> contact_held;
  /// With `contact.normal = "logistic_regression"`, per node (one copy, not per field): the unit
  /// normal of the plane separating the node's two bodies, from the body of lower index into the
  /// other; zero where none was fitted (step/contact_planes.cpp) and contact uses the gradients.
  std::vector<Vec3> contact_plane;
  /// With `contact.detection = "separation"`, per node: the gap between the bodies' particles
  /// [m] (> 0: apart, no contact), along contact_plane at a node of two, the smallest pair's at a
  /// node of three or more; NaN where none was measured (step/contact_planes.cpp); empty
  /// otherwise.
  std::vector<double> contact_gap;
  /// Scratch of step/contact_planes.cpp, per node: -1, or the node's place among the step's
  /// two-body nodes (and, with gaps, those of three or more bodies; reset after each use, so a
  /// step touches only its active nodes).
  std::vector<int> contact_plane_slot;
  /// v*_I - v_I before the face conditions at the boundary nodes (field-major, boundary_nodes()
  /// order): the faces' impulse is what they changed in it.
  std::vector<Vec3> free_increment;

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
  /// constrained face the constrained components on the face layer are zeroed (set to V on a
  /// moving face), and the ghost layer outside is set to the reflection of the first interior
  /// layer.
  /// A face moving at V (grid.face_velocity) is a mirror plane moving along its axis: the face
  /// layer's normal component is V, the ghost's the image 2 V - v_inner (docs/scenes.md#moving-
  /// faces); `when` picks V at the step's start or end.
  void apply_mirror(std::vector<Vec3>& v, MirrorTime when = MirrorTime::end) const;
  /// The moving faces' velocities at the step's start and end [m/s] (kFaceNames order; 0: still).
  void set_face_velocities(const std::array<double, 6>& start, const std::array<double, 6>& end) {
    face_velocity_[0] = start;
    face_velocity_[1] = end;
  }
  /// The work of the moving faces on a boundary node given the impulse the faces gave it [J]:
  /// each component of `impulse` times the mid-step velocity of the face of that axis the node
  /// lies on (its face or ghost layer), 0 where the node lies on no moving face.
  double moving_face_work(int node, const Vec3& impulse) const;
  /// The `wall` faces (grid/wall.cpp) on every field of the end velocity `end` (the step's v*, or
  /// MUSL's re-mapped velocity in the projection pass): at a face-layer node whose field touches a
  /// wall this step (wall_touch) and moves into it, the normal component is zeroed; the held
  /// faces of an edge or corner node are projected together, then one Coulomb correction (step
  /// pass) takes up to sum mu_f j_f off what remains tangential. A node that does not touch, or
  /// moves away, is left free (a face node never pulls). The projection pass holds exactly the
  /// faces the step pass held (wall_held), whatever the sign of the re-mapped velocity. The ghost
  /// node outside a touched face takes the mirror image of the first interior node's normal
  /// velocity while its face node is held, and moves inward at its normal speed |n . v| once the
  /// face node is let go, in `start` (the step's v_I, step pass) and `end`; elsewhere it keeps its
  /// own velocity. Step pass:
  /// adds the Coulomb heat to `heat` (if allocated) and returns its sum [J].
  double apply_walls(std::vector<Vec3>* start, std::vector<Vec3>& end, WallPass pass);
  bool has_walls() const {
    return !wall_all_.empty();
  }
  /// Rigid objects (GridSettings::rigid_field, grid/rigid_fields.cpp): at every active node where
  /// a rigid field has mass its entry of `v` becomes the object's velocity, whatever forces,
  /// contact and faces made of it. No-op without rigid objects.
  void hold_rigid_fields(std::vector<Vec3>& v) const;
  bool has_rigid_fields() const {
    return !settings_.rigid_field.empty();
  }
  /// The time at the step's start [s]: where the rigid objects are (Grid::rigid_inward_normal).
  void set_time(double t) {
    time_ = t;
  }
  /// The unit normal of rigid field f's surface into the object at node `node` (storage index
  /// within one field), as a body whose surface faces `toward` there (the body's mass gradient,
  /// pointing into it; zero: unknown) meets it: its geometry moved by V t
  /// (GridSettings::rigid_surface), the nearest surface's; zero without a surface or where no
  /// direction is defined (grid/rigid_fields.cpp).
  Vec3 rigid_inward_normal(int f, int node, const Vec3& toward) const;
  /// Whether field f carries a rigid object.
  bool is_rigid_field(int f) const {
    return has_rigid_fields() && settings_.rigid_field[std::size_t(f)] != 0;
  }
  /// Rigid field f's Coulomb coefficient against the bodies it meets [-] (`fallback` where the
  /// solver set none: a grid built without a scene).
  double rigid_friction(int f, double fallback) const {
    return std::size_t(f) < settings_.rigid_friction.size()
               ? settings_.rigid_friction[std::size_t(f)]
               : fallback;
  }
  /// The bits (1 << face) of the wall faces that a particle at `x` moving at `v`, of half-widths
  /// `half_width` [m], reaches within `dt`: n . (x - x_wall) - l_n + dt min(0, n . v) <= 1e-9 of
  /// the spacing (a particle seeded against the wall touches it whatever the round-off).
  std::uint8_t touched_walls(const Vec3& x, const Vec3& v, const Vec3& half_width,
                             double dt) const {
    std::uint8_t bits = 0;
    for (const WallPlane& w : wall_planes_) {
      const double approach = std::min(0.0, w.inward * v(w.axis));
      const double gap = w.inward * (x(w.axis) - w.plane) - half_width(w.axis) + dt * approach;
      if (gap <= 1e-9 * dx_(w.axis)) bits |= w.bit;
    }
    return bits;
  }
  /// Per entry: the bits (1 << face) of the wall faces that a particle of the entry's field with
  /// this node in its stencil reaches within the step (particles-to-grid; summed over the ranks as
  /// a bitwise or); allocated only with wall faces. A wall holds only where its body touches it.
  std::vector<std::uint8_t> wall_touch;
  /// Per entry: the bits of the wall faces the step pass held (its v*_n zeroed), which MUSL's
  /// re-map holds too, and only those (Grid::apply_walls); cleared with the grid each step.
  std::vector<std::uint8_t> wall_held;
  std::size_t bytes() const;

 private:
  void find_boundary_nodes();  ///< the constructor's: boundary_nodes_, free_increment
  void build_face_writes();    ///< the constructor's: the mirror's writes, the walls
  GridSpec spec_;
  GridSettings settings_;
  Vec3 dx_, inv_dx_;
  std::array<int, 3> first_;  ///< node index of the first stored node per axis
  int nx_, ny_, nz_;
  int fields_;   ///< settings_.fields, at least 1
  int threads_;  ///< settings_.threads, at least 1
  std::vector<NodeData> nodes_;
  std::vector<Vec3> remap_;
  std::vector<int> boundary_nodes_;
  std::vector<int> active_boundary_;
  std::array<std::array<double, 6>, 2> face_velocity_{};  ///< [start, end] per face [m/s]
  double time_ = 0.0;                                     ///< the step's start [s] (set_time)
  std::vector<MirrorWrite> mirror_all_;     ///< every face node, in the order of the mirror
  std::vector<MirrorWrite> mirror_active_;  ///< those whose target is in an active block
  /// Mirror writes whose source lies on a wall's layers: applied after the walls.
  std::vector<MirrorWrite> mirror_after_walls_all_, mirror_after_walls_active_;
  std::vector<WallNode> wall_all_;     ///< face-layer nodes of the wall faces, ascending
  std::vector<WallNode> wall_active_;  ///< those in an active block
  std::vector<WallPlane> wall_planes_;
  std::array<bool, 6> constrained_{};
  int bx_ = 0, by_ = 0, bz_ = 0;  ///< blocks per axis
  std::vector<int> active_;       ///< active nodes, ascending
  std::vector<char> marks_;       ///< per block (active blocks only)
  NodeBox owned_{{-1, -1, -1}, {1 << 30, 1 << 30, 1 << 30}};
};

}  // namespace impact::mpm
