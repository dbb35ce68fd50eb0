#include "fsi/output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io_test_support.hpp"
#include "xml_check.hpp"

namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
  const fs::path dir = fsi::test::scratch_dir("vtu_writer") / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_text(const fs::path& file) { return fsi::test::read_file(file); }

/// Two triangles on the unit square, the second solid, with distinct nodal values.
fsi::FieldView square_view() {
  fsi::FieldView v;
  v.time_s = 0.25;
  v.step = 125;
  v.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  v.triangles = {{0, 1, 2}, {0, 2, 3}};
  v.triangle_phase = {fsi::Phase::fluid, fsi::Phase::solid};
  v.vx = {0.1, 0.2, 0.3, 1.0 / 3.0};
  v.vy = {-1, -2, -3, -4};
  v.p = {10, 20, 30, 40};
  v.ux = {1e-9, 2e-9, 3e-9, 4e-9};
  v.uy = {0, 0, 0, 5e-300};
  v.interface = {{{0.2, 0.5}, {0.5, 0.8}}, {{0.5, 0.8}, {0.8, 0.5}}, {{0.8, 0.5}, {0.2, 0.5}}};
  return v;
}

TEST(VtuWriter, WritesAWellFormedGridThatReadsBack) {
  const fs::path file = temp_dir("grid") / "frame.vtu";
  const fsi::FieldView v = square_view();
  fsi::io::write_vtu(file, v);
  const std::string xml = read_text(file);
  std::string problem;
  EXPECT_TRUE(fsi::test::tags_balanced(xml, &problem)) << problem;
  EXPECT_EQ(fsi::test::attribute(xml, "VTKFile", "type"), "UnstructuredGrid");
  EXPECT_EQ(fsi::test::attribute(xml, "Piece", "NumberOfPoints"), "4");
  EXPECT_EQ(fsi::test::attribute(xml, "Piece", "NumberOfCells"), "2");

  const auto arrays = fsi::test::data_arrays(xml);
  for (const char* name : {"vx", "vy", "p", "ux", "uy"}) {
    ASSERT_TRUE(arrays.count(name)) << name;
    EXPECT_EQ(arrays.at(name).size(), 4u) << name;
  }
  EXPECT_EQ(arrays.at("vx"), v.vx);  // bit-exact round trip of the text
  EXPECT_EQ(arrays.at("uy"), v.uy);
  EXPECT_EQ(arrays.at("velocity"),
            (std::vector<double>{0.1, -1, 0, 0.2, -2, 0, 0.3, -3, 0, 1.0 / 3.0, -4, 0}));
  EXPECT_EQ(arrays.at("displacement").size(), 12u);
  EXPECT_EQ(arrays.at("phase"), (std::vector<double>{0, 1}));
  EXPECT_EQ(arrays.at(""), (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));
  EXPECT_EQ(arrays.at("connectivity"), (std::vector<double>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(arrays.at("offsets"), (std::vector<double>{3, 6}));
  EXPECT_EQ(arrays.at("types"), (std::vector<double>{5, 5}));
  EXPECT_EQ(arrays.at("TimeValue"), (std::vector<double>{0.25}));
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

TEST(VtuWriter, WritesTheInterfaceAsLines) {
  const fs::path file = temp_dir("lines") / "interface.vtp";
  fsi::io::write_vtp_segments(file, square_view().interface, 0.25);
  const std::string xml = read_text(file);
  EXPECT_TRUE(fsi::test::tags_balanced(xml));
  EXPECT_EQ(fsi::test::attribute(xml, "VTKFile", "type"), "PolyData");
  EXPECT_EQ(fsi::test::attribute(xml, "Piece", "NumberOfPoints"), "6");
  EXPECT_EQ(fsi::test::attribute(xml, "Piece", "NumberOfLines"), "3");
  const auto arrays = fsi::test::data_arrays(xml);
  EXPECT_EQ(arrays.at("").size(), 18u);
  EXPECT_EQ(arrays.at("connectivity"), (std::vector<double>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(arrays.at("offsets"), (std::vector<double>{2, 4, 6}));
}

TEST(VtuWriter, EmptyViewGivesAnEmptyButValidGrid) {
  const fs::path file = temp_dir("empty") / "empty.vtu";
  fsi::io::write_vtu(file, fsi::FieldView{});
  const std::string xml = read_text(file);
  EXPECT_TRUE(fsi::test::tags_balanced(xml));
  EXPECT_EQ(fsi::test::attribute(xml, "Piece", "NumberOfPoints"), "0");
}

TEST(VtuWriter, FramesBuildAPvdSeries) {
  const fs::path dir = temp_dir("series");
  fsi::io::PvdSeries series(dir / "run.pvd");
  fsi::FieldView v = square_view();
  for (int i = 0; i < 3; ++i) {
    v.step = 10 * i;
    v.time_s = 0.02 * i;
    fsi::io::write_vtk_frame(dir, "ball", v, series);
    // After every frame the .pvd is complete and lists every frame so far.
    const std::string pvd = read_text(dir / "run.pvd");
    EXPECT_TRUE(fsi::test::tags_balanced(pvd));
    EXPECT_NE(pvd.find("file=\"ball_" +
                       std::string(i == 0   ? "000000"
                                   : i == 1 ? "000010"
                                            : "000020") +
                       ".vtu\""),
              std::string::npos)
        << pvd;
  }
  EXPECT_EQ(series.size(), 6u);
  EXPECT_TRUE(fs::exists(dir / "ball_000020.vtu"));
  EXPECT_TRUE(fs::exists(dir / "ball_interface_000020.vtp"));
  const std::string pvd = read_text(dir / "run.pvd");
  EXPECT_NE(pvd.find("timestep=\"0.04\" group=\"\" part=\"1\" file=\"ball_interface_000020.vtp\""),
            std::string::npos)
      << pvd;
}

TEST(VtuWriter, RejectsAnInconsistentView) {
  const fs::path file = temp_dir("bad") / "bad.vtu";
  fsi::FieldView v = square_view();
  v.p.pop_back();
  EXPECT_THROW(fsi::io::write_vtu(file, v), std::invalid_argument);
  v = square_view();
  v.triangles[1][2] = 4;
  EXPECT_THROW(fsi::io::write_vtu(file, v), std::invalid_argument);
  v = square_view();
  v.triangle_phase.pop_back();
  EXPECT_THROW(fsi::io::write_vtu(file, v), std::invalid_argument);
  EXPECT_FALSE(fs::exists(file));
}

}  // namespace
