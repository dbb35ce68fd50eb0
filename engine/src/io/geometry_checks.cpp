// The relations validate() checks between values: mesh axes, mapped blocks, mesh size,
// walls, and where the ball starts.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "interface/body.hpp"
#include "io/number_text.hpp"
#include "io/scenario_checks.hpp"

namespace fsi::io {
namespace {

/// Coordinates are compared with this relative tolerance: the files give them with
/// a few digits, and sums of piece lengths may differ in the last bits.
constexpr double kRelTol = 1e-9;

struct Interval {
  double lo, hi;
};

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "(" + std::string temporaries.
std::string interval_text(const Interval& i) {
  std::string t = "[";
  t.append(number_text(i.lo)).append(", ").append(number_text(i.hi)).append("]");
  return t;
}

std::string point_text(const Point2& p) {
  std::string t = "(";
  t.append(number_text(p.x)).append(", ").append(number_text(p.y)).append(")");
  return t;
}

/// Checks one piece's length and grading (the mean patch size lies between the end sizes
/// of a monotone grading).
void check_piece(const AxisPiece& piece, const KeyPath& at) {
  const double length = std::abs(piece.to_m - piece.from_m);
  if (!(length > 0.0)) {
    fail(at / "to_m", "must differ from from_m = " + number_text(piece.from_m) +
                          " m (a piece needs a length), got " + number_text(piece.to_m));
  }
  for (const char* key : {"first_m", "last_m"}) {
    const double size = key[0] == 'f' ? piece.first_m : piece.last_m;
    if (size > length * (1.0 + kRelTol)) {
      fail(at / key, "must be in [0, " + number_text(length) +
                         "] m (at most the piece length |to_m - from_m|), got " +
                         number_text(size));
    }
  }
  if (piece.first_m > 0.0 && piece.last_m > 0.0) {
    const double mean = length / piece.patches;
    const double small = std::min(piece.first_m, piece.last_m);
    const double large = std::max(piece.first_m, piece.last_m);
    if (small > mean * (1.0 + kRelTol) || large < mean * (1.0 - kRelTol)) {
      fail(at / "first_m", "with last_m = " + number_text(piece.last_m) +
                               " m, the mean patch size " + number_text(mean) +
                               " m (length / patches) must lie in [min, max] of first_m " +
                               "and last_m (sizes change monotonically), got first_m = " +
                               number_text(piece.first_m));
    }
  }
}

/// Checks the pieces of one axis and returns the interval they tile.
Interval check_axis(const std::vector<AxisPiece>& pieces, const KeyPath& at) {
  std::vector<std::size_t> order(pieces.size());
  std::vector<Interval> spans(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    check_piece(pieces[i], at / i);
    spans[i] = {std::min(pieces[i].from_m, pieces[i].to_m),
                std::max(pieces[i].from_m, pieces[i].to_m)};
    order[i] = i;
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return spans[a].lo < spans[b].lo; });
  const Interval whole{spans[order.front()].lo, spans[order.back()].hi};
  const double tol = kRelTol * std::max(1.0, whole.hi - whole.lo);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Interval& before = spans[order[k - 1]];
    const Interval& here = spans[order[k]];
    if (here.lo > before.hi + tol) {
      fail(at / order[k], "pieces must join without a gap: piece " + std::to_string(order[k - 1]) +
                              " covers " + interval_text(before) + " m, this one " +
                              interval_text(here) + " m");
    }
    if (here.lo < before.hi - tol) {
      fail(at / order[k], "pieces must not overlap: piece " + std::to_string(order[k - 1]) +
                              " covers " + interval_text(before) + " m, this one " +
                              interval_text(here) + " m");
    }
  }
  return whole;
}

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// A mapped block's corners form a convex quadrilateral, counter-clockwise.
void check_corners(const std::array<Point2, 4>& c, const KeyPath& at) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (!(cross(c[i], c[(i + 1) % 4], c[(i + 2) % 4]) > 0.0)) {
      fail(at / "corners",
           "must form a convex quadrilateral, counter-clockwise from the "
           "lower left; it does not turn left at corner " +
               std::to_string((i + 1) % 4) + " " + point_text(c[(i + 1) % 4]));
    }
  }
}

/// The region a block covers, as corner points counter-clockwise.
std::array<Point2, 4> block_outline(const BlockSpec& block, const Interval& x, const Interval& y) {
  if (block.mapped) return block.corners;
  return {Point2{x.lo, y.lo}, Point2{x.hi, y.lo}, Point2{x.hi, y.hi}, Point2{x.lo, y.hi}};
}

/// Outlines of all blocks (assumes check_mesh passed).
std::vector<std::array<Point2, 4>> outlines(const MeshSpec& mesh, const KeyPath& at) {
  std::vector<std::array<Point2, 4>> result;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const BlockSpec& block = mesh.blocks[b];
    result.push_back(block_outline(block, check_axis(block.x, at / "blocks" / b / "x"),
                                   check_axis(block.y, at / "blocks" / b / "y")));
  }
  return result;
}

bool inside(const std::array<Point2, 4>& quad, const Point2& p) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (cross(quad[i], quad[(i + 1) % 4], p) < 0.0) return false;
  }
  return true;
}

double distance_to_segment(const Point2& p, const Segment2& s) {
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (s.a.x + t * dx), p.y - (s.a.y + t * dy));
}

/// A mapped block's right-side rows: unit-square coordinates covering [0, 1] with as many
/// patches as its left side (`y`), so that every row runs from one side to the other.
void check_right_side(const BlockSpec& block, const KeyPath& here) {
  if (!block.mapped) {
    fail(here / "y_right", "is only allowed in a mapped block (\"mapped\": true with corners): "
                           "an axis-aligned block has the same rows on both sides");
  }
  const Interval span = check_axis(block.y_right, here / "y_right");
  if (std::abs(span.lo) > kRelTol || std::abs(span.hi - 1.0) > kRelTol) {
    fail(here / "y_right", "must cover [0, 1] (unit-square coordinates, like y), got " + interval_text(span));
  }
  int left = 0, right = 0;
  for (const AxisPiece& p : block.y) left += p.patches;
  for (const AxisPiece& p : block.y_right) right += p.patches;
  if (left != right) {
    fail(here / "y_right", "must have as many patches as y (" + std::to_string(left) +
                               ", its rows run from the left side to the right side), got " +
                               std::to_string(right));
  }
}

}  // namespace

double block_node_count(const BlockSpec& block, int refinements) {
  const double scale = 2.0 * std::ldexp(1.0, refinements);  // 2 cells per patch, then 2^r
  double nx = 0.0, ny = 0.0;
  for (const AxisPiece& p : block.x) nx += p.patches;
  for (const AxisPiece& p : block.y) ny += p.patches;
  return (scale * nx + 1.0) * (scale * ny + 1.0);
}

void check_mesh(const MeshSpec& mesh, const KeyPath& at) {
  double nodes = 0.0;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const BlockSpec& block = mesh.blocks[b];
    const KeyPath here = at / "blocks" / b;
    const Interval x = check_axis(block.x, here / "x");
    const Interval y = check_axis(block.y, here / "y");
    if (block.mapped) {
      // The axes of a mapped block are coordinates in the unit square.
      for (const auto& [axis, span] : {std::pair{"x", x}, std::pair{"y", y}}) {
        const double tol = kRelTol;
        if (std::abs(span.lo) > tol || std::abs(span.hi - 1.0) > tol) {
          fail(here / axis,
               "must cover [0, 1] in a mapped block (unit-square coordinates), "
               "got " +
                   interval_text(span));
        }
      }
      check_corners(block.corners, here);
    }
    if (!block.y_right.empty()) check_right_side(block, here);
    nodes += block_node_count(block, mesh.refinements);
  }
  if (nodes > kMaxNodes) {
    fail(at / "refinements", "the mesh must have at most " + number_text(kMaxNodes) +
                                 " nodes (summed over blocks, after " +
                                 std::to_string(mesh.refinements) + " refinements), got " +
                                 number_text(nodes));
  }
}

namespace {

void check_walls(const Scenario& s, const KeyPath& at) {
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    const Segment2& wall = s.walls[w];
    if (!(std::hypot(wall.b.x - wall.a.x, wall.b.y - wall.a.y) > 0.0)) {
      fail(at / "walls" / w,
           "must have a positive length (two different end points), got "
           "both ends at " +
               point_text(wall.a));
    }
  }
}

/// The point of the body's boundary in direction a from its centre: the shapes are
/// star-shaped about it, so d0 changes sign once along the ray (bisection for the others).
Point2 boundary_point(const BodySpec& body, double a) {
  const Point2& c = body.center_m;
  const double ca = std::cos(a), sa = std::sin(a);
  if (body.shape == BodyShape::circle) return Point2{c.x + body.radius_m * ca, c.y + body.radius_m * sa};
  double lo = 0.0, hi = body_reach(body) * (1.0 + 1e-9);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (interface::initial_distance(body, {c.x + mid * ca, c.y + mid * sa}) < 0.0 ? lo : hi) = mid;
  }
  return Point2{c.x + hi * ca, c.y + hi * sa};
}

/// Boundary points 0.5 degree apart.
constexpr int kBoundarySamples = 720;

/// One body inside the meshed domain and clear of the walls; `at` is its key, `root` the file's.
void check_body(const Scenario& s, const BodySpec& body, const KeyPath& root, const KeyPath& at) {
  const auto quads = outlines(s.mesh, root / "mesh");
  Point2 lo{quads.front()[0]}, hi{quads.front()[0]};
  bool center_inside = false;
  for (const auto& quad : quads) {
    for (const Point2& p : quad) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    center_inside = center_inside || inside(quad, body.center_m);
  }
  const std::string box = interval_text({lo.x, hi.x}) + " x " + interval_text({lo.y, hi.y});
  const Point2& c = body.center_m;
  const double r = body.radius_m;
  const bool ball = body.shape == BodyShape::circle;
  if (body.shape == BodyShape::rounded_rectangle && !(r <= std::min(body.half_size_m.x, body.half_size_m.y))) {
    fail(at / "radius_m",
         "the corner radius of a rounded rectangle must not exceed its half width or half height (half_size_m = " +
             point_text(body.half_size_m) + "), got " + number_text(r));
  }
  if (!center_inside) {
    fail(at / "center_m",
         "must lie inside a mesh block (domain bounding box " + box + " m), got " + point_text(c));
  }
  // The domain is the union of the blocks, which need not be a rectangle (the stairs):
  // every point of the ball's boundary must lie in some block. Points 0.5 degree apart
  // miss at most r (1 - cos 0.25 deg) ~ 1e-5 r of a block corner poking into the ball.
  for (int i = 0; i < kBoundarySamples; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kBoundarySamples;
    const Point2 p = boundary_point(body, a);
    const bool covered = std::any_of(quads.begin(), quads.end(),
                                     [&](const auto& quad) { return inside(quad, p); });
    if (!covered) {
      fail(at / (ball ? "radius_m" : "half_size_m"),
           "must be small enough that the body at " + point_text(c) +
               " lies inside the meshed domain (the union of the blocks, bounding box " + box +
               " m); its boundary point " + point_text(p) + " lies outside every block, got " +
               (ball ? number_text(r) : point_text(body.half_size_m)));
    }
  }
  for (std::size_t w = 0; w < s.walls.size() && !ball; ++w) {
    // d0 of a convex body is convex along the wall: its least value by golden sections.
    const Segment2& wall = s.walls[w];
    const auto at_t = [&](double t) {
      return Point2{wall.a.x + t * (wall.b.x - wall.a.x), wall.a.y + t * (wall.b.y - wall.a.y)};
    };
    const auto d0 = [&](double t) { const Point2 p = at_t(t); return interface::initial_distance(body, {p.x, p.y}); };
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 80; ++i) {
      const double t1 = hi - phi * (hi - lo), t2 = lo + phi * (hi - lo);
      (d0(t1) < d0(t2) ? hi : lo) = d0(t1) < d0(t2) ? t2 : t1;
    }
    const double t = 0.5 * (lo + hi);
    const double d = std::min({d0(0.0), d0(1.0), d0(t)});
    if (!(d > 0.0)) {
      fail(at / "center_m",
           "the body must start clear of wall " + std::to_string(w) + ": its distance to the wall must be positive, got " +
               number_text(d) + " m near " + point_text(at_t(t)) + " with center " + point_text(c));
    }
  }
  for (std::size_t w = 0; w < s.walls.size() && ball; ++w) {
    const double d = distance_to_segment(c, s.walls[w]);
    if (!(d > r)) {
      fail(at / "center_m",
           "the ball must start clear of wall " + std::to_string(w) +
               ": distance from the center to the wall must exceed radius_m = " + number_text(r) +
               " m, got " + number_text(d) + " m at center " + point_text(c));
    }
  }
}

/// Two bodies must start apart: no boundary point of one inside or on the other (and
/// neither centre inside the other, for a body entirely inside another).
void check_bodies_apart(const Scenario& s, const KeyPath& at) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    for (std::size_t j = 0; j < s.bodies.size(); ++j) {
      if (i == j) continue;
      const BodySpec &a = s.bodies[i], &b = s.bodies[j];
      double closest = interface::initial_distance(b, {a.center_m.x, a.center_m.y});
      Point2 where = a.center_m;
      for (int n = 0; n < kBoundarySamples; ++n) {
        const Point2 p = boundary_point(a, 2.0 * std::numbers::pi * n / kBoundarySamples);
        const double d = interface::initial_distance(b, {p.x, p.y});
        if (d < closest) {
          closest = d;
          where = p;
        }
      }
      if (!(closest > 0.0))
        fail(at / "bodies" / std::max(i, j) / "center_m",
             "bodies must start apart: body" + std::to_string(i + 1) + " reaches into body" + std::to_string(j + 1) +
                 " at " + point_text(where) + " (distance " + number_text(closest) + " m)");
    }
}

}  // namespace

void check_body_and_walls(const Scenario& s, const KeyPath& at) {
  check_walls(s, at);
  if (s.bodies.empty()) {
    check_body(s, s.body, at, at / "body");
    return;
  }
  for (std::size_t i = 0; i < s.bodies.size(); ++i) check_body(s, s.bodies[i], at, at / "bodies" / i);
  check_bodies_apart(s, at);
}

}  // namespace fsi::io
