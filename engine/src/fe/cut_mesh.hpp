#pragma once
/// \file cut_mesh.hpp
/// Locally modified finite elements (Frei & Richter 2014): the patch mesh cut by a
/// level set into sub-elements that resolve the interface.
///
/// Uncut patch: 4 bilinear sub-quads. Cut patch: the midpoint nodes of the cut sides
/// move onto the interface, the centre node is placed so that the interface is a
/// union of sub-element edges, and the patch splits into 8 linear triangles:
///
///   A: two adjacent sides cut (one corner isolated)  -> triangle at the corner + fan
///   B: two opposite sides cut                         -> 4 quads through the moved
///                                                        centre, each split in two
///   C: a corner on the interface and a far side cut  -> 3 + 5 triangles
///   D: two opposite corners on the interface          -> 4 + 4 triangles
///
/// Snapping is global: a cut closer than `snap` (relative to the side length) to a
/// corner puts the interface through that corner for every patch sharing it, so the
/// moved nodes of neighbouring patches always agree (the space stays conforming).
/// The phase of a sub-element comes from the discrete nodal colouring (corner signs),
/// never from the continuous level set at quadrature points.
#include <array>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

#include "fsi/field_view.hpp"
#include "mesh/patch_mesh.hpp"

namespace fsi::fe {

using mesh::Vec2;

enum class PatchKind : std::uint8_t { uncut = 0, A, B, C, D };

struct SubElement {
  std::array<int, 4> node{-1, -1, -1, -1};  ///< global nodes, counter-clockwise
  int vertices = 4;                          ///< 4: bilinear quad, 3: linear triangle
  Phase phase = Phase::fluid;
  int patch = -1;
};

struct InterfaceSegment {
  Vec2 a, b;
  int patch = -1;
  std::array<int, 2> node{};  ///< the two mesh nodes it joins
};

/// Level set: negative in the solid, positive in the fluid.
using LevelSet = std::function<double(const Vec2&)>;

struct CutOptions {
  /// Cuts closer than snap * (side length) to a corner go through the corner.
  double snap = 1e-6;
  /// Cuts closer than this distance [m] to a corner go through it as well (0: off).
  double snap_distance_m = 0.0;
  /// Flat patches (a side at least kFlatAspect times the patch's other side): a cut on a
  /// long side moves to the side's end or midpoint if that moves the interface by at most
  /// align_fraction x the short side (twice that on a wall edge), and a type A fan with an
  /// angle above kFanAngleLimit may move its centre (0: off; docs/solver.md, "Cut
  /// snapping and thin rows").
  double align_fraction = 0.0;
};

/// Long side / short side from which a patch counts as flat for CutOptions::align_fraction.
inline constexpr double kFlatAspect = 8.0;
/// With CutOptions::align_fraction on, a type A fan whose largest angle exceeds this
/// [rad] (150 degrees) tries the centres across from its cuts.
inline constexpr double kFanAngleLimit = 150.0 * std::numbers::pi / 180.0;

struct CutMesh {
  std::vector<Vec2> x;                  ///< node positions [m] (moved in cut patches)
  std::vector<SubElement> elements;     ///< patch p owns [first_element[p], first_element[p+1])
  std::vector<int> first_element;
  std::vector<PatchKind> kind;          ///< per patch
  std::vector<std::int8_t> corner_sign; ///< per node: -1 solid, +1 fluid, 0 on the interface (corners only)
  std::vector<InterfaceSegment> interface;
  std::vector<char> touches_solid;      ///< per node: belongs to a solid sub-element
  std::vector<char> touches_fluid;      ///< per node: belongs to a fluid sub-element
  int saddle_patches = 0;               ///< patches with 4 cut sides (treated as uncut)

  int num_elements() const { return static_cast<int>(elements.size()); }
};

/// The discrete interface in compact form: everything build_cut_mesh needs besides the
/// patch mesh. Stored in checkpoints, so that a restored state rebuilds identical meshes.
struct CutData {
  std::vector<std::int8_t> corner_sign;  ///< per node: -1 solid, +1 fluid, 0 interface (0 for non-corners)
  std::vector<double> edge_cut;          ///< per grid edge: cut parameter t in (0,1), or -1
};

/// Colours the corners by phi and finds the cut points on sign-changing grid edges
/// (with global snapping to corners).
CutData cut_data(const mesh::PatchMesh& mesh, const LevelSet& phi, const CutOptions& options = {});

/// Builds the sub-elements from the compact description (`options`: the centre of a
/// type A patch's fan, see CutOptions::align_fraction; the same options as cut_data's).
CutMesh build_cut_mesh(const mesh::PatchMesh& mesh, const CutData& data, const CutOptions& options = {});

/// Both steps: cuts `mesh` by the level set `phi`.
inline CutMesh build_cut_mesh(const mesh::PatchMesh& mesh, const LevelSet& phi,
                              const CutOptions& options = {}) {
  return build_cut_mesh(mesh, cut_data(mesh, phi, options), options);
}

/// Signed area of a sub-element [m^2] (positive when counter-clockwise).
double element_area(const CutMesh& cut, const SubElement& e);
/// Smallest and largest interior angle of a sub-element [rad].
std::array<double, 2> element_angle_range(const CutMesh& cut, const SubElement& e);

}  // namespace fsi::fe
