// A whole run of a scenario with its own numerics, as `tools/bench example1` runs it:
// wall and CPU time, steps and their lengths, Newton's work, time per stage and peak
// memory, with the wall time in units of one reference LU factorization
// (reference_factorization.hpp) measured in the same process before and after the run.
//
//   build/bench/fsi-bench-run SCENARIO.json [--end-time T] [--reference-nodes N]
//                             [--set KEY=VALUE ...] [--csv FILE] [--verbose]
//
// --reference-nodes: nodes per side of the reference matrix (default 65: the 4225-node
// system's size; 129 for 16641 nodes). --csv writes the chapter's functionals per step
// (time, min distance, bottom, mean v_y, mass error, step length, iterations) and the
// step's cost (factorizations, seconds per stage, the step's wall time).
// --verbose prints every step's report. Exit code 0 when the run reached its end time
// with every step converged, 1 otherwise.
// Run with OPENBLAS_NUM_THREADS=1 (tools/bench sets it).
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fsi/engine.hpp>
#include <fsi/error.hpp>
#include <map>
#include <string>
#include <vector>

#include "heap_tuning.hpp"
#include "scenario_overrides.hpp"
#include "cpu_seconds.hpp"
#include "reference_factorization.hpp"

namespace {

struct Totals {
  long steps = 0, unconverged = 0, rejected = 0;
  long newton = 0, factorizations = 0, jacobians = 0, krylov = 0;
  double geometry = 0, mapping = 0, assembly = 0, factorization = 0, solve = 0;
  std::map<double, long> step_histogram;  ///< step length [s], rounded to 0.1 us -> steps
};

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

int usage() {
  std::fprintf(stderr,
               "usage: fsi-bench-run SCENARIO.json [--end-time T] [--reference-nodes N] [--set KEY=VALUE ...] "
               "[--csv FILE] [--verbose]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) try {
  fsi::app::keep_large_blocks_in_heap();  // as fsi-movie and fsi-step run
  if (argc < 2) return usage();
  std::string file = argv[1], csv_file;
  std::vector<fsi::app::Override> overrides;
  double end_time = -1.0;
  int reference_nodes = 65;
  bool verbose = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--verbose") {
      verbose = true;
      continue;
    }
    if (i + 1 >= argc) return usage();
    if (a == "--end-time") end_time = std::atof(argv[++i]);
    else if (a == "--reference-nodes") reference_nodes = std::atoi(argv[++i]);
    else if (a == "--set") overrides.push_back(fsi::app::parse_override(argv[++i]));
    else if (a == "--csv") csv_file = argv[++i];
    else return usage();
  }
  if (end_time > 0.0) overrides.push_back({"/numerics/end_time_s", end_time});
  const fsi::Scenario scenario = fsi::app::load_scenario_with_overrides(file, overrides);
  const double end = scenario.numerics.end_time_s;

  fsi::bench::ReferenceFactorization reference(reference_nodes);
  const fsi::bench::ReferenceFactorization::Timing before = reference.time();
  const double reference_before_s = before.wall_s;

  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = fsi::bench::cpu_seconds();
  fsi::Engine engine(scenario);
  const double setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::FILE* csv = csv_file.empty() ? nullptr : std::fopen(csv_file.c_str(), "w");
  if (!csv_file.empty() && !csv) throw fsi::InputError(csv_file, "", "cannot be written");
  if (csv)
    std::fprintf(csv, "time_s,min_distance_m,bottom_y_m,centroid_y_m,mean_vy_mps,mass_error,time_step_s,"
                      "newton_iterations,converged,time_error_m,factorizations,geometry_s,mapping_s,assembly_s,"
                      "factorization_s,solve_s,step_wall_s\n");
  Totals t;
  std::string stop_reason;
  while (engine.state().time_s < end - 1e-9) {
    const auto step0 = std::chrono::steady_clock::now();
    const fsi::StepReport r = engine.step();
    const double step_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - step0).count();
    if (verbose) {
      std::printf("t = %.6f k = %.3g  %s  [", r.time_s, r.time_step_s, r.message.c_str());
      for (double n : r.residual_norms) std::printf(" %.2g", n);
      std::printf(" ]\n");
    }
    if (!r.accepted) {
      ++t.rejected;
      stop_reason = r.message;
      break;
    }
    ++t.steps;
    if (!r.converged) ++t.unconverged;
    t.newton += r.newton_iterations;
    t.factorizations += r.factorizations;
    t.jacobians += r.jacobian_assemblies;
    t.krylov += r.krylov_iterations;
    t.geometry += r.geometry_seconds;
    t.mapping += r.mapping_seconds;
    t.assembly += r.assembly_seconds;
    t.factorization += r.factorization_seconds;
    t.solve += r.solve_seconds;
    ++t.step_histogram[std::round(r.time_step_s * 1e7) / 1e7];  // 0.1 us bins: the k 2^j ladder
    if (csv) {
      const fsi::Functionals& f = engine.state().functionals;
      std::fprintf(csv, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d,%.3g,%d,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g\n", r.time_s,
                   f.min_distance_m, f.bottom_y_m, f.centroid_y_m, f.mean_vy_mps, f.mass_error, r.time_step_s,
                   r.newton_iterations, r.converged, r.time_error_m, r.factorizations, r.geometry_seconds,
                   r.mapping_seconds, r.assembly_seconds, r.factorization_seconds, r.solve_seconds, step_wall_s);
    }
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double cpu_s = fsi::bench::cpu_seconds() - cpu0;
  if (csv) std::fclose(csv);
  const fsi::bench::ReferenceFactorization::Timing after = reference.time();
  const double reference_after_s = after.wall_s;
  const double cpu_unit_s = 0.5 * (before.cpu_s + after.cpu_s);
  const double unit_s = 0.5 * (reference_before_s + reference_after_s);

  const double t_end = engine.state().time_s;
  std::printf("scenario        %s (%ld nodes), t = 0 -> %.4g s of %.4g s\n", file.c_str(),
              static_cast<long>(engine.state().solution.size() / fsi::kFieldsPerNode), t_end, end);
  std::printf("wall            %.2f s (set-up %.2f s)   CPU %.2f s (%.2f cores)\n", wall_s, setup_s, cpu_s,
              cpu_s / wall_s);
  std::printf("reference LU    %.4f s before, %.4f s after (%d^2 nodes, 5 fields, 9-point stencil)\n",
              reference_before_s, reference_after_s, reference.nodes_per_side());
  std::printf("WALL / REF      %.1f reference factorizations\n", wall_s / unit_s);
  // On a shared machine the wall time counts the other jobs too; the CPU time does not.
  std::printf("CPU / REF       %.1f reference factorizations (CPU %.4f s each)\n", cpu_s / cpu_unit_s, cpu_unit_s);
  std::printf("steps           %ld (%ld unconverged, %ld rejected)\n", t.steps, t.unconverged, t.rejected);
  std::printf("step lengths    ");
  for (const auto& [length_s, count] : t.step_histogram) std::printf("%.4g ms: %ld   ", 1e3 * length_s, count);
  std::printf("\n");
  std::printf("Newton          %ld iterations (%.2f per step), %ld factorizations, %ld Jacobians, %ld Krylov "
              "iterations\n",
              t.newton, double(t.newton) / std::max(1L, t.steps), t.factorizations, t.jacobians, t.krylov);
  const double staged = t.geometry + t.mapping + t.assembly + t.factorization + t.solve;
  std::printf("stages [ref]    geometry %.1f  IPS/T_m %.1f  assembly %.1f  factorization %.1f  solves %.1f  "
              "other %.1f\n",
              t.geometry / unit_s, t.mapping / unit_s, t.assembly / unit_s, t.factorization / unit_s,
              t.solve / unit_s, (wall_s - staged) / unit_s);
  std::printf("peak RSS        %.0f MB\n", peak_rss_mb());
  const bool finished = t.rejected == 0 && t_end >= end - 1e-9;
  if (!finished) std::printf("STOPPED         %s\n", stop_reason.c_str());
  return finished && t.unconverged == 0 ? 0 : 1;
} catch (const fsi::InputError& e) {
  std::fprintf(stderr, "fsi-bench-run: %s\n", e.what());
  return 2;
}
