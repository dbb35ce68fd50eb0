#include "fe/cut_mesh.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace fsi::fe {
namespace {

using mesh::kCornerLocal;
using mesh::kSideCorners;
using mesh::kSideMidpoint;
using mesh::Patch;
using mesh::PatchMesh;

/// Zero of phi on the segment a -> b (phi(a), phi(b) of opposite sign): Illinois
/// variant of regula falsi, safeguarded so it always stays inside the bracket.
double edge_zero(const LevelSet& phi, const Vec2& a, const Vec2& b, double fa, double fb) {
  double t0 = 0.0, t1 = 1.0;
  int side = 0;
  double t = 0.5;
  for (int it = 0; it < 60; ++it) {
    t = (t0 * fb - t1 * fa) / (fb - fa);
    if (!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
    const double ft = phi(a + t * (b - a));
    if (ft == 0.0 || t1 - t0 < 1e-15) break;
    if ((ft < 0.0) == (fa < 0.0)) {
      t0 = t;
      fa = ft;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      t1 = t;
      fb = ft;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return t;
}

/// Local 3x3 index rotated r quarter turns counter-clockwise: (i, j) -> (2 - j, i).
int rotate(int local, int r) {
  for (int k = 0; k < r; ++k) {
    const int i = local % 3, j = local / 3;
    local = 3 * i + (2 - j);
  }
  return local;
}

double tri_area(const Vec2& a, const Vec2& b, const Vec2& c) {
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

double max_angle(const Vec2& a, const Vec2& b, const Vec2& c) {
  auto ang = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    const Vec2 u = q - p, v = r - p;
    return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
  };
  return std::max({ang(a, b, c), ang(b, c, a), ang(c, a, b)});
}

/// Builds the sub-elements of one patch in a canonical frame: local indices given in
/// the canonical orientation are rotated by `r` to the patch's own numbering.
class PatchBuilder {
 public:
  PatchBuilder(const Patch& patch, std::vector<Vec2>& x, int r, int patch_id, CutMesh& out)
      : patch_(patch), x_(x), r_(r), id_(patch_id), out_(out) {}

  int node(int canonical) const { return patch_.node[rotate(canonical, r_)]; }
  const Vec2& pos(int canonical) const { return x_[node(canonical)]; }
  void set_centre(const Vec2& c) { x_[patch_.node[4]] = c; }

  void triangle(int a, int b, int c, Phase phase) {
    SubElement e;
    e.vertices = 3;
    e.node = {node(a), node(b), node(c), -1};
    if (tri_area(x_[e.node[0]], x_[e.node[1]], x_[e.node[2]]) < 0.0) std::swap(e.node[1], e.node[2]);
    e.phase = phase;
    e.patch = id_;
    out_.elements.push_back(e);
  }
  /// Quad a-b-c-d (counter-clockwise) split along the diagonal with the smaller
  /// largest angle (keeps the maximum angle bounded, Frei & Richter's condition).
  void split_quad(int a, int b, int c, int d, Phase phase) {
    const double ac = std::max(max_angle(pos(a), pos(b), pos(c)), max_angle(pos(a), pos(c), pos(d)));
    const double bd = std::max(max_angle(pos(a), pos(b), pos(d)), max_angle(pos(b), pos(c), pos(d)));
    if (ac <= bd) {
      triangle(a, b, c, phase);
      triangle(a, c, d, phase);
    } else {
      triangle(a, b, d, phase);
      triangle(b, c, d, phase);
    }
  }
  /// The largest angle of the type A fan around the centre (canonical ring 1-2-5-8-7-6-3-1).
  double fan_max_angle() const {
    constexpr std::array<int, 8> ring{1, 2, 5, 8, 7, 6, 3, 1};
    double worst = 0.0;
    for (int i = 0; i < 7; ++i) worst = std::max(worst, max_angle(pos(4), pos(ring[i]), pos(ring[i + 1])));
    return worst;
  }
  void interface(int a, int b) {
    out_.interface.push_back(InterfaceSegment{pos(a), pos(b), id_, {node(a), node(b)}});
  }

 private:
  const Patch& patch_;
  std::vector<Vec2>& x_;
  int r_, id_;
  CutMesh& out_;
};

Phase phase_of(int sign) { return sign < 0 ? Phase::solid : Phase::fluid; }

/// Phase of patch p's sub-element that has the grid nodes n1 and n2 as vertices (a corner
/// and the midpoint of one of its sides: every configuration has exactly one such).
Phase phase_along(const CutMesh& cut, int p, int n1, int n2) {
  for (int k = cut.first_element[p]; k < cut.first_element[p + 1]; ++k) {
    const SubElement& e = cut.elements[k];
    const auto end = e.node.begin() + e.vertices;
    if (std::find(e.node.begin(), end, n1) != end && std::find(e.node.begin(), end, n2) != end) return e.phase;
  }
  assert(false && "no sub-element along the side");
  return Phase::fluid;
}

/// 4. The interface along patch sides. Where the level set vanishes at both corners of a
/// side (exactly, or snapped there by CutOptions::snap, common for a ball lying flat on
/// thin rows by a wall) no patch is cut, yet the side parts solid from fluid: the two
/// patches are uncut, one solid, one fluid. That side is interface too (two segments,
/// corner - midpoint - corner), added once, from the solid patch, so that the contact
/// force and the functionals see it like a cut; without it the interface has a hole.
void add_interface_on_sides(const PatchMesh& mesh, CutMesh& cut) {
  for (int p = 0; p < mesh.num_patches(); ++p) {
    const Patch& patch = mesh.patches[p];
    for (int side = 0; side < 4; ++side) {
      const int q = patch.neighbor[side];
      const int c0 = patch.node[kSideCorners[side][0]], c1 = patch.node[kSideCorners[side][1]];
      const int mid = patch.node[kSideMidpoint[side]];
      if (q < 0 || cut.corner_sign[c0] != 0 || cut.corner_sign[c1] != 0) continue;
      if (phase_along(cut, p, c0, mid) != Phase::solid || phase_along(cut, q, c0, mid) != Phase::fluid) continue;
      cut.interface.push_back(InterfaceSegment{cut.x[c0], cut.x[mid], p, {c0, mid}});
      cut.interface.push_back(InterfaceSegment{cut.x[mid], cut.x[c1], p, {mid, c1}});
    }
  }
}

/// CutOptions::align_fraction. In a flat patch (sides L x H, L >= kFlatAspect H) a
/// sub-element with two vertices on one long side and the third on the other has an angle
/// of up to 180 - 2 atan(2 H / L) degrees unless the third lies across from one of the
/// two: a cut on a long side anywhere but across from the opposite side's nodes (its ends
/// and midpoint) leaves such triangles in every configuration (the type A fan of a ball's
/// bottom in a 3.1 mm x 6.3 cm floor row: 174.5 degrees, det(I - grad u) of -4 from an
/// interpolated start and no Newton convergence at any step length). The cut moves to
/// the end or midpoint of its side that moves the interface least, measured across the
/// interface's direction in the patches on both sides, if that is at most `fraction` x H.
/// Where the interface crosses the long side at a shallow angle (the bottom of a body
/// near a wall) a move of centimetres along the side moves it by a fraction of a
/// millimetre; where it crosses steeply, nothing moves. Never onto a wall node in the
/// fluid (real contact; see the snapping above).
void align_long_side_cuts(const PatchMesh& mesh, double fraction, CutData& data) {
  const auto is_cut = [&](int e) {
    const mesh::GridEdge& g = mesh.edges[e];
    return data.edge_cut[e] >= 0.0 && data.corner_sign[g.a] * data.corner_sign[g.b] < 0;
  };
  const auto cut_point = [&](int e) {
    const mesh::GridEdge& g = mesh.edges[e];
    return Vec2(mesh.nodes[g.a] + data.edge_cut[e] * (mesh.nodes[g.b] - mesh.nodes[g.a]));
  };
  for (int e = 0; e < static_cast<int>(mesh.edges.size()); ++e) {
    if (!is_cut(e)) continue;
    const mesh::GridEdge& g = mesh.edges[e];
    const Vec2 a = mesh.nodes[g.a], b = mesh.nodes[g.b];
    const double h = g.thickness_m;
    if (!((b - a).norm() >= kFlatAspect * h)) continue;
    // The interface's direction in each patch beside the edge: towards that patch's other
    // interface point (its other cut side, or a corner on the interface).
    const Vec2 at = cut_point(e);
    std::vector<Vec2> direction;
    bool unclear = false;
    for (int p : g.patch) {
      if (p < 0) continue;
      std::vector<Vec2> other;
      for (int f : mesh.patches[p].edge)
        if (f != e && is_cut(f)) other.push_back(cut_point(f));
      for (int k : kCornerLocal) {
        const int n = mesh.patches[p].node[k];
        if (data.corner_sign[n] == 0 && n != g.a && n != g.b) other.push_back(mesh.nodes[n]);
      }
      if (other.size() != 1 || (other[0] - at).norm() == 0.0) unclear = true;
      else direction.push_back((other[0] - at).normalized());
    }
    if (unclear || direction.empty()) continue;
    // How far moving the cut to x moves the interface: across its direction, the larger
    // of the two patches.
    const auto shift = [&](const Vec2& x) {
      double worst = 0.0;
      for (const Vec2& d : direction) worst = std::max(worst, std::abs(d.x() * (x - at).y() - d.y() * (x - at).x()));
      return worst;
    };
    // 0: corner a, 1: midpoint, 2: corner b. A cut on a wall is where the body touches
    // it (the contact line): the interface runs along the wall beside it, and moving the
    // cut reshapes only the wedge of fluid between the two, so twice the move is allowed
    // (the contact line of a ball landing on a floor row slides by centimetres per step;
    // with 0.1 x the short side it left the aligned midpoint and a fan of 170 degrees
    // turned the solid inside out, campaign seed 4, cases 3 and 7).
    const std::array<double, 3> moved{shift(a), shift(0.5 * (a + b)), shift(b)};
    const double allowed = (g.wall >= 0 ? 2.0 : 1.0) * fraction * h;
    int best = -1;
    for (int k = 0; k < 3; ++k) {
      if (moved[k] > allowed) continue;
      const int corner = k == 0 ? g.a : (k == 2 ? g.b : -1);
      if (corner >= 0 && mesh.on_wall[corner] && data.corner_sign[corner] > 0) continue;
      if (best < 0 || moved[k] < moved[best]) best = k;
    }
    if (best == 1) data.edge_cut[e] = 0.5;
    else if (best == 0) data.corner_sign[g.a] = 0;
    else if (best == 2) data.corner_sign[g.b] = 0;
  }
}

}  // namespace

CutData cut_data(const PatchMesh& mesh, const LevelSet& phi, const CutOptions& options) {
  CutData data;
  const int n_nodes = mesh.num_nodes();
  // 1. Corner colouring. Exact zeros are interface points.
  std::vector<double> value(n_nodes, 0.0);
  data.corner_sign.assign(n_nodes, 0);
  for (int n = 0; n < n_nodes; ++n) {
    if (!mesh.is_corner[n]) continue;
    value[n] = phi(mesh.nodes[n]);
    data.corner_sign[n] = value[n] > 0.0 ? 1 : (value[n] < 0.0 ? -1 : 0);
  }
  // 2. Cut points on sign-changing grid edges; global snapping to corners, so that
  // every patch sharing a corner sees the same decision.
  const int n_edges = static_cast<int>(mesh.edges.size());
  data.edge_cut.assign(n_edges, -1.0);
  for (int e = 0; e < n_edges; ++e) {
    const mesh::GridEdge& g = mesh.edges[e];
    if (data.corner_sign[g.a] * data.corner_sign[g.b] >= 0) continue;
    data.edge_cut[e] = edge_zero(phi, mesh.nodes[g.a], mesh.nodes[g.b], value[g.a], value[g.b]);
  }
  for (int e = 0; e < n_edges; ++e) {
    const double t = data.edge_cut[e];
    if (t < 0.0) continue;
    const mesh::GridEdge& g = mesh.edges[e];
    // The distance rule in the side's parameter: near 1 on a short side, small on a long one.
    const double length = (mesh.nodes[g.b] - mesh.nodes[g.a]).norm();
    const double snap = std::max(options.snap, length > 0.0 ? options.snap_distance_m / length : 0.0);
    // Never onto a wall node in the fluid: the interface there would be real contact, and
    // the no-slip node holds the body (a cut 1.9 mm beside the stairs' tread edge, on the
    // 6.3 cm sides of the fan patch, snapped onto the edge and the ball stuck to it;
    // docs/method.md "Corners push like walls"). Such a cut moves to snap x side from the
    // wall node instead: no thinner sliver than snapping allows, and still off the wall.
    // A wall node inside the body is real contact already and is snapped onto like any
    // other corner: kept solid, it left two solid slivers snap x side wide on the wall
    // (Example 1 at t = 4.905 s: 2.5e-8 m on the 2.5 cm ground sides, 2e-11 m^2, u_x
    // differing by 1.1e-3 m across them).
    const double off_wall = std::min(snap, 0.5);
    const auto onto_wall_node = [&](int n) { return mesh.on_wall[n] && data.corner_sign[n] > 0; };
    if (t < snap && t <= 1.0 - t) {  // the nearer corner
      if (onto_wall_node(g.a)) data.edge_cut[e] = off_wall;
      else data.corner_sign[g.a] = 0;
    } else if (1.0 - t < snap) {
      if (onto_wall_node(g.b)) data.edge_cut[e] = 1.0 - off_wall;
      else data.corner_sign[g.b] = 0;
    }
  }
  if (options.align_fraction > 0.0) align_long_side_cuts(mesh, options.align_fraction, data);
  for (int e = 0; e < n_edges; ++e) {
    const mesh::GridEdge& g = mesh.edges[e];
    if (data.corner_sign[g.a] * data.corner_sign[g.b] >= 0) data.edge_cut[e] = -1.0;
  }
  return data;
}

CutMesh build_cut_mesh(const PatchMesh& mesh, const CutData& data, const CutOptions& options) {
  CutMesh cut;
  cut.x = mesh.nodes;
  cut.corner_sign = data.corner_sign;
  const int n_nodes = mesh.num_nodes();
  const int n_edges = static_cast<int>(mesh.edges.size());
  std::vector<char> edge_cut(n_edges, 0);
  for (int e = 0; e < n_edges; ++e) {
    if (data.edge_cut[e] < 0.0) continue;
    const mesh::GridEdge& g = mesh.edges[e];
    edge_cut[e] = 1;
    cut.x[g.mid] = mesh.nodes[g.a] + data.edge_cut[e] * (mesh.nodes[g.b] - mesh.nodes[g.a]);
  }

  // 3. Patch by patch: configuration, centre node, sub-elements.
  cut.first_element.reserve(mesh.num_patches() + 1);
  cut.kind.assign(mesh.num_patches(), PatchKind::uncut);
  for (int p = 0; p < mesh.num_patches(); ++p) {
    const Patch& patch = mesh.patches[p];
    cut.first_element.push_back(cut.num_elements());
    std::array<int, 4> sign{}, zero{}, cut_side{};
    int n_zero = 0, n_cut = 0, some_sign = 0;
    for (int k = 0; k < 4; ++k) {
      sign[k] = cut.corner_sign[patch.node[kCornerLocal[k]]];
      zero[k] = sign[k] == 0;
      n_zero += zero[k];
      if (sign[k] != 0) some_sign = sign[k];
      cut_side[k] = edge_cut[patch.edge[k]];
      n_cut += cut_side[k];
    }
    // Corner k sits between side k-1 and side k (side k joins corners k and k+1).
    auto sgn = [&](int k) { return sign[(k % 4 + 4) % 4]; };
    PatchKind kind = PatchKind::uncut;
    int r = 0;          // rotation: canonical corner 0 = actual corner r
    bool c_top = false;  // C: cut on the canonical top side instead of the right side
    if (n_zero == 0 && n_cut == 2) {
      for (int k = 0; k < 4; ++k)
        if (cut_side[k] && cut_side[(k + 3) % 4]) { kind = PatchKind::A; r = k; }
      if (kind == PatchKind::uncut)
        for (int k = 0; k < 2; ++k)
          if (cut_side[k] && cut_side[k + 2]) { kind = PatchKind::B; r = k; }
    } else if (n_zero == 0 && n_cut == 4) {
      ++cut.saddle_patches;  // ambiguous saddle: below the mesh resolution, keep it uncut
    } else if (n_zero == 1 && n_cut == 1) {
      for (int k = 0; k < 4; ++k)
        if (zero[k]) {
          r = k;
          kind = PatchKind::C;
          c_top = cut_side[(k + 2) % 4];
        }
    } else if (n_zero == 1 && n_cut == 2) {
      // Far corner isolated by two cuts while the zero corner only touches: type A there.
      for (int k = 0; k < 4; ++k)
        if (cut_side[k] && cut_side[(k + 3) % 4]) { kind = PatchKind::A; r = k; }
    } else if (n_zero == 2 && n_cut == 0) {
      for (int k = 0; k < 2; ++k)
        if (zero[k] && zero[k + 2] && sgn(k + 1) * sgn(k + 3) < 0) { kind = PatchKind::D; r = k; }
    } else if (n_zero == 2 && n_cut == 1) {
      // A zero corner facing the cut side (not adjacent to it) anchors a type C cut.
      for (int k = 0; k < 4 && kind == PatchKind::uncut; ++k)
        if (zero[k] && (cut_side[(k + 1) % 4] || cut_side[(k + 2) % 4])) {
          kind = PatchKind::C;
          r = k;
          c_top = cut_side[(k + 2) % 4];
        }
    }
    cut.kind[p] = kind;

    PatchBuilder b(patch, cut.x, r, p, cut);
    switch (kind) {
      case PatchKind::uncut: {
        const Phase ph = phase_of(some_sign == 0 ? 1 : some_sign);
        for (const auto& q : {std::array<int, 4>{0, 1, 4, 3}, {1, 2, 5, 4}, {4, 5, 8, 7}, {3, 4, 7, 6}}) {
          SubElement e;
          for (int i = 0; i < 4; ++i) e.node[i] = patch.node[q[i]];
          e.phase = ph;
          e.patch = p;
          cut.elements.push_back(e);
        }
        break;
      }
      case PatchKind::A: {
        // Corner 0 isolated; interface 1-3. Centre halfway between the interface's
        // midpoint and the opposite corner: inside the convex remainder, away from
        // the interface, so the fan's angles stay bounded.
        b.set_centre(0.5 * (0.5 * (b.pos(1) + b.pos(3)) + b.pos(8)));
        // In a flat patch that centre can leave the fan with angles up to 175 degrees.
        // With CutOptions::align_fraction on, a fan worse than kFanAngleLimit takes the
        // better of two centres across from a cut, halfway to the opposite side's
        // midpoint: with the cut aligned to its side's midpoint the fan's angles are then
        // right angles and less.
        if (options.align_fraction > 0.0 && b.fan_max_angle() > kFanAngleLimit) {
          Vec2 best = b.pos(4);
          double best_angle = b.fan_max_angle();
          for (const Vec2& c : {Vec2(0.5 * (b.pos(1) + b.pos(7))), Vec2(0.5 * (b.pos(3) + b.pos(5)))}) {
            b.set_centre(c);
            if (b.fan_max_angle() < best_angle) {
              best_angle = b.fan_max_angle();
              best = c;
            }
          }
          b.set_centre(best);
        }
        const Phase inner = phase_of(sgn(r)), outer = phase_of(sgn(r + 2));
        b.triangle(0, 1, 3, inner);
        const std::array<int, 8> ring{1, 2, 5, 8, 7, 6, 3, 1};
        for (int i = 0; i < 7; ++i) b.triangle(4, ring[i], ring[i + 1], outer);
        b.interface(1, 3);
        break;
      }
      case PatchKind::B: {
        // Cuts on sides 0 (bottom) and 2 (top): centre on the interface chord.
        b.set_centre(0.5 * (b.pos(1) + b.pos(7)));
        const Phase left = phase_of(sgn(r)), right = phase_of(sgn(r + 1));
        b.split_quad(0, 1, 4, 3, left);
        b.split_quad(3, 4, 7, 6, left);
        b.split_quad(1, 2, 5, 4, right);
        b.split_quad(4, 5, 8, 7, right);
        b.interface(1, 4);
        b.interface(4, 7);
        break;
      }
      case PatchKind::C: {
        // Each region takes the colour of a corner on a cut side (never a zero corner).
        const Phase lower = phase_of(c_top ? sgn(r + 2) : sgn(r + 1));
        const Phase upper = phase_of(c_top ? sgn(r + 3) : sgn(r + 2));
        if (!c_top) {  // interface 0 - 4 - 5
          b.set_centre(0.5 * (b.pos(0) + b.pos(5)));
          b.triangle(0, 1, 4, lower);
          b.triangle(1, 2, 4, lower);
          b.triangle(2, 5, 4, lower);
          for (const auto& t : {std::array<int, 3>{4, 5, 8}, {4, 8, 7}, {4, 7, 6}, {4, 6, 3}, {4, 3, 0}})
            b.triangle(t[0], t[1], t[2], upper);
          b.interface(0, 4);
          b.interface(4, 5);
        } else {  // interface 0 - 4 - 7
          b.set_centre(0.5 * (b.pos(0) + b.pos(7)));
          for (const auto& t : {std::array<int, 3>{0, 1, 4}, {1, 2, 4}, {2, 5, 4}, {4, 5, 8}, {4, 8, 7}})
            b.triangle(t[0], t[1], t[2], lower);
          b.triangle(4, 7, 6, upper);
          b.triangle(4, 6, 3, upper);
          b.triangle(4, 3, 0, upper);
          b.interface(0, 4);
          b.interface(4, 7);
        }
        break;
      }
      case PatchKind::D: {
        b.set_centre(0.5 * (b.pos(0) + b.pos(8)));
        const Phase lower = phase_of(sgn(r + 1)), upper = phase_of(sgn(r + 3));
        b.triangle(0, 1, 4, lower);
        b.split_quad(1, 2, 5, 4, lower);
        b.triangle(4, 5, 8, lower);
        b.triangle(0, 4, 3, upper);
        b.split_quad(3, 4, 7, 6, upper);
        b.triangle(4, 8, 7, upper);
        b.interface(0, 4);
        b.interface(4, 8);
        break;
      }
    }
  }
  cut.first_element.push_back(cut.num_elements());
  add_interface_on_sides(mesh, cut);

  cut.touches_solid.assign(n_nodes, 0);
  cut.touches_fluid.assign(n_nodes, 0);
  for (const SubElement& e : cut.elements)
    for (int i = 0; i < e.vertices; ++i)
      (e.phase == Phase::solid ? cut.touches_solid : cut.touches_fluid)[e.node[i]] = 1;
  return cut;
}

double element_area(const CutMesh& cut, const SubElement& e) {
  const Vec2& a = cut.x[e.node[0]];
  double area = 0.0;
  for (int i = 1; i + 1 < e.vertices; ++i) area += tri_area(a, cut.x[e.node[i]], cut.x[e.node[i + 1]]);
  return area;
}

std::array<double, 2> element_angle_range(const CutMesh& cut, const SubElement& e) {
  double lo = std::numbers::pi, hi = 0.0;
  for (int i = 0; i < e.vertices; ++i) {
    const Vec2& p = cut.x[e.node[i]];
    const Vec2 u = cut.x[e.node[(i + 1) % e.vertices]] - p;
    const Vec2 v = cut.x[e.node[(i + e.vertices - 1) % e.vertices]] - p;
    const double ang = std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
    lo = std::min(lo, ang);
    hi = std::max(hi, ang);
  }
  return {lo, hi};
}

}  // namespace fsi::fe
