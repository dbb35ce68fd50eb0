#include "study_meshes.hpp"

namespace fsi::study {

std::string to_string(Grading g) { return g == Grading::uniform ? "uniform" : "graded"; }

mesh::PatchMesh square_mesh(Grading grading, int refinements) {
  BlockSpec block;
  if (grading == Grading::uniform) {
    block.x = {AxisPiece{-1.0, 1.0, 8, 0.0, 0.0}};
    block.y = {AxisPiece{-1.0, 1.0, 8, 0.0, 0.0}};
  } else {
    // 8 sizes growing linearly from h0 to 4 h0 fill the length 2: 8 * 2.5 h0 = 2.
    block.x = {AxisPiece{-1.0, 1.0, 8, 0.1, 0.4}};
    block.y = {AxisPiece{-1.0, 1.0, 8, 0.4, 0.1}};
  }
  MeshSpec spec;
  spec.blocks = {block};
  spec.refinements = refinements;
  return mesh::build_patch_mesh(spec, {});
}

}  // namespace fsi::study
