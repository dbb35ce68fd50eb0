#pragma once
/// \file patch_colouring.hpp
/// Patches grouped so that no two patches of a group share a node: the element loops
/// then run each group's patches in parallel without two threads adding into the same
/// residual row or Jacobian entry. Every row's contributions arrive group by group in a
/// fixed order, whatever the number of threads: assembly stays bit-for-bit deterministic.
#include <vector>

#include "mesh/patch_mesh.hpp"

namespace fsi::mesh {

/// Groups of patch indices, each in increasing order; greedy colouring in patch order
/// (four groups on a structured block, a few more where blocks meet).
std::vector<std::vector<int>> colour_patches(const PatchMesh& mesh);

}  // namespace fsi::mesh
