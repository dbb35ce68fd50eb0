// Cost of one FSI time step, split into the stages of Engine::step(), as ratios of one
// LU factorization (machines here are shared and noisy: compare ratios, not seconds).
//
//   build/bench/fsi-bench-step [steps=20] [max_refinements=1]
//
// Runs Example 1 from rest for `steps` steps on the 65^2-node mesh (and 129^2 with
// max_refinements = 1), after 5 warm-up steps.
#include <fsi/engine.hpp>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 20;
  const int max_refinements = argc > 2 ? std::atoi(argv[2]) : 1;
  std::printf("%-8s %6s %9s %9s %9s %9s %9s %9s %7s %7s\n", "nodes", "steps", "geometry", "IPS/T_m",
              "assembly", "factor.", "solves", "step", "iters", "facts");
  for (int refinements = 0; refinements <= max_refinements; ++refinements) {
    fsi::Scenario s = fsi::example1_scenario();
    s.mesh.refinements = refinements;
    s.numerics.time_step_s = 2e-3 / (1 << refinements);
    fsi::Engine engine(s);
    for (int i = 0; i < 5; ++i) engine.step();
    double geo = 0, map = 0, assembly = 0, fact = 0, solve = 0;
    int iterations = 0, factorizations = 0;
    for (int i = 0; i < steps; ++i) {
      const fsi::StepReport r = engine.step();
      geo += r.geometry_seconds;
      map += r.mapping_seconds;
      assembly += r.assembly_seconds;
      fact += r.factorization_seconds;
      solve += r.solve_seconds;
      iterations += r.newton_iterations;
      factorizations += r.factorizations;
    }
    const long nodes = engine.state().solution.size() / fsi::kFieldsPerNode;
    const double one_fact = factorizations > 0 ? fact / factorizations : 1.0;
    const double total = geo + map + assembly + fact + solve;
    std::printf("%-8ld %6d %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %7.2f %7.2f   (per step, in units of one factorization = %.3f s)\n",
                nodes, steps, geo / steps / one_fact, map / steps / one_fact, assembly / steps / one_fact,
                fact / steps / one_fact, solve / steps / one_fact, total / steps / one_fact,
                double(iterations) / steps, double(factorizations) / steps, one_fact);
  }
}
