#pragma once
/// \file field_view_builder.hpp
/// Copies the current discretization into the renderer-facing FieldView.
#include "fe/cut_mesh.hpp"
#include "fsi/field_view.hpp"
#include "fsi/scenario.hpp"
#include "fsi/state.hpp"

namespace fsi::core {

FieldView build_field_view(const mesh::PatchMesh& mesh, const fe::CutMesh& cut, const State& state,
                           const Scenario& scenario);

}  // namespace fsi::core
