#pragma once
/// \file pressure_stabilization.hpp
/// Anisotropic continuous interior penalty (CIP) pressure stabilization, Sect. 12.2:
///
///   S_aniso(p, xi) = gamma h_P^2 sum_{e in E_h^i} int_e {h_n grad p . grad xi}_e
///                  + gamma h_P^2 sum_{e in E_h^0} int_e h_n [grad p]_e . [grad xi]_e
///
/// E_h^i: edges of a sub-triangle (edges of cut patches), where neighbouring cells may
/// have wildly different normal sizes h_n, so the mean of the one-sided products
/// replaces the jump; E_h^0: edges between two sub-quads (jump form, h_n the mean of
/// both sides). Only fluid cells contribute (a solid neighbour's half is dropped).
/// h_P is the larger patch size of the two sides.
#include <vector>

#include "fe/stabilization_edges.hpp"
#include "mesh/patch_mesh.hpp"
#include "solve/sparsity.hpp"

namespace fsi::forms {

/// Adds S_aniso(p, xi) into matrix `a` at (stride * node + field) rows and columns.
///
/// `gamma` is the dimensionless gamma divided by the dynamic viscosity rho_f nu_f
/// [1/(Pa s)], so that S balances (div v, xi) in the Stokes regime. With
/// `transient_scale` = rho_f / (k rho_f nu_f) [1/m^2] > 0 the edge coefficient becomes
///     gamma / (1 + transient_scale h_P^2) = gamma_0 / (rho_f nu_f + rho_f h_P^2 / k),
/// the usual PSPG-type scaling once the time derivative dominates the viscous term
/// (rho_f h_P^2 / k >> rho_f nu_f: by a factor ~300 at the ground in Example 1).
/// Without it the stabilization lets the fluid leak out of a thin gap through the
/// pressure diffusion, and the squeeze-film pressure that stops the ball never builds.
///
/// With `wall_film_factor` = kappa > 0, a fluid sub-element K of a cut patch with a node
/// on a no-slip wall uses h = min(h_P, kappa h_K) for its side of an E_h^i edge, h_K the
/// smallest height of K (2|K| / longest side for triangles). Why: in a film of height
/// h_K under a body, the h_P-scaled term lets fluid through like a Darcy flux
/// gamma h_P^2 / (1 + ...) h_K grad p, while lubrication flow carries only
/// h_K^3 / (12 mu) grad p, so the film drains too fast once h_K is below about 1 mm
/// (Example 1). With h = h_K the leak scales like h_K^3, as lubrication does.
void add_pressure_stabilization(const mesh::PatchMesh& mesh, const fe::CutMesh& cut,
                                const std::vector<fe::StabilizationEdge>& edges, double gamma,
                                int stride, int field, solve::SparseMatrix& a,
                                double transient_scale = 0.0, double wall_film_factor = 0.0);

}  // namespace fsi::forms
