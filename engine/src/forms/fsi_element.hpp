#pragma once
/// \file fsi_element.hpp
/// The monolithic FSI residual of one sub-element: the modified dG(0) step of
/// Sect. 12.3 for (v, u, p), divided by the time step k. The terms are numbered; the
/// lines of element_residual that assemble them carry the numbers (fsi_element.cpp).
///
/// Fluid sub-element (rho_f, sigma_f = rho_f nu_f (grad v + grad v^T) - p I):
///   momentum   (1) (rho_f (v - v_old∘T)/k, phi) + (2) (rho_f ((v - d_t T) . grad) v, phi)
///              + (3) (sigma_f, grad phi)
///              - (4) <rho_f nu_f grad v^T n, phi>_{open boundary}     (do-nothing correction, 12.1)
///              - (5) <beta rho_f / 2 (v.n)_- v, phi>_{open boundary} (backflow, 0 by default)
///   pressure   (6) (div v - ramp(p_cav - p) / (rho_f nu_f), xi)_F  [+ S_aniso(p, xi), assembled
///              separately; the ramp is the optional cavitation floor, 0 by default]
///   displacement (7) harmonic extension (grad u, grad psi)_F on nodes not touching the solid
/// Solid sub-element (St. Venant-Kirchhoff, Eulerian, 12.2; F = I - grad u, J = det F,
/// E = (F^-T F^-1 - I)/2, sigma_s = J F^-1 (2 mu E + lambda tr E I) F^-T, rho_s = J rho_s^0):
///   momentum   (8) (rho_s ((v - v_old∘T)/k + ((v - d_t T) . grad) v), phi)
///              - (9) ((rho_s - rho_b) g, phi) + (10) (sigma_s, grad phi)
///              (rho_b = rho_f with buoyancy, else 0)
///   displacement (11) ((u - u_old∘T)/k + ((v - d_t T) . grad) u - v, psi)_S
///              - (12) alpha h^s (grad v, grad psi)_S   (12.7);
///              at a wall node the solid lets go of, (7) instead (core/contact_release.hpp)
///   pressure   (13) harmonic extension (grad p, grad xi)_S on nodes not touching the fluid
///
/// Test spaces: a displacement row belongs to the solid equation as soon as its node
/// touches a solid sub-element (W_s), otherwise to the extension; a pressure row to
/// the divergence equation as soon as its node touches a fluid sub-element (L_f).
#include <array>
#include <vector>

#include "core/dual.hpp"
#include "fe/element.hpp"

namespace fsi::forms {

inline constexpr int kMaxLocal = 20;  ///< 4 nodes x 5 fields
using Jet = Dual<kMaxLocal>;

/// Material and step constants (SI units).
struct FsiCoefficients {
  double k_s = 1e-3;            ///< time step
  double rho_f = 1e3, nu_f = 1e-3;
  double rho_s0 = 1e3, mu_s = 2e5, lambda_s = 8e5;
  double gx = 0.0, gy = -0.5;   ///< gravity on the solid [m/s^2]
  /// The density [kg/m^3] the solid's weight is reduced by: rho_f with buoyancy (the
  /// reduced-pressure form: the solid feels (rho_s - rho_f) g), 0 without.
  double rho_buoyancy = 0.0;
  double alpha = 0.1, s = 2.0;  ///< solid velocity stabilization alpha h^s
  double extension_u = 1.0;     ///< weight of the displacement extension rows
  double extension_p = 1.0;     ///< weight of the pressure extension rows
  /// Cavitation floor (NumericsSpec::cavitation_pressure_pa): off when cavitation_p_pa == 0.
  double cavitation_p_pa = 0.0;
  double cavitation_smoothing_pa = 0.0;  ///< width of the C^1 rounding of the ramp
  double backflow_beta = 0.0;  ///< directional do-nothing on inflow (NumericsSpec::backflow_beta)
};

/// Width of the rounding of the cavitation floor's ramp: a quarter of |p_cav|.
inline double cavitation_smoothing_pa(double cavitation_p_pa) {
  return 0.25 * (cavitation_p_pa < 0.0 ? -cavitation_p_pa : cavitation_p_pa);
}

/// max(0, x) rounded C^1 over [-w/2, w/2]: the quadratic (x + w/2)^2 / (2 w) in between.
/// Newton sees a continuous derivative where the floor switches on; a kink there made
/// the iteration bounce between the two branches.
template <class S>
S rounded_ramp(const S& x, double w) {
  const double xv = value_of(x);
  if (xv <= -0.5 * w) return S(0.0);
  if (xv >= 0.5 * w) return x;
  const S t = x + 0.5 * w;
  return t * t / (2.0 * w);
}

/// Rate at which the floor lets the fluid expand at pressure p [1/s]: the term taken off
/// div v in the fluid's divergence row (0 with the floor off, p_cav == 0).
inline double cavitation_expansion_rate(double p_pa, double cavitation_p_pa, double mu_f_pas) {
  if (cavitation_p_pa == 0.0) return 0.0;
  return rounded_ramp(cavitation_p_pa - p_pa, cavitation_smoothing_pa(cavitation_p_pa)) / mu_f_pas;
}

/// Per quadrature point values fixed during the Newton loop: old values at T_m(x, t_{m-1})
/// and the mesh velocity d_t T.
struct OldValues {
  double vx = 0, vy = 0, ux = 0, uy = 0;  ///< v^{m-1}, u^{m-1} at T_m(x, t_{m-1})
  double tx = 0, ty = 0;                  ///< d_t T [m/s]
};

/// One sub-element side on an open (do-nothing) boundary.
struct OpenBoundarySide {
  std::array<fe::ShapeValues, 2> shape;  ///< at two Gauss points
  std::array<double, 2> weight{};        ///< Gauss weight x length [m]
  double nx = 0, ny = 0;                 ///< outward unit normal
};

struct ElementInput {
  const fe::SubElement* element = nullptr;
  const fe::QuadraturePoint* qp = nullptr;  ///< its quadrature points
  const OldValues* old = nullptr;           ///< one per quadrature point
  int num_qp = 0;
  double h_patch_m = 0.0;                   ///< h_P of the element's patch
  std::array<char, 4> u_row_solid{};        ///< node touches the solid: u row = solid equation
  std::array<char, 4> p_row_fluid{};        ///< node touches the fluid: p row = divergence equation
  /// A wall node the solid may leave (core/contact_release.hpp): in a solid sub-element its
  /// u row is the harmonic extension, not the displacement equation.
  std::array<char, 4> u_row_released{};
  const OpenBoundarySide* open_sides = nullptr;
  int num_open_sides = 0;
};

/// Local residual (5 per node: vx, vy, ux, uy, p) for local unknowns `x` of the same layout.
template <class S>
void element_residual(const ElementInput& in, const FsiCoefficients& c,
                      const std::array<S, kMaxLocal>& x, std::array<S, kMaxLocal>& r);

extern template void element_residual<double>(const ElementInput&, const FsiCoefficients&,
                                              const std::array<double, kMaxLocal>&,
                                              std::array<double, kMaxLocal>&);
extern template void element_residual<Jet>(const ElementInput&, const FsiCoefficients&,
                                           const std::array<Jet, kMaxLocal>&,
                                           std::array<Jet, kMaxLocal>&);

}  // namespace fsi::forms
