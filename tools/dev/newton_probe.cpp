// fsi-newton-probe: what Newton faces in the next step of a checkpointed state.
//
//   fsi-newton-probe SCENARIO.json CHECKPOINT [--iterations N] [--k SECONDS] [--cut-snap S] [--cut-snap-distance M] [--cut-align F] [--start interpolated|repair|solid]
//
// Builds the step the engine would take next (the geometry from u, T_m and the old
// values, Newton's start) and reports: how the start was made (nodes re-interpolated,
// nodes continued from the solid field), the smallest det(I - grad u) over the solid
// quadrature points at the start, the largest Jacobian entry and UMFPACK's rcond, then N
// iterations of plain Newton (a fresh exact Jacobian in every iteration, a line search of
// up to 12 halvings) with the residual's peak and the smallest det(I - grad u) after
// each. `--start` picks Newton's start (core/initial_guess.hpp): `repair` (the default) is
// the engine's first attempt, `solid` its retry, `interpolated` plain re-interpolation. A
// diagnostic for stalled steps (docs/solver.md, "Diagnostics"); it changes nothing.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/fsi_system.hpp"
#include "core/initial_guess.hpp"
#include "fe/cut_mesh.hpp"
#include "fe/element.hpp"
#include "fe/point_locator.hpp"
#include "fsi/scenario.hpp"
#include "interface/body.hpp"
#include "interface/step_mapping.hpp"
#include "io/checkpoint.hpp"
#include "mesh/patch_mesh.hpp"
#include "solve/sparse_lu.hpp"

namespace {

using namespace fsi;

const char* kFieldName[] = {"v_x", "v_y", "u_x", "u_y", "p"};

struct Options {
  std::string scenario, checkpoint;
  int iterations = 8;
  double k_s = 0.0;  ///< the step's length (0: the scenario's time_step_s)
  double cut_snap = -1.0;  ///< the next geometry's cut_snap (negative: the scenario's)
  double cut_snap_distance_m = -1.0;  ///< and its cut_snap_distance_m
  double cut_align_fraction = -1.0;   ///< and its cut_align_fraction
  core::StartMode start = core::StartMode::repair_unphysical;
};

Options parse(int argc, char** argv) {
  Options o;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--iterations" && i + 1 < argc) {
      o.iterations = std::atoi(argv[++i]);
      if (o.iterations < 0 || o.iterations > 200)
        throw std::invalid_argument("fsi-newton-probe: --iterations must be an integer in [0, 200]");
    } else if (a == "--k" && i + 1 < argc) {
      o.k_s = std::atof(argv[++i]);
      if (!(o.k_s > 0.0 && o.k_s <= 1.0)) throw std::invalid_argument("fsi-newton-probe: --k must be a step length in (0, 1] s");
    } else if (a == "--cut-snap" && i + 1 < argc) {
      o.cut_snap = std::atof(argv[++i]);
      if (!(o.cut_snap >= 0.0 && o.cut_snap <= 0.25)) throw std::invalid_argument("fsi-newton-probe: --cut-snap must be in [0, 0.25]");
    } else if (a == "--cut-snap-distance" && i + 1 < argc) {
      o.cut_snap_distance_m = std::atof(argv[++i]);
      if (!(o.cut_snap_distance_m >= 0.0 && o.cut_snap_distance_m <= 0.1))
        throw std::invalid_argument("fsi-newton-probe: --cut-snap-distance must be in [0, 0.1] m");
    } else if (a == "--cut-align" && i + 1 < argc) {
      o.cut_align_fraction = std::atof(argv[++i]);
      if (!(o.cut_align_fraction >= 0.0 && o.cut_align_fraction <= 0.5))
        throw std::invalid_argument("fsi-newton-probe: --cut-align must be in [0, 0.5]");
    } else if (a == "--start" && i + 1 < argc) {
      const std::string m = argv[++i];
      if (m == "interpolated") o.start = core::StartMode::interpolated;
      else if (m == "repair") o.start = core::StartMode::repair_unphysical;
      else if (m == "solid") o.start = core::StartMode::solid_field;
      else throw std::invalid_argument("fsi-newton-probe: --start must be interpolated, repair or solid, not " + m);
    } else if (!a.empty() && a[0] == '-') {
      throw std::invalid_argument("fsi-newton-probe: unknown option " + a);
    } else {
      positional.push_back(a);
    }
  }
  if (positional.size() != 2)
    throw std::invalid_argument("usage: fsi-newton-probe SCENARIO.json CHECKPOINT [--iterations N] [--k SECONDS] [--cut-snap S] [--cut-snap-distance M] [--cut-align F] [--start interpolated|repair|solid]");
  o.scenario = positional[0];
  o.checkpoint = positional[1];
  return o;
}

/// Row scale of the engine's residual norm: 1 / max_j |J_ij|.
Eigen::VectorXd row_scale(const solve::SparseMatrix& j) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(j.rows());
  for (int c = 0; c < j.outerSize(); ++c)
    for (solve::SparseMatrix::InnerIterator it(j, c); it; ++it)
      s[it.row()] = std::max(s[it.row()], std::abs(it.value()));
  for (Eigen::Index i = 0; i < s.size(); ++i) s[i] = s[i] > 0.0 ? 1.0 / s[i] : 1.0;
  return s;
}

void print_row(const char* what, Eigen::Index row, const fe::CutMesh& cut) {
  const int node = static_cast<int>(row / kFieldsPerNode);
  std::printf("%s%s%s of node %d (%.5f, %.5f) m", what, *what ? " " : "", kFieldName[row % kFieldsPerNode], node,
              cut.x[node].x(), cut.x[node].y());
}

int run(const Options& o) {
  const Scenario scenario = load_scenario(o.scenario);
  const State state = io::read_checkpoint(o.checkpoint, fingerprint(scenario));
  const mesh::PatchMesh mesh = mesh::build_patch_mesh(scenario.mesh, scenario.walls);
  const fe::PatchBuckets buckets(mesh);
  const NumericsSpec& n = scenario.numerics;
  const fe::CutOptions cut_options{o.cut_snap >= 0.0 ? o.cut_snap : n.cut_snap,
                                   o.cut_snap_distance_m >= 0.0 ? o.cut_snap_distance_m : n.cut_snap_distance_m,
                                   o.cut_align_fraction >= 0.0 ? o.cut_align_fraction : n.cut_align_fraction};

  // The step as Engine::step() builds it (engine.cpp: after_state_change, attempt).
  // The saved levels as the run built them (its own options), the next with the probe's.
  const fe::CutOptions saved_options{n.cut_snap, n.cut_snap_distance_m, n.cut_align_fraction};
  const fe::CutMesh current = fe::build_cut_mesh(mesh, fe::CutData{state.corner_sign, state.edge_cut}, saved_options);
  const fe::CutMesh previous =
      fe::build_cut_mesh(mesh, fe::CutData{state.previous_corner_sign, state.previous_edge_cut}, saved_options);
  // The body as the state refers its displacement to (re-referencing moved and turned it).
  BodySpec body = scenario.body;
  body.center_m.x += state.reference_offset_x_m;
  body.center_m.y += state.reference_offset_y_m;
  body.angle_rad += state.reference_rotation_rad;
  const fe::CutMesh next = fe::build_cut_mesh(
      mesh, fe::cut_data(mesh, interface::ips_level_set(body, current, buckets, state.solution), cut_options), cut_options);
  const fe::QuadratureTable quad = fe::build_quadrature(next);
  const double k = o.k_s > 0.0 ? o.k_s : n.time_step_s;
  core::FsiSystem system(scenario, mesh);
  system.set_geometry(next, quad, k);
  interface::MappingOptions mo;
  mo.k_s = k;
  mo.eps_patches = n.blend_eps_patches;
  mo.delta_patches = n.blend_delta_patches;
  mo.identity_gap_m = n.identity_gap_m;
  std::vector<forms::OldValues> old;
  interface::compute_old_values(mesh, buckets, next, quad, {&current, &state.solution},
                                {&previous, &state.previous_solution}, std::span<const BodySpec>(&body, 1), scenario.walls, mo, old);
  system.set_old_values(std::move(old));

  core::InitialGuessStats guess;
  Eigen::VectorXd x = core::initial_guess(mesh, buckets, current, next, state.solution, &guess, o.start);
  std::printf("step %ld -> %ld (t = %.6f s, k = %g s), %d unknowns\n", state.step, state.step + 1, state.time_s, k,
              system.size());
  std::printf("start: %d nodes re-interpolated, %d continued from the solid field\n", guess.moved_nodes,
              guess.extrapolated_nodes);
  const core::SolidDeterminant start_det = core::solid_determinant(next, quad, x);
  // The solid sub-elements an iterate inverts: their nodes on both meshes.
  const auto print_inverted = [&](const Eigen::VectorXd& x) {
  for (int e = 0; e < next.num_elements(); ++e) {
    const fe::SubElement& el = next.elements[e];
    if (el.phase != Phase::solid) continue;
    double worst = 1e300;
    for (int q = quad.first[e]; q < quad.first[e + 1]; ++q)
      worst = std::min(worst, core::deformation_determinant(el, quad.points[q], x));
    if (worst > 0.0) continue;
    const auto angles = fe::element_angle_range(next, el);
    std::printf("inverted element %d (patch %d, kind %d): det >= %.3f, angles %.1f-%.1f deg, area %.3g m^2\n", e, el.patch,
                static_cast<int>(next.kind[el.patch]), worst, angles[0] * 180 / 3.14159265, angles[1] * 180 / 3.14159265,
                fe::element_area(next, el));
    std::printf("  patch nodes (grid order):");
    for (int nd : mesh.patches[el.patch].node)
      std::printf(" %d (%.5f, %.5f) was (%.5f, %.5f) s %d;", nd, next.x[nd].x(), next.x[nd].y(), current.x[nd].x(),
                  current.x[nd].y(), int(next.corner_sign[nd]));
    std::printf("\n");
    for (int i = 0; i < el.vertices; ++i) {
      const int nd = el.node[i];
      std::printf("  node %d at (%.6f, %.6f) was (%.6f, %.6f) wall %d sign %d->%d solid %d->%d u (%.4e, %.4e) was (%.4e, %.4e)\n", nd,
                  next.x[nd].x(), next.x[nd].y(), current.x[nd].x(), current.x[nd].y(), int(mesh.on_wall[nd]),
                  int(current.corner_sign[nd]), int(next.corner_sign[nd]), int(current.touches_solid[nd]),
                  int(next.touches_solid[nd]), x[kFieldsPerNode * nd + kUx], x[kFieldsPerNode * nd + kUy],
                  state.solution[kFieldsPerNode * nd + kUx], state.solution[kFieldsPerNode * nd + kUy]);
    }
  }
  };
  print_inverted(x);
  std::printf("det(I - grad u) at the start: smallest %.4f at (%.5f, %.5f) m; %d solid points <= 0\n",
              start_det.smallest, start_det.where.x(), start_det.where.y(), start_det.non_positive);

  solve::SparseMatrix jacobian = system.pattern();
  Eigen::VectorXd r, r_try;
  bool inverted_shown = false;  // the first iterate that inverts what the start did not
  for (int it = 0; it <= o.iterations; ++it) {
    system.residual_and_jacobian(x, r, jacobian);
    const Eigen::VectorXd scale = row_scale(jacobian);
    Eigen::Index peak = 0;
    const double norm = r.cwiseProduct(scale).cwiseAbs().maxCoeff(&peak);
    solve::SparseLU lu;
    const bool ok = lu.factorize(jacobian);
    if (it == 0) {
      Eigen::Index row = 0, col = 0;
      double largest = 0.0;
      for (int c = 0; c < jacobian.outerSize(); ++c)
        for (solve::SparseMatrix::InnerIterator e(jacobian, c); e; ++e)
          if (std::abs(e.value()) > largest) {
            largest = std::abs(e.value());
            row = e.row();
            col = c;
          }
      std::printf("largest Jacobian entry %.3g: ", largest);
      print_row("row", row, next);
      print_row(", column", col, next);
      std::printf("\n");
    }
    std::printf("iteration %2d: residual %.4g at ", it, norm);
    print_row("", peak, next);
    std::printf(", rcond %.2g", lu.rcond());
    if (!ok) {
      std::printf(": singular\n");
      return 1;
    }
    if (it == o.iterations || norm < 1e-10) {
      std::printf("\n");
      break;
    }
    const Eigen::VectorXd dx = -lu.solve(r);
    double lambda = 1.0, trial = norm;
    for (int h = 0; h <= 12; ++h, lambda *= 0.5) {
      system.residual(x + lambda * dx, r_try);
      trial = r_try.cwiseProduct(scale).cwiseAbs().maxCoeff();
      if (trial < norm) break;
    }
    if (!(trial < norm)) {
      std::printf(": no decrease down to 1/4096 of the step\n");
      return 1;
    }
    x += lambda * dx;
    // Where Newton goes: St. Venant-Kirchhoff has no barrier against inversion, and a
    // stalled step that leaves solid points at det <= 0 is what the solid cannot recover from.
    const core::SolidDeterminant det = core::solid_determinant(next, quad, x);
    std::printf(", step x %g -> %.4g; det(I - grad u) >= %.3f (%d <= 0)\n", lambda, trial, det.smallest,
                det.non_positive);
    if (det.non_positive > 0 && !(start_det.non_positive > 0) && !inverted_shown) {
      print_inverted(x);
      inverted_shown = true;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
