// Several bodies in one scene (Scenario::bodies): the scene's d0 and which body a point
// belongs to, the file format, the start checks, the penalty force between two bodies,
// the functionals of each body and the detection of two bodies that touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "core/degeneration.hpp"
#include "core/fsi_system.hpp"
#include "fe/cut_mesh.hpp"
#include "fe/element.hpp"
#include "fe/point_locator.hpp"
#include "fsi/engine.hpp"
#include "fsi/error.hpp"
#include "fsi/output.hpp"
#include "fsi/scenario.hpp"
#include "interface/body.hpp"
#include "io/checkpoint.hpp"
#include "mesh/patch_mesh.hpp"

namespace {

using Vec2 = Eigen::Vector2d;

fsi::BodySpec ball(double x, double y, double r) {
  fsi::BodySpec b;
  b.center_m = {x, y};
  b.radius_m = r;
  return b;
}

/// Two balls of radius 0.25 m `gap_m` apart on the line y = 0 in a 2 m x 1 m channel of
/// 48 x 24 patches, without gravity.
fsi::Scenario two_balls(double gap_m) {
  fsi::Scenario s = fsi::example1_scenario();
  s.name = "two_balls";
  fsi::BlockSpec b;
  b.x = {fsi::AxisPiece{-1.0, 1.0, 48, 0.0, 0.0}};
  b.y = {fsi::AxisPiece{-0.5, 0.5, 24, 0.0, 0.0}};
  s.mesh.blocks = {b};
  s.walls = {{{-1.0, -0.5}, {-1.0, 0.5}}, {{1.0, -0.5}, {1.0, 0.5}}};
  const double c = 0.25 + 0.5 * gap_m;
  s.bodies = {ball(-c, 0.0, 0.25), ball(c, 0.0, 0.25)};
  s.gravity_mps2 = {0.0, 0.0};
  return s;
}

TEST(Bodies, TheSceneDistanceIsThatOfTheNearestBody) {
  const fsi::BodySpec bodies[] = {ball(-0.5, 0.0, 0.2), ball(0.5, 0.0, 0.3)};
  EXPECT_DOUBLE_EQ(fsi::interface::scene_distance(bodies, {-0.5, 0.0}), -0.2);
  EXPECT_DOUBLE_EQ(fsi::interface::scene_distance(bodies, {0.0, 0.0}), 0.2);  // 0.3 to the left ball
  EXPECT_EQ(fsi::interface::nearest_body(bodies, {-0.1, 0.0}), 0);
  EXPECT_EQ(fsi::interface::nearest_body(bodies, {0.1, 0.0}), 1);
  // Equidistant (on the mirror line of two equal balls): the lower index, or the tie value asked for.
  const fsi::BodySpec mirrored[] = {ball(-0.5, 0.0, 0.2), ball(0.5, 0.0, 0.2)};
  EXPECT_EQ(fsi::interface::nearest_body(mirrored, {0.0, 0.1}), 0);
  EXPECT_EQ(fsi::interface::nearest_body(mirrored, {0.0, 0.1}, -1), -1);
  EXPECT_EQ(fsi::interface::nearest_body(mirrored, {1e-9, 0.1}, -1), 1);
}

TEST(Bodies, FileListsBodiesWithTheirOwnMaterials) {
  const fsi::Scenario s = fsi::parse_scenario(R"({
    "bodies": [{"center_m": [-0.5, 0.0], "radius_m": 0.2,
                "solid": {"density_kgpm3": 1500, "mu_pa": 5e4, "lambda_pa": 2e5}},
               {"center_m": [0.5, 0.0], "radius_m": 0.2, "initial_velocity_mps": [-0.1, 0]}],
    "solid": {"mu_pa": 3e5}})", "bodies.json");
  ASSERT_EQ(fsi::scene_bodies(s).size(), 2u);
  EXPECT_EQ(fsi::body_solid(s, s.bodies[0]).density_kgpm3, 1500.0);
  EXPECT_EQ(fsi::body_solid(s, s.bodies[0]).mu_pa, 5e4);
  EXPECT_EQ(fsi::body_solid(s, s.bodies[1]).mu_pa, 3e5);  // the scenario's solid
  const fsi::Scenario again = fsi::parse_scenario(fsi::to_json(s), "again.json");
  EXPECT_EQ(fsi::to_json(again), fsi::to_json(s));
  EXPECT_EQ(fsi::fingerprint(again), fsi::fingerprint(s));
  fsi::Scenario other = s;
  other.bodies[1].initial_velocity_mps.x = -0.2;
  EXPECT_NE(fsi::fingerprint(other), fsi::fingerprint(s));
  // One body: the one `body`, as before the list existed.
  EXPECT_EQ(fsi::scene_bodies(fsi::example1_scenario()).size(), 1u);
}

TEST(Bodies, OverlappingOrTooManyBodiesAreRefused) {
  try {
    fsi::parse_scenario(R"({"bodies": [{"center_m": [-0.2, 0.0], "radius_m": 0.25},
                                        {"center_m": [0.2, 0.0], "radius_m": 0.25}]})",
                        "overlap.json");
    FAIL() << "overlapping bodies were accepted";
  } catch (const fsi::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("overlap.json"), std::string::npos) << what;
    EXPECT_NE(what.find("/bodies/1/center_m"), std::string::npos) << what;
    EXPECT_NE(what.find("body1 reaches into body2"), std::string::npos) << what;
  }
  std::string nine = R"({"bodies": [)";
  for (int i = 0; i < 9; ++i) nine += std::string(i ? "," : "") + R"({"center_m": [)" + std::to_string(-0.8 + 0.2 * i) + R"(, 0.0], "radius_m": 0.05})";
  nine += "]}";
  try {
    fsi::parse_scenario(nine, "nine.json");
    FAIL() << "nine bodies were accepted";
  } catch (const fsi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/bodies"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0 to 8 entries"), std::string::npos) << e.what();
  }
  try {
    fsi::parse_scenario(R"({"body": {"radius_m": 0.3}, "bodies": [{"center_m": [0.0, 0.0], "radius_m": 0.2}]})",
                        "both.json");
    FAIL() << "body and bodies together were accepted";
  } catch (const fsi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("either body"), std::string::npos) << e.what();
  }
  // A body of its own material is checked like the scenario's.
  try {
    fsi::parse_scenario(R"({"bodies": [{"center_m": [0.0, 0.0], "radius_m": 0.2, "solid": {"mu_pa": -1}}]})",
                        "material.json");
    FAIL() << "a negative shear modulus was accepted";
  } catch (const fsi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/bodies/0/solid/mu_pa"), std::string::npos) << e.what();
  }
}

TEST(Bodies, PenaltyPushesTwoBodiesApartWithEqualAndOppositeForces) {
  fsi::Scenario s = two_balls(0.03);
  s.contact = {2000.0, 0.1};
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::PatchBuckets buckets(mesh);
  const auto bodies = fsi::scene_bodies(s);
  const fsi::fe::CutMesh cut =
      fsi::fe::build_cut_mesh(mesh, [&](const Vec2& x) { return fsi::interface::scene_distance(bodies, x); });
  const fsi::fe::QuadratureTable quadrature = fsi::fe::build_quadrature(cut);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * mesh.num_nodes());
  fsi::core::FsiSystem system(s, mesh);
  system.set_element_bodies(fsi::interface::element_bodies(bodies, cut, cut, buckets, zero));
  system.set_geometry(cut, quadrature, s.numerics.time_step_s);
  ASSERT_EQ(system.contact_force_per_body().size(), 2u);
  const Vec2 left = system.contact_force_per_body()[0], right = system.contact_force_per_body()[1];
  EXPECT_LT(left.x(), -10.0);  // pushed apart
  EXPECT_GT(right.x(), 10.0);
  EXPECT_NEAR(left.x(), -right.x(), 1e-9 * std::abs(left.x()));  // the mesh is mirror-symmetric
  EXPECT_NEAR(left.y(), 0.0, 1e-9 * std::abs(left.x()));
  // The gap between the discrete interfaces: 3 cm, up to the chords' sagitta.
  EXPECT_NEAR(system.min_body_gap(), 0.03, 2e-3);
  EXPECT_EQ(system.closest_bodies()[0] + system.closest_bodies()[1], 1);
  // Beyond dist_0 no force.
  s.contact.dist0_m = 0.02;
  fsi::core::FsiSystem far(s, mesh);
  far.set_element_bodies(fsi::interface::element_bodies(bodies, cut, cut, buckets, zero));
  far.set_geometry(cut, quadrature, s.numerics.time_step_s);
  EXPECT_EQ(far.max_contact_pressure(), 0.0);
}

TEST(Bodies, FunctionalsOfEachBody) {
  fsi::Scenario s = two_balls(0.2);
  s.bodies[1].radius_m = 0.2;
  const fsi::Engine engine(s);
  const fsi::Functionals& f = engine.state().functionals;
  ASSERT_EQ(f.bodies.size(), 2u);
  const double c = 0.25 + 0.1;
  EXPECT_NEAR(f.bodies[0].centroid_x_m, -c, 1e-3);
  EXPECT_NEAR(f.bodies[1].centroid_x_m, c, 1e-3);
  EXPECT_NEAR(f.bodies[0].solid_area_m2, std::numbers::pi * 0.25 * 0.25, 0.01 * std::numbers::pi * 0.25 * 0.25);
  EXPECT_NEAR(f.bodies[1].solid_area_m2, std::numbers::pi * 0.2 * 0.2, 0.01 * std::numbers::pi * 0.2 * 0.2);
  // The gap between them: 2 * 0.35 - 0.25 - 0.2 = 0.25 m; to the walls 0.4 and 0.45 m.
  EXPECT_NEAR(f.bodies[0].min_body_distance_m, 0.25, 2e-3);
  EXPECT_NEAR(f.bodies[1].min_body_distance_m, 0.25, 2e-3);
  EXPECT_NEAR(f.bodies[0].min_distance_m, 0.4, 2e-3);
  EXPECT_NEAR(f.bodies[1].min_distance_m, 0.45, 2e-3);
  EXPECT_LT(f.bodies[0].mass_error, 0.01);
  EXPECT_LT(f.bodies[1].mass_error, 0.01);
  // The scene's: the nearest wall, the largest mass error.
  EXPECT_DOUBLE_EQ(f.min_distance_m, f.bodies[0].min_distance_m);
  EXPECT_DOUBLE_EQ(f.mass_error, std::max(f.bodies[0].mass_error, f.bodies[1].mass_error));
  // The view knows which body each interface segment and solid triangle belongs to.
  const fsi::FieldView v = engine.view();
  ASSERT_EQ(v.interface_body.size(), v.interface.size());
  for (std::size_t i = 0; i < v.interface.size(); ++i)
    EXPECT_EQ(v.interface_body[i], v.interface[i].a.x < 0.0 ? 0 : 1);
  ASSERT_EQ(v.triangle_body.size(), v.triangles.size());
  for (std::size_t t = 0; t < v.triangles.size(); ++t)
    EXPECT_EQ(v.triangle_body[t] >= 0, v.triangle_phase[t] == fsi::Phase::solid);
  // VTU frames carry the body of each cell.
  const std::filesystem::path vtu = std::filesystem::path(FSI_BINARY_DIR) / "test_tmp" / "two_bodies.vtu";
  std::filesystem::create_directories(vtu.parent_path());
  fsi::io::write_vtu(vtu, v);
  std::ifstream in(vtu);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find("Name=\"body_id\"");
  ASSERT_NE(at, std::string::npos);
  const std::string values = text.substr(text.find('>', at) + 1, 200);
  EXPECT_NE(values.find("-1"), std::string::npos);  // fluid cells
}

TEST(Bodies, TwoBodiesThatTouchAreDetected) {
  const fsi::Scenario s = two_balls(0.3);
  const fsi::mesh::PatchMesh mesh = fsi::mesh::build_patch_mesh(s.mesh, s.walls);
  const fsi::fe::PatchBuckets buckets(mesh);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(fsi::kFieldsPerNode * mesh.num_nodes());
  const auto merged = [&](double centre_m) {
    const fsi::BodySpec bodies[] = {ball(-centre_m, 0.0, 0.25), ball(centre_m, 0.0, 0.25)};
    const fsi::fe::CutMesh cut =
        fsi::fe::build_cut_mesh(mesh, [&](const Vec2& x) { return fsi::interface::scene_distance(bodies, x); });
    return fsi::core::merged_bodies(cut, fsi::interface::element_bodies(bodies, cut, cut, buckets, zero));
  };
  EXPECT_FALSE(merged(0.4).has_value());  // 30 cm apart
  const auto touching = merged(0.24);     // overlapping by 2 cm: one solid region
  ASSERT_TRUE(touching.has_value());
  EXPECT_NE(touching->cause.find("body1 and body2 touch"), std::string::npos) << touching->cause;
  EXPECT_NEAR(touching->where_m.x, 0.0, 0.05);
}

TEST(Bodies, FunctionalsCsvHasColumnsForEachBody) {
  fsi::Functionals f;
  f.mass_error = 0.003;
  f.bodies.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    f.bodies[i].centroid_x_m = 0.1 * static_cast<double>(i) + 1.0 / 3.0;
    f.bodies[i].min_body_distance_m = 0.01 * static_cast<double>(i + 1);
    f.bodies[i].rotation_rad = -0.5 * static_cast<double>(i);
  }
  const std::string header = fsi::io::functionals_csv_header(true, 3);
  EXPECT_NE(header.find(",body1_centroid_x_m,"), std::string::npos) << header;
  EXPECT_NE(header.find(",body3_min_body_distance_m,"), std::string::npos) << header;
  EXPECT_TRUE(fsi::io::is_functionals_csv_header(header, true));
  fsi::StepReport report;
  report.newton_iterations = 4;
  report.converged = true;
  const std::string row = fsi::io::functionals_csv_row(7, 0.25, f, report);
  EXPECT_EQ(std::count(row.begin(), row.end(), ','), std::count(header.begin(), header.end(), ','));
  const fsi::io::FunctionalsCsvRow back = fsi::io::parse_functionals_csv_row(row);
  ASSERT_EQ(back.functionals.bodies.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.functionals.bodies[i].centroid_x_m, f.bodies[i].centroid_x_m);
    EXPECT_EQ(back.functionals.bodies[i].min_body_distance_m, f.bodies[i].min_body_distance_m);
    EXPECT_EQ(back.functionals.bodies[i].rotation_rad, f.bodies[i].rotation_rad);
  }
  EXPECT_EQ(back.newton_iterations, 4);
  EXPECT_TRUE(back.converged);
}

TEST(Bodies, CheckpointKeepsEachBodysReference) {
  fsi::State s;
  s.step = 3;
  s.solution = Eigen::VectorXd::LinSpaced(10, 0.0, 1.0);
  s.previous_solution = s.solution;
  s.body_references = {{0.125, -0.25, 0.5}, {-1.0 / 3.0, 0.0, -2.0}};
  const std::filesystem::path file = std::filesystem::path(FSI_BINARY_DIR) / "test_tmp" / "bodies.ckpt";
  std::filesystem::create_directories(file.parent_path());
  fsi::io::write_checkpoint(file, s, "print");
  const fsi::State back = fsi::io::read_checkpoint(file, "print");
  ASSERT_EQ(back.body_references.size(), 2u);
  EXPECT_EQ(back.body_references[1].offset_x_m, -1.0 / 3.0);
  EXPECT_EQ(back.body_references[1].rotation_rad, -2.0);
  EXPECT_EQ(back.body_references[0].offset_y_m, -0.25);
}

}  // namespace
