#include "functionals_json.hpp"

#include <cmath>

namespace fsi::app {

nlohmann::ordered_json number_json(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json functionals_json(const Functionals& f) {
  nlohmann::ordered_json o;  // CSV column order reads best
  o["min_distance_m"] = number_json(f.min_distance_m);
  o["bottom_y_m"] = number_json(f.bottom_y_m);
  o["top_y_m"] = number_json(f.top_y_m);
  o["left_x_m"] = number_json(f.left_x_m);
  o["right_x_m"] = number_json(f.right_x_m);
  o["centroid_x_m"] = number_json(f.centroid_x_m);
  o["centroid_y_m"] = number_json(f.centroid_y_m);
  o["mean_vx_mps"] = number_json(f.mean_vx_mps);
  o["mean_vy_mps"] = number_json(f.mean_vy_mps);
  o["solid_area_m2"] = number_json(f.solid_area_m2);
  o["mass_error"] = number_json(f.mass_error);
  o["cavitation_rate_m2ps"] = number_json(f.cavitation_rate_m2ps);
  o["rotation_rad"] = number_json(f.rotation_rad);
  return o;
}

}  // namespace fsi::app
