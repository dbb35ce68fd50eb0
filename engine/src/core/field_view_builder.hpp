#pragma once
/// \file field_view_builder.hpp
/// Copies the current discretization into the renderer-facing FieldView.
#include <vector>

#include "fe/cut_mesh.hpp"
#include "fsi/field_view.hpp"
#include "fsi/scenario.hpp"
#include "fsi/state.hpp"

namespace fsi::core {

/// `element_body`: the body of each sub-element of `cut` (interface::element_bodies; empty:
/// body1 for every solid one).
FieldView build_field_view(const mesh::PatchMesh& mesh, const fe::CutMesh& cut, const State& state,
                           const Scenario& scenario, const std::vector<int>& element_body = {});

}  // namespace fsi::core
