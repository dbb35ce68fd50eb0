#include "interface/body.hpp"

#include <cmath>

#include "fsi/state.hpp"

namespace fsi::interface {

Vec2 initial_fluid_velocity(const BodySpec& body, const Vec2& x) {
  const Vec2 u(body.initial_velocity_mps.x, body.initial_velocity_mps.y);
  const Vec2 d = x - Vec2(body.center_m.x, body.center_m.y);
  const double r2 = d.squaredNorm();
  if (u.isZero() || !(r2 > 0.0)) return Vec2::Zero();
  const double s = body.radius_m * body.radius_m / r2;  // (R/r)^2
  const Vec2 e = d / std::sqrt(r2);
  return s * (2.0 * u.dot(e) * e - u);
}

fe::LevelSet ips_level_set(const BodySpec& body, const fe::CutMesh& cut,
                           const fe::PatchBuckets& buckets, const Eigen::VectorXd& solution) {
  return [&body, &cut, &buckets, &solution](const Vec2& x) {
    const fe::Location loc = fe::locate(cut, buckets, x, 1e-6);
    if (loc.element < 0) return initial_distance(body, x);
    const Vec2 u(fe::evaluate(cut, loc, solution, kFieldsPerNode, kUx),
                 fe::evaluate(cut, loc, solution, kFieldsPerNode, kUy));
    return initial_distance(body, x - u);
  };
}

}  // namespace fsi::interface
