#include "fsi/output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io_test_support.hpp"
#include "xml_check.hpp"

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) { return fsi::test::read_file(file); }

TEST(PvdSeries, IsCompleteAfterEveryAdd) {
  const fs::path dir = fsi::test::scratch_dir("pvd_series");
  fs::remove(dir / "run.pvd");
  fsi::io::PvdSeries series(dir / "run.pvd");
  EXPECT_FALSE(fs::exists(series.file()));  // nothing written before the first frame
  series.add(0.0, "a_0.vtu");
  series.add(1.0 / 3.0, fs::path("sub") / "a&b.vtu", 1);
  const std::string pvd = read_text(series.file());
  EXPECT_TRUE(fsi::test::tags_balanced(pvd));
  EXPECT_EQ(fsi::test::attribute(pvd, "VTKFile", "type"), "Collection");
  EXPECT_NE(pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"a_0.vtu\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0.3333333333333333\" group=\"\" part=\"1\" "
                     "file=\"sub/a&amp;b.vtu\""),
            std::string::npos)
      << pvd;
}

TEST(PvdSeries, EscapesXmlSpecialCharacters) {
  EXPECT_EQ(fsi::io::xml_escaped("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&apos;");
  EXPECT_EQ(fsi::io::xml_escaped("plain"), "plain");
}

}  // namespace
