#pragma once
/// \file functionals.hpp
/// The chapter's quantities of interest (Sect. 12.6): distance to the walls and extent
/// of the ball from the discrete interface, and volume integrals over the discrete
/// solid: area, centroid, mean velocity, relative mass error
///   j_mass = |A rho_s^0 - int_S J rho_s^0 dx| / (A rho_s^0),  J = det(I - grad u),
/// A the body's area at t = 0 (pi r^2 for the ball), and the body's rotation.
#include <vector>

#include "fe/element.hpp"
#include "fsi/scenario.hpp"
#include "fsi/state.hpp"

namespace fsi::core {

/// `geometry`: the cut mesh whose interface is the body's current position (built from
/// the newest displacement); `cut` + `quadrature`: the mesh the solution lives on;
/// `reference_rotation_rad`: the turn re-referencing took out of u (State).
/// With several bodies, `geometry_body` and `cut_body` give the body of each sub-element
/// of `geometry` and `cut` (interface::element_bodies) for the per-body functionals, and
/// `body_references` the turns re-referencing took out of each body's u.
Functionals compute_functionals(const Scenario& scenario, const fe::CutMesh& geometry,
                                const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                                const Eigen::VectorXd& solution, double reference_rotation_rad,
                                const std::vector<int>& geometry_body = {}, const std::vector<int>& cut_body = {},
                                const std::vector<State::BodyReference>& body_references = {});


}  // namespace fsi::core
