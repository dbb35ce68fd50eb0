#include "interface/body.hpp"

#include "fsi/state.hpp"

namespace fsi::interface {

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
