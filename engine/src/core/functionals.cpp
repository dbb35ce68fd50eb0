#include "core/functionals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/rereference.hpp"
#include "forms/fsi_element.hpp"
#include "interface/body.hpp"
#include "mesh/walls.hpp"

namespace fsi::core {

Functionals compute_functionals(const Scenario& scenario, const fe::CutMesh& geometry,
                                const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                                const Eigen::VectorXd& solution, double reference_rotation_rad) {
  Functionals f;
  const double inf = std::numeric_limits<double>::infinity();
  f.min_distance_m = inf;
  f.bottom_y_m = f.left_x_m = inf;
  f.top_y_m = f.right_x_m = -inf;
  for (const fe::InterfaceSegment& s : geometry.interface)
    for (const mesh::Vec2& x : {s.a, s.b}) {
      f.min_distance_m = std::min(f.min_distance_m, mesh::distance_to_walls(scenario.walls, x).distance_m);
      f.bottom_y_m = std::min(f.bottom_y_m, x.y());
      f.top_y_m = std::max(f.top_y_m, x.y());
      f.left_x_m = std::min(f.left_x_m, x.x());
      f.right_x_m = std::max(f.right_x_m, x.x());
    }
  if (geometry.interface.empty()) f.min_distance_m = f.bottom_y_m = f.top_y_m = f.left_x_m = f.right_x_m = 0.0;

  double area = 0.0, mass = 0.0, cx = 0.0, cy = 0.0, mvx = 0.0, mvy = 0.0, created = 0.0;
  const double p_cav = scenario.numerics.cavitation_pressure_pa;
  const double mu_f = scenario.fluid.density_kgpm3 * scenario.fluid.viscosity_m2ps;
  for (int k = 0; k < cut.num_elements(); ++k) {
    const fe::SubElement& e = cut.elements[k];
    if (e.phase != Phase::solid) {
      if (p_cav == 0.0) continue;
      for (int q = quadrature.first[k]; q < quadrature.first[k + 1]; ++q) {
        const fe::QuadraturePoint& qp = quadrature.points[q];
        double p = 0.0;
        for (int a = 0; a < e.vertices; ++a) p += qp.value[a] * solution[kFieldsPerNode * e.node[a] + kP];
        created += qp.weight * forms::cavitation_expansion_rate(p, p_cav, mu_f);
      }
      continue;
    }
    for (int q = quadrature.first[k]; q < quadrature.first[k + 1]; ++q) {
      const fe::QuadraturePoint& qp = quadrature.points[q];
      double vx = 0, vy = 0, h00 = 0, h01 = 0, h10 = 0, h11 = 0;
      for (int a = 0; a < e.vertices; ++a) {
        const int base = kFieldsPerNode * e.node[a];
        vx += qp.value[a] * solution[base + kVx];
        vy += qp.value[a] * solution[base + kVy];
        h00 += qp.grad[a].x() * solution[base + kUx];
        h01 += qp.grad[a].y() * solution[base + kUx];
        h10 += qp.grad[a].x() * solution[base + kUy];
        h11 += qp.grad[a].y() * solution[base + kUy];
      }
      const double J = (1.0 - h00) * (1.0 - h11) - h01 * h10;
      area += qp.weight;
      mass += qp.weight * J;
      cx += qp.weight * qp.x.x();
      cy += qp.weight * qp.x.y();
      mvx += qp.weight * vx;
      mvy += qp.weight * vy;
    }
  }
  f.solid_area_m2 = area;
  f.cavitation_rate_m2ps = created;
  if (area > 0.0) {
    f.centroid_x_m = cx / area;
    f.centroid_y_m = cy / area;
    f.mean_vx_mps = mvx / area;
    f.mean_vy_mps = mvy / area;
  }
  const double reference = body_area(scenario.body);  // rho_s^0 cancels
  const RigidFit fit = fit_rigid_motion(cut, solution);
  f.rotation_rad = reference_rotation_rad + fit.angle_rad;
  f.mass_error = std::abs(reference - mass) / reference;
  return f;
}

}  // namespace fsi::core
