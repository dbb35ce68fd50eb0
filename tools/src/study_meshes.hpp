#pragma once
/// \file study_meshes.hpp
/// The meshes of the FE convergence studies: (-1,1)^2, uniform or anisotropically graded,
/// refined globally (MeshSpec::refinements) so that the graded family stays nested.
#include <string>

#include "mesh/patch_mesh.hpp"

namespace fsi::study {

enum class Grading { uniform, graded };

std::string to_string(Grading g);

/// (-1,1)^2 with 8 x 8 base patches refined `refinements` times: 2 -> 65^2 nodes,
/// 3 -> 129^2, 4 -> 257^2. Graded: patch widths grow 1:4 from left to right and
/// heights shrink 4:1 from bottom to top (AxisPiece, linearly growing sizes), so cells
/// range from 1:4 to 4:1 aspect ratio and the grading direction changes across the
/// interface.
mesh::PatchMesh square_mesh(Grading grading, int refinements);

}  // namespace fsi::study
