#pragma once
// Helpers shared by the io tests: scratch folders under the build tree, whole-file
// reads, and the InputError message check.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <string>

#include "fsi/error.hpp"

namespace fsi::test {

/// `<build>/test_tmp/<suite>`, created if missing. Each test uses its own file names,
/// so tests of one suite may run in parallel (ctest -j).
inline std::filesystem::path scratch_dir(const std::string& suite) {
  const std::filesystem::path dir = std::filesystem::path(FSI_BINARY_DIR) / "test_tmp" / suite;
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs `action`, which must throw fsi::InputError whose message contains every piece.
inline void expect_input_error(const std::function<void()>& action,
                               std::initializer_list<std::string> pieces) {
  try {
    action();
    ADD_FAILURE() << "no InputError; expected one mentioning \"" << *pieces.begin() << "\"";
  } catch (const fsi::InputError& e) {
    const std::string message = e.what();
    for (const std::string& piece : pieces) {
      EXPECT_NE(message.find(piece), std::string::npos)
          << "message lacks \"" << piece << "\":\n  " << message;
    }
  }
}

}  // namespace fsi::test
