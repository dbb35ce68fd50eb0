#pragma once
/// \file fsi_system.hpp
/// The monolithic nonlinear system of one time step: R(x) = 0 for x = (v, u, p) per node.
///
/// The geometry of step m is explicit (built from u^{m-1}), so everything that depends
/// on it -- sub-elements, quadrature, stabilization edges, old values at T_m, contact
/// forces, positions of element entries in the fixed sparsity pattern -- is computed
/// once per step in set_step() and reused by every Newton iteration.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "fe/stabilization_edges.hpp"
#include "forms/fsi_element.hpp"
#include "fsi/scenario.hpp"
#include "solve/sparsity.hpp"

namespace fsi::core {

class FsiSystem {
 public:
  FsiSystem(const Scenario& scenario, const mesh::PatchMesh& mesh);

  /// The empty (all-zero) matrix with the fixed pattern.
  const solve::SparseMatrix& pattern() const { return pattern_; }
  int size() const { return static_cast<int>(pattern_.rows()); }

  /// Prepares a step on the sub-elements of `cut`: quadrature, edges, CIP matrix,
  /// boundary sides, contact forces. Old values are set separately (set_old_values).
  void set_geometry(const fe::CutMesh& cut, const fe::QuadratureTable& quadrature,
                    double time_step_s);
  /// The body of each sub-element of the next geometry (interface::element_bodies; -1:
  /// fluid): its material, and whose interface each contact force acts on. Set before
  /// set_geometry, which builds the contact forces. Empty: every solid element is body 0.
  void set_element_bodies(std::vector<int> body) { element_body_ = std::move(body); }
  /// Old values at T_m, one per quadrature point of the current geometry.
  void set_old_values(std::vector<forms::OldValues> old) { old_ = std::move(old); }
  void set_time_step(double k_s) { coefficients_.k_s = k_s; }
  /// New numerical parameters between steps (Engine::set_numerics): the solid velocity
  /// stabilization (alpha, s) at once, the CIP weights from the next set_geometry on.
  void set_numerics(const NumericsSpec& numerics);
  /// The wall nodes whose u row is the extension this step (core/contact_release.hpp;
  /// empty: none).
  void set_released_nodes(std::vector<char> released) { released_ = std::move(released); }
  /// Whether the cavitation floor of the numerics acts (true, the default) or not (the
  /// step from an impulsive start: Engine::Impl::attempt).
  void set_cavitation_floor(bool on) {
    coefficients_.cavitation_p_pa = on ? numerics_.cavitation_pressure_pa : 0.0;
  }

  /// R(x). Dirichlet rows read x - g.
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) const;
  /// R(x) with the Dirichlet rows left as assembled: the momentum rows of a wall node hold
  /// the force [N/m] the wall exerts there on the solid and fluid beside it (the weak
  /// form's boundary term, t = sigma n integrated against the node's shape function).
  void unconstrained_residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) const;
  /// R(x) and its exact Jacobian (values written into `jacobian`, which must have the
  /// pattern of pattern()).
  void residual_and_jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& r,
                             solve::SparseMatrix& jacobian) const;

  /// Marks the unknowns whose rows only extend a field beyond its domain (u at nodes that
  /// touch no solid sub-element, p at nodes that touch no fluid one): no other row
  /// depends on them, so the LU can take them after the rest (solve/split_lu.hpp).
  void extension_unknowns(std::vector<char>& extension) const;

  /// How many solid quadrature points x deforms past inversion, det(I - grad u) <= 0
  /// (J = 1/det(I - grad u) would be negative or infinite). Newton's line search refuses
  /// an update that adds any: St. Venant-Kirchhoff has no barrier against inversion, the
  /// stress in F = (I - grad u)^{-1} grows without bound towards it, and a step that
  /// stalls with points inverted leaves a body that degenerates (docs/method.md,
  /// "Inversion guard").
  int inverted_solid_points(const Eigen::VectorXd& x) const;

  /// The largest penalty contact pressure of this step [Pa] (0: inactive).
  double max_contact_pressure() const { return max_contact_pressure_; }
  /// Whether a convex corner's barrier pushed a body this step (corner_barrier.hpp).
  bool corner_barrier_acted() const { return corner_barrier_acted_; }
  /// The penalty force on the bodies this step, -int_I P_c n_s [N per m of depth], summed.
  mesh::Vec2 contact_force_on_body() const { return contact_force_on_body_n_per_m_; }
  /// The same for each body (scene order).
  const std::vector<mesh::Vec2>& contact_force_per_body() const { return contact_force_per_body_n_per_m_; }
  /// The smallest distance between the interfaces of two bodies this step [m] (infinity
  /// with one body), and the two bodies.
  double min_body_gap() const { return min_body_gap_m_; }
  std::array<int, 2> closest_bodies() const { return closest_bodies_; }
  const forms::FsiCoefficients& coefficients() const { return coefficients_; }

 private:
  template <bool kJacobian>
  void assemble(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* jacobian,
                bool constrain = true) const;
  void build_open_sides();
  void build_contact_forces();
  /// The coefficients of sub-element k: the body's own material for a solid one.
  const forms::FsiCoefficients& element_coefficients(int k, forms::FsiCoefficients& scratch) const;

  const Scenario& scenario_;
  NumericsSpec numerics_;  ///< the scenario's, or what set_numerics was last given
  const mesh::PatchMesh& mesh_;
  forms::FsiCoefficients coefficients_;
  solve::SparseMatrix pattern_;
  std::vector<std::vector<int>> patch_groups_;  ///< mesh::colour_patches: assembled group by group
  std::vector<char> released_;                  ///< set_released_nodes
  int threads_ = 1;                              ///< threads of the element loop
  std::vector<SolidSpec> body_material_;        ///< per body (scene_bodies order)
  std::vector<int> dirichlet_dofs_;
  std::vector<std::vector<int>> dirichlet_row_entries_;  ///< value indices of each Dirichlet row

  // Per step:
  const fe::CutMesh* cut_ = nullptr;
  const fe::QuadratureTable* quadrature_ = nullptr;
  std::vector<forms::OldValues> old_;
  std::vector<int> element_body_;                  ///< set_element_bodies
  solve::SparseMatrix cip_;                        ///< S_aniso on the p-p block, node by node
  std::vector<int> cip_position_;                  ///< value index in pattern_ of each cip_ entry
  std::vector<int> entry_first_;                   ///< per element: offset into entry_
  std::vector<int> entry_;                         ///< value index of (local i, local j)
  std::vector<int> open_first_;                    ///< per element: offset into open_sides_
  std::vector<forms::OpenBoundarySide> open_sides_;
  Eigen::VectorXd contact_force_;                  ///< constant residual part
  double max_contact_pressure_ = 0.0;
  bool corner_barrier_acted_ = false;
  mesh::Vec2 contact_force_on_body_n_per_m_ = mesh::Vec2::Zero();
  std::vector<mesh::Vec2> contact_force_per_body_n_per_m_;
  double min_body_gap_m_ = 0.0;
  std::array<int, 2> closest_bodies_{-1, -1};
};

}  // namespace fsi::core
