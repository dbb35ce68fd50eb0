// Checkpoint files: State <-> bytes, with a checksum and an atomic write.
#include "io/checkpoint.hpp"

#include <array>
#include <bit>
#include <string_view>
#include <vector>

#include "fsi/error.hpp"
#include "io/atomic_file.hpp"
#include "io/bounded_file.hpp"
#include "io/fnv1a.hpp"

namespace fsi::io {
namespace {

constexpr std::array<char, 8> kMagic{'F', 'S', 'I', '-', 'C', 'K', 'P', 'T'};
/// Longer fingerprints are not ours (fsi::fingerprint gives 16 hex digits).
constexpr std::uint32_t kMaxFingerprintBytes = 256;
/// Larger files are not checkpoints of a mesh validate() accepts (2e6 nodes).
constexpr std::size_t kMaxCheckpointBytes = std::size_t{4} << 30;

/// The functionals in file order.
std::array<double*, 11> functional_fields(Functionals& f) {
  return {&f.min_distance_m, &f.bottom_y_m,    &f.top_y_m,      &f.left_x_m,
          &f.right_x_m,      &f.centroid_x_m,  &f.centroid_y_m, &f.mean_vy_mps,
          &f.mean_vx_mps,    &f.solid_area_m2, &f.mass_error};
}

/// Appends little-endian values to a byte buffer.
class Writer {
 public:
  std::string bytes;

  void u32(std::uint32_t v) { little_endian(v, 4); }
  void u64(std::uint64_t v) { little_endian(v, 8); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void text(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    bytes += s;
  }
  void vector(const Eigen::VectorXd& v) {
    u64(static_cast<std::uint64_t>(v.size()));
    for (Eigen::Index i = 0; i < v.size(); ++i) f64(v[i]);
  }
  void vector(const std::vector<double>& v) {
    u64(static_cast<std::uint64_t>(v.size()));
    for (double x : v) f64(x);
  }
  void signs(const std::vector<std::int8_t>& v) {
    u64(static_cast<std::uint64_t>(v.size()));
    for (std::int8_t x : v) bytes += static_cast<char>(x);
  }

 private:
  void little_endian(std::uint64_t v, int count) {
    for (int i = 0; i < count; ++i) bytes += static_cast<char>((v >> (8 * i)) & 0xffu);
  }
};

/// Reads little-endian values from a byte buffer; every read is bounds-checked.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  std::uint32_t u32(const char* what) { return static_cast<std::uint32_t>(little_endian(4, what)); }
  std::uint64_t u64(const char* what) { return little_endian(8, what); }
  double f64(const char* what) { return std::bit_cast<double>(u64(what)); }
  std::string raw(std::size_t size, const char* what) {
    need(size, what);
    std::string s(bytes_.substr(offset_, size));
    offset_ += size;
    return s;
  }
  Eigen::VectorXd vector(const char* what) {
    const std::uint64_t count = u64(what);
    // Checked before allocating: a corrupt count must not ask for terabytes.
    if (count > (bytes_.size() - offset_) / 8) {
      throw InputError(file_, std::string("/") + what,
                       "truncated or corrupt: " + std::to_string(count) +
                           " values announced, only " +
                           std::to_string((bytes_.size() - offset_) / 8) + " fit in the file");
    }
    Eigen::VectorXd v(static_cast<Eigen::Index>(count));
    for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = f64(what);
    return v;
  }
  std::vector<double> doubles(const char* what) {
    const Eigen::VectorXd v = vector(what);
    return std::vector<double>(v.data(), v.data() + v.size());
  }
  std::vector<std::int8_t> signs(const char* what) {
    const std::uint64_t count = u64(what);
    if (count > bytes_.size() - offset_) {
      throw InputError(file_, std::string("/") + what,
                       "truncated or corrupt: " + std::to_string(count) + " signs announced");
    }
    std::vector<std::int8_t> v(count);
    for (std::uint64_t i = 0; i < count; ++i) v[i] = static_cast<std::int8_t>(bytes_[offset_ + i]);
    offset_ += count;
    return v;
  }
  std::size_t offset() const { return offset_; }

 private:
  void need(std::size_t size, const char* what) {
    if (size > bytes_.size() - offset_) {
      throw InputError(file_, std::string("/") + what,
                       "truncated: needs " + std::to_string(size) + " bytes at offset " +
                           std::to_string(offset_) + ", the file has " +
                           std::to_string(bytes_.size()) + " bytes");
    }
  }
  std::uint64_t little_endian(int count, const char* what) {
    need(static_cast<std::size_t>(count), what);
    std::uint64_t v = 0;
    for (int i = 0; i < count; ++i) {
      v |= std::uint64_t{static_cast<unsigned char>(bytes_[offset_ + i])} << (8 * i);
    }
    offset_ += static_cast<std::size_t>(count);
    return v;
  }

  std::string_view bytes_;
  const std::string& file_;
  std::size_t offset_ = 0;
};

/// The level data of a state (everything but functionals and origin).
void write_levels(Writer& w, const State& state) {
  w.f64(state.time_s);
  w.u64(static_cast<std::uint64_t>(state.step));
  w.f64(state.time_step_s);
  w.vector(state.solution);
  w.vector(state.previous_solution);
  w.signs(state.corner_sign);
  w.signs(state.previous_corner_sign);
  w.vector(state.edge_cut);
  w.vector(state.previous_edge_cut);
  w.f64(state.reference_offset_x_m);
  w.f64(state.reference_offset_y_m);
  w.f64(state.reference_rotation_rad);
  w.u64(state.body_references.size());
  for (const State::BodyReference& b : state.body_references) {
    w.f64(b.offset_x_m);
    w.f64(b.offset_y_m);
    w.f64(b.rotation_rad);
  }
}

void read_levels(Reader& r, State& state, std::uint32_t version) {
  state.time_s = r.f64("time_s");
  state.step = static_cast<long>(r.u64("step"));
  state.time_step_s = r.f64("time_step_s");
  state.solution = r.vector("solution");
  state.previous_solution = r.vector("previous_solution");
  state.corner_sign = r.signs("corner_sign");
  state.previous_corner_sign = r.signs("previous_corner_sign");
  state.edge_cut = r.doubles("edge_cut");
  state.previous_edge_cut = r.doubles("previous_edge_cut");
  if (version >= 6) {  // before: never re-referenced
    state.reference_offset_x_m = r.f64("reference_offset_x_m");
    state.reference_offset_y_m = r.f64("reference_offset_y_m");
    state.reference_rotation_rad = r.f64("reference_rotation_rad");
  }
  if (version >= 7) {  // before: one body
    const std::uint64_t bodies = r.u64("body_references");
    // Bounded allocation; a count that does not match the bytes fails the reads or the
    // "unexpected bytes" check below.
    state.body_references.resize(std::min<std::uint64_t>(bodies, 64));
    for (State::BodyReference& b : state.body_references) {
      b.offset_x_m = r.f64("body_references/offset_x_m");
      b.offset_y_m = r.f64("body_references/offset_y_m");
      b.rotation_rad = r.f64("body_references/rotation_rad");
    }
  }
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const State& state,
                      const std::string& scenario_fingerprint) {
  Writer w;
  w.bytes.reserve(128 + 8 * static_cast<std::size_t>(state.solution.size() * 5));
  w.bytes.append(kMagic.data(), kMagic.size());
  w.u32(kCheckpointVersion);
  w.text(scenario_fingerprint);
  write_levels(w, state);
  Functionals functionals = state.functionals;
  for (const double* value : functional_fields(functionals)) w.f64(*value);
  w.f64(state.time_step_limit_s);
  // Where the reused LU factorization came from (bit-identical continuation).
  const FactorizationOrigin* origin = state.factorization_origin.get();
  w.u32(origin ? 1 : 0);
  if (origin) {
    write_levels(w, origin->step_start);
    w.vector(origin->iterate);
    w.f64(origin->time_step_s);
  }
  w.u64(fnv1a(w.bytes.data(), w.bytes.size()));

  write_file_atomically(file, w.bytes);
}

State read_checkpoint(const std::filesystem::path& file, const std::string& expected_fingerprint,
                      const std::string& expected_v3_fingerprint) {
  const std::string name = file.string();
  const std::string bytes = read_bounded_file(file, kMaxCheckpointBytes, "checkpoint");

  if (bytes.size() < kMagic.size() ||
      bytes.compare(0, kMagic.size(), kMagic.data(), kMagic.size()) != 0) {
    throw InputError(name, "/magic", "not an fsi checkpoint (it must start with \"FSI-CKPT\")");
  }
  Reader head(bytes, name);
  head.raw(kMagic.size(), "magic");
  const std::uint32_t version = head.u32("version");
  if (version < kOldestCheckpointVersion || version > kCheckpointVersion) {
    throw InputError(name, "/version",
                     "checkpoint format version " + std::to_string(version) +
                         ", this engine reads versions " + std::to_string(kOldestCheckpointVersion) +
                         " to " + std::to_string(kCheckpointVersion));
  }
  // The checksum covers everything, so check it before trusting any count or value.
  if (bytes.size() < head.offset() + 8) {
    throw InputError(name, "/checksum",
                     "truncated: the file has only " + std::to_string(bytes.size()) + " bytes");
  }
  const std::size_t body = bytes.size() - 8;
  Reader tail(std::string_view(bytes).substr(body), name);
  if (tail.u64("checksum") != fnv1a(bytes.data(), body)) {
    throw InputError(name, "/checksum",
                     "checksum mismatch: the file is truncated or corrupt (" +
                         std::to_string(bytes.size()) + " bytes)");
  }

  Reader r(std::string_view(bytes).substr(0, body), name);
  r.raw(head.offset(), "version");
  const std::uint32_t length = r.u32("fingerprint");
  if (length > kMaxFingerprintBytes) {
    throw InputError(name, "/fingerprint",
                     "corrupt: fingerprint of " + std::to_string(length) + " bytes, at most " +
                         std::to_string(kMaxFingerprintBytes) + " allowed");
  }
  const std::string found = r.raw(length, "fingerprint");
  const std::string& expected =
      version == 3 && !expected_v3_fingerprint.empty() ? expected_v3_fingerprint : expected_fingerprint;
  if (found != expected) {
    throw InputError(name, "/fingerprint",
                     "checkpoint (format " + std::to_string(version) + ") belongs to scenario fingerprint " +
                         found + ", this engine runs " + expected +
                         (version == 3 ? " (format 3 fingerprints cover the solver controls too: "
                                         "load it with the numerics it was written with)"
                                       : ""));
  }

  State state;
  read_levels(r, state, version);
  for (double* value : functional_fields(state.functionals)) *value = r.f64("functionals");
  // Before version 5 the step-length controller had no memory: continue at the last step.
  state.time_step_limit_s = version >= 5 ? r.f64("time_step_limit_s") : state.time_step_s;
  if (r.u32("factorization_origin") != 0) {
    auto origin = std::make_shared<FactorizationOrigin>();
    read_levels(r, origin->step_start, version);
    origin->iterate = r.vector("factorization_origin/iterate");
    origin->time_step_s = r.f64("factorization_origin/time_step_s");
    state.factorization_origin = std::move(origin);
  }
  if (r.offset() != body) {  // the reader never passes `body`
    throw InputError(
        name, "/checksum",
        "corrupt: " + std::to_string(body - r.offset()) + " unexpected bytes before the checksum");
  }
  return state;
}

}  // namespace fsi::io
