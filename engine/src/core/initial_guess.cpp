#include "core/initial_guess.hpp"

#include <utility>
#include <vector>

#include "fsi/state.hpp"

namespace fsi::core {
namespace {

/// The solid sub-element of patch p to continue the field from: the largest, since
/// extrapolating a sliver magnifies the sliver's own errors (-1: none).
int solid_element_for(const fe::CutMesh& cut, int p) {
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

/// A patch the body reaches only in the new geometry has no solid sub-element of its
/// own to continue the field from: the largest one of the patches beside it (-1: none).
/// Without it a wall node the landing body newly covered kept the fluid's extension of
/// the displacement, 16 mm off the solid's 1.6 mm above it (det(I - grad u) = -6.7 at
/// the side wall throw's landing, t = 2.9355 s).
int neighbouring_solid_element(const mesh::PatchMesh& mesh, const fe::CutMesh& cut, int p) {
  int best = -1;
  double best_area = 0.0;
  for (int q : mesh.patches[p].neighbor) {
    if (q < 0) continue;
    const int k = solid_element_for(cut, q);
    const double a = k < 0 ? 0.0 : fe::element_area(cut, cut.elements[k]);
    if (a > best_area) {
      best_area = a;
      best = k;
    }
  }
  return best;
}

/// det(I - grad u) at the centre of solid sub-element e within [1/2, 2].
bool physical_deformation(const fe::CutMesh& cut, const fe::SubElement& e, const Eigen::VectorXd& x) {
  const double centre = e.vertices == 3 ? 1.0 / 3.0 : 0.5;
  const double det = deformation_determinant(e, fe::shape_at_reference(cut, e, centre, centre), x);
  return det >= 0.5 && det <= 2.0;
}

/// Wall nodes keep their (zero) velocity.
Eigen::VectorXd finish(const mesh::PatchMesh& mesh, Eigen::VectorXd& x, const InitialGuessStats& counts,
                       InitialGuessStats* stats) {
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.on_wall[n]) x.segment(kFieldsPerNode * n, 2).setZero();
  if (stats) *stats = counts;
  return std::move(x);
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
bool continue_solid_field(const fe::CutMesh& cut, int element, const mesh::Vec2& x, const Eigen::VectorXd& solution,
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

double deformation_determinant(const fe::SubElement& e, const fe::ShapeValues& s, const Eigen::VectorXd& x) {
  double h[2][2] = {{0.0, 0.0}, {0.0, 0.0}};  // grad u
  for (int a = 0; a < e.vertices; ++a)
    for (int c = 0; c < 2; ++c) {
      h[c][0] += s.grad[a].x() * x[kFieldsPerNode * e.node[a] + kUx + c];
      h[c][1] += s.grad[a].y() * x[kFieldsPerNode * e.node[a] + kUx + c];
    }
  return (1.0 - h[0][0]) * (1.0 - h[1][1]) - h[0][1] * h[1][0];
}

SolidDeterminant solid_determinant(const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                                   const Eigen::VectorXd& x) {
  SolidDeterminant d;
  for (int e = 0; e < cut.num_elements(); ++e) {
    const fe::SubElement& el = cut.elements[e];
    if (el.phase != Phase::solid) continue;
    for (int q = quadrature.first[e]; q < quadrature.first[e + 1]; ++q) {
      const double det = deformation_determinant(el, quadrature.points[q], x);
      d.non_positive += !(det > 0.0);
      if (det < d.smallest) {
        d.smallest = det;
        d.where = quadrature.points[q].x;
      }
    }
  }
  return d;
}

Eigen::VectorXd initial_guess(const mesh::PatchMesh& mesh, const fe::PatchBuckets& buckets,
                              const fe::CutMesh& current, const fe::CutMesh& next,
                              const Eigen::VectorXd& solution, InitialGuessStats* stats, StartMode mode) {
  InitialGuessStats counts;
  Eigen::VectorXd x = solution;
  // Where each node lies on the current mesh (-1: not looked up, or outside). Only moved
  // nodes are looked up here; the others only if the repair below wants them.
  std::vector<int> located(mesh.num_nodes(), -1);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (next.x[n] == current.x[n]) continue;
    const fe::Location loc = fe::locate(current, buckets, next.x[n], 1e-6);
    if (loc.element < 0) continue;
    located[n] = loc.element;
    for (int f = 0; f < kFieldsPerNode; ++f)
      x[kFieldsPerNode * n + f] = fe::evaluate(current, loc, solution, kFieldsPerNode, f);
    ++counts.moved_nodes;
  }
  if (mode == StartMode::interpolated) return finish(mesh, x, counts, stats);
  // repair_unphysical: only the nodes of solid sub-elements that the interpolated start
  // deforms beyond any physical state (det(I - grad u) outside [1/2, 2] at the centre).
  std::vector<char> wanted(mesh.num_nodes(), mode == StartMode::solid_field);
  if (mode == StartMode::repair_unphysical)
    for (const fe::SubElement& e : next.elements)
      if (e.phase == Phase::solid && !physical_deformation(next, e, x))
        for (int i = 0; i < e.vertices; ++i) wanted[e.node[i]] = 1;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (!wanted[n] || !next.touches_solid[n]) continue;
    if (located[n] < 0 && next.x[n] == current.x[n])
      located[n] = fe::locate(current, buckets, next.x[n], 1e-6).element;
    if (located[n] < 0) continue;
    if (current.elements[located[n]].phase == Phase::solid) continue;
    const int patch = current.elements[located[n]].patch;
    if (patch_unchanged(mesh, current, next, patch)) continue;  // the last step solved on these
    int solid = solid_element_for(current, patch);
    if (solid < 0) solid = neighbouring_solid_element(mesh, current, patch);
    if (solid >= 0 && continue_solid_field(current, solid, next.x[n], solution, x.segment(kFieldsPerNode * n, kFieldsPerNode)))
      ++counts.extrapolated_nodes;
  }
  return finish(mesh, x, counts, stats);
}

}  // namespace fsi::core
