#include "core/field_view_builder.hpp"

#include <algorithm>
#include <set>

#include "interface/body.hpp"

namespace fsi::core {

FieldView build_field_view(const mesh::PatchMesh& mesh, const fe::CutMesh& cut, const State& state,
                           const Scenario& scenario, const std::vector<int>& element_body) {
  FieldView v;
  v.time_s = state.time_s;
  v.step = state.step;
  const int n = mesh.num_nodes();
  v.nodes.reserve(n);
  for (const mesh::Vec2& x : cut.x) v.nodes.push_back({x.x(), x.y()});
  auto field = [&](int f) {
    std::vector<double> out(n);
    for (int i = 0; i < n; ++i) out[i] = state.solution[kFieldsPerNode * i + f];
    return out;
  };
  v.vx = field(kVx);
  v.vy = field(kVy);
  v.ux = field(kUx);
  v.uy = field(kUy);
  v.p = field(kP);
  std::set<std::pair<int, int>> edges;
  const bool with_bodies = element_body.size() == cut.elements.size();
  for (std::size_t k = 0; k < cut.elements.size(); ++k) {
    const fe::SubElement& e = cut.elements[k];
    const int body = with_bodies ? element_body[k] : (e.phase == Phase::solid ? 0 : -1);
    // Sub-quads are drawn as two triangles; the colour is interpolated per pixel anyway.
    v.triangles.push_back({e.node[0], e.node[1], e.node[2]});
    v.triangle_phase.push_back(e.phase);
    v.triangle_body.push_back(body);
    if (e.vertices == 4) {
      v.triangles.push_back({e.node[0], e.node[2], e.node[3]});
      v.triangle_phase.push_back(e.phase);
      v.triangle_body.push_back(body);
    }
    for (int i = 0; i < e.vertices; ++i) edges.insert(std::minmax(e.node[i], e.node[(i + 1) % e.vertices]));
  }
  for (const auto& [a, b] : edges) v.mesh_edges.push_back({a, b});
  for (const fe::InterfaceSegment& s : cut.interface) v.interface.push_back({{s.a.x(), s.a.y()}, {s.b.x(), s.b.y()}});
  v.interface_body = interface::segment_bodies(cut, element_body);
  v.walls = scenario.walls;
  v.domain_min = {mesh.min.x(), mesh.min.y()};
  v.domain_max = {mesh.max.x(), mesh.max.y()};
  return v;
}

}  // namespace fsi::core
