#include "core/rereference.hpp"

#include <cmath>

#include "fsi/state.hpp"

namespace fsi::core {
namespace {

mesh::Vec2 displacement(const Eigen::VectorXd& solution, int node) {
  return {solution[kFieldsPerNode * node + kUx], solution[kFieldsPerNode * node + kUy]};
}

mesh::Vec2 rotate(double angle, const mesh::Vec2& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

std::vector<char> body_nodes(const fe::CutMesh& cut, const std::vector<int>& element_body, int body) {
  std::vector<char> nodes(cut.x.size(), 0);
  for (std::size_t k = 0; k < cut.elements.size() && k < element_body.size(); ++k)
    if (element_body[k] == body)
      for (int a = 0; a < cut.elements[k].vertices; ++a) nodes[cut.elements[k].node[a]] = 1;
  return nodes;
}

RigidFit fit_rigid_motion(const fe::CutMesh& cut, const Eigen::VectorXd& solution, const std::vector<char>* nodes) {
  RigidFit fit;
  const int n = static_cast<int>(cut.x.size());
  const auto used = [&](int i) { return cut.touches_solid[i] && !cut.touches_fluid[i] && (!nodes || (*nodes)[i]); };
  for (int i = 0; i < n; ++i)
    if (used(i)) {
      fit.from_mean += cut.x[i] - displacement(solution, i);
      fit.to_mean += cut.x[i];
      ++fit.nodes;
    }
  if (fit.nodes < 3) return RigidFit{};
  fit.from_mean /= fit.nodes;
  fit.to_mean /= fit.nodes;
  // 2D Procrustes: the angle maximizing sum b . Q a is atan2(sum a x b, sum a . b).
  double cross = 0.0, dot = 0.0;
  for (int i = 0; i < n; ++i)
    if (used(i)) {
      const mesh::Vec2 a = cut.x[i] - displacement(solution, i) - fit.from_mean;
      const mesh::Vec2 b = cut.x[i] - fit.to_mean;
      cross += a.x() * b.y() - a.y() * b.x();
      dot += a.dot(b);
    }
  fit.angle_rad = std::atan2(cross, dot);
  return fit;
}

void rereference_displacement(const fe::CutMesh& cut, const RigidFit& fit, Eigen::VectorXd& solution,
                              const std::vector<char>* nodes) {
  for (int i = 0; i < static_cast<int>(cut.x.size()); ++i) {
    if (nodes && !(*nodes)[i]) continue;
    const mesh::Vec2 X = cut.x[i] - displacement(solution, i);
    const mesh::Vec2 u = cut.x[i] - rereferenced_point(fit, X);
    solution[kFieldsPerNode * i + kUx] = u.x();
    solution[kFieldsPerNode * i + kUy] = u.y();
  }
}

mesh::Vec2 rereferenced_point(const RigidFit& fit, const mesh::Vec2& c) {
  return rotate(fit.angle_rad, c - fit.from_mean) + fit.to_mean;
}

}  // namespace fsi::core
