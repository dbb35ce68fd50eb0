#pragma once
/// \file point_locator.hpp
/// Which sub-element of a cut mesh contains a point, and FE function evaluation there.
/// Needed by the IPS mapping (old solutions at mapped points) and by the level set.
///
/// Patches never move (only nodes inside them do), so a bucket grid over the patches
/// is built once per patch mesh; the search inside a patch uses the current cut mesh.
#include <vector>

#include <Eigen/Core>

#include "fe/element.hpp"

namespace fsi::fe {

class PatchBuckets {
 public:
  explicit PatchBuckets(const mesh::PatchMesh& mesh);
  /// Patches whose bounding box contains x (may be empty outside the domain).
  const std::vector<int>& candidates(const Vec2& x) const;
  /// The bucket cell nearest to x (for points slightly outside the domain).
  const std::vector<int>& nearest_candidates(const Vec2& x) const;
  /// Whether x lies in patch p's bounding box, widened by 1e-9 of its diagonal: no
  /// sub-element of a patch outside it can contain x.
  bool near_patch(int p, const Vec2& x) const {
    const std::size_t i = static_cast<std::size_t>(p);
    return x.x() >= box_lo_[i].x() && x.x() <= box_hi_[i].x() && x.y() >= box_lo_[i].y() && x.y() <= box_hi_[i].y();
  }

 private:
  int cell(const Vec2& x, bool clamp) const;
  Vec2 min_, inv_size_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> buckets_;
  std::vector<Vec2> box_lo_, box_hi_;  // per patch, widened (near_patch)
  std::vector<int> empty_;
};

struct Location {
  int element = -1;       ///< -1: not found
  ShapeValues shape;      ///< shape values and gradients at the point
  double margin = 0.0;    ///< inside_margin of the reference point (< 0: slightly outside)
};

/// Locates x in the cut mesh. Points on element boundaries are found; points outside
/// the domain get the closest element within `tolerance` (in reference units) or -1.
Location locate(const CutMesh& cut, const PatchBuckets& buckets, const Vec2& x,
                double tolerance = 1e-8);

/// Value of the FE function with nodal coefficients coeffs[stride * node + offset].
double evaluate(const CutMesh& cut, const Location& loc, const Eigen::VectorXd& coeffs,
                int stride, int offset);
/// Gradient [1/m times the unit of coeffs] of the same.
Vec2 evaluate_gradient(const CutMesh& cut, const Location& loc, const Eigen::VectorXd& coeffs,
                       int stride, int offset);

}  // namespace fsi::fe
