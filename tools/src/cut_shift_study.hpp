#pragma once
/// \file cut_shift_study.hpp
/// Study 2: the interface Poisson error must not depend on where the interface cuts the
/// patches. Three families of circles on the uniform 65^2-node mesh (h = 1/16):
///
///   generic  - an off-grid centre, radius 0.6;
///   vertex   - centre (0,0), radius 10 h: the circle passes exactly through 4 patch
///              vertices and is tangent to grid lines there;
///   tangent  - centre (h/2, 0), radius 10 h: tangent to the grid line y = 10 h in the
///              middle of a patch side (and through the vertex (10.5 h, 0)).
///
/// Each family is moved by 1e-5 patch sizes in x, y and diagonally, and its radius is
/// changed by 1e-8, 1e-10, 1e-12 h (cuts land that close to vertices: they are snapped)
/// and by 1e-5 h (not snapped: a tiny sub-triangle). The L2 error must change by < 5 %
/// relative to the family's unshifted circle, UMFPACK's rcond and the angles stay sane.
#include <string>
#include <vector>

#include "interface_poisson.hpp"

namespace fsi::study {

struct ShiftCase {
  std::string family;
  std::string name;
  Circle circle;
  PoissonResult result;
  double relative_change = 0.0;  ///< |e - e_family| / e_family of the L2 error
};

std::vector<ShiftCase> run_shift_study();

}  // namespace fsi::study
