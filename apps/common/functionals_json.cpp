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
  if (!f.bodies.empty()) {  // several bodies: body1, body2, ... in order
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (const Functionals::Body& b : f.bodies) {
      nlohmann::ordered_json j;
      j["centroid_x_m"] = number_json(b.centroid_x_m);
      j["centroid_y_m"] = number_json(b.centroid_y_m);
      j["mean_vx_mps"] = number_json(b.mean_vx_mps);
      j["mean_vy_mps"] = number_json(b.mean_vy_mps);
      j["min_distance_m"] = number_json(b.min_distance_m);
      j["min_body_distance_m"] = number_json(b.min_body_distance_m);
      j["mass_error"] = number_json(b.mass_error);
      j["rotation_rad"] = number_json(b.rotation_rad);
      j["solid_area_m2"] = number_json(b.solid_area_m2);
      bodies.push_back(std::move(j));
    }
    o["bodies"] = std::move(bodies);
  }
  return o;
}

}  // namespace fsi::app
