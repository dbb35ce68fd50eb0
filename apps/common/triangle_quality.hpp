#pragma once
/// \file triangle_quality.hpp
/// How well shaped the sub-elements of a FieldView are. Locally modified finite elements
/// (Frei & Richter) keep the largest interior angle of every sub-triangle bounded on a
/// square patch; in flat patches (the stairs' 4-8 mm rows, 5.6 cm wide) an interface
/// crossing at a shallow angle makes triangles with angles near 180 degrees (the stairs'
/// rho_f = 100 run failed where they reached 175: docs/solver.md "Diagnostics"). fsi-step's `quality`
/// command reports this measure.
#include <fsi/field_view.hpp>

namespace fsi::app {

struct TriangleQuality {
  int triangles = 0;
  int max_angle_above_150_deg = 0;  ///< triangles whose largest angle exceeds 150 degrees
  int max_angle_above_160_deg = 0;
  int max_angle_above_170_deg = 0;
  double worst_max_angle_deg = 0.0;  ///< the largest interior angle of any triangle
  Point2 worst_at;                   ///< centroid of that triangle [m]
  double smallest_area_m2 = 0.0;     ///< the smallest triangle
  Point2 smallest_at;                ///< its centroid [m]
};

/// Measures every triangle of `view` (uncut sub-quads are two right triangles each).
TriangleQuality measure_triangles(const FieldView& view);

}  // namespace fsi::app
