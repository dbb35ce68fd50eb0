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

/// Adds `weight` * S_aniso(p, xi) into matrix `a` at (stride * node + field) rows and
/// columns. `gamma` is the dimensionless gamma divided by the dynamic viscosity
/// rho_f nu_f [1/(Pa s)], so that S balances (div v, xi).
void add_pressure_stabilization(const mesh::PatchMesh& mesh, const fe::CutMesh& cut,
                                const std::vector<fe::StabilizationEdge>& edges, double gamma,
                                int stride, int field, solve::SparseMatrix& a);

}  // namespace fsi::forms
