#pragma once
/// \file error_quadrature.hpp
/// A quadrature of higher degree than the assembly rule (fe/element.hpp), for error
/// norms only: 3x3 Gauss on sub-quads (degree 5), the 7-point Radon/Dunavant rule on
/// sub-triangles (degree 5). With the degree-2 assembly rule the measured errors would
/// partly be quadrature errors, and Gauss points are superconvergence points of Q1
/// gradients, which would flatter the H1 error.
#include <vector>

#include "fe/element.hpp"

namespace fsi::study {

/// Quadrature points (physical position, weight * |det J|, shape values/gradients).
std::vector<fe::QuadraturePoint> error_quadrature(const fe::CutMesh& cut, const fe::SubElement& e);

}  // namespace fsi::study
