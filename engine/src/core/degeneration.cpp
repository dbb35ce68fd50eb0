#include "core/degeneration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fsi::core {

std::optional<Degeneration> detect_degeneration(const Functionals& before, const Functionals& after,
                                                double time_step_s, double patch_side_m, int inverted_points,
                                                Point2 inverted_where_m, double patch_area_m2) {
  char text[240];
  const Point2 centroid{after.centroid_x_m, after.centroid_y_m};
  const double values[] = {after.bottom_y_m, after.top_y_m, after.left_x_m, after.right_x_m,
                           after.mass_error, after.centroid_x_m, after.centroid_y_m};
  for (double v : values)
    if (!std::isfinite(v))
      return Degeneration{"the body's functionals are not finite (no solid left to measure)", centroid};
  if (inverted_points > 0) {
    std::snprintf(text, sizeof text, "the solid is turned inside out at %d quadrature point(s), det(I - grad u) <= 0",
                  inverted_points);
    return Degeneration{text, inverted_where_m};
  }
  // The bound of the mass error's jump for a body whose (sound) area was area_m2.
  const auto jump_bound = [patch_area_m2](double area_m2) {
    return area_m2 > 0.0 ? std::max(kMassErrorJump, patch_area_m2 / area_m2) : kMassErrorJump;
  };
  const double jump = std::abs(after.mass_error - before.mass_error);
  if (const double bound = jump_bound(before.solid_area_m2); jump > bound) {
    std::snprintf(text, sizeof text, "the mass error jumped from %.3g to %.3g in one step (more than %.2g)",
                  before.mass_error, after.mass_error, bound);
    return Degeneration{text, centroid};
  }
  double speed = std::max(std::hypot(before.mean_vx_mps, before.mean_vy_mps),
                          std::hypot(after.mean_vx_mps, after.mean_vy_mps));
  // Several bodies: each body's own mass error and speed (the scene's mean velocity is
  // near zero for two bodies that fly apart).
  for (std::size_t i = 0; i < after.bodies.size() && i < before.bodies.size(); ++i) {
    const Functionals::Body &b0 = before.bodies[i], &b1 = after.bodies[i];
    if (const double bound = jump_bound(b0.solid_area_m2); std::abs(b1.mass_error - b0.mass_error) > bound) {
      std::snprintf(text, sizeof text, "the mass error of body%zu jumped from %.3g to %.3g in one step (more than %.2g)",
                    i + 1, b0.mass_error, b1.mass_error, bound);
      return Degeneration{text, {b1.centroid_x_m, b1.centroid_y_m}};
    }
    speed = std::max({speed, std::hypot(b0.mean_vx_mps, b0.mean_vy_mps), std::hypot(b1.mean_vx_mps, b1.mean_vy_mps)});
  }
  const double allowed = 2.0 * speed * time_step_s + kInterfaceJumpPatchSides * patch_side_m;
  const double moved = std::max({std::abs(after.bottom_y_m - before.bottom_y_m), std::abs(after.top_y_m - before.top_y_m),
                                 std::abs(after.left_x_m - before.left_x_m), std::abs(after.right_x_m - before.right_x_m)});
  if (moved > allowed) {
    std::snprintf(text, sizeof text,
                  "the interface jumped by %.3g m in one step (the body's speed and the mesh allow %.3g m)", moved,
                  allowed);
    return Degeneration{text, centroid};
  }
  return std::nullopt;
}

std::optional<Degeneration> merged_bodies(const fe::CutMesh& cut, const std::vector<int>& element_body) {
  if (element_body.size() != cut.elements.size()) return std::nullopt;
  std::vector<int> node_body(cut.x.size(), -1);
  for (std::size_t k = 0; k < cut.elements.size(); ++k) {
    const int b = element_body[k];
    if (b < 0) continue;
    const fe::SubElement& e = cut.elements[k];
    for (int a = 0; a < e.vertices; ++a) {
      int& nb = node_body[e.node[a]];
      if (nb >= 0 && nb != b) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "body%d and body%d touch: their solids share a mesh node (real contact between bodies); "
                      "a contact force (contact.gamma_c > 0, contact.dist0_m about two patch sides) keeps bodies apart",
                      std::min(nb, b) + 1, std::max(nb, b) + 1);
        const mesh::Vec2& x = cut.x[e.node[a]];
        return Degeneration{text, {x.x(), x.y()}};
      }
      nb = b;
    }
  }
  return std::nullopt;
}

std::optional<Degeneration> body_at_open_boundary(const mesh::PatchMesh& mesh, const fe::CutMesh& cut) {
  const std::size_t nodes = std::min({mesh.on_boundary.size(), mesh.on_wall.size(), cut.touches_solid.size()});
  for (std::size_t n = 0; n < nodes; ++n) {
    if (!mesh.on_boundary[n] || mesh.on_wall[n] || !cut.touches_solid[n]) continue;
    const mesh::Vec2& x = n < cut.x.size() ? cut.x[n] : mesh.nodes[n];
    char text[320];
    std::snprintf(text, sizeof text,
                  "the body reached the open boundary at (%.4g, %.4g) m: the domain ends there and a body "
                  "leaving it cannot be followed (a wall there, or a larger domain, keeps it inside)",
                  x.x(), x.y());
    return Degeneration{text, {x.x(), x.y()}, true};
  }
  return std::nullopt;
}

CutPatchScale largest_cut_patch(const mesh::PatchMesh& mesh, const fe::CutMesh& before, const fe::CutMesh& after) {
  CutPatchScale scale;
  for (int p = 0; p < mesh.num_patches(); ++p) {
    const mesh::Patch& patch = mesh.patches[p];
    bool at_interface = before.kind[p] != fe::PatchKind::uncut || after.kind[p] != fe::PatchKind::uncut;
    for (int c : mesh::kCornerLocal)
      at_interface = at_interface || before.corner_sign[patch.node[c]] == 0 || after.corner_sign[patch.node[c]] == 0;
    if (!at_interface) continue;
    scale.side_m = std::max(scale.side_m, patch.size_m);
    double twice_area = 0.0;  // the shoelace formula over the four corners in order
    for (std::size_t i = 0; i < mesh::kCornerLocal.size(); ++i) {
      const mesh::Vec2& a = mesh.nodes[patch.node[mesh::kCornerLocal[i]]];
      const mesh::Vec2& b = mesh.nodes[patch.node[mesh::kCornerLocal[(i + 1) % mesh::kCornerLocal.size()]]];
      twice_area += a.x() * b.y() - b.x() * a.y();
    }
    scale.area_m2 = std::max(scale.area_m2, 0.5 * std::abs(twice_area));
  }
  return scale;
}

}  // namespace fsi::core
