#pragma once
/// \file step_mapping.hpp
/// The map T_m of the modified dG(0) scheme (Sect. 12.3) at every quadrature point of
/// the new mesh, and the old values v^{m-1}, u^{m-1} at T_m(x, t_{m-1}).
///
/// Near the interface T_m follows the Initial Point Set: x^{m-1} solves (12.4)
///     x^{m-1} - u^{m-2}(x^{m-1}) = x^m - u^{m-1}(x^m)
/// by Newton (start x^m - (u^{m-1} - u^{m-2})(x^m)). T_m(x, t_{m-1}) = g x^{m-1} +
/// (1 - g) x blends to the identity: g = 1 within eps of the interface, 0 beyond delta,
/// C^1 cubic in between, with |d0(x - u^{m-1}(x))| as the distance (exact for a rigid
/// motion). In the fluid gap between body and wall T_m = id (the chapter's contact
/// treatment), and so in the gap between two bodies (ours). d_t T = g (x^m - x^{m-1}) / k.
#include <span>
#include <vector>

#include "fe/point_locator.hpp"
#include "forms/fsi_element.hpp"
#include "fsi/scenario.hpp"

namespace fsi::interface {

/// A mesh level: cut mesh and its solution coefficients.
struct Level {
  const fe::CutMesh* cut = nullptr;
  const Eigen::VectorXd* solution = nullptr;
};

struct MappingOptions {
  double k_s = 1e-3;
  double eps_patches = 1.5, delta_patches = 3.0;
  double identity_gap_m = 0.0;  ///< fluid points closer to a wall: T = id (0: the patch's shorter side)
  int threads = 1;              ///< threads of the point loop (the result does not depend on it)
  /// Several bodies: the body of each sub-element of the new mesh (element_bodies), for
  /// the gaps between bodies. Null or empty: one body.
  const std::vector<int>* element_body = nullptr;
};

struct MappingStats {
  int ips_points = 0;       ///< points where (12.4) was solved
  int ips_failures = 0;     ///< Newton did not converge (fixed-point result used)
  int max_ips_iterations = 0;
};

/// Old values at T_m for every quadrature point of `quadrature` on the new mesh `next`.
/// `current` = level m-1 (its solution gives v, u old and u^{m-1}), `previous` = level m-2.
MappingStats compute_old_values(const mesh::PatchMesh& mesh, const fe::PatchBuckets& buckets,
                                const fe::CutMesh& next, const fe::QuadratureTable& quadrature,
                                const Level& current, const Level& previous, std::span<const BodySpec> bodies,
                                const std::vector<Segment2>& walls, const MappingOptions& options,
                                std::vector<forms::OldValues>& old);

}  // namespace fsi::interface
