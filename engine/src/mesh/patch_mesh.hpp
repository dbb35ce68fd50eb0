#pragma once
/// \file patch_mesh.hpp
/// The patch mesh of the locally modified finite element method.
///
/// A patch is a (possibly bilinearly mapped) quadrilateral with 3x3 nodes: corners,
/// edge midpoints and centre. Local node (i, j), i along the patch's first direction
/// and j along the second, has local index 3 j + i:
///
///     6---7---8
///     |   |   |        corners 0, 2, 8, 6 (counter-clockwise)
///     3---4---5        edge midpoints 1 (bottom), 5 (right), 7 (top), 3 (left)
///     |   |   |        centre 4
///     0---1---2
///
/// The nodes of all patches form one global set (shared nodes merged, also across
/// blocks). Their number and the patch connectivity never change; only the positions
/// of edge-midpoint and centre nodes of cut patches move (fe/cut_mesh.hpp).
#include <array>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "fsi/scenario.hpp"

namespace fsi::mesh {

using Vec2 = Eigen::Vector2d;

/// Patch sides, counter-clockwise from the bottom; side s joins corners kSideCorners[s].
enum Side : int { kBottom = 0, kRight = 1, kTop = 2, kLeft = 3 };
inline constexpr std::array<std::array<int, 2>, 4> kSideCorners{{{0, 2}, {2, 8}, {8, 6}, {6, 0}}};
inline constexpr std::array<int, 4> kSideMidpoint{1, 5, 7, 3};
inline constexpr std::array<int, 4> kCornerLocal{0, 2, 8, 6};  ///< counter-clockwise

struct Patch {
  std::array<int, 9> node{};      ///< global node ids, local numbering above
  std::array<int, 4> neighbor{};  ///< patch across each Side, -1 on the boundary
  std::array<int, 4> edge{};      ///< global grid-edge id of each Side
  double size_m = 0.0;            ///< h_P: the longer of the patch's two mean side lengths
  double min_size_m = 0.0;        ///< the shorter of the two (the patch height at the ground)
};

/// A grid edge: one side of one or two patches. Its midpoint node may move when the
/// interface cuts it; both patches then see the same moved node.
struct GridEdge {
  int a = -1, b = -1;  ///< corner node ids (a -> b is the parametrisation t in [0, 1])
  int mid = -1;        ///< midpoint node id
  int wall = -1;       ///< boundary edges: index of the wall it lies on, -1 if open
  bool boundary = false;
  /// The patches beside it (the lower index first; -1: none, on the boundary).
  std::array<int, 2> patch{-1, -1};
  /// The shortest side running across it of the patches beside it: how thick they are
  /// seen from this edge [m] (infinity until build_patch_mesh sets it).
  double thickness_m = std::numeric_limits<double>::infinity();
};

struct PatchMesh {
  std::vector<Vec2> nodes;          ///< reference node positions [m] (uncut configuration)
  std::vector<Patch> patches;
  std::vector<GridEdge> edges;
  std::vector<char> is_corner;      ///< 1 for patch corners (never move)
  std::vector<char> on_wall;        ///< 1 for nodes on a no-slip wall (v = 0)
  std::vector<char> on_boundary;    ///< 1 for nodes on the domain boundary
  Vec2 min, max;                    ///< bounding box [m]

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_patches() const { return static_cast<int>(patches.size()); }
};

/// Builds the patch mesh of a scenario's MeshSpec (all blocks, refinements applied),
/// merging coincident nodes, and marks boundary edges lying on `walls`.
/// Throws std::invalid_argument for inconsistent block data.
PatchMesh build_patch_mesh(const MeshSpec& spec, const std::vector<Segment2>& walls);

}  // namespace fsi::mesh
