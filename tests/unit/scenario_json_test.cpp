#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <string>

#include "fsi/error.hpp"
#include "fsi/scenario.hpp"
#include "io/fingerprint.hpp"
#include "io_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fsi::test::expect_input_error;

/// parse_scenario of `text` must fail with a message naming the origin, `key` and `why`.
void expect_parse_error(const std::string& text, const std::string& key,
                        std::initializer_list<std::string> why) {
  SCOPED_TRACE(text.substr(0, 200));
  std::initializer_list<std::string> head{"test.json", key};
  expect_input_error([&] { fsi::parse_scenario(text, "test.json"); }, head);
  expect_input_error([&] { fsi::parse_scenario(text, "test.json"); }, why);
}

fs::path temp_file(const std::string& name) {
  return fsi::test::scratch_dir("scenario_json") / name;
}

TEST(ScenarioJson, EmptyObjectIsExample1) {
  const fsi::Scenario s = fsi::parse_scenario("{}", "empty.json");
  EXPECT_EQ(fsi::to_json(s), fsi::to_json(fsi::example1_scenario()));
  EXPECT_EQ(s.source, fs::path("empty.json"));
  EXPECT_EQ(s.mesh.blocks.size(), 1u);
  EXPECT_EQ(s.numerics.time_step_s, 2.0e-3);
}

TEST(ScenarioJson, FileOverridesOnlyWhatItNames) {
  const fsi::Scenario s = fsi::parse_scenario(
      R"({"name": "soft", "solid": {"mu_pa": 5e4}, "numerics": {"failure_policy": "halve_step"}})",
      "soft.json");
  EXPECT_EQ(s.name, "soft");
  EXPECT_EQ(s.solid.mu_pa, 5e4);
  EXPECT_EQ(s.solid.lambda_pa, 8e5);  // untouched default
  EXPECT_EQ(s.numerics.failure_policy, fsi::FailurePolicy::halve_step);
  EXPECT_EQ(s.numerics.end_time_s, 5.0);
}

TEST(ScenarioJson, RoundTripsExactly) {
  fsi::Scenario s = fsi::example1_scenario();
  s.name = "odd_numbers";
  s.body.initial_velocity_mps = {0.1, -1.0 / 3.0};
  s.solid.mu_pa = 123456.789012345678;
  s.numerics.time_step_s = std::nextafter(1e-3, 1.0);
  s.numerics.failure_policy = fsi::FailurePolicy::stop_and_rollback;
  s.contact = {1600.0, 5e-3};
  s.output.field = "umag";
  s.output.mesh_overlay = true;
  s.output.range_min = -0.1;
  s.output.range_max = 0.7;
  const std::string text = fsi::to_json(s);
  const fsi::Scenario back = fsi::parse_scenario(text, "round.json");
  EXPECT_EQ(fsi::to_json(back), text);
  EXPECT_EQ(back.numerics.time_step_s, s.numerics.time_step_s);
  EXPECT_EQ(back.body.initial_velocity_mps.y, s.body.initial_velocity_mps.y);
  EXPECT_EQ(back.solid.mu_pa, s.solid.mu_pa);
  EXPECT_EQ(fsi::fingerprint(back), fsi::fingerprint(s));
}

TEST(ScenarioJson, WritesEveryField) {
  const std::string text = fsi::to_json(fsi::example1_scenario());
  for (const char* key :
       {"\"name\"", "\"blocks\"", "\"from_m\"", "\"corners\"", "\"refinements\"", "\"walls\"",
        "\"initial_velocity_mps\"", "\"viscosity_m2ps\"", "\"lambda_pa\"", "\"gravity_mps2\"",
        "\"failure_policy\"", "\"identity_gap_m\"", "\"cip_wall_film_factor\"", "\"cut_snap\"",
        "\"cut_snap_distance_m\"", "\"cavitation_pressure_pa\"", "\"dist0_m\"", "\"corners_as_walls\"", "\"range_max\"", "\"mesh_overlay\"", "\"y_right\""}) {
    EXPECT_NE(text.find(key), std::string::npos) << key;
  }
}

TEST(ScenarioJson, FingerprintIsStableAndSensitive) {
  // The chapter's numerics: the keys added later are at the value they count from.
  const fsi::Scenario a = fsi::example1_scenario(fsi::Method::chapter);
  const std::string f = fsi::fingerprint(a);
  EXPECT_EQ(f.size(), 16u);
  EXPECT_EQ(f.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_EQ(fsi::fingerprint(fsi::example1_scenario(fsi::Method::chapter)), f);
  EXPECT_NE(fsi::fingerprint(fsi::example1_scenario()), f);  // the fsi preset: other numerics

  fsi::Scenario renamed = a;  // name, source and output do not change the physics
  renamed.name = "other";
  renamed.source = "elsewhere.json";
  renamed.output.width_px = 640;
  renamed.output.field = "p";
  renamed.numerics.end_time_s = 7.5;  // a finished run may be continued to a later end
  EXPECT_EQ(fsi::fingerprint(renamed), f);

  fsi::Scenario b = a;
  b.numerics.time_step_s = 1e-3;
  EXPECT_NE(fsi::fingerprint(b), f);
  fsi::Scenario c = a;
  c.solid.mu_pa = std::nextafter(c.solid.mu_pa, 1e9);  // one ulp
  EXPECT_NE(fsi::fingerprint(c), f);
  fsi::Scenario d = a;
  d.mesh.blocks[0].y[0].patches = 33;
  EXPECT_NE(fsi::fingerprint(d), f);
  fsi::Scenario e = a;  // solver controls do not change the problem a state belongs to
  e.numerics.failure_policy = fsi::FailurePolicy::halve_step;
  e.numerics.newton_budget = 20;
  e.numerics.newton_rel_tol = 1e-6;
  e.numerics.newton_abs_tol = 1e-9;
  e.numerics.reuse_contraction = 0.5;
  e.numerics.max_halvings = 1;
  e.numerics.accept_flagged_reduction = 1e-4;
  e.numerics.time_step_max_doublings = 2;  // longer steps away from the walls: like halve_step
  e.numerics.time_step_wall_zone_m = 0.05;
  e.numerics.time_step_wall_zone_doublings = 1;
  e.numerics.accept_best_max_residual = 10.0;
  EXPECT_EQ(fsi::fingerprint(e), f);
  EXPECT_NE(fsi::io::fingerprint_v3(e), fsi::io::fingerprint_v3(a));  // format 3 covered them
  fsi::Scenario g = a;
  g.contact.min_dist_fraction = 0.2;
  EXPECT_NE(fsi::fingerprint(g), f);
  fsi::Scenario h = a;  // added later: counts only when set (pinned value below unchanged)
  h.numerics.cip_wall_film_factor = 1.0;
  EXPECT_NE(fsi::fingerprint(h), f);
  fsi::Scenario i = a;  // the same
  i.numerics.cut_snap = 3e-2;
  EXPECT_NE(fsi::fingerprint(i), f);
  fsi::Scenario j = a;  // the same
  j.numerics.cavitation_pressure_pa = -1e4;
  EXPECT_NE(fsi::fingerprint(j), f);
  fsi::Scenario k = a;  // the same
  k.numerics.cut_snap_distance_m = 8e-4;
  EXPECT_NE(fsi::fingerprint(k), f);
  fsi::Scenario l = a;  // contact added later: the same (the default, true, keeps the pin)
  l.contact.corners_as_walls = false;
  EXPECT_NE(fsi::fingerprint(l), f);
  fsi::Scenario m = a;  // the preset's name alone does not count, only the numerics
  m.method = fsi::Method::fsi;
  EXPECT_EQ(fsi::fingerprint(m), f);
}

TEST(ScenarioJson, FingerprintOfOldKeysIsTheSameAsOfDoublings) {
  // A checkpoint written with time_step_max_s = 8e-3 under format 3 still matches.
  const fsi::Scenario old_keys = fsi::parse_scenario(
      R"({"method": "chapter", "numerics": {"time_step_max_s": 8e-3, "time_step_wall_zone_max_s": 4e-3}})", "old.json");
  fsi::Scenario doublings = fsi::example1_scenario(fsi::Method::chapter);
  doublings.numerics.time_step_max_doublings = 2;
  doublings.numerics.time_step_wall_zone_doublings = 1;
  EXPECT_EQ(fsi::io::fingerprint_v3(old_keys), fsi::io::fingerprint_v3(doublings));
  EXPECT_EQ(fsi::fingerprint(old_keys), fsi::fingerprint(doublings));
}

TEST(ScenarioJson, FingerprintIsPinned) {
  // Changing this value invalidates every checkpoint written so far: bump the checkpoint
  // format version with it.
  // The chapter's numerics: the same values as before the presets existed.
  EXPECT_EQ(fsi::fingerprint(fsi::example1_scenario(fsi::Method::chapter)), "655e059f0ab3abd4");
  // Format 3's, which the oldest checkpoints carry.
  EXPECT_EQ(fsi::io::fingerprint_v3(fsi::example1_scenario(fsi::Method::chapter)), "039e20b201cdf25e");
}

TEST(ScenarioJson, RejectsBrokenJsonWithLineAndColumn) {
  expect_parse_error("{\n  \"name\": \"x\",\n  oops\n}", "", {"not valid JSON", "line 3, column"});
  expect_parse_error("", "", {"not valid JSON", "line 1"});
  expect_parse_error("{\"numerics\": {\"time_step_s\": 1e-3,}}", "", {"not valid JSON"});
  expect_parse_error("{} trailing", "", {"not valid JSON"});
  expect_parse_error("{\"name\": \"\xff\xfe\"}", "", {"not valid JSON"});
  expect_parse_error(std::string("{\"na\0me\": 1}", 12), "", {"not valid JSON"});
}

TEST(ScenarioJson, RejectsWrongTypes) {
  expect_parse_error("[]", "", {"must be an object"});
  expect_parse_error(R"({"numerics": {"time_step_s": "0.002"}})", "/numerics/time_step_s",
                     {"must be a finite number in (0, 1] s", "got string \"0.002\""});
  expect_parse_error(R"({"numerics": {"newton_budget": 8.5}})", "/numerics/newton_budget",
                     {"must be an integer in [1, 100]", "got number 8.5"});
  expect_parse_error(R"({"output": {"mesh_overlay": 1}})", "/output/mesh_overlay",
                     {"must be true or false"});
  expect_parse_error(R"({"body": {"center_m": [0]}})", "/body/center_m",
                     {"must be a point [x, y]", "[-1000, 1000] m"});
  expect_parse_error(R"({"body": [1, 2]})", "/body", {"must be an object"});
  expect_parse_error(R"({"walls": [[[0, 0], [1, null]]]})", "/walls/0/1/1",
                     {"must be a finite number in [-1000, 1000] m", "got null"});
  expect_parse_error(R"({"name": 7})", "/name", {"characters from", "got number 7"});
  expect_parse_error(R"({"mesh": {"blocks": {}}})", "/mesh/blocks",
                     {"must be an array of 1 to 64"});
}

TEST(ScenarioJson, RejectsUnknownAndDuplicateKeys) {
  expect_parse_error(R"({"numerics": {"time_stepp_s": 1e-3}})", "/numerics/time_stepp_s",
                     {"unknown key", "time_step_s, end_time_s"});
  expect_parse_error(R"({"nmae": "x"})", "/nmae", {"unknown key", "name, mesh"});
  expect_parse_error(R"({"source": "x"})", "/source", {"unknown key"});
  expect_parse_error(R"({"solid": {"mu_pa": 1e5, "mu_pa": 2e5}})", "/solid/mu_pa",
                     {"duplicate key"});
}

TEST(ScenarioJson, RejectsValuesOutOfRange) {
  expect_parse_error(R"({"numerics": {"time_step_s": -0.002}})", "/numerics/time_step_s",
                     {"must be a finite number in (0, 1] s, got -0.002"});
  expect_parse_error(R"({"numerics": {"newton_budget": 0}})", "/numerics/newton_budget",
                     {"[1, 100]", "got 0"});
  expect_parse_error(R"({"numerics": {"newton_budget": 101}})", "/numerics/newton_budget",
                     {"[1, 100]", "got 101"});
  expect_parse_error(R"({"numerics": {"newton_budget": 18446744073709551615}})",
                     "/numerics/newton_budget", {"[1, 100]"});
  expect_parse_error(R"({"numerics": {"newton_budget": -9223372036854775808}})",
                     "/numerics/newton_budget", {"[1, 100]"});
  expect_parse_error(R"({"numerics": {"accept_best_max_residual": -1}})", "/numerics/accept_best_max_residual",
                     {"[0, 1e+12] (0: no bound)", "got -1"});
  expect_parse_error(R"({"mesh": {"refinements": 5}})", "/mesh/refinements", {"[0, 4]", "got 5"});
  expect_parse_error(R"({"output": {"width_px": 8000}})", "/output/width_px", {"[16, 7680]"});
  expect_parse_error(R"({"output": {"height_px": 15}})", "/output/height_px", {"[16, 7680]"});
  expect_parse_error(R"({"output": {"field": "vz"}})", "/output/field",
                     {"one of \"vx\", \"vy\", \"vmag\", \"p\", \"umag\"", "got \"vz\""});
  expect_parse_error(R"({"numerics": {"failure_policy": "retry"}})", "/numerics/failure_policy",
                     {"one of \"accept_and_flag\"", "got \"retry\""});
  expect_parse_error(R"({"fluid": {"density_kgpm3": 0}})", "/fluid/density_kgpm3",
                     {"(0, 1e+05] kg/m^3", "got 0"});
  expect_parse_error(R"({"name": "a/b"})", "/name", {"characters from", "got \"a/b\""});
  expect_parse_error(R"({"numerics": {"time_step_s": 2e-3, "time_step_max_s": 1e-3}})", "/numerics/time_step_max_s",
                     {"old form of time_step_max_doublings", "[0.002, 0.128] s", "got number 0.001"});
  expect_parse_error(R"({"numerics": {"time_step_s": 1e-3, "time_step_max_s": 0.2}})", "/numerics/time_step_max_s",
                     {"[0.001, 0.064] s", "got number 0.2"});
  expect_parse_error(R"({"numerics": {"time_step_max_s": 8e-3, "time_step_max_doublings": 2}})",
                     "/numerics/time_step_max_s", {"replaced by time_step_max_doublings"});
  expect_parse_error(R"({"numerics": {"time_step_wall_zone_m": -1}})", "/numerics/time_step_wall_zone_m",
                     {"[0, 1000] m", "got -1"});
  expect_parse_error(R"({"numerics": {"time_step_max_doublings": 7}})", "/numerics/time_step_max_doublings",
                     {"[0, 6]", "got 7"});
  expect_parse_error(R"({"numerics": {"time_step_wall_zone_doublings": -1}})",
                     "/numerics/time_step_wall_zone_doublings", {"[0, 6]", "got -1"});
  expect_parse_error(R"({"name": ""})", "/name", {"1 to 128"});
}

TEST(ScenarioJson, RejectsNonFiniteAndHugeNumbers) {
  expect_parse_error(R"({"numerics": {"time_step_s": 1e999}})", "/numerics/time_step_s",
                     {"must be a finite number in (0, 1] s", "overflow"});
  expect_parse_error(R"({"gravity_mps2": [0, -1e400]})", "/gravity_mps2/1",
                     {"[-1000, 1000] m/s^2", "overflow"});
  expect_parse_error(R"({"solid": {"mu_pa": 1e300}})", "/solid/mu_pa",
                     {"(0, 1e+12] Pa", "got 1e+300"});
  expect_parse_error(R"({"numerics": {"end_time_s": NaN}})", "", {"not valid JSON"});
  expect_parse_error(R"({"numerics": {"end_time_s": Infinity}})", "", {"not valid JSON"});

  fsi::Scenario s = fsi::example1_scenario();
  s.source = "built.json";
  s.solid.mu_pa = std::numeric_limits<double>::quiet_NaN();
  expect_input_error([&] { fsi::validate(s); }, {"built.json", "/solid/mu_pa", "(0, ", "nan"});
  s = fsi::example1_scenario();
  s.body.center_m.x = std::numeric_limits<double>::infinity();
  expect_input_error([&] { fsi::validate(s); }, {"/body/center_m/0", "[-1000, 1000] m", "inf"});
}

TEST(ScenarioJson, RejectsMissingRequiredArrays) {
  expect_parse_error(R"({"mesh": {"blocks": []}})", "/mesh/blocks",
                     {"must have 1 to 64 entries, got 0"});
  expect_parse_error(R"({"mesh": {"blocks": [{"x": [], "y": []}]}})", "/mesh/blocks/0/x",
                     {"must have 1 to 64 entries, got 0"});
  expect_parse_error(R"({"mesh": {"blocks": [{"y": []}]}})", "/mesh/blocks/0/",
                     {"1 to 64 entries"});
  expect_parse_error(
      R"({"mesh": {"blocks": [{"x": [{"from_m": -1, "to_m": 1, "patches": 4}],
                               "y": [{"from_m": -1, "to_m": 1, "patches": 4, "first_m": 0, "last_m": 0}]}]}})",
      "/mesh/blocks/0/x/0/first_m", {"missing", "from_m, to_m, patches, first_m, last_m"});
}

/// A one-block mesh over [x0, x1] x [y0, y1] with uniform pieces, as JSON.
std::string box_mesh(const std::string& x_pieces, const std::string& y_pieces) {
  return R"({"mesh": {"blocks": [{"x": [)" + x_pieces + R"(], "y": [)" + y_pieces + "]}]}}";
}
std::string piece(double from, double to, int patches, double first = 0, double last = 0) {
  return "{\"from_m\": " + std::to_string(from) + ", \"to_m\": " + std::to_string(to) +
         ", \"patches\": " + std::to_string(patches) + ", \"first_m\": " + std::to_string(first) +
         ", \"last_m\": " + std::to_string(last) + "}";
}

TEST(ScenarioJson, AcceptsAUniformBox) {
  const fsi::Scenario s = fsi::parse_scenario(
      box_mesh(piece(-1, 1, 8), piece(-1, 0, 4) + ", " + piece(0, 0.5, 2)), "box.json");
  EXPECT_EQ(s.mesh.blocks[0].y.size(), 2u);
}

TEST(ScenarioJson, RejectsInconsistentGeometry) {
  const std::string y = piece(-1, 0.5, 8);
  expect_parse_error(box_mesh(piece(-1, 0, 4) + ", " + piece(0.1, 1, 4), y), "/mesh/blocks/0/x/1",
                     {"without a gap", "[-1, 0]", "[0.1, 1]"});
  expect_parse_error(box_mesh(piece(-1, 0.2, 4) + ", " + piece(0, 1, 4), y), "/mesh/blocks/0/x/1",
                     {"must not overlap"});
  expect_parse_error(box_mesh(piece(0.5, 0.5, 4), y), "/mesh/blocks/0/x/0/to_m",
                     {"must differ from from_m"});
  expect_parse_error(box_mesh(piece(-1, 1, 4, 0.1, 0.2), y), "/mesh/blocks/0/x/0/first_m",
                     {"mean patch size 0.5 m"});
  expect_parse_error(box_mesh(piece(-1, 1, 4, 3, 0.2), y), "/mesh/blocks/0/x/0/first_m",
                     {"[0, 2] m"});
  // The ball (r = 0.4 at the origin) must fit.
  expect_parse_error(box_mesh(piece(-0.3, 1, 8), y), "/body/radius_m",
                     {"lies inside the meshed domain", "bounding box [-0.3, 1] x [-1, 0.5] m", "got 0.4"});
  expect_parse_error(R"({"body": {"center_m": [5, 0]}})", "/body/center_m",
                     {"inside a mesh block", "[-1, 1] x [-1, 0.5]", "got (5, 0)"});
  expect_parse_error(R"({"walls": [[[0, -0.2], [1, -0.2]]]})", "/body/center_m",
                     {"clear of wall 0", "must exceed radius_m = 0.4 m", "got 0.2 m"});
  expect_parse_error(R"({"walls": [[[-1, -1], [1, -1]], [[0.5, 0.5], [0.5, 0.5]]]})", "/walls/1",
                     {"positive length", "(0.5, 0.5)"});
  expect_parse_error(R"({"mesh": {"refinements": 4, "blocks": [{"x": [)" + piece(-1, 1, 64) +
                         "], \"y\": [" + piece(-1, 0.5, 64) + "]}]}}",
                     "/mesh/refinements", {"at most 2e+06 nodes", "got 4198401"});
  expect_parse_error(R"({"numerics": {"time_step_s": 0.5, "end_time_s": 0.25}})",
                     "/numerics/time_step_s", {"must not exceed end_time_s = 0.25 s", "got 0.5"});
  expect_parse_error(R"({"numerics": {"blend_eps_patches": 3}})", "/numerics/blend_eps_patches",
                     {"smaller than blend_delta_patches = 3 patches", "got 3"});
  expect_parse_error(R"({"contact": {"gamma_c": 800}})", "/contact/dist0_m",
                     {"(0, 1000] m when gamma_c > 0", "got 0"});
  expect_parse_error(R"({"output": {"range_min": 1, "range_max": 0}})", "/output/range_min",
                     {"<= range_max = 0"});
}

TEST(ScenarioJson, ChecksMappedBlocks) {
  const std::string unit = piece(0, 1, 4);
  const std::string good =
      R"({"mesh": {"blocks": [{"x": [)" + unit + "], \"y\": [" + unit +
      R"(], "mapped": true, "corners": [[-1, -1], [1, -1], [1, 0.5], [-1, 0.5]]}]}})";
  EXPECT_NO_THROW(fsi::parse_scenario(good, "mapped.json"));
  const std::string clockwise =
      R"({"mesh": {"blocks": [{"x": [)" + unit + "], \"y\": [" + unit +
      R"(], "mapped": true, "corners": [[-1, -1], [-1, 0.5], [1, 0.5], [1, -1]]}]}})";
  expect_parse_error(clockwise, "/mesh/blocks/0/corners", {"counter-clockwise"});
  const std::string wide =
      R"({"mesh": {"blocks": [{"x": [)" + piece(0, 2, 4) + "], \"y\": [" + unit +
      R"(], "mapped": true, "corners": [[-1, -1], [1, -1], [1, 0.5], [-1, 0.5]]}]}})";
  expect_parse_error(wide, "/mesh/blocks/0/x", {"must cover [0, 1]", "got [0, 2]"});
}

TEST(ScenarioJson, ChecksTheRightSideRowsOfAFanBlock) {
  const std::string unit = piece(0, 1, 4);
  auto fan = [&](const std::string& y_right) {
    return R"({"mesh": {"blocks": [{"x": [)" + unit + "], \"y\": [" + unit + R"(], "mapped": true,)" +
           R"( "corners": [[-1, -1], [1, -1], [1, 0.5], [-1, 0.5]], "y_right": [)" + y_right + "]}]}}";
  };
  const std::string graded = R"({"from_m": 0, "to_m": 1, "patches": 4, "first_m": 0.1, "last_m": 0.4})";
  const fsi::Scenario with = fsi::parse_scenario(fan(graded), "fan.json");
  EXPECT_EQ(with.mesh.blocks[0].y_right.size(), 1u);
  // Without right-side rows (or with the left side's) it is the plain mapped block.
  const std::string plain = fsi::fingerprint(fsi::parse_scenario(fan(""), "fan.json"));
  EXPECT_NE(fsi::fingerprint(with), plain);
  expect_parse_error(fan(piece(0, 1, 5)), "/mesh/blocks/0/y_right", {"as many patches as y (4", "got 5"});
  expect_parse_error(fan(piece(0, 2, 4)), "/mesh/blocks/0/y_right", {"must cover [0, 1]", "got [0, 2]"});
  // An axis-aligned block has the same rows on both sides.
  const std::string box = R"({"mesh": {"blocks": [{"x": [)" + piece(-1, 1, 4) + "], \"y\": [" + piece(-1, 0.5, 4) +
                          "], \"y_right\": [" + unit + "]}]}}";
  expect_parse_error(box, "/mesh/blocks/0/y_right", {"only allowed in a mapped block"});
}

TEST(ScenarioJson, SurvivesDeepNestingAndHugeInput) {
  const std::string deep = std::string(10000, '[') + std::string(10000, ']');
  expect_parse_error(deep, "", {"nested deeper than 32 levels"});
  const std::string deep_object = R"({"mesh": )" + std::string(100000, '[');
  expect_parse_error(deep_object, "/mesh", {"nested deeper than"});

  std::string huge = "{\"name\": \"" + std::string((1u << 20) + 10, 'a') + "\"}";
  expect_parse_error(huge, "", {"must be at most 1048576 bytes"});

  const fs::path big = temp_file("big.json");
  {
    std::ofstream out(big, std::ios::binary);
    out.seekp(100 * 1024 * 1024);  // a 100 MB sparse file: never read into memory
    out.put('}');
  }
  expect_input_error([&] { fsi::load_scenario(big); },
                     {"big.json", "scenario file is 104857601 bytes, must be at most 1048576 bytes"});
  fs::remove(big);
}

TEST(ScenarioJson, LoadReportsFileProblems) {
  expect_input_error([] { fsi::load_scenario("/nonexistent/nothing.json"); },
                     {"/nonexistent/nothing.json", "cannot read scenario: no such file"});
  expect_input_error([] { fsi::load_scenario(FSI_BINARY_DIR); }, {"not a regular file"});
  const fs::path file = temp_file("typo.json");
  std::ofstream(file) << R"({"numerics": {"end_tme_s": 2}})";
  expect_input_error([&] { fsi::load_scenario(file); },
                     {file.string(), "/numerics/end_tme_s", "unknown key", "end_time_s"});
}

TEST(ScenarioJson, ValidateNamesTheSourceOfABuiltScenario) {
  fsi::Scenario s = fsi::example1_scenario();
  EXPECT_NO_THROW(fsi::validate(s));
  s.source = "my_program";
  s.numerics.newton_budget = 0;
  expect_input_error([&] { fsi::validate(s); },
                     {"my_program", "/numerics/newton_budget", "[1, 100]", "got 0"});
  s = fsi::example1_scenario();
  s.mesh.blocks.clear();
  expect_input_error([&] { fsi::validate(s); }, {"/mesh/blocks", "1 to 64 entries, got 0"});
  s = fsi::example1_scenario();
  s.output.field = "speed";
  expect_input_error([&] { fsi::validate(s); }, {"/output/field", "\"vmag\"", "got \"speed\""});
  s = fsi::example1_scenario();
  s.numerics.failure_policy = static_cast<fsi::FailurePolicy>(7);
  expect_input_error([&] { fsi::validate(s); }, {"/numerics/failure_policy", "enum value 7"});
}

}  // namespace

namespace {

// An L-shaped domain: [-1, 1] x [-1, 0] plus [-1, 0] x [0, 1] (two blocks, node to node).
fsi::Scenario l_shaped(fsi::Point2 center) {
  fsi::Scenario s = fsi::example1_scenario();
  fsi::BlockSpec lower, upper;
  lower.x = {fsi::AxisPiece{-1, 0, 4, 0, 0}, fsi::AxisPiece{0, 1, 4, 0, 0}};
  lower.y = {fsi::AxisPiece{-1, 0, 4, 0, 0}};
  upper.x = {fsi::AxisPiece{-1, 0, 4, 0, 0}};
  upper.y = {fsi::AxisPiece{0, 1, 4, 0, 0}};
  s.mesh.blocks = {lower, upper};
  s.body.center_m = center;
  s.body.radius_m = 0.3;
  return s;
}

TEST(ScenarioValidate, BallMustLieInTheUnionOfTheBlocks) {
  EXPECT_NO_THROW(fsi::validate(l_shaped({-0.5, 0.2})));  // crosses the block border y = 0
  EXPECT_NO_THROW(fsi::validate(l_shaped({0.5, -0.5})));
  // Inside the bounding box, centre inside a block, but reaching into the missing corner.
  expect_input_error([] { fsi::validate(l_shaped({0.2, -0.2})); },
                     {"/body/radius_m", "inside the meshed domain", "outside every block"});
}

}  // namespace

namespace {

// ---- the method presets -------------------------------------------------------------

TEST(ScenarioMethod, FsiIsTheDefaultAndDiffersFromTheChapterWhereListed) {
  const fsi::Scenario s = fsi::parse_scenario("{}", "empty.json");
  EXPECT_EQ(s.method, fsi::Method::fsi);
  const fsi::NumericsSpec& n = s.numerics;
  EXPECT_EQ(n.time_step_max_doublings, 3);
  EXPECT_EQ(n.time_step_wall_zone_doublings, 2);
  EXPECT_EQ(n.time_error_tolerance_m, 1e-5);
  EXPECT_EQ(n.newton_rel_tol, 1e-6);
  EXPECT_EQ(n.reuse_contraction, 0.5);
  EXPECT_EQ(n.newton_budget, 12);
  EXPECT_EQ(n.cavitation_pressure_pa, -1e4);
  EXPECT_EQ(n.backflow_beta, 1.0);
  EXPECT_EQ(n.rereference_angle_rad, 0.05);
  EXPECT_EQ(n.time_step_max_s(), 1.6e-2);
  EXPECT_EQ(n.time_step_wall_zone_max_s(), 8e-3);
  // The member initialisers are the fsi preset.
  fsi::Scenario a = fsi::example1_scenario();
  fsi::Scenario b = a;
  a.numerics = fsi::NumericsSpec{};
  b.numerics = fsi::numerics_for(fsi::Method::fsi);
  EXPECT_EQ(fsi::to_json(a), fsi::to_json(b));
}

TEST(ScenarioMethod, ChapterIsTheChaptersNumerics) {
  const fsi::Scenario s = fsi::parse_scenario(R"({"method": "chapter"})", "chapter.json");
  EXPECT_EQ(s.method, fsi::Method::chapter);
  const fsi::NumericsSpec& n = s.numerics;
  EXPECT_EQ(n.time_step_max_doublings, 0);
  EXPECT_EQ(n.time_step_wall_zone_doublings, 0);
  EXPECT_EQ(n.time_error_tolerance_m, 0.0);
  EXPECT_EQ(n.newton_rel_tol, 1e-8);
  EXPECT_EQ(n.reuse_contraction, 0.2);
  EXPECT_EQ(n.newton_budget, 8);
  EXPECT_EQ(n.cavitation_pressure_pa, 0.0);
  EXPECT_EQ(n.backflow_beta, 0.0);
  EXPECT_EQ(n.rereference_angle_rad, 0.0);
  EXPECT_EQ(n.cut_align_fraction, 0.0);
  EXPECT_EQ(n.failure_policy, fsi::FailurePolicy::accept_and_flag);
  EXPECT_EQ(n.time_step_max_s(), 0.0);
  EXPECT_EQ(n.time_step_wall_zone_max_s(), 0.0);
  // Everything else as the fsi preset.
  fsi::NumericsSpec same = fsi::numerics_for(fsi::Method::fsi);
  same.time_step_max_doublings = 0;
  same.time_step_wall_zone_doublings = 0;
  same.time_error_tolerance_m = 0.0;
  same.newton_rel_tol = 1e-8;
  same.reuse_contraction = 0.2;
  same.newton_budget = 8;
  same.cavitation_pressure_pa = 0.0;
  same.backflow_beta = 0.0;
  same.rereference_angle_rad = 0.0;
  same.cut_align_fraction = 0.0;
  same.failure_policy = fsi::FailurePolicy::accept_and_flag;
  fsi::Scenario expected = fsi::example1_scenario(fsi::Method::chapter);
  expected.numerics = same;
  expected.source = s.source;
  EXPECT_EQ(fsi::to_json(s), fsi::to_json(expected));
}

TEST(ScenarioMethod, KeysGivenWinOverThePresetWhereverMethodStands) {
  const fsi::Scenario s = fsi::parse_scenario(
      R"({"numerics": {"backflow_beta": 0.5, "newton_budget": 20}, "method": "chapter"})", "mixed.json");
  EXPECT_EQ(s.method, fsi::Method::chapter);
  EXPECT_EQ(s.numerics.backflow_beta, 0.5);
  EXPECT_EQ(s.numerics.newton_budget, 20);
  EXPECT_EQ(s.numerics.cavitation_pressure_pa, 0.0);  // the chapter's
  const fsi::Scenario f = fsi::parse_scenario(R"({"numerics": {"cavitation_pressure_pa": 0}})", "f.json");
  EXPECT_EQ(f.numerics.cavitation_pressure_pa, 0.0);
  EXPECT_EQ(f.numerics.backflow_beta, 1.0);  // the fsi preset's
}

TEST(ScenarioMethod, RoundTripsWithItsMethod) {
  for (const fsi::Method m : {fsi::Method::fsi, fsi::Method::chapter}) {
    fsi::Scenario s = fsi::example1_scenario(m);
    s.numerics.backflow_beta = 0.25;
    const std::string text = fsi::to_json(s);
    EXPECT_NE(text.find(m == fsi::Method::fsi ? R"("method": "fsi")" : R"("method": "chapter")"), std::string::npos);
    const fsi::Scenario back = fsi::parse_scenario(text, "back.json");
    EXPECT_EQ(back.method, m);
    EXPECT_EQ(fsi::to_json(back), text);
  }
}

TEST(ScenarioMethod, BadMethodNamesFileKeyAndAllowedValues) {
  expect_parse_error(R"({"method": "book"})", "/method", {"one of \"fsi\", \"chapter\"", "got \"book\""});
  expect_parse_error(R"({"method": 1})", "/method", {"one of \"fsi\", \"chapter\"", "got number 1"});
}

TEST(ScenarioMethod, OldStepLimitKeysConvertToDoublings) {
  // floor(log2(max / time_step_s)): 8e-3 / 2e-3 = 4 -> 2; 6e-3 / 2e-3 = 3 -> 1; 0 -> off.
  fsi::Scenario s = fsi::parse_scenario(
      R"({"numerics": {"time_step_max_s": 8e-3, "time_step_wall_zone_max_s": 6e-3}})", "old.json");
  EXPECT_EQ(s.numerics.time_step_max_doublings, 2);
  EXPECT_EQ(s.numerics.time_step_wall_zone_doublings, 1);
  // The file's time_step_s, wherever it stands: 2e-3 / 5e-4 = 4 -> 2.
  s = fsi::parse_scenario(R"({"numerics": {"time_step_max_s": 2e-3, "time_step_s": 5e-4}})", "old.json");
  EXPECT_EQ(s.numerics.time_step_max_doublings, 2);
  EXPECT_EQ(s.numerics.time_step_max_s(), 2e-3);
  // The wall zone's limit is at most the one outside: the fsi default 2 under 1 acts as 1.
  EXPECT_EQ(s.numerics.time_step_wall_zone_doublings, 2);
  s.numerics.time_step_max_doublings = 1;
  EXPECT_EQ(s.numerics.time_step_wall_zone_max_s(), 1e-3);
  s.numerics.time_step_max_doublings = 0;
  EXPECT_EQ(s.numerics.time_step_wall_zone_max_s(), 0.0);
  s = fsi::parse_scenario(R"({"numerics": {"time_step_max_s": 0, "time_step_wall_zone_max_s": 0}})", "old.json");
  EXPECT_EQ(s.numerics.time_step_max_doublings, 0);
  EXPECT_EQ(s.numerics.time_step_wall_zone_doublings, 0);
  // Rounding: 1.6e-2 / 2e-3 is 8 up to the last bit.
  s = fsi::parse_scenario(R"({"numerics": {"time_step_max_s": 1.6e-2}})", "old.json");
  EXPECT_EQ(s.numerics.time_step_max_doublings, 3);
  // Written back in the new keys only.
  const std::string text = fsi::to_json(s);
  EXPECT_EQ(text.find("time_step_max_s"), std::string::npos);
  EXPECT_NE(text.find(R"("time_step_max_doublings": 3)"), std::string::npos);
}

}  // namespace
