// Engine::remesh_from: a run goes on on another mesh of the same domain (the stairs runs
// moved onto the fan-block mesh this way). Onto the same mesh nothing
// changes; onto another one the body stays where it was and the run goes on converging.
#include <fsi/engine.hpp>
#include <fsi/error.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace {

fsi::Scenario tiny_drop() {
  return fsi::load_scenario(std::filesystem::path(FSI_SOURCE_DIR) / "tests" / "data" / "tiny_drop.json");
}

/// The same box [-1, 1] x [-1, 0.5] with other patch lines: other counts and grading.
fsi::MeshSpec other_mesh_of_the_box() {
  fsi::BlockSpec b;
  b.x = {fsi::AxisPiece{0.0, -1.0, 7, 0.04, 0.25}, fsi::AxisPiece{0.0, 1.0, 7, 0.04, 0.25}};
  b.y = {fsi::AxisPiece{-1.0, 0.5, 13, 0.01, 0.3}};
  fsi::MeshSpec m;
  m.blocks = {b};
  return m;
}

void run(fsi::Engine& engine, int steps) {
  for (int i = 0; i < steps; ++i) {
    const fsi::StepReport r = engine.step();
    ASSERT_TRUE(r.converged) << "step " << engine.state().step << ": " << r.message;
  }
}

TEST(Remesh, OntoTheSameMeshTheStateIsTheSame) {
  fsi::Engine source(tiny_drop());
  run(source, 3);
  fsi::Engine copy(tiny_drop());
  copy.remesh_from(source);
  const fsi::State& a = source.state();
  const fsi::State& b = copy.state();
  EXPECT_EQ(b.step, a.step);
  EXPECT_EQ(b.time_s, a.time_s);
  EXPECT_EQ(b.time_step_limit_s, a.time_step_limit_s);
  // Nodal interpolation at the same nodes, and the interface rebuilt from the same u^{m-1}.
  EXPECT_LT((b.solution - a.solution).lpNorm<Eigen::Infinity>(), 1e-12 * (1.0 + a.solution.lpNorm<Eigen::Infinity>()));
  EXPECT_EQ(b.corner_sign, a.corner_sign);
  EXPECT_EQ(b.edge_cut, a.edge_cut);
  EXPECT_EQ(b.functionals.centroid_y_m, a.functionals.centroid_y_m);
  // Going on: only level m-1's interface differs (taken as level m's), by one step's motion.
  run(source, 3);
  run(copy, 3);
  EXPECT_NEAR(copy.state().functionals.centroid_y_m, source.state().functionals.centroid_y_m, 1e-5);
  EXPECT_NEAR(copy.state().functionals.mean_vy_mps, source.state().functionals.mean_vy_mps,
              0.01 * std::abs(source.state().functionals.mean_vy_mps));
}

TEST(Remesh, OntoAnotherMeshTheBodyStaysAndTheRunGoesOn) {
  fsi::Engine source(tiny_drop());
  run(source, 4);
  fsi::Scenario other = tiny_drop();
  other.mesh = other_mesh_of_the_box();
  fsi::Engine moved(other);
  moved.remesh_from(source);
  const fsi::Functionals a = source.state().functionals;  // copies: both go on below
  const fsi::Functionals b = moved.state().functionals;
  // The body where it was, up to the other mesh's discrete interface.
  EXPECT_NEAR(b.centroid_y_m, a.centroid_y_m, 2e-3);
  EXPECT_NEAR(b.bottom_y_m, a.bottom_y_m, 5e-3);
  EXPECT_NEAR(b.solid_area_m2, a.solid_area_m2, 0.01 * a.solid_area_m2);
  EXPECT_NEAR(b.mean_vy_mps, a.mean_vy_mps, 0.03 * std::abs(a.mean_vy_mps));
  EXPECT_EQ(moved.state().time_s, source.state().time_s);
  // Both go on falling at nearly the same speed.
  run(source, 3);
  run(moved, 3);
  EXPECT_NEAR(moved.state().functionals.mean_vy_mps, source.state().functionals.mean_vy_mps,
              0.05 * std::abs(source.state().functionals.mean_vy_mps));
  EXPECT_LT(moved.state().functionals.centroid_y_m, b.centroid_y_m);
}

/// The message of the InputError that taking `source`'s run onto `target` throws ("" if none).
std::string remesh_error(fsi::Engine& target, const fsi::Engine& source) {
  try {
    target.remesh_from(source);
  } catch (const fsi::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Remesh, RefusesAnotherScenarioOrDomain) {
  fsi::Engine source(tiny_drop());
  fsi::Scenario denser = tiny_drop();
  denser.fluid.density_kgpm3 *= 2.0;
  fsi::Engine other_physics(denser);
  EXPECT_NE(remesh_error(other_physics, source).find("more than its mesh"), std::string::npos);
  // A mesh reaching beyond the old one: its nodes there have no old values.
  fsi::Scenario taller = tiny_drop();
  taller.mesh.blocks[0].y[0].to_m = 0.7;
  fsi::Engine beyond(taller);
  EXPECT_NE(remesh_error(beyond, source).find("outside the old mesh"), std::string::npos);
}

}  // namespace
