#pragma once
/// \file checkpoint.hpp
/// Binary checkpoints of a State: restoring one and stepping on gives bit-identical
/// results, so every double is stored bit for bit.
///
/// Layout (all integers and doubles little-endian):
///   magic       8 bytes "FSI-CKPT"
///   version     u32 (kCheckpointVersion)
///   fingerprint u32 length + bytes (fsi::fingerprint of the scenario that wrote it)
///   time_s f64, step i64, time_step_s f64
///   solution, previous_solution, node_xy, previous_node_xy: each u64 count + count f64
///   reference_offset_x_m, reference_offset_y_m, reference_rotation_rad f64 (version 6 on)
///   body_references: u64 count + count x (offset_x_m, offset_y_m, rotation_rad) f64 (version 7 on)
///   functionals: 11 f64 in the order of fsi::Functionals' members
///   time_step_limit_s f64 (version 5 on)
///   checksum    u64 FNV-1a of every byte before it
/// The Engine's save_checkpoint/load_checkpoint wrap these.
#include <cstdint>
#include <filesystem>
#include <string>

#include "fsi/state.hpp"

namespace fsi::io {

/// Bump when the layout or the meaning of a stored field changes (3: the scenario
/// fingerprint leaves out the end time and covers contact.min_dist_fraction and
/// numerics.cip_transient_weight; 4: the fingerprint leaves out the solver controls,
/// io/fingerprint.hpp -- the layout is that of 3; 5: State::time_step_limit_s after the
/// functionals; 6: the body's reference, State::reference_*, after each level block; 7:
/// State::body_references after it).
inline constexpr std::uint32_t kCheckpointVersion = 7;
/// The oldest version read: a version 3 file is the same layout with the older fingerprint,
/// 3 and 4 continue with the limit at their last step.
inline constexpr std::uint32_t kOldestCheckpointVersion = 3;

/// Writes `state` to `file` atomically (a temporary file in the same folder, then a
/// rename): a crash mid-write leaves the previous checkpoint intact. Throws InputError if
/// the file cannot be written.
void write_checkpoint(const std::filesystem::path& file, const State& state,
                      const std::string& scenario_fingerprint);

/// Reads a checkpoint written for the scenario with `expected_fingerprint` (a version 3
/// file: with `expected_v3_fingerprint`, io::fingerprint_v3 of the same scenario; empty:
/// the same as `expected_fingerprint`). Throws InputError naming the file and what is
/// wrong: not a checkpoint, another format version, corrupt or truncated, or written by
/// another scenario.
State read_checkpoint(const std::filesystem::path& file, const std::string& expected_fingerprint,
                      const std::string& expected_v3_fingerprint = "");

}  // namespace fsi::io
