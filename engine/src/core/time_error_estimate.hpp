#pragma once
/// \file time_error_estimate.hpp
/// The local error of a dG(0) (backward Euler) step in the body's motion, and the step
/// length that keeps it at a tolerance: the error-controlled half of the time-step choice
/// (the geometric half is core/time_step_choice.hpp).
///
/// A backward Euler step of length k from t_m to t_m + k makes a local error of about
///   (k^2 / 2) y''
/// in a quantity y. With the step before it (length k_prev), y'' is estimated from the
/// three levels: y'' ~ 2 / (k + k_prev) (dy_new / k - dy_last / k_prev), so the error is
///   e = k / (k + k_prev) |dy_new - (k / k_prev) dy_last|,
/// the distance of the new value from the linear continuation of the last two (the
/// standard predictor-corrector estimate of implicit integrators). y is the body's mean
/// displacement, the mean of u over the nodes inside the solid at all three levels (a
/// translating body has u = its displacement at every such node), so e is the error of
/// where the body is: what the bounce's events (turn, contact, rebound) depend on. Its
/// velocity error, k^2 / 2 |a'|, enters through the next step's displacement.
#include <vector>

#include <Eigen/Core>

#include "fe/cut_mesh.hpp"

namespace fsi::core {

/// The estimate e [m] for the step from `current` to `next` (length k_s [s]) after the
/// step from `previous` to `current` (length previous_k_s [s]); negative when it cannot
/// be estimated (the first step, or no node inside the solid at all three levels).
/// Several bodies: `node_body` gives the body of each node (-1: none), y is each body's
/// own mean displacement and e the largest of the bodies' (the mean over all would cancel
/// for two bodies that move apart). Empty: one body.
double displacement_error_estimate(const fe::CutMesh& previous_cut, const Eigen::VectorXd& previous,
                                   const fe::CutMesh& current_cut, const Eigen::VectorXd& current,
                                   const fe::CutMesh& next_cut, const Eigen::VectorXd& next, double previous_k_s,
                                   double k_s, const std::vector<int>& node_body = {});

/// The longest step [s] after a step of length k_s [s] with error estimate error_m [m] for
/// the tolerance tolerance_m [m] per step: k (tolerance / e)^{1/2} (e grows like k^2) with a
/// safety factor 0.8, at most 2 k and at least k / 4 (infinite while no estimate exists).
double step_for_error(double k_s, double error_m, double tolerance_m);

}  // namespace fsi::core
