#pragma once
/// \file interface_poisson.hpp
/// Study 1: the interface Poisson problem of Frei & Richter (2014) with a coefficient
/// jump across a circle,
///
///   -div(kappa grad u) = f in (-1,1)^2,  u = g on the boundary,
///   kappa = kappa_in inside the circle |x - c| < r0, kappa_out outside,
///
/// and the manufactured solution u = w / kappa with
///
///   w = (|x - c|^2 - r0^2) s(x),  s = 1 + sin(2x) cos(y) / 2.
///
/// w vanishes on the circle, so u is continuous, and kappa grad u = grad w is the same
/// smooth field on both sides, so the flux is continuous too; f = -Laplace(w) is smooth
/// across the interface. The kink of u is not aligned with the mesh: only the locally
/// modified elements resolve it. Each side's formula is a smooth function on all of
/// (-1,1)^2; the error on a sub-element uses the formula of the sub-element's phase.
#include "fe/cut_mesh.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::study {

struct Circle {
  mesh::Vec2 centre = mesh::Vec2::Zero();
  double radius = 0.6;
};

struct PoissonResult {
  int nodes = 0;
  double l2_error = 0.0;      ///< ||u - u_h||_L2
  double h1_error = 0.0;      ///< |u - u_h|_H1 (semi-norm)
  double rcond = 0.0;         ///< UMFPACK reciprocal condition estimate
  bool factorized = false;    ///< false: singular matrix (then errors are meaningless)
  double min_angle = 0.0;     ///< smallest interior angle of all sub-elements [rad]
  double max_angle = 0.0;     ///< largest interior angle [rad]
  int cut_patches = 0;
  int saddle_patches = 0;
};

/// Assembles, solves and measures the interface problem on `mesh` (kappa_in = 1,
/// kappa_out = 10).
PoissonResult solve_interface_poisson(const mesh::PatchMesh& mesh, const Circle& circle);

}  // namespace fsi::study
