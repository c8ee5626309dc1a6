#include "mpm/contact/contact.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/grid/mirror_view.hpp"
#include "mpm/threads/chunk_sums.hpp"
#include "mpm/threads/threads.hpp"

namespace impact::mpm {

namespace {

constexpr int kMaxFields = kMaxContactFields;  // fields sharing one node (materials x 2)
// Grid::contact_held bits per entry: what the step pass decided for the field's body against the
// others, and within the body (a material's parent field and its companion); and where that hold
// stuck the pair (Coulomb took all the slip).
constexpr unsigned char kHeldBetweenBodies = 1, kHeldWithinBody = 2, kStuckBetweenBodies = 4,
                        kStuckWithinBody = 8;

// `separation`: a pair counts as apart only where its gap (along the fitted plane, with the
// particles' ellipse radii) exceeds this fraction of the node's smallest cell. Two bodies pressed
// together measure a gap of about zero, whose sign flips from
// step to step: a block spanning two rigid blocks lost 53 % of its energy by 20 us that way, and
// keeps it (-2.1 %, as `approach`) from 0.02 of a cell on; a wider margin starts contact earlier
// and widens a rolling cylinder's patch (its acceleration -25 % of 2/3 g sin(theta) at 0.02, -45
// % at 0.1, -51 % at 0.3 of a cell, at 8 cells per radius).
constexpr double kGapMargin = 0.02;

// The smallest edge of the cells around node (i, j, k) along the mesh's axes [m].
double smallest_cell_at(const Grid& G, const std::array<int, 3>& ijk) {
  const GridSpec& s = G.spec();
  double h = std::numeric_limits<double>::infinity();
  for (int d = 0; d < s.dimensions(); ++d)
    h = std::min(h, s.graded() ? s.dual_size(d, ijk[d]) : G.spacing()(d));
  return h;
}

// The mass at node n with the body's mirror images: at a `symmetric` face the body continues as
// its image, which gives the nodes within one of the face (-1, 0, 1, or cells - 1 .. cells + 1)
// what the body gives their mirror nodes: m(n) + m(mirror n) along each axis in `axes` (bit d),
// the face node counted twice. Particles reach only their own side, so the face layer held half a
// body's mass and the ghost only tails: differenced as they were, the normals of the face layer
// and of the next one in tilted towards the symmetry plane by up to 27 degrees (issue 53; the
// first fix, the ghost read as its mirror node, left the next layer at 7 degrees).
// A `wall` face cuts a body that reaches it as a symmetry plane does, so its normals take the
// images too (its velocities are not mirrored): a rigid floor running into an x- wall had a mass
// gradient across the wall at its face nodes, every correction pushed a block resting on it
// into the wall, and the books drifted to -0.137 by 100 us (rigid_body_test).
bool mirrors(FaceCondition c) {
  return c == FaceCondition::symmetric || c == FaceCondition::wall;
}

double mass_with_images(const Grid& G, const double* m, const std::array<int, 3>& n, int axes) {
  const GridSpec& s = G.spec();
  std::array<int, 2> along[3];  // per axis: the node and, near a symmetric face, its mirror
  int count[3];
  for (int d = 0; d < 3; ++d) {
    along[d] = {n[d], n[d]};
    count[d] = 1;
    if (!(axes & (1 << d))) continue;
    if (mirrors(s.faces[2 * d]) && n[d] >= -1 && n[d] <= 1) {
      along[d][1] = -n[d];
      count[d] = 2;
    } else if (mirrors(s.faces[2 * d + 1]) && n[d] >= s.cells[d] - 1 && n[d] <= s.cells[d] + 1) {
      along[d][1] = 2 * s.cells[d] - n[d];
      count[d] = 2;
    }
  }
  double total = 0.0;
  for (int a = 0; a < count[0]; ++a)
    for (int b = 0; b < count[1]; ++b)
      for (int c = 0; c < count[2]; ++c) total += m[G.index(along[0][a], along[1][b], along[2][c])];
  return total;
}

// A graded grid's node I holds the mass of its dual cell, prod_d (h_{i-1} + h_i) / 2 over the mesh
// axes: a body of one density has more mass at a node among larger cells. The gradients below
// difference the mass over that volume there (a density, as Uintah's and Nairn's normals are),
// else a flat interface's normal would tilt toward the coarse cells at a grading step. 1 on a
// uniform grid (not used there: its arithmetic is unchanged).
double dual_volume(const GridSpec& s, int i, int j, int k) {
  double v = 1.0;
  const int n[3] = {i, j, k};
  for (int d = 0; d < s.dimensions(); ++d) v *= s.dual_size(d, n[d]);
  return v;
}

// Axisymmetric: the gradient of the mass per unit radius m_I / r_I. A ring's mass grows with its
// radius, so the mass gradient of a uniform body points outward by m / r: one and two cells from
// the axis it tilted a flat interface's normal by 14-24 degrees, 52 on it (issue 53). Dividing by
// the radius weighs the nodes as a density does, Uintah's choice (n ~ sum_p rho_p grad S_ip;
// Nairn's volume gradient does the same). On the axis the radial component is zero by symmetry;
// the node next to it differences outward (r = 0 has no m / r); every component carries the
// same 1 / r, so the normal's direction is that of grad (m / r). `side` as mass_gradient's.
Vec3 axisymmetric_mass_gradient(const Grid& G, const double* m, const std::array<int, 3>& ijk,
                                const std::array<int, 3>& side) {
  const NodeBox stored = G.stored();
  const GridSpec& s = G.spec();
  const bool graded = s.graded();
  const double h = G.spacing()(1);
  const auto radius = [&](int j) { return graded ? s.node(1, j) : G.lower()(1) + j * h; };
  // Images along the axis only: the radial faces are the axis itself and the outer radius.
  const auto mass = [&](int i, int j) {
    const double mi = mass_with_images(G, m, {i, j, ijk[2]}, 1);
    return graded ? mi / dual_volume(s, i, j, 0) : mi;
  };
  const auto per_radius = [&](int i, int j) { return mass(i, j) / radius(j); };
  // The distance from node lo to node hi along axis d.
  const auto span = [&](int d, int lo, int hi) {
    return graded ? s.node(d, hi) - s.node(d, lo) : (hi - lo) * G.spacing()(d);
  };
  const double r = radius(ijk[1]);
  Vec3 g = Vec3::Zero();
  const int i_lo = side[0] > 0 ? ijk[0] : std::max(ijk[0] - 1, stored.first[0]);
  const int i_hi = side[0] < 0 ? ijk[0] : std::min(ijk[0] + 1, stored.last[0]);
  if (r <= 1e-9 * h) {  // on the axis: the axial difference of the mass, no radial component
    if (i_hi > i_lo) g(0) = (mass(i_hi, ijk[1]) - mass(i_lo, ijk[1])) / span(0, i_lo, i_hi);
    return g;
  }
  if (i_hi > i_lo)
    g(0) = (per_radius(i_hi, ijk[1]) - per_radius(i_lo, ijk[1])) / span(0, i_lo, i_hi);
  int j_lo = side[1] > 0 ? ijk[1] : std::max(ijk[1] - 1, stored.first[1]);
  const int j_hi = side[1] < 0 ? ijk[1] : std::min(ijk[1] + 1, stored.last[1]);
  if (radius(j_lo) <= 1e-9 * h) j_lo = ijk[1];  // the axis or the ghost beyond it
  if (j_hi > j_lo)
    g(1) = (per_radius(ijk[0], j_hi) - per_radius(ijk[0], j_lo)) / span(1, j_lo, j_hi);
  return g;
}

// Gradient of one field's nodal mass at node (i, j, k) by central differences (one-sided at the
// outermost stored layers). The report's normals came from the same differences (sec. 14). A 2D
// grid stores one node plane along z: no difference, no gradient along z. `side[d]` -1 or +1
// takes the one-sided difference towards the lower or upper neighbour along axis d instead.
Vec3 mass_gradient(const Grid& G, const double* m, const std::array<int, 3>& ijk,
                   const std::array<int, 3>& side = {0, 0, 0}) {
  if (G.spec().geometry_facts().rings) return axisymmetric_mass_gradient(G, m, ijk, side);
  Vec3 g;
  const NodeBox stored = G.stored();
  const GridSpec& s = G.spec();
  const int axes = s.planar() ? 0b011 : 0b111;  // a 2D grid has no images along z
  for (int d = 0; d < 3; ++d) {
    std::array<int, 3> lo = ijk, hi = ijk;
    if (side[d] <= 0) lo[d] = std::max(ijk[d] - 1, stored.first[d]);
    if (side[d] >= 0) hi[d] = std::min(ijk[d] + 1, stored.last[d]);
    if (hi[d] == lo[d]) {
      g(d) = 0.0;
      continue;
    }
    if (s.graded()) {  // the nodal density, over the nodes' distance
      const double a = mass_with_images(G, m, lo, axes) / dual_volume(s, lo[0], lo[1], lo[2]);
      const double b = mass_with_images(G, m, hi, axes) / dual_volume(s, hi[0], hi[1], hi[2]);
      g(d) = (b - a) / (s.node(d, hi[d]) - s.node(d, lo[d]));
      continue;
    }
    const double span = (hi[d] - lo[d]) * G.spacing()(d);
    g(d) = (mass_with_images(G, m, hi, axes) - mass_with_images(G, m, lo, axes)) / span;
  }
  return g;
}

// The contact of n >= 2 bodies at one node: each body b has mass m[b], velocity v[b], mass
// gradient grad[b] and start velocity v0[b] (the slip the step starts from). correct() writes the
// velocity correction dv[b] (momentum-conserving: the mass-weighted mean correction removed, zero
// to round-off for a pair; against a rigid body, whose reaction the momentum gained is, not) and
// the Coulomb work heat[b] >= 0.
struct Bodies {
  int n = 0;
  double m[kMaxFields];
  double volume[kMaxFields];  ///< sum over the body's fields of m_f / rho_f [m^3]
  Vec3 v[kMaxFields], grad[kMaxFields], v0[kMaxFields];
  /// A rigid object (SceneObject::rigid): a partner of infinite mass, never corrected.
  bool rigid[kMaxFields] = {};
  /// A rigid object's Coulomb coefficient against the bodies (Grid::rigid_friction).
  double rigid_mu[kMaxFields] = {};
  /// The rigid partner's one-sided mass differences, towards the lower and the upper neighbour
  /// along each axis (set where a rigid partner meets another body; normal_against_rigid).
  Vec3 rigid_lower = Vec3::Zero(), rigid_upper = Vec3::Zero();
  /// Per body, the rigid partner's own surface normal into it as the body meets it
  /// (Grid::rigid_inward_normal, as the mirror leaves it); zero where its geometry gives none.
  Vec3 rigid_surface[kMaxFields];
  /// A pair's fitted plane (`logistic_regression`): the normal of each body into the other.
  bool has_plane = false;
  Vec3 plane[2];
};

// The (unnormalised) normal of body b, pointing from it into the others (contact.hpp):
// grad m_rest - grad m_b, or for a pair with `larger_volume` the surface of the body with more
// volume at the node, or the plane that separates their particles where one was fitted.
Vec3 surface_normal(const Bodies& B, const Vec3& grad_total, int b, ContactNormal rule) {
  const Vec3 sum = grad_total - 2.0 * B.grad[b];
  if (B.n == 2 && B.has_plane) return B.plane[b];
  if (B.n != 2 || rule != ContactNormal::larger_volume) return sum;
  const int larger = B.volume[1] > B.volume[0] ? 1 : 0;
  // A larger body without a gradient here (no surface of its own): the sum.
  if (B.grad[larger].squaredNorm() == 0.0) return sum;
  return larger == b ? Vec3(-B.grad[b]) : Vec3(B.grad[larger]);
}

// The normal of body b against the rigid object r: the rigid body's own surface, whatever
// contact.normal says. First its geometry's (Grid::rigid_inward_normal): exact, where the mass
// gradient of its seeded particles is a staircase. A block on a rigid ramp at 20 degrees to the
// grid slid at 0.64 of Coulomb's rate on the gradient and at 0.76 on the fitted plane; on the
// geometry's normal at 1.000 (contact_friction_test); at a node inside the rigid body, the face
// on body b's side (Grid::rigid_inward_normal). Where the geometry gives no direction, grad m_r
// (its mass grows into it); the pair's sum
// grad m_r - grad m_b where the node is deep inside it (its gradient there is round-off, whose
// direction is noise). A rigid body
// does not deform, so its surface is the contact surface (NairnMPM biases rigid contact to the
// rigid material's gradient likewise). The deformable body's gradient tilts at its own edges: a
// block at rest on a floor moving at 5 m/s under it read the floor's slide as an approach of its
// rear face, and the first step made 1.4e-7 J of strain from nothing (5.6 times the energy that had
// entered); beside a second block the sum over all bodies pushed the blocks apart.
// Each gradient is taken over its body's own nodal mass (1 / length), so the test does not
// depend on the bodies' densities.
// A rigid body two cells thick has no central difference at its middle node worth the name: its
// faces are one node away each, and their masses differ only by the body's offset from the grid
// (4 delta / 2h for a floor delta off it), so the difference is zero or points out through the
// face the other body came through. There the sum tilted with body b's own edges, and a block
// crushed by 1e11 m/s^2 onto a 1 mm floor at 0.5 mm cells slipped through it at its corner (step
// 26); a floor moving at 0.01 m/s, its difference pointing out, let it through too (step 42). The
// face body b came through is the rigid body's one-sided difference on b's side, axis by axis
// (an axis along which b's gradient is round-off left out). It serves where the central
// difference opposes it or is much the weaker (a quarter: at a thick body's top node and the
// node below it they are equal or half, and agree).
Vec3 normal_against_rigid(const Bodies& B, int b, int r) {
  const double rigid = B.grad[r].norm() / B.m[r], other = B.grad[b].norm() / B.m[b];
  if (B.rigid_surface[b].squaredNorm() > 0.0) return B.rigid_surface[b];
  const double tiny = 1e-6 * B.grad[b].norm();
  Vec3 facing;
  for (int d = 0; d < 3; ++d)
    facing(d) = B.grad[b](d) > tiny    ? B.rigid_upper(d)
                : B.grad[b](d) < -tiny ? B.rigid_lower(d)
                                       : 0.0;
  const double face = facing.norm() / B.m[r];
  const bool facing_counts = face > 1e-6 * (face + other);
  if (facing_counts && (B.grad[r].dot(facing) <= 0.0 || rigid < 0.25 * face)) return facing;
  if (rigid > 1e-6 * (rigid + other)) return B.grad[r];
  return B.grad[r] - B.grad[b];
}

// The rigid object a node's bodies are corrected against: the one with the most volume there
// (NairnMPM's choice; not its density, which is arbitrary for a rigid body); -1 if none.
int rigid_partner(const Bodies& B) {
  int r = -1;
  for (int b = 0; b < B.n; ++b)
    if (B.rigid[b] && (r < 0 || B.volume[b] > B.volume[r])) r = b;
  return r;
}

// `hold[b]` (the strain pass, null otherwise): body b was held by the step (contact.hpp), so its
// relative normal velocity is zeroed whatever its sign; Coulomb acts only where it approaches.
// `stick[b]` (the strain pass): the step's friction stuck body b, so all its velocity relative to
// the centre of mass is removed. `approached[b]`: body b passed the approach test (the step's
// decision); `stuck[b]`: and Coulomb took all its slip.
bool correct(const Bodies& B, double mu_between_bodies, ContactNormal rule, bool book,
             const bool* hold, const bool* stick, Vec3* dv, double* heat, bool* approached,
             bool* stuck) {
  double M = 0.0;
  Vec3 P = Vec3::Zero(), P0 = Vec3::Zero(), gradM = Vec3::Zero();
  for (int b = 0; b < B.n; ++b) {
    M += B.m[b];
    P += B.m[b] * B.v[b];
    gradM += B.grad[b];
    if (book) P0 += B.m[b] * B.v0[b];
  }
  Vec3 vcm = P / M;
  Vec3 vcm_start = P0 / M;
  // A rigid object has infinite mass: the centre of mass moves with it (with two at one node,
  // the larger there; each is held at its own velocity, grid/rigid_fields.cpp).
  const int rigid = rigid_partner(B);
  if (rigid >= 0) {
    vcm = B.v[rigid];
    vcm_start = B.v0[rigid];
  }
  // Against a rigid object its own coefficient (objects.<name>.mu), else contact.mu.
  const double mu = rigid >= 0 ? B.rigid_mu[rigid] : mu_between_bodies;
  Vec3 net = Vec3::Zero();
  bool any = false;
  for (int b = 0; b < B.n; ++b) {
    dv[b].setZero();
    heat[b] = 0.0;
    approached[b] = false;
    stuck[b] = false;
    if (B.rigid[b]) continue;
    const Vec3 g =
        rigid >= 0 ? normal_against_rigid(B, b, rigid) : surface_normal(B, gradM, b, rule);
    const double gn = g.norm();
    if (!(gn > 0.0)) continue;  // no surface here: leave the body alone
    const Vec3 n = g / gn;
    const Vec3 u = B.v[b] - vcm;
    if (stick && stick[b]) {  // the step stuck it: no slip and no gap in its strain either
      dv[b] = -u;
      net += B.m[b] * dv[b];
      any = true;
      continue;
    }
    const double un = u.dot(n);
    approached[b] = un > 0.0;
    if (!approached[b] && !(hold && hold[b])) continue;  // touching or separating: left alone
    const Vec3 ut = u - un * n;
    const double ut_norm = ut.norm();
    dv[b] = -un * n;
    // Coulomb: the slip is reduced by s = min(mu u_n, |u_t|) (stick when it is all of it).
    double s = 0.0;
    if (mu > 0.0 && ut_norm > 0.0 && un > 0.0) {
      s = std::min(mu * un, ut_norm);
      dv[b] -= s * (ut / ut_norm);
    }
    stuck[b] = mu > 0.0 && un > 0.0 && !(s < ut_norm);
    // Coulomb work, only in slip (static friction does no work): the friction impulse m s times
    // the relative slip at the start of the step along t (contact.hpp). The normal reaction only
    // keeps u_n = 0 and does no work.
    if (book && s > 0.0 && s < ut_norm)
      heat[b] = B.m[b] * s * std::max(0.0, (B.v0[b] - vcm_start).dot(ut / ut_norm));
    net += B.m[b] * dv[b];
    any = true;
  }
  if (rigid >= 0) return any;  // the momentum gained is the rigid object's reaction
  const Vec3 mean = net / M;   // zero to round-off for a pair; removes it for three or more
  for (int b = 0; b < B.n; ++b) dv[b] -= mean;
  return any;
}

}  // namespace

// Long on purpose (about 170 lines): one pass over the contact nodes, each node's fields read,
// corrected and booked together in a loop a profiler reads as one (docs/architecture.md).
ContactTotals apply_contact(Grid& G, const ContactSpec& contact, std::vector<Vec3>& v,
                            ContactPass pass) {
  const bool book = pass == ContactPass::step;
  const bool strain = pass == ContactPass::strain;
  if (G.contact_held.size() != G.mass.size())  // sized by the Grid with two or more fields
    throw std::logic_error("apply_contact: a grid with " + std::to_string(G.fields()) +
                           " velocity field(s) has no contact marks");
  const bool write_heat = book && !G.heat.empty();
  const int nn = G.node_count();
  // read_scene refuses scenes with more fields; a grid built otherwise must not overrun the arrays.
  if (G.fields() > kMaxFields)
    throw std::logic_error("apply_contact: " + std::to_string(G.fields()) +
                           " velocity fields, at most " + std::to_string(kMaxFields));
  const int nf = G.fields();
  const int nt = G.threads();
  // Body of each field: its material (a material's parent and companion fields are one body
  // against the others); every field its own body if the solver set none.
  int body_of[kMaxFields];
  double inverse_density[kMaxFields];  // 1 / rho_f: the nodal volume m_f / rho_f
  bool rigid_field[kMaxFields];        // a rigid object's field (grid/rigid_fields.cpp)
  double rigid_mu[kMaxFields];         // its Coulomb coefficient against the bodies
  for (int f = 0; f < nf; ++f) {
    rigid_field[f] = G.is_rigid_field(f);
    rigid_mu[f] = G.rigid_friction(f, contact.mu);
    body_of[f] =
        f < static_cast<int>(G.settings().field_body.size()) ? G.settings().field_body[f] : f;
    inverse_density[f] = f < static_cast<int>(G.settings().field_density.size())
                             ? 1.0 / G.settings().field_density[f]
                             : 1.0;
  }
  // G.heat was zeroed at the start of the step (grid_update): contact adds to it.
  const std::vector<int>& nodes = G.active_nodes();  // heat is read at active nodes only
  const int na_nodes = static_cast<int>(nodes.size());
  // The totals per chunk of 1024 active nodes, then in chunk order: the same bits on any thread
  // count (mpm/threads/chunk_sums.hpp).
  ChunkSums<ContactTotals> chunk_sums(na_nodes, 1024);
  const std::ptrdiff_t chunks = chunk_sums.chunks();
#pragma omp parallel for schedule(static) num_threads(nt)
  for (std::ptrdiff_t chunk = 0; chunk < chunks; ++chunk) {
    ContactTotals& sum = chunk_sums[chunk];
    const int chunk_end = static_cast<int>(chunk_sums.end(chunk));
    for (int a_node = static_cast<int>(chunk_sums.begin(chunk)); a_node < chunk_end; ++a_node) {
      const int I = nodes[a_node];
      // The step marks per entry what it held (between bodies, within one); the strain pass
      // holds that, and elsewhere corrects where the fields approach.
      int active[kMaxFields];
      int na = 0;
      for (int f = 0; f < nf; ++f) {
        if (book) G.contact_held[f * nn + I] = 0;
        if (G.mass[f * nn + I] > 0.0) active[na++] = f;
      }
      if (na < 2) continue;
      const bool owned = G.owns(I);  // booked once in a domain decomposition
      const std::array<int, 3> ijk = G.ijk(I);
      const MirrorView mirror = mirror_view(G, ijk);
      if (mirror.skip) continue;
      const auto as_mirrored = [&](const Vec3& x) { return mirror.applied_to(x); };
      Vec3 grad[kMaxFields];
      for (int a = 0; a < na; ++a)
        grad[a] = mass_gradient(G, G.mass.data() + std::size_t(active[a]) * nn, ijk);
      // 1. Between bodies: each body's fields summed (mass, momentum, mass gradient).
      int body_index[kMaxFields];  // active field -> body slot
      int members[kMaxFields];     // fields per body slot
      int slot_of_body[kMaxFields];
      int slot_body[kMaxFields];  // body slot -> body
      for (int b = 0; b < nf; ++b) slot_of_body[b] = -1;
      Bodies B;
      Vec3 P[kMaxFields], P0[kMaxFields];
      for (int a = 0; a < na; ++a) {
        const int e = active[a] * nn + I;
        int& slot = slot_of_body[body_of[active[a]]];
        if (slot < 0) {
          slot_body[B.n] = body_of[active[a]];
          slot = B.n++;
          B.m[slot] = 0.0;
          B.volume[slot] = 0.0;
          B.grad[slot].setZero();
          B.rigid[slot] = rigid_field[active[a]];
          B.rigid_mu[slot] = rigid_mu[active[a]];
          P[slot].setZero();
          P0[slot].setZero();
          members[slot] = 0;
        }
        body_index[a] = slot;
        ++members[slot];
        B.m[slot] += G.mass[e];
        B.volume[slot] += G.mass[e] * inverse_density[active[a]];
        B.grad[slot] += grad[a];
        P[slot] += G.mass[e] * v[e];
        P0[slot] += G.mass[e] * G.velocity[e];
      }
      for (int b = 0; b < B.n; ++b) {
        B.v[b] = as_mirrored(P[b] / B.m[b]);
        B.v0[b] = as_mirrored(P0[b] / B.m[b]);
      }
      if (const int r = rigid_partner(B); r >= 0) {
        for (int b = 0; b < B.n; ++b) B.rigid_surface[b].setZero();
        for (int a = 0; a < na; ++a) {
          if (body_index[a] != r) continue;
          const double* m = G.mass.data() + std::size_t(active[a]) * nn;
          B.rigid_lower += mass_gradient(G, m, ijk, {-1, -1, -1});
          B.rigid_upper += mass_gradient(G, m, ijk, {1, 1, 1});
          // As each other body meets it, from the side its own gradient points from (none where
          // that gradient is round-off: a body on both sides of a thin blade).
          if (!G.is_rigid_field(active[a])) continue;
          for (int b = 0; b < B.n; ++b) {
            if (b == r) continue;
            const double own = B.grad[b].norm() / B.m[b], partner = B.grad[r].norm() / B.m[r];
            const Vec3 toward = own > 1e-6 * (own + partner) ? B.grad[b] : Vec3::Zero();
            B.rigid_surface[b] = as_mirrored(G.rigid_inward_normal(active[a], I, toward));
          }
        }
      }
      // The separating plane (`logistic_regression`, step/contact_planes.cpp) between two
      // bodies, oriented from the lower-numbered body into the other, as the mirror leaves it
      // (a face node's normal lies in the face, as its image's does).
      if (B.n == 2 && contact.normal == ContactNormal::logistic_regression &&
          !G.contact_plane.empty()) {
        const Vec3 plane = as_mirrored(G.contact_plane[I]);
        if (plane.squaredNorm() > 0.0) {
          const bool first_is_lower = slot_body[0] < slot_body[1];
          B.plane[0] = first_is_lower ? plane : Vec3(-plane);
          B.plane[1] = -B.plane[0];
          B.has_plane = true;
        }
      }
      for (int a = 0; a < na; ++a) {  // a one-field body keeps its velocity bit for bit
        const int b = body_index[a];
        if (members[b] == 1) {
          B.v[b] = as_mirrored(v[active[a] * nn + I]);
          B.v0[b] = as_mirrored(G.velocity[active[a] * nn + I]);
        }
      }
      Vec3 dv[kMaxFields];
      double heat[kMaxFields];
      bool hold[kMaxFields], stick[kMaxFields], approached[kMaxFields], stuck[kMaxFields];
      if (strain) {
        for (int b = 0; b < B.n; ++b) hold[b] = stick[b] = false;
        for (int a = 0; a < na; ++a) {
          const unsigned char held = G.contact_held[active[a] * nn + I];
          if (held & kHeldBetweenBodies) hold[body_index[a]] = true;
          if (held & kStuckBetweenBodies) stick[body_index[a]] = true;
        }
      }
      // `separation`: bodies whose particles have not met (along the fitted plane, or pair by
      // pair at a node of three or more) are apart, approaching or not, in every pass of the
      // step; where no gap was measured it is NaN and approach decides.
      // The margin at a pair's node only: at a node of three or more bodies the gap is measured
      // with the particles' box reach, which already errs towards contact (contact_planes.cpp).
      const double margin = B.n == 2 ? kGapMargin * smallest_cell_at(G, ijk) : 0.0;
      const bool apart = contact.detection == ContactDetection::separation &&
                         !G.contact_gap.empty() && G.contact_gap[I] > margin;
      bool any = false;
      if (B.n >= 2 && !apart &&
          correct(B, contact.mu, contact.normal, book, strain ? hold : nullptr,
                  strain ? stick : nullptr, dv, heat, approached, stuck)) {
        any = true;
        const int partner = rigid_partner(B);  // the rigid body they were corrected against
        const bool rigid_here = partner >= 0;
        Vec3 rigid_impulse = Vec3::Zero();  // what the step's corrections gained: the reaction
        for (int a = 0; a < na; ++a) {
          const int e = active[a] * nn + I;
          const int b = body_index[a];
          v[e] += dv[b];
          if (book && rigid_here) rigid_impulse += G.mass[e] * dv[b];
          if (book && approached[b]) G.contact_held[e] |= kHeldBetweenBodies;
          if (book && stuck[b]) G.contact_held[e] |= kStuckBetweenBodies;
          if (book && heat[b] > 0.0) {  // shared by the body's fields by mass
            const double h = members[b] == 1 ? heat[b] : heat[b] * G.mass[e] / B.m[b];
            if (owned) sum.friction_heat += h;
            if (write_heat) G.heat[e] += h;
          }
        }
        if (book && rigid_here && owned) {  // at the velocity of the partner that held them
          sum.rigid_impulse += rigid_impulse;
          sum.rigid_work += rigid_impulse.dot(B.v[partner]);
        }
      }
      // 2. Within a body with two fields here (a material's parent and its converted particles):
      //    a pair, on the velocities step 1 left.
      for (int b = 0; b < B.n; ++b) {
        if (members[b] < 2) continue;
        Bodies pair;
        int field_of[kMaxFields];
        bool hold_pair = false, stick_pair = false;
        for (int a = 0; a < na; ++a) {
          if (body_index[a] != b) continue;
          const int e = active[a] * nn + I;
          if (strain && (G.contact_held[e] & kHeldWithinBody)) hold_pair = true;
          if (strain && (G.contact_held[e] & kStuckWithinBody)) stick_pair = true;
          field_of[pair.n] = e;
          pair.m[pair.n] = G.mass[e];
          pair.volume[pair.n] = G.mass[e] * inverse_density[active[a]];
          pair.v[pair.n] = as_mirrored(v[e]);
          pair.grad[pair.n] = grad[a];
          pair.v0[pair.n] = as_mirrored(G.velocity[e]);
          pair.rigid[pair.n] = false;  // within a body: never a rigid object's
          ++pair.n;
        }
        for (int k = 0; k < pair.n; ++k) {
          hold[k] = hold_pair;
          stick[k] = stick_pair;
        }
        if (!correct(pair, contact.mu, contact.normal, book, strain ? hold : nullptr,
                     strain ? stick : nullptr, dv, heat, approached, stuck))
          continue;
        any = true;
        for (int k = 0; k < pair.n; ++k) {
          v[field_of[k]] += dv[k];
          if (book) G.contact_held[field_of[k]] |= kHeldWithinBody;
          if (book && stuck[k]) G.contact_held[field_of[k]] |= kStuckWithinBody;
          if (book) {
            if (owned) sum.friction_heat += heat[k];
            if (write_heat) G.heat[field_of[k]] += heat[k];
          }
        }
      }
      if (any && owned) ++sum.contact_nodes;
    }
  }
  ContactTotals total;
  chunk_sums.add_in_order([&](const ContactTotals& sum) { merge_into(total, sum); });
  return total;
}

}  // namespace impact::mpm
