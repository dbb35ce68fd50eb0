#pragma once
/// \file stokes_cip.hpp
/// Study 3: equal-order Stokes with the anisotropic CIP stabilization S_aniso of
/// Sect. 12.2 (forms::add_pressure_stabilization) on a cut domain.
///
/// Fluid F = (-1,1)^2 outside the circle |x - c| = r (the "solid" inside), nu = 1:
///
///   (grad v, grad phi)_F - (p, div phi)_F = (f, phi)_F,
///   (div v, xi)_F + S_aniso(p, xi)       = 0,
///
/// with the manufactured solution v = (sin pi x cos pi y, -cos pi x sin pi y)
/// (divergence-free, a stream-function velocity), p = sin(pi x) cos(pi y / 2) + x y,
/// f = 2 pi^2 v + grad p. Velocity: Dirichlet from v on the outer boundary and at every
/// node of a solid sub-element (this includes the discrete interface, whose nodes lie on
/// the circle or, for the moved centres, O(h^2) from it). The solid's dofs are thereby
/// excluded (identity rows) instead of extended harmonically: the pressure at nodes
/// without a fluid sub-element is set to 0 and never enters a fluid equation, because
/// S_aniso drops solid cells. The outflow x = 1 carries the do-nothing condition
/// dv/dn - p n = g (g from the exact solution), as the FSI solver's open boundaries do;
/// it fixes the pressure level, so no pressure node is pinned and no mean is removed.
/// (Pinning one pressure node instead puts the discrete flux defect of the interpolated
/// velocity data into that node's continuity row: an O(1) pressure spike there.)
#include <array>
#include <vector>

#include "interface_poisson.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::study {

struct StokesResult {
  int nodes = 0;
  double velocity_l2 = 0.0;   ///< ||v - v_h||_L2(F_h)
  double pressure_l2 = 0.0;   ///< ||p - p_h||_L2(F_h)
  double pressure_max = 0.0;  ///< max over fluid nodes of |p - p_h|: checkerboard detector
  double rcond = 0.0;
  bool factorized = false;
  /// p_h and p along the fine-grid row nearest y = 0.75: x, p_h, p.
  std::vector<std::array<double, 3>> line;
};

StokesResult solve_stokes_cip(const mesh::PatchMesh& mesh, const Circle& circle, double gamma);

}  // namespace fsi::study
