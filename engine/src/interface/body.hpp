#pragma once
/// \file body.hpp
/// The body's initial geometry d0 (signed distance, negative inside) and the Initial
/// Point Set level set phi(x) = d0(x - u(x)) (docs/method.md, "The interface").
#include "fe/point_locator.hpp"
#include "fsi/scenario.hpp"

namespace fsi::interface {

using mesh::Vec2;

/// Signed distance to the initial ball: |X - c| - r [m].
inline double initial_distance(const BodySpec& body, const Vec2& X) {
  return (X - Vec2(body.center_m.x, body.center_m.y)).norm() - body.radius_m;
}

/// phi(x) = d0(x - u(x)) for the displacement coefficients `solution` on `cut`. Points
/// the locator cannot place (outside the domain) use u = 0.
fe::LevelSet ips_level_set(const BodySpec& body, const fe::CutMesh& cut,
                           const fe::PatchBuckets& buckets, const Eigen::VectorXd& solution);

}  // namespace fsi::interface
