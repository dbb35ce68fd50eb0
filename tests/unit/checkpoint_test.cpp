#include "io/checkpoint.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "fsi/error.hpp"
#include "io/fnv1a.hpp"
#include "io_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fsi::test::expect_input_error;

fs::path temp_file(const std::string& name) { return fsi::test::scratch_dir("checkpoint") / name; }

Eigen::VectorXd random_vector(std::mt19937_64& rng, int size) {
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  Eigen::VectorXd v(size);
  for (int i = 0; i < size; ++i) v[i] = u(rng);
  return v;
}

/// A state with awkward doubles: signed zero, subnormals, infinities, a NaN payload.
fsi::State sample_state() {
  std::mt19937_64 rng(42);
  fsi::State s;
  s.time_s = 1.0 / 3.0;
  s.step = 123456789012L;
  s.time_step_s = 2e-3;
  s.time_step_limit_s = 4e-3;
  s.solution = random_vector(rng, 5 * 40);
  s.solution[0] = -0.0;
  s.solution[1] = std::numeric_limits<double>::denorm_min();
  s.solution[2] = std::numeric_limits<double>::infinity();
  s.solution[3] = std::bit_cast<double>(std::uint64_t{0x7ff8000000000abcull});
  s.previous_solution = random_vector(rng, 5 * 40);
  s.corner_sign = {-1, 0, 1, 1, -1};
  s.previous_corner_sign = {};
  s.edge_cut = {-1.0, 0.25, 1.0 / 3.0};
  s.previous_edge_cut = {0.5};
  s.functionals = {1e-3, -0.6, 0.4, -0.4, 0.4, 0.01, -0.2, -0.3, 0.001, 0.5026, 1e-9, 0.0, 0.0, {}};
  s.reference_offset_x_m = 1.75;
  s.reference_offset_y_m = -0.5;
  s.reference_rotation_rad = -3.25;
  auto origin = std::make_shared<fsi::FactorizationOrigin>();
  origin->step_start = s;
  origin->iterate = random_vector(rng, 5 * 40);
  origin->time_step_s = 1e-3;
  s.factorization_origin = origin;
  return s;
}

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  // memcmp on the data of an empty vector (nullptr) would be undefined.
  return a.size() == b.size() &&
         (a.size() == 0 ||
          std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0);
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(Checkpoint, RoundTripIsBitIdentical) {
  const fs::path file = temp_file("round.ckpt");
  const fsi::State s = sample_state();
  fsi::io::write_checkpoint(file, s, "0123456789abcdef");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  const fsi::State back = fsi::io::read_checkpoint(file, "0123456789abcdef");
  EXPECT_EQ(std::bit_cast<std::uint64_t>(back.time_s), std::bit_cast<std::uint64_t>(s.time_s));
  EXPECT_EQ(back.step, s.step);
  EXPECT_EQ(back.time_step_s, s.time_step_s);
  EXPECT_EQ(back.time_step_limit_s, s.time_step_limit_s);
  EXPECT_TRUE(same_bits(back.solution, s.solution));
  EXPECT_TRUE(same_bits(back.previous_solution, s.previous_solution));
  EXPECT_EQ(back.corner_sign, s.corner_sign);
  EXPECT_EQ(back.previous_corner_sign, s.previous_corner_sign);
  EXPECT_EQ(back.edge_cut, s.edge_cut);
  EXPECT_EQ(back.previous_edge_cut, s.previous_edge_cut);
  ASSERT_TRUE(back.factorization_origin);
  EXPECT_TRUE(same_bits(back.factorization_origin->iterate, s.factorization_origin->iterate));
  EXPECT_TRUE(same_bits(back.factorization_origin->step_start.solution, s.solution));
  EXPECT_EQ(back.factorization_origin->time_step_s, 1e-3);
  EXPECT_EQ(back.reference_offset_x_m, 1.75);
  EXPECT_EQ(back.reference_offset_y_m, -0.5);
  EXPECT_EQ(back.reference_rotation_rad, -3.25);
  EXPECT_EQ(back.factorization_origin->step_start.reference_rotation_rad, -3.25);
  EXPECT_EQ(std::memcmp(&back.functionals, &s.functionals, sizeof s.functionals), 0);

  // Writing again over an existing checkpoint gives the same bytes.
  const std::string first = fsi::test::read_file(file);
  fsi::io::write_checkpoint(file, back, "0123456789abcdef");
  EXPECT_EQ(fsi::test::read_file(file), first);
}

TEST(Checkpoint, RefusesAnotherScenario) {
  const fs::path file = temp_file("other.ckpt");
  fsi::io::write_checkpoint(file, sample_state(), "aaaaaaaaaaaaaaaa");
  expect_input_error(
      [&] { fsi::io::read_checkpoint(file, "bbbbbbbbbbbbbbbb"); },
      {file.string(), "/fingerprint", "belongs to scenario fingerprint aaaaaaaaaaaaaaaa",
       "this engine runs bbbbbbbbbbbbbbbb"});
}

TEST(Checkpoint, RefusesAnotherVersion) {
  const fs::path file = temp_file("version.ckpt");
  fsi::io::write_checkpoint(file, sample_state(), "f");
  std::string bytes = fsi::test::read_file(file);
  bytes[8] = static_cast<char>(fsi::io::kCheckpointVersion + 1);
  write_bytes(file, bytes);
  expect_input_error([&] { fsi::io::read_checkpoint(file, "f"); },
                     {file.string(), "/version",
                      "format version " + std::to_string(fsi::io::kCheckpointVersion + 1),
                      "reads versions " + std::to_string(fsi::io::kOldestCheckpointVersion) + " to " +
                          std::to_string(fsi::io::kCheckpointVersion)});
}

/// `bytes` with another format version and a checksum that fits.
std::string with_version(std::string bytes, std::uint32_t version) {
  for (int i = 0; i < 4; ++i) bytes[8 + i] = static_cast<char>((version >> (8 * i)) & 0xff);
  bytes.resize(bytes.size() - 8);
  const std::uint64_t sum = fsi::io::fnv1a(bytes.data(), bytes.size());
  for (int i = 0; i < 8; ++i) bytes += static_cast<char>((sum >> (8 * i)) & 0xff);
  return bytes;
}

/// A checkpoint of `state` (without a factorization origin) in the layout of formats 3
/// to 6: before 7 without the count of the bodies' references (a u64 before the 11
/// functionals), before 6 also without the body's reference (3 f64 before that), before
/// 5 also without time_step_limit_s (the 8 bytes before the origin flag and the checksum).
std::string older_layout(fsi::State state, const std::string& fingerprint, std::uint32_t version) {
  state.factorization_origin.reset();
  const fs::path file = temp_file("older_layout.ckpt");
  fsi::io::write_checkpoint(file, state, fingerprint);
  std::string bytes = fsi::test::read_file(file);
  const std::size_t limit_at = bytes.size() - 8 - 4 - 8;
  if (version < 5) bytes = bytes.substr(0, limit_at) + bytes.substr(limit_at + 8);
  const std::size_t bodies_at = limit_at - 11 * 8 - 8;  // the count of State::body_references (none)
  if (version < 7) bytes = bytes.substr(0, bodies_at) + bytes.substr(bodies_at + 8);
  const std::size_t reference_at = bodies_at - 3 * 8;
  if (version < 6) bytes = bytes.substr(0, reference_at) + bytes.substr(reference_at + 3 * 8);
  return with_version(bytes, version);
}

TEST(Checkpoint, Format5LoadsWithTheScenariosOwnReference) {
  const fs::path file = temp_file("v5.ckpt");
  write_bytes(file, older_layout(sample_state(), "aaaaaaaaaaaaaaaa", 5));
  const fsi::State back = fsi::io::read_checkpoint(file, "aaaaaaaaaaaaaaaa");
  EXPECT_EQ(back.reference_offset_x_m, 0.0);
  EXPECT_EQ(back.reference_offset_y_m, 0.0);
  EXPECT_EQ(back.reference_rotation_rad, 0.0);
  EXPECT_EQ(back.time_step_limit_s, sample_state().time_step_limit_s);
  EXPECT_TRUE(same_bits(back.previous_solution, sample_state().previous_solution));
  EXPECT_EQ(back.functionals.mass_error, sample_state().functionals.mass_error);
}

TEST(Checkpoint, Format6LoadsAsOneBody) {
  const fs::path file = temp_file("v6.ckpt");
  write_bytes(file, older_layout(sample_state(), "aaaaaaaaaaaaaaaa", 6));
  const fsi::State back = fsi::io::read_checkpoint(file, "aaaaaaaaaaaaaaaa");
  EXPECT_TRUE(back.body_references.empty());
  EXPECT_EQ(back.reference_rotation_rad, sample_state().reference_rotation_rad);
  EXPECT_EQ(back.reference_offset_x_m, sample_state().reference_offset_x_m);
  EXPECT_EQ(back.functionals.mass_error, sample_state().functionals.mass_error);
}

TEST(Checkpoint, Formats3And4ContinueWithTheStepLimitAtTheirLastStep) {
  // Before format 5 the step-length controller had no memory.
  const fs::path file = temp_file("v4.ckpt");
  for (std::uint32_t version : {3u, 4u}) {
    write_bytes(file, older_layout(sample_state(), "aaaaaaaaaaaaaaaa", version));
    const fsi::State back = fsi::io::read_checkpoint(file, "aaaaaaaaaaaaaaaa");
    EXPECT_EQ(back.time_step_limit_s, sample_state().time_step_s) << version;
    EXPECT_TRUE(same_bits(back.solution, sample_state().solution)) << version;
    EXPECT_EQ(back.functionals.mass_error, sample_state().functionals.mass_error) << version;
  }
}

TEST(Checkpoint, AFormat3FileIsCheckedAgainstTheFormat3Fingerprint) {
  // Format 3 fingerprints covered the solver controls.
  const fs::path file = temp_file("v3.ckpt");
  const std::string v4 = older_layout(sample_state(), "aaaaaaaaaaaaaaaa", 4);
  write_bytes(file, v4);
  EXPECT_NO_THROW(fsi::io::read_checkpoint(file, "aaaaaaaaaaaaaaaa", "cccccccccccccccc"));
  write_bytes(file, with_version(v4, 3));
  EXPECT_EQ(fsi::io::read_checkpoint(file, "bbbbbbbbbbbbbbbb", "aaaaaaaaaaaaaaaa").step, sample_state().step);
  EXPECT_NO_THROW(fsi::io::read_checkpoint(file, "aaaaaaaaaaaaaaaa"));  // no format 3 one given
  expect_input_error([&] { fsi::io::read_checkpoint(file, "aaaaaaaaaaaaaaaa", "cccccccccccccccc"); },
                     {file.string(), "/fingerprint", "format 3", "this engine runs cccccccccccccccc",
                      "solver controls"});
  write_bytes(file, with_version(v4, 2));
  expect_input_error([&] { fsi::io::read_checkpoint(file, "aaaaaaaaaaaaaaaa", "aaaaaaaaaaaaaaaa"); },
                     {"/version", "format version 2"});
}

TEST(Checkpoint, RefusesTruncatedAndCorruptFiles) {
  const fs::path file = temp_file("cut.ckpt");
  fsi::io::write_checkpoint(file, sample_state(), "f");
  const std::string bytes = fsi::test::read_file(file);
  for (std::size_t keep :
       {std::size_t{0}, std::size_t{5}, std::size_t{12}, bytes.size() / 2, bytes.size() - 1}) {
    SCOPED_TRACE(keep);
    write_bytes(file, bytes.substr(0, keep));
    expect_input_error([&] { fsi::io::read_checkpoint(file, "f"); }, {file.string()});
  }
  write_bytes(file, bytes.substr(0, bytes.size() / 2));
  expect_input_error([&] { fsi::io::read_checkpoint(file, "f"); },
                     {"/checksum", "truncated or corrupt"});

  std::string flipped = bytes;
  flipped[flipped.size() / 2] ^= 0x10;
  write_bytes(file, flipped);
  expect_input_error([&] { fsi::io::read_checkpoint(file, "f"); }, {"checksum mismatch"});

  write_bytes(file, "{\"name\": \"not a checkpoint\"}");
  expect_input_error([&] { fsi::io::read_checkpoint(file, "f"); },
                     {file.string(), "/magic", "not an fsi checkpoint"});
  expect_input_error([&] { fsi::io::read_checkpoint(temp_file("missing.ckpt"), "f"); },
                     {"missing.ckpt", "cannot read checkpoint: no such file"});
}

TEST(Checkpoint, RefusesAnAbsurdCountEvenWithAValidChecksum) {
  // A writer bug or a forged file: the count must not trigger a huge allocation.
  const fs::path file = temp_file("count.ckpt");
  fsi::io::write_checkpoint(file, sample_state(), "f");
  std::string bytes = fsi::test::read_file(file);
  const std::size_t count_at = 8 + 4 + 4 + 1 + 8 + 8 + 8;  // magic, version, "f", t, step, k
  for (int i = 0; i < 8; ++i) bytes[count_at + i] = static_cast<char>(0x7f);
  bytes.resize(bytes.size() - 8);
  const std::uint64_t sum = fsi::io::fnv1a(bytes.data(), bytes.size());
  for (int i = 0; i < 8; ++i) bytes += static_cast<char>((sum >> (8 * i)) & 0xff);
  write_bytes(file, bytes);
  expect_input_error([&] { fsi::io::read_checkpoint(file, "f"); },
                     {"/solution", "values announced"});
}

TEST(Checkpoint, ReportsAnUnwritableTarget) {
  expect_input_error(
      [] { fsi::io::write_checkpoint("/nonexistent/dir/x.ckpt", sample_state(), "f"); },
      {"/nonexistent/dir/x.ckpt", "cannot write"});
}

}  // namespace
