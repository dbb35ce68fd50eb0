#include "fe/stabilization_edges.hpp"

#include <cmath>
#include <unordered_map>

namespace fsi::fe {

std::vector<StabilizationEdge> build_stabilization_edges(const CutMesh& cut) {
  // First occurrence of each undirected edge: (element, local edge index).
  std::unordered_map<long long, std::pair<int, int>> seen;
  seen.reserve(cut.elements.size() * 4);
  std::vector<StabilizationEdge> edges;
  edges.reserve(cut.elements.size() * 2);
  const long long n = static_cast<long long>(cut.x.size());
  const double g = 0.5 / std::sqrt(3.0);
  const std::array<double, 2> gauss{0.5 - g, 0.5 + g};

  for (int k = 0; k < cut.num_elements(); ++k) {
    const SubElement& e = cut.elements[k];
    for (int i = 0; i < e.vertices; ++i) {
      const int a = e.node[i], b = e.node[(i + 1) % e.vertices];
      const long long key = std::min(a, b) * n + std::max(a, b);
      auto [it, inserted] = seen.emplace(key, std::make_pair(k, i));
      if (inserted) continue;
      const auto [k1, i1] = it->second;
      const SubElement& e1 = cut.elements[k1];
      StabilizationEdge se;
      se.element1 = k1;
      se.element2 = k;
      se.length_m = (cut.x[a] - cut.x[b]).norm();
      const double area1 = std::abs(element_area(cut, e1)), area2 = std::abs(element_area(cut, e));
      se.hn1_m = (e1.vertices == 3 ? 2.0 : 1.0) * area1 / se.length_m;
      se.hn2_m = (e.vertices == 3 ? 2.0 : 1.0) * area2 / se.length_m;
      se.in_cut_patch = e1.vertices == 3 || e.vertices == 3;
      for (int q = 0; q < 2; ++q) {
        // Element 1 runs its edge from b to a (both counter-clockwise): parameter 1 - s.
        const auto r2 = edge_reference(e, i, gauss[q]);
        const auto r1 = edge_reference(e1, i1, 1.0 - gauss[q]);
        se.side2[q] = shape_at_reference(cut, e, r2[0], r2[1]);
        se.side1[q] = shape_at_reference(cut, e1, r1[0], r1[1]);
        se.weight[q] = 0.5 * se.length_m;
      }
      edges.push_back(se);
    }
  }
  return edges;
}

}  // namespace fsi::fe
