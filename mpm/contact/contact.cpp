#include "mpm/contact/contact.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "mpm/step/parallel.hpp"

namespace impact::mpm {

namespace {

constexpr int kMaxFields = 64;  // fields sharing one node (materials x 2)

// Gradient of one field's nodal mass at node (i, j, k) by central differences (one-sided at the
// outermost layers). The report's normals came from the same differences (sec. 14).
Vec3 mass_gradient(const Grid& G, const double* m, const std::array<int, 3>& ijk) {
  Vec3 g;
  const std::array<int, 3>& c = G.cells();
  for (int d = 0; d < 3; ++d) {
    std::array<int, 3> lo = ijk, hi = ijk;
    lo[d] = std::max(ijk[d] - 1, -1);
    hi[d] = std::min(ijk[d] + 1, c[d] + 1);
    const double span = (hi[d] - lo[d]) * G.spacing()(d);
    g(d) = (m[G.index(hi[0], hi[1], hi[2])] - m[G.index(lo[0], lo[1], lo[2])]) / span;
  }
  return g;
}

}  // namespace

ContactTotals apply_contact(Grid& G, const ContactSpec& contact, std::vector<Vec3>& v,
                            ContactPass pass) {
  const bool book = pass == ContactPass::step;
  const bool write_heat = book && !G.heat.empty();
  const int nn = G.node_count();
  const int nf = std::min(G.fields(), kMaxFields);
  const int nt = G.threads();
  const bool friction = contact.type == ContactType::friction && G.has_nodal_stress();
  ContactTotals partial[kMaxThreads];
  if (write_heat) G.for_active_entries([&](int e) { G.heat[e] = 0.0; });
  const std::vector<int>& nodes = G.active_nodes();  // heat is read at active nodes only
  const int na_nodes = static_cast<int>(nodes.size());
#pragma omp parallel num_threads(nt)
  {
    ContactTotals sum;
#pragma omp for schedule(static)
    for (int a_node = 0; a_node < na_nodes; ++a_node) {
      const int I = nodes[a_node];
      int active[kMaxFields];
      int na = 0;
      for (int f = 0; f < nf; ++f)
        if (G.mass[f * nn + I] > 0.0) active[na++] = f;
      if (na < 2) continue;
      double M = 0.0;
      Vec3 P = Vec3::Zero(), gradM = Vec3::Zero();
      Vec3 grad[kMaxFields];
      const std::array<int, 3> ijk = G.ijk(I);
      for (int a = 0; a < na; ++a) {
        const int e = active[a] * nn + I;
        M += G.mass[e];
        P += G.mass[e] * v[e];
        grad[a] = mass_gradient(G, G.mass.data() + std::size_t(active[a]) * nn, ijk);
        gradM += grad[a];
      }
      const Vec3 vcm = P / M;
      // The start field's centre-of-mass velocity: the slip the bodies make over the step.
      Vec3 vcm_start = Vec3::Zero();
      if (book) {
        for (int a = 0; a < na; ++a) {
          const int e = active[a] * nn + I;
          vcm_start += G.mass[e] * G.velocity[e];
        }
        vcm_start /= M;
      }
      Mat3 sigma = Mat3::Zero();
      if (friction) {
        for (int a = 0; a < na; ++a) {
          const double* s = G.nodal_stress()[active[a] * nn + I].s;
          Mat3 t;
          t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
          sigma += t;
        }
      }
      Vec3 dv[kMaxFields];
      double heat[kMaxFields];
      Vec3 net = Vec3::Zero();
      bool any = false;
      for (int a = 0; a < na; ++a) {
        dv[a].setZero();
        heat[a] = 0.0;
        const Vec3 g = gradM - 2.0 * grad[a];  // grad m_rest - grad m_f
        const double gn = g.norm();
        if (!(gn > 0.0)) continue;  // no surface here: leave the field alone
        const Vec3 n = g / gn;
        const int e = active[a] * nn + I;
        const double m = G.mass[e];
        const Vec3 u = v[e] - vcm;
        const double un = u.dot(n);
        const bool approaching = un > 0.0;
        // The report's friction also held surfaces that SEPARATE while the nodal stress is
        // compressive. With sigma_I summed from the particles inside the interface that glued
        // rebounding blocks whose interior still rang in compression, and the switching between
        // glued and free fed energy in (contact_blocks_test). Compression now
        // keeps a touching (u_n = 0) pair in contact, never pulls a separating pair back.
        const bool compressed = friction && n.dot(sigma * n) < 0.0 && un >= 0.0;
        if (!approaching && !compressed) continue;
        const Vec3 ut = u - un * n;
        const double ut_norm = ut.norm();
        dv[a] = -un * n;
        // Coulomb: the slip is reduced by s = min(mu |u_n|, |u_t|) (stick when it is all of it).
        double s = 0.0;
        if (contact.mu > 0.0 && ut_norm > 0.0) {
          s = std::min(contact.mu * std::abs(un), ut_norm);
          dv[a] -= s * (ut / ut_norm);
        }
        // Coulomb work: the friction impulse m s times the slip speed of the motion over the
        // step, that of the corrected start field (what the positions follow), >= 0. The
        // normal reaction only keeps u_n = 0 and does no work.
        if (book && s > 0.0) {
          const Vec3 u0 = G.velocity[e] - vcm_start;
          heat[a] = m * s * (u0 - u0.dot(n) * n).norm();
        }
        net += m * dv[a];
        any = true;
      }
      if (!any) continue;
      ++sum.contact_nodes;
      const Vec3 mean = net / M;  // zero to round-off for a pair; removes it for three or more
      for (int a = 0; a < na; ++a) {
        const int e = active[a] * nn + I;
        v[e] += dv[a] - mean;
        if (book) {
          sum.friction_heat += heat[a];
          if (write_heat) G.heat[e] += heat[a];
        }
      }
    }
    partial[omp_get_thread_num()] = sum;
  }
  ContactTotals total;
  for (int t = 0; t < nt; ++t) {  // thread order: deterministic
    total.friction_heat += partial[t].friction_heat;
    total.contact_nodes += partial[t].contact_nodes;
  }
  return total;
}

}  // namespace impact::mpm
