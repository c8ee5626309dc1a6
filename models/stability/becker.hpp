// Loss of ellipticity (for the rate problem: loss of hyperbolicity of the dynamic equations)
// through the acoustic tensor: Hill (1962), J. Mech. Phys. Solids 10:1-16; Rudnicki & Rice (1975),
// J. Mech. Phys. Solids 23:371-394; Rice (1976), Proc. 14th IUTAM Congress, 207-220; report eq.
// (11) with Becker's (2002, Int. J. Solids Struct. 39:3555-3580) simplification of the normal
// search.
//
// A band with unit normal n across which the velocity gradient jumps by g (x) n can form when
//   A(n) g = 0,   A_jk(n) = n_i C_ijkl n_l,
// has a non-zero g, i.e. when det A(n) = 0. The indicator reported here is
//   min_n det A^ep(n) / det A^e(n),
// dimensionless: 1 for an elastic tangent, <= 0 when some band normal has lost ellipticity.
// Dividing by the elastic determinant (positive for any stable isotropic elasticity) removes the
// mu^3 scale and makes the indicator comparable between materials and load states.
//
// Normal search (NormalSearch):
//   principal_plane (default; Becker 2002, as the report describes): n = cos t e_max + sin t e_min,
//     in the plane of the largest and smallest principal stresses (eigenvectors of sigma); a
//     coarse sweep of 36 angles in [0, pi), then a Brent refinement (gsl_min) around the best
//     sample. For associated J2 plasticity with isotropic elasticity this plane is exact: Rudnicki
//     & Rice (1975) show that the critical normal is perpendicular to the intermediate principal
//     direction, at H_crit = -(3/2) (1 + nu) mu (s_II / tau)^2 (tau = sqrt(s:s / 2), s_II the
//     intermediate principal deviatoric stress; their h is H/3 in shear measures). Hence
//     H_crit = -(1 + nu) mu / 2 in uniaxial tension, with band normals on the cone
//     cos^2 theta = (2 - nu)/3 about the tension axis, and H_crit = 0 in plane strain / pure shear
//     (s_II = 0, normals at 45 degrees), where Becker coincides with Drucker.
//   full_sphere: a coarse sweep of the hemisphere (5 x 10 degree grid in the principal frame) and a
//     Nelder-Mead refinement (gsl_multimin nmsimplex2) in the two angles; for tangents other than
//     associated J2, whose critical normal need not lie in that plane.
// Both return the critical normal in the lab frame, and the indicator is the ratio at that normal.
//
// Geometric stress terms: eq. (11) adds terms of order sigma to the tangent's acoustic tensor (the
// difference between the co-rotational stress rate of the tangent and the rate of nominal stress
// that the band equilibrium needs). They are omitted here, as in Rudnicki & Rice's leading-order
// result, because (i) they are O(sigma_eq / mu) ~ 1e-2 of A for aluminium (sigma_y / mu = 324 MPa /
// 26 GPa), below the accuracy of the tangent itself; (ii) the hypoelastic stress update they would
// belong to neglects terms of the same order; (iii) their exact form depends on the objective rate
// (Jaumann, Green-Naghdi, Truesdell) and the printed eq. (11) is not even symmetric in (i, j), so
// copying it would add an error of the same order it claims to correct; (iv) without them an
// elastic state gives exactly 1 and the indicator stays a pure property of the tangent. Their
// effect matters only where H_crit = 0 (plane strain), where they move the threshold by
// O(sigma_eq) in either direction; there the Drucker check (which fires at H <= 0) gives the same
// verdict as Becker without them.
//
// Differences from the 2004 code (docs/report_code.md sec. 9): it evaluated Becker's
// closed-form quadratic with C^ep components in the working (unrotated material) frame, not the
// principal-stress frame, did no direction search, and used the inconsistent, effectively
// ideal-plastic tangent of sec. 7. Here the search is done in the principal frame (or over the
// sphere) with the consistent tangent.
//
// Cost: the sweep is allocation-free; the refinement allocates a small GSL workspace once per call
// (gsl_min / gsl_multimin have no caller-provided storage). Objective values that are not finite
// are replaced by DBL_MAX so GSL's error handler is never reached; non-finite inputs return a NaN
// indicator that is not "unstable".
#pragma once

#include "models/core/tensor.hpp"

namespace impact {

/// Acoustic tensor A_jk = n_i C_ijkl n_l of a fourth-order tensor C for a unit normal n.
Mat3 acoustic_tensor(const Tensor4& C, const Vec3& n);

enum class NormalSearch { principal_plane, full_sphere };

struct BeckerResult {
  double indicator = 1.0;      ///< min_n det A^ep(n) / det A^e(n) [-]; 1 when the check did not run
  Vec3 normal = Vec3::Zero();  ///< critical band normal in the lab frame (unit) [-]
  bool unstable = false;       ///< indicator <= 0
};

/// Becker's check: tangent C^ep, elastic tangent C^e (the reference for the ratio), Cauchy stress
/// [Pa] (its principal frame orients the search), search strategy.
BeckerResult becker_check(const Tensor4& tangent, const Tensor4& elastic, const Mat3& stress,
                          NormalSearch search);

/// Becker's principal-plane check for the associated J2 tangent
/// C^ep = C^e - (2 mu)^2 N (x) N / (3 mu + H), N = 3 s / (2 sigma_eq), in closed form. By the
/// matrix determinant lemma, with A^e = mu I + (K + mu/3) n (x) n and v = N n,
///   det A^ep / det A^e = 1 - (a / mu) [ |v|^2 - beta (n.v)^2 ],  a = 4 mu^2 / (3 mu + H),
///   beta = (K + mu/3) / (K + 4 mu/3).
/// With n = sqrt(x) e_max + sqrt(1 - x) e_min the bracket is a concave quadratic in x = cos^2 t,
///   f(x) = N_min^2 + (N_max^2 - N_min^2) x - beta (N_min + (N_max - N_min) x)^2,
/// so the minimum over the plane is at x in {0, 1, x*} with f'(x*) = 0. Same answer as
/// becker_check(elastic_plastic_tangent(...), ..., principal_plane) (tested), ~100 times cheaper:
/// the MPM runs it on every plastic point of every step.
BeckerResult becker_check_j2(double bulk_modulus, double shear_modulus, const Mat3& stress,
                             double H);

}  // namespace impact
