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
void add_pressure_stabilization(const mesh::PatchMesh& mesh, const fe::CutMesh& cut,
                                const std::vector<fe::StabilizationEdge>& edges, double gamma,
                                int stride, int field, solve::SparseMatrix& a,
                                double transient_scale = 0.0);

}  // namespace fsi::forms
