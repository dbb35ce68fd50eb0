// What longer steps away from the walls (numerics.time_step_max_doublings) save, and what they
// change: the same stretch of simulated time with every step k, then with steps up to
// 2k, 4k and 8k, each in one process from the same start.
//
//   build/bench/fsi-bench-flight [SCENARIO.json=assets/scenarios/stairs/stairs_rho150.json]
//                                [milliseconds=40] [CHECKPOINT]
//
// The stretch starts at t = 0 (the stairs ball at rest, 20 cm above the plane) or at the
// checkpoint (e.g. a stairs run's in flight). Prints per setting the steps, Newton
// iterations, factorizations and CPU seconds (user + sys, the steps alone), the ball's
// mean velocity, bottom and mass error at the end, and the CPU ratios to k. The velocities
// tell whether the longer steps changed the motion; the bottom and centroid are evaluated
// on the geometry the last step was solved on, one step (v k) behind. Run it with
// OPENBLAS_NUM_THREADS=1 on a shared machine and compare ratios.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fsi/engine.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "cpu_seconds.hpp"

namespace {

using fsi::bench::cpu_seconds;

struct Outcome {
  double k_max_s = 0.0, cpu_s = 0.0;
  int steps = 0, iterations = 0, factorizations = 0, unconverged = 0;
  fsi::Functionals end;
};

Outcome run(fsi::Scenario s, int doublings, double stretch_s, const std::string& checkpoint) {
  s.numerics.time_step_max_doublings = doublings;
  s.numerics.time_step_wall_zone_doublings = std::min(s.numerics.time_step_wall_zone_doublings, doublings);
  const double k_max_s = s.numerics.time_step_max_s();
  fsi::Engine engine(s);
  if (!checkpoint.empty()) fsi::load_checkpoint(engine, checkpoint);
  const double end_s = engine.state().time_s + stretch_s;
  fsi::NumericsSpec n = engine.scenario().numerics;
  n.end_time_s = end_s;  // the longer steps do not overshoot it
  engine.set_numerics(n);
  Outcome o;
  o.k_max_s = k_max_s;
  const double before = cpu_seconds();
  while (engine.state().time_s < end_s - 0.5 * s.numerics.time_step_s) {
    const fsi::StepReport r = engine.step();
    if (!r.accepted) throw std::runtime_error("step rejected at t = " + std::to_string(r.time_s) + ": " + r.message);
    ++o.steps;
    o.iterations += r.newton_iterations;
    o.factorizations += r.factorizations;
    o.unconverged += r.converged ? 0 : 1;
  }
  o.cpu_s = cpu_seconds() - before;
  o.end = engine.state().functionals;
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : "assets/scenarios/stairs/stairs_rho150.json";
  const double stretch_ms = argc > 2 ? std::atof(argv[2]) : 40.0;
  const std::string checkpoint = argc > 3 ? argv[3] : "";
  if (!(stretch_ms > 0.0 && stretch_ms <= 1e4)) {
    std::fprintf(stderr, "fsi-bench-flight: milliseconds must be in (0, 10000], got %s\n", argv[2]);
    return 2;
  }
  std::vector<Outcome> outcomes;
  try {
    fsi::Scenario s = fsi::load_scenario(file);
    s.numerics.failure_policy = fsi::FailurePolicy::halve_step;
    for (int doublings : {0, 1, 2, 3}) outcomes.push_back(run(s, doublings, 1e-3 * stretch_ms, checkpoint));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fsi-bench-flight: %s\n", e.what());
    return 2;
  }
  std::printf("%-10s %6s %6s %6s %6s %8s %6s %22s %10s %10s\n", "k_max [s]", "steps", "Newton", "LU",
              "unconv", "CPU s", "ratio", "mean v [m/s]", "bottom [m]", "mass err");
  for (const Outcome& o : outcomes)
    std::printf("%-10.3g %6d %6d %6d %6d %8.2f %6.3f (%9.6f, %9.6f) %10.5f %10.3e\n",
                o.k_max_s > 0.0 ? o.k_max_s : 0.0, o.steps, o.iterations, o.factorizations, o.unconverged,
                o.cpu_s, o.cpu_s / outcomes[0].cpu_s, o.end.mean_vx_mps, o.end.mean_vy_mps, o.end.bottom_y_m,
                o.end.mass_error);
  std::printf("(k_max 0: every step k; %s, %.4g ms from %s)\n", file.c_str(), stretch_ms,
              checkpoint.empty() ? "t = 0" : checkpoint.c_str());
}
