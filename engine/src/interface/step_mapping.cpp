#include "interface/step_mapping.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel_chunks.hpp"
#include "fsi/state.hpp"
#include "interface/body.hpp"
#include "mesh/walls.hpp"

namespace fsi::interface {
namespace {

/// C^1 step: 1 for d <= eps, 0 for d >= delta, cubic in between.
double blend(double d, double eps, double delta) {
  if (d <= eps) return 1.0;
  if (d >= delta) return 0.0;
  const double s = (d - eps) / (delta - eps);
  return 1.0 - s * s * (3.0 - 2.0 * s);
}

/// True when patch p has the same sub-elements in both cut meshes (uncut in both,
/// same node positions): quadrature data of one mesh then applies to the other.
bool same_patch(const mesh::PatchMesh& mesh, const fe::CutMesh& a, const fe::CutMesh& b, int p) {
  if (a.kind[p] != fe::PatchKind::uncut || b.kind[p] != fe::PatchKind::uncut) return false;
  for (int n : mesh.patches[p].node)
    if (a.x[n] != b.x[n]) return false;
  return true;
}

Vec2 displacement(const fe::CutMesh& cut, const fe::Location& loc, const Eigen::VectorXd& s) {
  return Vec2(fe::evaluate(cut, loc, s, kFieldsPerNode, kUx), fe::evaluate(cut, loc, s, kFieldsPerNode, kUy));
}

}  // namespace

MappingStats compute_old_values(const mesh::PatchMesh& mesh, const fe::PatchBuckets& buckets,
                                const fe::CutMesh& next, const fe::QuadratureTable& quadrature,
                                const Level& current, const Level& previous, std::span<const BodySpec> bodies,
                                const std::vector<Segment2>& walls, const MappingOptions& options,
                                std::vector<forms::OldValues>& old) {
  old.assign(quadrature.points.size(), forms::OldValues{});
  const fe::CutMesh& cur = *current.cut;
  const Eigen::VectorXd& s_cur = *current.solution;
  const fe::CutMesh& prev = *previous.cut;
  const Eigen::VectorXd& s_prev = *previous.solution;
  // Several bodies: each one's interface segments in the new mesh. A fluid point within
  // the identity gap of two bodies' interfaces is in the gap between them.
  std::vector<std::vector<Segment2>> body_segments;
  if (bodies.size() > 1 && options.element_body != nullptr && options.element_body->size() == next.elements.size()) {
    body_segments.resize(bodies.size());
    const std::vector<int> segment_body = segment_bodies(next, *options.element_body);
    for (std::size_t i = 0; i < next.interface.size(); ++i) {
      const fe::InterfaceSegment& seg = next.interface[i];
      body_segments[static_cast<std::size_t>(segment_body[i])].push_back({{seg.a.x(), seg.a.y()}, {seg.b.x(), seg.b.y()}});
    }
  }
  const auto between_bodies = [&](const Vec2& x, double gap) {
    int near = 0;
    for (const std::vector<Segment2>& segments : body_segments)
      for (const Segment2& s : segments)
        if (mesh::distance_to_segment(s, x) < gap) {
          ++near;
          break;
        }
    return near >= 2;
  };

  // Every quadrature point is mapped on its own and writes only old[q]: the patches go to
  // the threads in blocks dealt round-robin (the points that need (12.4) crowd around the
  // body, which contiguous halves would give to one thread), each thread counting into
  // its own stats; the result is the same bits for any thread count.
  const auto map_patch = [&](int p, MappingStats& stats) {
    const bool same = same_patch(mesh, next, cur, p);
    const double h = mesh.patches[p].size_m;
    for (int k = next.first_element[p]; k < next.first_element[p + 1]; ++k) {
      const bool fluid = next.elements[k].phase == Phase::fluid;
      for (int q = quadrature.first[k]; q < quadrature.first[k + 1]; ++q) {
        const fe::QuadraturePoint& qp = quadrature.points[q];
        const Vec2 x = qp.x;
        fe::Location loc;
        if (same) {
          loc.element = cur.first_element[p] + (k - next.first_element[p]);
          loc.shape = qp;
        } else {
          loc = fe::locate(cur, buckets, x, 1e-6);
        }
        forms::OldValues& o = old[q];
        if (loc.element < 0) continue;  // outside the domain: cannot happen for interior points
        const Vec2 u_cur = displacement(cur, loc, s_cur);
        const double phi = scene_distance(bodies, x - u_cur);
        double g = blend(std::abs(phi), options.eps_patches * h, options.delta_patches * h);
        // The chapter's contact treatment: T_m = id in the fluid gap near a wall.
        const double gap = options.identity_gap_m > 0.0 ? options.identity_gap_m : mesh.patches[p].min_size_m;
        if (g > 0.0 && fluid && mesh::distance_to_walls(walls, x).distance_m < gap) g = 0.0;
        if (g > 0.0 && fluid && !body_segments.empty() && phi < gap && between_bodies(x, gap)) g = 0.0;
        Vec2 t = x;
        if (g > 0.0) {
          // (12.4): y - u_prev(y) = x - u_cur(x), Newton from y0 = x - u_cur(x) + u_prev(x).
          ++stats.ips_points;
          const Vec2 b = x - u_cur;
          fe::Location lp = fe::locate(prev, buckets, x, 1e-6);
          Vec2 y = lp.element >= 0 ? Vec2(b + displacement(prev, lp, s_prev)) : Vec2(b);
          bool converged = false;
          int it = 0;
          for (; it < 10; ++it) {
            lp = fe::locate(prev, buckets, y, 1e-6);
            if (lp.element < 0) break;
            const Vec2 f = y - displacement(prev, lp, s_prev) - b;
            if (f.norm() <= 1e-12 * h) {
              converged = true;
              break;
            }
            const Vec2 gx = fe::evaluate_gradient(prev, lp, s_prev, kFieldsPerNode, kUx);
            const Vec2 gy = fe::evaluate_gradient(prev, lp, s_prev, kFieldsPerNode, kUy);
            // Jacobian I - grad u_prev
            const double a00 = 1.0 - gx.x(), a01 = -gx.y(), a10 = -gy.x(), a11 = 1.0 - gy.y();
            const double det = a00 * a11 - a01 * a10;
            if (!(std::abs(det) > 1e-12)) break;
            y -= Vec2((a11 * f.x() - a01 * f.y()) / det, (-a10 * f.x() + a00 * f.y()) / det);
          }
          stats.max_ips_iterations = std::max(stats.max_ips_iterations, it);
          if (!converged) {
            ++stats.ips_failures;
            y = x;  // fall back to the identity (old values at x)
          }
          t = g * y + (1.0 - g) * x;
          o.tx = (x.x() - t.x()) / options.k_s;
          o.ty = (x.y() - t.y()) / options.k_s;
        }
        const fe::Location lt = (t == x) ? loc : fe::locate(cur, buckets, t, 1e-6);
        const fe::Location& use = lt.element >= 0 ? lt : loc;
        o.vx = fe::evaluate(cur, use, s_cur, kFieldsPerNode, kVx);
        o.vy = fe::evaluate(cur, use, s_cur, kFieldsPerNode, kVy);
        o.ux = fe::evaluate(cur, use, s_cur, kFieldsPerNode, kUx);
        o.uy = fe::evaluate(cur, use, s_cur, kFieldsPerNode, kUy);
      }
    }
  };
  constexpr int kPatchesPerBlock = 16;
  const int patches = mesh.num_patches();
  const int blocks = (patches + kPatchesPerBlock - 1) / kPatchesPerBlock;
  const int threads = std::clamp(options.threads, 1, std::max(1, blocks));
  std::vector<MappingStats> per_thread(static_cast<std::size_t>(threads));
  core::parallel_chunks(threads, threads, [&](int first, int last) {
    for (int t = first; t < last; ++t)
      for (int b = t; b < blocks; b += threads)
        for (int p = b * kPatchesPerBlock; p < std::min(patches, (b + 1) * kPatchesPerBlock); ++p)
          map_patch(p, per_thread[static_cast<std::size_t>(t)]);
  });
  MappingStats stats;
  for (const MappingStats& part : per_thread) {
    stats.ips_points += part.ips_points;
    stats.ips_failures += part.ips_failures;
    stats.max_ips_iterations = std::max(stats.max_ips_iterations, part.max_ips_iterations);
  }
  return stats;
}

}  // namespace fsi::interface
