#include "core/functionals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

#include "core/rereference.hpp"
#include "forms/fsi_element.hpp"
#include "interface/body.hpp"
#include "mesh/walls.hpp"

namespace fsi::core {

namespace {

/// The solid's velocity and J = det(I - grad u) at a quadrature point of element e.
struct SolidPoint {
  double vx, vy, J;
};
SolidPoint solid_point(const fe::SubElement& e, const fe::QuadraturePoint& qp, const Eigen::VectorXd& solution) {
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
  return {vx, vy, (1.0 - h00) * (1.0 - h11) - h01 * h10};
}

/// The per-body functionals of a scene with several bodies.
std::vector<Functionals::Body> body_functionals(const Scenario& scenario, const fe::CutMesh& geometry,
                                                const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                                                const Eigen::VectorXd& solution, const std::vector<int>& geometry_body,
                                                const std::vector<int>& cut_body,
                                                const std::vector<State::BodyReference>& body_references) {
  const std::span<const BodySpec> bodies = scene_bodies(scenario);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Functionals::Body> out(bodies.size());
  for (Functionals::Body& b : out) b.min_distance_m = b.min_body_distance_m = inf;
  const std::vector<int> seg_body = interface::segment_bodies(geometry, geometry_body);
  for (std::size_t i = 0; i < geometry.interface.size(); ++i) {
    Functionals::Body& b = out[static_cast<std::size_t>(seg_body[i])];
    for (const mesh::Vec2& x : {geometry.interface[i].a, geometry.interface[i].b}) {
      b.min_distance_m = std::min(b.min_distance_m, mesh::distance_to_walls(scenario.walls, x).distance_m);
      for (std::size_t j = 0; j < geometry.interface.size(); ++j) {
        if (seg_body[j] == seg_body[i]) continue;
        const fe::InterfaceSegment& s = geometry.interface[j];
        b.min_body_distance_m =
            std::min(b.min_body_distance_m, mesh::distance_to_segment(Segment2{{s.a.x(), s.a.y()}, {s.b.x(), s.b.y()}}, x));
      }
    }
  }
  std::vector<double> mass(bodies.size(), 0.0);
  for (int k = 0; k < cut.num_elements(); ++k) {
    if (cut.elements[k].phase != Phase::solid || static_cast<std::size_t>(k) >= cut_body.size() || cut_body[k] < 0) continue;
    const fe::SubElement& e = cut.elements[k];
    const std::size_t n = static_cast<std::size_t>(cut_body[k]);
    Functionals::Body& b = out[n];
    for (int q = quadrature.first[k]; q < quadrature.first[k + 1]; ++q) {
      const fe::QuadraturePoint& qp = quadrature.points[q];
      const SolidPoint sp = solid_point(e, qp, solution);
      b.solid_area_m2 += qp.weight;
      mass[n] += qp.weight * sp.J;
      b.centroid_x_m += qp.weight * qp.x.x();
      b.centroid_y_m += qp.weight * qp.x.y();
      b.mean_vx_mps += qp.weight * sp.vx;
      b.mean_vy_mps += qp.weight * sp.vy;
    }
  }
  for (std::size_t n = 0; n < out.size(); ++n) {
    Functionals::Body& b = out[n];
    if (b.min_distance_m == inf) b.min_distance_m = 0.0;
    if (b.min_body_distance_m == inf) b.min_body_distance_m = 0.0;
    if (b.solid_area_m2 > 0.0) {
      b.centroid_x_m /= b.solid_area_m2;
      b.centroid_y_m /= b.solid_area_m2;
      b.mean_vx_mps /= b.solid_area_m2;
      b.mean_vy_mps /= b.solid_area_m2;
    }
    const double reference = body_area(bodies[n]);
    b.mass_error = std::abs(reference - mass[n]) / reference;
    const std::vector<char> nodes = body_nodes(cut, cut_body, static_cast<int>(n));
    b.rotation_rad = (n < body_references.size() ? body_references[n].rotation_rad : 0.0) +
                     fit_rigid_motion(cut, solution, &nodes).angle_rad;
  }
  return out;
}

}  // namespace

Functionals compute_functionals(const Scenario& scenario, const fe::CutMesh& geometry,
                                const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                                const Eigen::VectorXd& solution, double reference_rotation_rad,
                                const std::vector<int>& geometry_body, const std::vector<int>& cut_body,
                                const std::vector<State::BodyReference>& body_references) {
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
      const SolidPoint sp = solid_point(e, qp, solution);
      area += qp.weight;
      mass += qp.weight * sp.J;
      cx += qp.weight * qp.x.x();
      cy += qp.weight * qp.x.y();
      mvx += qp.weight * sp.vx;
      mvy += qp.weight * sp.vy;
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
  if (scene_bodies(scenario).size() > 1) {
    f.bodies = body_functionals(scenario, geometry, cut, quadrature, solution, geometry_body, cut_body, body_references);
    f.mass_error = 0.0;
    for (const Functionals::Body& b : f.bodies) f.mass_error = std::max(f.mass_error, b.mass_error);
    f.rotation_rad = f.bodies[0].rotation_rad;
    return f;
  }
  const double reference = body_area(scene_bodies(scenario)[0]);  // rho_s^0 cancels
  const RigidFit fit = fit_rigid_motion(cut, solution);
  f.rotation_rad = reference_rotation_rad + fit.angle_rad;
  f.mass_error = std::abs(reference - mass) / reference;
  return f;
}

}  // namespace fsi::core
