// What numerics.krylov_iterations saves: the same steps with Newton's new Jacobians
// factorized every time, then solved by GMRES on the factorization held, in one process.
//
//   build/bench/fsi-bench-krylov [SCENARIO.json=assets/scenarios/stairs/stairs_rho1000.json]
//                                [steps=8] [CHECKPOINT] [krylov_iterations=40]
//
// The steps start at t = 0 or at the checkpoint (a stairs run's, where the ball rolls and
// the step refactorized 1-3 times). Prints CPU seconds (user + sys), factorizations, GMRES
// iterations and Newton iterations of the steps alone, their ratio, and how far apart the
// two end states are (both solve every step to Newton's tolerance). Compare ratios; run
// with OPENBLAS_NUM_THREADS=1 on a shared machine.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fsi/engine.hpp>
#include <string>

#include "cpu_seconds.hpp"

namespace {

using fsi::bench::cpu_seconds;

struct Run {
  double cpu_s = 0.0;
  int factorizations = 0, krylov_iterations = 0, newton_iterations = 0, unconverged = 0;
  fsi::Functionals last;
  double time_s = 0.0;
};

Run run(fsi::Scenario s, int krylov_iterations, int steps, const std::string& checkpoint) {
  s.numerics.krylov_iterations = krylov_iterations;  // a solver control: checkpoints load either way
  fsi::Engine engine(s);
  if (!checkpoint.empty()) fsi::load_checkpoint(engine, checkpoint);
  Run r;
  const double t0 = cpu_seconds();
  for (int i = 0; i < steps; ++i) {
    const fsi::StepReport report = engine.step();
    r.factorizations += report.factorizations;
    r.krylov_iterations += report.krylov_iterations;
    r.newton_iterations += report.newton_iterations;
    r.unconverged += report.converged ? 0 : 1;
  }
  r.cpu_s = cpu_seconds() - t0;
  r.last = engine.state().functionals;
  r.time_s = engine.state().time_s;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : "assets/scenarios/stairs/stairs_rho1000.json";
  const int steps = argc > 2 ? std::atoi(argv[2]) : 8;
  const std::string checkpoint = argc > 3 ? argv[3] : "";
  const int krylov = argc > 4 ? std::atoi(argv[4]) : 40;
  if (steps < 1 || krylov < 1) {
    std::fprintf(stderr, "fsi-bench-krylov: steps and krylov_iterations must be at least 1\n");
    return 2;
  }
  Run direct, gmres;
  try {
    const fsi::Scenario s = fsi::load_scenario(file);
    direct = run(s, 0, steps, checkpoint);
    gmres = run(s, krylov, steps, checkpoint);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-bench-krylov: %s\n", e.what());
    return 2;
  }
  std::printf("%-28s %8s %15s %17s %18s %12s\n", "", "CPU s", "factorizations", "GMRES iterations",
              "Newton iterations", "unconverged");
  for (const auto& [name, r] : {std::pair<const char*, const Run&>{"factorize every Jacobian", direct},
                                {"GMRES on the held LU", gmres}})
    std::printf("%-28s %8.2f %15d %17d %18d %12d\n", name, r.cpu_s, r.factorizations, r.krylov_iterations,
                r.newton_iterations, r.unconverged);
  std::printf("GMRES / factorizations: CPU %.3f (%s, %d steps from %s, krylov_iterations %d)\n",
              gmres.cpu_s / direct.cpu_s, file.c_str(), steps, checkpoint.empty() ? "t = 0" : checkpoint.c_str(),
              krylov);
  std::printf("end states: t %.6f / %.6f s, centroid y differs by %.2e m, mean v_x by %.2e m/s\n", direct.time_s,
              gmres.time_s, std::abs(direct.last.centroid_y_m - gmres.last.centroid_y_m),
              std::abs(direct.last.mean_vx_mps - gmres.last.mean_vx_mps));
}
