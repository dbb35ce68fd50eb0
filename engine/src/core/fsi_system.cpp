#include "core/fsi_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "core/contact_distance.hpp"
#include "core/corner_barrier.hpp"
#include "core/initial_guess.hpp"
#include "core/parallel_chunks.hpp"
#include "forms/fluid_element_jacobian.hpp"
#include "forms/pressure_stabilization.hpp"
#include "interface/body.hpp"
#include "fsi/state.hpp"
#include "mesh/patch_colouring.hpp"
#include "mesh/walls.hpp"

namespace fsi::core {
namespace {

/// Field coupling of the monolithic system (fields vx, vy, ux, uy, p):
/// momentum couples to everything; the displacement equation to v and u; the
/// pressure rows (divergence / extension) to v and p. Between neighbouring patches
/// only the CIP stabilization couples (p-p).
solve::FieldCoupling patch_coupling() {
  return {{1, 1, 1, 1, 1}, {1, 1, 1, 1, 1}, {1, 1, 1, 1, 0}, {1, 1, 1, 1, 0}, {1, 1, 0, 0, 1}};
}
solve::FieldCoupling neighbor_coupling() {
  solve::FieldCoupling c(5, std::vector<char>(5, 0));
  c[kP][kP] = 1;
  return c;
}

}  // namespace

FsiSystem::FsiSystem(const Scenario& scenario, const mesh::PatchMesh& mesh)
    : scenario_(scenario), numerics_(scenario.numerics), mesh_(mesh) {
  forms::FsiCoefficients& c = coefficients_;
  c.k_s = scenario.numerics.time_step_s;
  c.rho_f = scenario.fluid.density_kgpm3;
  c.nu_f = scenario.fluid.viscosity_m2ps;
  for (const BodySpec& body : scene_bodies(scenario)) body_material_.push_back(body_solid(scenario, body));
  c.rho_s0 = body_material_[0].density_kgpm3;
  c.mu_s = body_material_[0].mu_pa;
  c.lambda_s = body_material_[0].lambda_pa;
  c.gx = scenario.gravity_mps2.x;
  c.gy = scenario.gravity_mps2.y;
  c.rho_buoyancy = scenario.buoyancy ? scenario.fluid.density_kgpm3 : 0.0;
  set_numerics(numerics_);

  patch_groups_ = mesh::colour_patches(mesh);
  pattern_ = solve::build_pattern(mesh, kFieldsPerNode, patch_coupling(), neighbor_coupling());
  // No-slip walls: v = 0 on their nodes.
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (mesh.on_wall[n])
      for (int f : {kVx, kVy}) dirichlet_dofs_.push_back(kFieldsPerNode * n + f);
  // The CIP term couples pressures only: its own node-by-node matrix (the p-p block),
  // with where each entry sits in the full pattern. Kept as a full-size matrix it cost a
  // copy of the whole pattern per step and a product over it per residual.
  {
    std::vector<Eigen::Triplet<double>> pp;
    for (int col = kP; col < pattern_.cols(); col += kFieldsPerNode)
      for (solve::SparseMatrix::InnerIterator it(pattern_, col); it; ++it)
        if (it.row() % kFieldsPerNode == kP) pp.emplace_back(it.row() / kFieldsPerNode, col / kFieldsPerNode, 0.0);
    cip_.resize(mesh.num_nodes(), mesh.num_nodes());
    cip_.setFromTriplets(pp.begin(), pp.end());
    cip_.makeCompressed();
    cip_position_.resize(cip_.nonZeros());
    for (int col = 0; col < cip_.cols(); ++col)
      for (int k = cip_.outerIndexPtr()[col]; k < cip_.outerIndexPtr()[col + 1]; ++k)
        cip_position_[k] = solve::value_index(pattern_, kFieldsPerNode * cip_.innerIndexPtr()[k] + kP,
                                              kFieldsPerNode * col + kP);
  }
  std::vector<int> row_slot(pattern_.rows(), -1);
  for (std::size_t i = 0; i < dirichlet_dofs_.size(); ++i) row_slot[dirichlet_dofs_[i]] = static_cast<int>(i);
  dirichlet_row_entries_.assign(dirichlet_dofs_.size(), {});
  for (int k = 0; k < pattern_.nonZeros(); ++k) {
    const int row = pattern_.innerIndexPtr()[k];
    if (row_slot[row] >= 0) dirichlet_row_entries_[row_slot[row]].push_back(k);
  }
}

void FsiSystem::set_numerics(const NumericsSpec& numerics) {
  numerics_ = numerics;
  coefficients_.alpha = numerics.solid_alpha;
  coefficients_.s = numerics.solid_s;
  coefficients_.cavitation_p_pa = numerics.cavitation_pressure_pa;
  coefficients_.cavitation_smoothing_pa = forms::cavitation_smoothing_pa(numerics.cavitation_pressure_pa);
  coefficients_.backflow_beta = numerics.backflow_beta;
  threads_ = resolve_threads(numerics.assembly_threads);
}

void FsiSystem::set_geometry(const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                             double time_step_s) {
  cut_ = &cut;
  quadrature_ = &quadrature;
  coefficients_.k_s = time_step_s;

  // Positions of every element's local entries in the value array, (local i, local j)
  // row-major (-1: not in the pattern). In a column the rows of one node's fields are
  // sorted and adjacent, so one search per (node, column) finds the first and a short walk
  // the others, instead of one search per entry (those searches were 6 % of a stairs step:
  // this runs every step over every element).
  entry_first_.assign(cut.num_elements() + 1, 0);
  entry_.clear();
  for (int k = 0; k < cut.num_elements(); ++k) {
    entry_first_[k] = static_cast<int>(entry_.size());
    const fe::SubElement& e = cut.elements[k];
    const int nl = kFieldsPerNode * e.vertices;
    const std::size_t first = entry_.size();
    entry_.resize(first + static_cast<std::size_t>(nl) * nl);
    int* local = entry_.data() + first;
    for (int jn = 0; jn < e.vertices; ++jn)
      for (int jf = 0; jf < kFieldsPerNode; ++jf) {
        const int j = kFieldsPerNode * jn + jf, col = kFieldsPerNode * e.node[jn] + jf;
        for (int in = 0; in < e.vertices; ++in) {
          const int row0 = kFieldsPerNode * e.node[in];
          const int* inner = pattern_.innerIndexPtr();
          const int* end = inner + pattern_.outerIndexPtr()[col + 1];
          const int* it = std::lower_bound(inner + pattern_.outerIndexPtr()[col], end, row0);
          for (int f = 0; f < kFieldsPerNode; ++f) {
            while (it != end && *it < row0 + f) ++it;
            local[(kFieldsPerNode * in + f) * nl + j] =
                (it != end && *it == row0 + f) ? static_cast<int>(it - inner) : -1;
          }
        }
      }
  }
  entry_first_[cut.num_elements()] = static_cast<int>(entry_.size());

  // CIP pressure stabilization: linear in p and fixed during the step.
  std::fill(cip_.valuePtr(), cip_.valuePtr() + cip_.nonZeros(), 0.0);
  const double mu = coefficients_.rho_f * coefficients_.nu_f;
  const double gamma = numerics_.cip_gamma / mu;
  const double transient = numerics_.cip_transient_weight * coefficients_.rho_f / (time_step_s * mu);
  forms::add_pressure_stabilization(mesh_, cut, fe::build_stabilization_edges(cut), gamma,
                                    1, 0, cip_, transient,
                                    numerics_.cip_wall_film_factor);
  build_open_sides();
  build_contact_forces();
}

void FsiSystem::build_open_sides() {
  const fe::CutMesh& cut = *cut_;
  open_first_.assign(cut.num_elements() + 1, 0);
  open_sides_.clear();
  // Collect (element, local edge) of every sub-element side on an open grid edge.
  std::vector<std::vector<forms::OpenBoundarySide>> per_element(cut.num_elements());
  const double g = 0.5 / std::sqrt(3.0);
  for (int p = 0; p < mesh_.num_patches(); ++p) {
    const mesh::Patch& patch = mesh_.patches[p];
    for (int s = 0; s < 4; ++s) {
      const mesh::GridEdge& ge = mesh_.edges[patch.edge[s]];
      if (!ge.boundary || ge.wall >= 0) continue;
      for (int k = cut.first_element[p]; k < cut.first_element[p + 1]; ++k) {
        const fe::SubElement& e = cut.elements[k];
        for (int i = 0; i < e.vertices; ++i) {
          const int a = e.node[i], b = e.node[(i + 1) % e.vertices];
          const bool on_side = (a == ge.mid && (b == ge.a || b == ge.b)) || (b == ge.mid && (a == ge.a || a == ge.b));
          if (!on_side) continue;
          forms::OpenBoundarySide side;
          const mesh::Vec2 d = cut.x[b] - cut.x[a];
          const double len = d.norm();
          side.nx = d.y() / len;
          side.ny = -d.x() / len;
          for (int q = 0; q < 2; ++q) {
            const auto ref = fe::edge_reference(e, i, q == 0 ? 0.5 - g : 0.5 + g);
            side.shape[q] = fe::shape_at_reference(cut, e, ref[0], ref[1]);
            side.weight[q] = 0.5 * len;
          }
          per_element[k].push_back(side);
        }
      }
    }
  }
  for (int k = 0; k < cut.num_elements(); ++k) {
    open_first_[k] = static_cast<int>(open_sides_.size());
    open_sides_.insert(open_sides_.end(), per_element[k].begin(), per_element[k].end());
  }
  open_first_[cut.num_elements()] = static_cast<int>(open_sides_.size());
}

const forms::FsiCoefficients& FsiSystem::element_coefficients(int k, forms::FsiCoefficients& scratch) const {
  if (body_material_.size() < 2 || static_cast<std::size_t>(k) >= element_body_.size() || element_body_[k] <= 0)
    return coefficients_;
  const SolidSpec& m = body_material_[static_cast<std::size_t>(element_body_[k])];
  scratch = coefficients_;
  scratch.rho_s0 = m.density_kgpm3;
  scratch.mu_s = m.mu_pa;
  scratch.lambda_s = m.lambda_pa;
  return scratch;
}

void FsiSystem::build_contact_forces() {
  // Penalty contact (Sect. 12.5): on the interface, where dist < dist_0, the solid feels
  // the pressure P_c = gamma_c (dist_0 - dist) / dist, i.e. the traction -P_c n_s
  // (n_s: outer normal of the solid), which pushes it away from the wall. In residual
  // form this adds + int_I P_c n_s . phi. With several bodies dist is also the distance
  // to the other bodies' interfaces: two bodies push each other apart as a body and a
  // wall do (ours).
  const fe::CutMesh& cut = *cut_;
  contact_force_.setZero(pattern_.rows());
  max_contact_pressure_ = 0.0;
  corner_barrier_acted_ = false;
  contact_force_on_body_n_per_m_ = mesh::Vec2::Zero();
  min_body_gap_m_ = std::numeric_limits<double>::infinity();
  closest_bodies_ = {-1, -1};
  const std::size_t num_bodies = body_material_.size();
  contact_force_per_body_n_per_m_.assign(num_bodies, mesh::Vec2::Zero());
  const std::vector<int> segment_body =
      num_bodies > 1 ? interface::segment_bodies(cut, element_body_) : std::vector<int>(cut.interface.size(), 0);
  // The distance of a point of `body`'s interface to the other bodies' interfaces, and
  // the body it is to.
  struct Gap {
    double distance_m = std::numeric_limits<double>::infinity();
    int body = -1;
  };
  const auto gap_to_other_bodies = [&](const mesh::Vec2& x, int body) {
    Gap gap;
    for (std::size_t i = 0; i < cut.interface.size(); ++i) {
      if (segment_body[i] == body) continue;
      const fe::InterfaceSegment& seg = cut.interface[i];
      const double d = mesh::distance_to_segment(Segment2{{seg.a.x(), seg.a.y()}, {seg.b.x(), seg.b.y()}}, x);
      if (d < gap.distance_m) gap = {d, segment_body[i]};
    }
    return gap;
  };
  if (num_bodies > 1)
    for (std::size_t i = 0; i < cut.interface.size(); ++i)
      for (const mesh::Vec2& x : {cut.interface[i].a, cut.interface[i].b}) {
        const Gap gap = gap_to_other_bodies(x, segment_body[i]);
        if (gap.distance_m < min_body_gap_m_) {
          min_body_gap_m_ = gap.distance_m;
          closest_bodies_ = {segment_body[i], gap.body};
        }
      }
  const ContactSpec& contact = scenario_.contact;
  const double gamma_c = contact.gamma_c, dist0 = contact.dist0_m;
  const bool penalty = gamma_c > 0.0 && dist0 > 0.0;
  const bool barrier = contact.corner_barrier_speed_mps > 0.0 && contact.corner_barrier_reach_m > 0.0 &&
                       scenario_.walls.size() >= 2;
  if (!penalty && !barrier) return;
  // Tread edges push like a flat wall tangent to the body (contact_distance.hpp), and
  // convex corners keep bodies off (corner_barrier.hpp): one of each per body, each with
  // the body's own centroid.
  std::vector<Eigen::Vector2d> body_centroid_m(num_bodies, Eigen::Vector2d::Zero());
  std::vector<double> solid_area_m2(num_bodies, 0.0);
  for (int k = 0; k < cut.num_elements(); ++k) {
    if (cut.elements[k].phase != Phase::solid) continue;
    const std::size_t b = element_body_.size() == cut.elements.size() ? static_cast<std::size_t>(std::max(0, element_body_[k])) : 0;
    for (int q = quadrature_->first[k]; q < quadrature_->first[k + 1]; ++q) {
      solid_area_m2[b] += quadrature_->points[q].weight;
      body_centroid_m[b] += quadrature_->points[q].weight * quadrature_->points[q].x;
    }
  }
  const std::span<const BodySpec> bodies = scene_bodies(scenario_);
  std::vector<ContactDistance> distances;
  std::vector<CornerBarrier> barriers;
  for (std::size_t b = 0; b < num_bodies; ++b) {
    if (solid_area_m2[b] > 0.0) body_centroid_m[b] /= solid_area_m2[b];
    std::vector<fe::InterfaceSegment> own;
    for (std::size_t i = 0; i < cut.interface.size(); ++i)
      if (segment_body[i] == static_cast<int>(b)) own.push_back(cut.interface[i]);
    distances.emplace_back(scenario_.walls, own, body_centroid_m[b], penalty ? dist0 : 0.0, body_reach(bodies[b]),
                           penalty && contact.corners_as_walls && solid_area_m2[b] > 0.0);
    const double reach = corner_barrier_reach_m(scenario_, bodies[b]);
    const double gamma_b = barrier && solid_area_m2[b] > 0.0
                               ? CornerBarrier::gamma_for(body_material_[b].density_kgpm3 * body_area(bodies[b]),
                                                          contact.corner_barrier_speed_mps, body_reach(bodies[b]), reach)
                               : 0.0;
    barriers.emplace_back(scenario_.walls, own, body_centroid_m[b], reach, body_reach(bodies[b]), gamma_b,
                          contact.min_dist_fraction);
  }
  const bool bodies_near = min_body_gap_m_ < dist0;
  const double g = 0.5 / std::sqrt(3.0);
  for (std::size_t i = 0; i < cut.interface.size(); ++i) {
    const fe::InterfaceSegment& seg = cut.interface[i];
    // Solid side: centroid of the patch's solid sub-elements.
    mesh::Vec2 centroid = mesh::Vec2::Zero();
    int count = 0;
    for (int k = cut.first_element[seg.patch]; k < cut.first_element[seg.patch + 1]; ++k) {
      const fe::SubElement& e = cut.elements[k];
      if (e.phase != Phase::solid) continue;
      for (int i = 0; i < e.vertices; ++i) centroid += cut.x[e.node[i]];
      count += e.vertices;
    }
    if (count == 0) continue;
    centroid /= count;
    const mesh::Vec2 d = seg.b - seg.a;
    const double len = d.norm();
    if (len <= 0.0) continue;
    mesh::Vec2 n(d.y() / len, -d.x() / len);
    if (n.dot(0.5 * (seg.a + seg.b) - centroid) < 0.0) n = -n;
    const ContactDistance& distance = distances[static_cast<std::size_t>(segment_body[i])];
    const CornerBarrier& corner_barrier = barriers[static_cast<std::size_t>(segment_body[i])];
    for (double s : {0.5 - g, 0.5 + g}) {
      const mesh::Vec2 x = seg.a + s * d;
      double pc = corner_barrier.pressure_pa(x);
      corner_barrier_acted_ = corner_barrier_acted_ || pc > 0.0;
      if (penalty) {
        double dist = distance(x);
        if (bodies_near) dist = std::min(dist, gap_to_other_bodies(x, segment_body[i]).distance_m);
        if (dist < dist0) pc = std::max(pc, gamma_c * (dist0 - dist) / std::max(dist, contact.min_dist_fraction * dist0));
      }
      if (!(pc > 0.0)) continue;
      max_contact_pressure_ = std::max(max_contact_pressure_, pc);
      const double w = 0.5 * len * pc;
      contact_force_on_body_n_per_m_ -= mesh::Vec2(w * n[0], w * n[1]);
      contact_force_per_body_n_per_m_[static_cast<std::size_t>(segment_body[i])] -= mesh::Vec2(w * n[0], w * n[1]);
      for (int f = 0; f < 2; ++f) {
        contact_force_[kFieldsPerNode * seg.node[0] + f] += w * (1.0 - s) * n[f];
        contact_force_[kFieldsPerNode * seg.node[1] + f] += w * s * n[f];
      }
    }
  }
}

template <bool kJacobian>
void FsiSystem::assemble(const Eigen::VectorXd& x, Eigen::VectorXd& r,
                         solve::SparseMatrix* jacobian, bool constrain) const {
  using Scalar = std::conditional_t<kJacobian, forms::Jet, double>;
  const fe::CutMesh& cut = *cut_;
  r = contact_force_;
  const double* cip = cip_.valuePtr();
  for (int col = 0; col < cip_.cols(); ++col) {
    const double p = x[kFieldsPerNode * col + kP];
    for (int k = cip_.outerIndexPtr()[col]; k < cip_.outerIndexPtr()[col + 1]; ++k)
      r[kFieldsPerNode * cip_.innerIndexPtr()[k] + kP] += cip[k] * p;
  }
  if constexpr (kJacobian) {
    double* values = jacobian->valuePtr();
    std::fill(values, values + jacobian->nonZeros(), 0.0);
    for (std::size_t k = 0; k < cip_position_.size(); ++k)
      if (cip_position_[k] >= 0) values[cip_position_[k]] = cip[k];
  }
  // The element loop, patch group by patch group (no two patches of a group share a node,
  // so the threads of a group write disjoint rows): every entry receives its terms in the
  // same order whatever the number of threads.
  const auto assemble_patches = [&](const std::vector<int>& patches, int begin, int end) {
    std::array<Scalar, forms::kMaxLocal> xl, rl;
    // Fluid sub-elements off the open boundary: the residual in double and the
    // Jacobian by hand (forms/fluid_element_jacobian.hpp), with the same residual bits.
    std::array<double, forms::kMaxLocal> xd, rd;
    forms::ElementMatrix kd;
    forms::FsiCoefficients own;  // a solid element's body material (element_coefficients)
    double* values = kJacobian ? jacobian->valuePtr() : nullptr;
    for (int i = begin; i < end; ++i) {
      const int p = patches[i];
      for (int k = cut.first_element[p]; k < cut.first_element[p + 1]; ++k) {
        const fe::SubElement& e = cut.elements[k];
        forms::ElementInput in;
        in.element = &e;
        in.qp = quadrature_->points.data() + quadrature_->first[k];
        in.old = old_.data() + quadrature_->first[k];
        in.num_qp = quadrature_->first[k + 1] - quadrature_->first[k];
        in.h_patch_m = mesh_.patches[e.patch].size_m;
        in.open_sides = open_sides_.data() + open_first_[k];
        in.num_open_sides = open_first_[k + 1] - open_first_[k];
        const int nl = kFieldsPerNode * e.vertices;
        for (int a = 0; a < e.vertices; ++a) {
          in.u_row_solid[a] = cut.touches_solid[e.node[a]];
          in.p_row_fluid[a] = cut.touches_fluid[e.node[a]];
          in.u_row_released[a] = !released_.empty() && released_[e.node[a]];
        }
        if constexpr (kJacobian) {
          if (forms::has_hand_jacobian(in)) {
            for (int a = 0; a < e.vertices; ++a)
              for (int f = 0; f < kFieldsPerNode; ++f) xd[kFieldsPerNode * a + f] = x[kFieldsPerNode * e.node[a] + f];
            for (int l = nl; l < forms::kMaxLocal; ++l) xd[l] = 0.0;
            forms::element_residual<double>(in, coefficients_, xd, rd);
            forms::fluid_element_jacobian(in, coefficients_, xd, kd);
            for (int l = 0; l < nl; ++l) {
              r[kFieldsPerNode * e.node[l / kFieldsPerNode] + l % kFieldsPerNode] += rd[l];
              const int* idx = entry_.data() + entry_first_[k] + l * nl;
              for (int j = 0; j < nl; ++j)
                if (idx[j] >= 0) values[idx[j]] += kd[l][j];
            }
            continue;
          }
        }
        for (int a = 0; a < e.vertices; ++a) {
          for (int f = 0; f < kFieldsPerNode; ++f) {
            const double value = x[kFieldsPerNode * e.node[a] + f];
            if constexpr (kJacobian) xl[kFieldsPerNode * a + f] = Scalar::variable(value, kFieldsPerNode * a + f);
            else xl[kFieldsPerNode * a + f] = value;
          }
        }
        for (int l = nl; l < forms::kMaxLocal; ++l) xl[l] = Scalar(0.0);
        forms::element_residual<Scalar>(in, element_coefficients(k, own), xl, rl);
        for (int l = 0; l < nl; ++l) {
          const int row = kFieldsPerNode * e.node[l / kFieldsPerNode] + l % kFieldsPerNode;
          if constexpr (kJacobian) {
            r[row] += rl[l].v;
            const int* idx = entry_.data() + entry_first_[k] + l * nl;
            for (int j = 0; j < nl; ++j)
              if (idx[j] >= 0) values[idx[j]] += rl[l].d[j];
          } else {
            r[row] += rl[l];
          }
        }
      }
    }
  };
  for (const std::vector<int>& group : patch_groups_)
    parallel_chunks(threads_, static_cast<int>(group.size()),
                    [&](int begin, int end) { assemble_patches(group, begin, end); });
  // Dirichlet rows: x_d - 0 (no-slip walls).
  for (std::size_t i = 0; constrain && i < dirichlet_dofs_.size(); ++i) {
    const int d = dirichlet_dofs_[i];
    r[d] = x[d];
    if constexpr (kJacobian) {
      for (int k : dirichlet_row_entries_[i]) jacobian->valuePtr()[k] = 0.0;
      jacobian->coeffRef(d, d) = 1.0;
    }
  }
}

void FsiSystem::residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
  assemble<false>(x, r, nullptr);
}

void FsiSystem::unconstrained_residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
  assemble<false>(x, r, nullptr, false);
}

void FsiSystem::residual_and_jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& r,
                                      solve::SparseMatrix& jacobian) const {
  assemble<true>(x, r, &jacobian);
}

void FsiSystem::extension_unknowns(std::vector<char>& extension) const {
  extension.assign(pattern_.rows(), 0);
  if (cut_ == nullptr) return;
  const std::size_t nodes = std::min(cut_->touches_solid.size(), extension.size() / kFieldsPerNode);
  for (std::size_t node = 0; node < nodes; ++node) {
    char* e = extension.data() + kFieldsPerNode * node;
    e[kUx] = e[kUy] = !cut_->touches_solid[node];
    e[kP] = !cut_->touches_fluid[node];
  }
}

int FsiSystem::inverted_solid_points(const Eigen::VectorXd& x) const {
  if (cut_ == nullptr || quadrature_ == nullptr) return 0;
  return solid_determinant(*cut_, *quadrature_, x).non_positive;
}

}  // namespace fsi::core
