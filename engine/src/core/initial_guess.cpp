#include "core/initial_guess.hpp"

#include "fsi/state.hpp"

namespace fsi::core {
namespace {

/// The largest solid sub-element of patch p in `cut` (-1: none).
int largest_solid_element(const fe::CutMesh& cut, int p) {
  int best = -1;
  double best_area = 0.0;
  for (int k = cut.first_element[p]; k < cut.first_element[p + 1]; ++k) {
    if (cut.elements[k].phase != Phase::solid) continue;
    const double a = fe::element_area(cut, cut.elements[k]);
    if (a > best_area) {
      best_area = a;
      best = k;
    }
  }
  return best;
}

/// True when patch p is cut into the same sub-elements on both meshes.
bool patch_unchanged(const mesh::PatchMesh& mesh, const fe::CutMesh& a, const fe::CutMesh& b, int p) {
  if (a.kind[p] != b.kind[p]) return false;
  const int count = a.first_element[p + 1] - a.first_element[p];
  if (count != b.first_element[p + 1] - b.first_element[p]) return false;
  for (int n : mesh.patches[p].node)
    if (a.x[n] != b.x[n]) return false;
  for (int k = 0; k < count; ++k) {
    const fe::SubElement& ea = a.elements[a.first_element[p] + k];
    const fe::SubElement& eb = b.elements[b.first_element[p] + k];
    if (ea.node != eb.node || ea.phase != eb.phase) return false;
  }
  return true;
}

/// The solid field of `element` continued to x (its shape functions evaluated outside
/// the element: linear for triangles, bilinear for quads). False if x has no reference
/// coordinates for it.
bool extrapolate_solid(const fe::CutMesh& cut, int element, const mesh::Vec2& x, const Eigen::VectorXd& solution,
                       Eigen::Ref<Eigen::VectorXd> node_values) {
  double xi = 0.0, eta = 0.0;
  if (!fe::reference_coordinates(cut, cut.elements[element], x, xi, eta)) return false;
  fe::Location at;
  at.element = element;
  at.shape = fe::shape_at_reference(cut, cut.elements[element], xi, eta);
  for (int f : {kVx, kVy, kUx, kUy}) node_values[f] = fe::evaluate(cut, at, solution, kFieldsPerNode, f);
  return true;
}

}  // namespace

Eigen::VectorXd initial_guess(const mesh::PatchMesh& mesh, const fe::PatchBuckets& buckets,
                              const fe::CutMesh& current, const fe::CutMesh& next,
                              const Eigen::VectorXd& solution, InitialGuessStats* stats) {
  InitialGuessStats counts;
  Eigen::VectorXd x = solution;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const bool moved = next.x[n] != current.x[n];
    if (!moved && !next.touches_solid[n]) continue;
    const fe::Location loc = fe::locate(current, buckets, next.x[n], 1e-6);
    if (loc.element < 0) continue;
    if (moved) {
      for (int f = 0; f < kFieldsPerNode; ++f)
        x[kFieldsPerNode * n + f] = fe::evaluate(current, loc, solution, kFieldsPerNode, f);
      ++counts.moved_nodes;
    }
    // In the body on the new mesh, but in a fluid sub-element of the current one: the
    // solid field, not the fluid's extension. Also for a node that touched the body
    // before only through slivers: its value need not continue the solid's field, and
    // next to a larger solid sub-element that matters (rho_f = 1000, t = 8.389 s: a node
    // at the ball's top).
    if (!next.touches_solid[n] || current.elements[loc.element].phase == Phase::solid) continue;
    const int patch = current.elements[loc.element].patch;
    if (patch_unchanged(mesh, current, next, patch)) continue;  // the last step solved on these
    const int solid = largest_solid_element(current, patch);
    if (solid >= 0 && extrapolate_solid(current, solid, next.x[n], solution, x.segment(kFieldsPerNode * n, kFieldsPerNode)))
      ++counts.extrapolated_nodes;
  }
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.on_wall[n]) x.segment(kFieldsPerNode * n, 2).setZero();
  if (stats) *stats = counts;
  return x;
}

}  // namespace fsi::core
