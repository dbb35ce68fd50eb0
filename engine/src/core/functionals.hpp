#pragma once
/// \file functionals.hpp
/// The chapter's quantities of interest (Sect. 12.6): distance to the walls and extent
/// of the ball from the discrete interface, and volume integrals over the discrete
/// solid: area, centroid, mean velocity, relative mass error
///   j_mass = |pi r^2 rho_s^0 - int_S J rho_s^0 dx| / (pi r^2 rho_s^0),  J = det(I - grad u).
#include <vector>

#include "fe/element.hpp"
#include "fsi/scenario.hpp"
#include "fsi/state.hpp"

namespace fsi::core {

/// `geometry`: the cut mesh whose interface is the body's current position (built from
/// the newest displacement); `cut` + `quadrature`: the mesh the solution lives on.
Functionals compute_functionals(const Scenario& scenario, const fe::CutMesh& geometry,
                                const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                                const Eigen::VectorXd& solution);

}  // namespace fsi::core
