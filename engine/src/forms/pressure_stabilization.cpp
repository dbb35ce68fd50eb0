#include "forms/pressure_stabilization.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace fsi::forms {
namespace {

/// Smallest height of a sub-element [m]: 2|K| / longest side (triangle), |K| / longest side (quad).
double smallest_height(const fe::CutMesh& cut, const fe::SubElement& e) {
  double longest = 0.0;
  for (int i = 0; i < e.vertices; ++i)
    longest = std::max(longest, (cut.x[e.node[(i + 1) % e.vertices]] - cut.x[e.node[i]]).norm());
  return (e.vertices == 3 ? 2.0 : 1.0) * std::abs(fe::element_area(cut, e)) / longest;
}

bool touches_wall(const mesh::PatchMesh& mesh, const fe::SubElement& e) {
  for (int i = 0; i < e.vertices; ++i)
    if (mesh.on_wall[e.node[i]]) return true;
  return false;
}

}  // namespace

void add_pressure_stabilization(const mesh::PatchMesh& mesh, const fe::CutMesh& cut,
                                const std::vector<fe::StabilizationEdge>& edges, double gamma,
                                int stride, int field, solve::SparseMatrix& a,
                                double transient_scale, double wall_film_factor) {
  auto scaling = [transient_scale](double h) { return h * h / (1.0 + transient_scale * h * h); };
  for (const fe::StabilizationEdge& se : edges) {
    const fe::SubElement& e1 = cut.elements[se.element1];
    const fe::SubElement& e2 = cut.elements[se.element2];
    const bool fluid1 = e1.phase == Phase::fluid, fluid2 = e2.phase == Phase::fluid;
    if (!fluid1 && !fluid2) continue;
    const double hp = std::max(mesh.patches[e1.patch].size_m, mesh.patches[e2.patch].size_m);
    const double scale = gamma * scaling(hp);
    // Wall films: each side's factor scaling(h) / scaling(h_P), once per edge.
    std::array<double, 2> film{1.0, 1.0};
    if (se.in_cut_patch && wall_film_factor > 0.0)
      for (int s = 0; s < 2; ++s) {
        const fe::SubElement& e = s == 0 ? e1 : e2;
        if (e.phase != Phase::fluid || !touches_wall(mesh, e)) continue;
        film[s] = scaling(std::min(hp, wall_film_factor * smallest_height(cut, e))) / scaling(hp);
      }
    // The value positions of the pairs this edge couples, found once for both quadrature
    // points (this runs every step over every edge; the searches dominated it). -1: the
    // pattern lacks the pair (such a contribution is dropped, as before).
    std::array<std::array<int, 16>, 2> side_at{};  // cut patch: per side, (i, j) of <= 4 nodes
    std::array<int, 64> jump_at{};                   // else: (i, j) of <= 8 nodes
    auto position = [&](int ni, int nj) { return solve::value_index(a, stride * ni + field, stride * nj + field); };
    if (se.in_cut_patch) {
      for (int s = 0; s < 2; ++s) {
        const fe::SubElement& e = s == 0 ? e1 : e2;
        if (e.phase != Phase::fluid) continue;
        for (int i = 0; i < e.vertices; ++i)
          for (int j = 0; j < e.vertices; ++j) side_at[s][i * e.vertices + j] = position(e.node[i], e.node[j]);
      }
    } else if (fluid1 && fluid2) {
      std::array<int, 8> node{};
      int n = 0;
      for (int i = 0; i < e1.vertices; ++i) node[n++] = e1.node[i];
      for (int i = 0; i < e2.vertices; ++i) node[n++] = e2.node[i];
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) jump_at[i * n + j] = position(node[i], node[j]);
    }
    double* value = a.valuePtr();
    auto add_at = [value](int at, double v) {
      if (at >= 0) value[at] += v;
    };
    for (int q = 0; q < 2; ++q) {
      const double w = scale * se.weight[q];
      if (se.in_cut_patch) {
        // {h_n grad p . grad xi}: each fluid side on its own, half weight.
        for (int s = 0; s < 2; ++s) {
          const fe::SubElement& e = s == 0 ? e1 : e2;
          if (e.phase != Phase::fluid) continue;
          const fe::ShapeValues& sv = s == 0 ? se.side1[q] : se.side2[q];
          const double f = 0.5 * w * film[s] * (s == 0 ? se.hn1_m : se.hn2_m);
          for (int i = 0; i < e.vertices; ++i)
            for (int j = 0; j < e.vertices; ++j)
              add_at(side_at[s][i * e.vertices + j], f * sv.grad[i].dot(sv.grad[j]));
        }
      } else {
        if (!(fluid1 && fluid2)) continue;
        // [grad p] = grad p|K1 - grad p|K2 over the union of both elements' nodes.
        std::array<int, 8> node{};
        std::array<mesh::Vec2, 8> jump;
        int n = 0;
        for (int i = 0; i < e1.vertices; ++i) {
          node[n] = e1.node[i];
          jump[n++] = se.side1[q].grad[i];
        }
        for (int i = 0; i < e2.vertices; ++i) {
          node[n] = e2.node[i];
          jump[n++] = -se.side2[q].grad[i];
        }
        const double f = w * 0.5 * (se.hn1_m + se.hn2_m);
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) add_at(jump_at[i * n + j], f * jump[i].dot(jump[j]));
      }
    }
  }
}

}  // namespace fsi::forms
