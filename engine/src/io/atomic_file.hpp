#pragma once
/// \file atomic_file.hpp
/// Replacing a file all at once: readers (ParaView, a restarted run) see the old or the
/// new content, never half of it, even if the writer stops mid-way.
#include <filesystem>
#include <string_view>

namespace fsi::io {

/// Writes `content` to `<file>.tmp` in the same folder and renames it over `file`.
/// Throws InputError(file, "", "cannot write ...") on failure (and removes the temp).
void write_file_atomically(const std::filesystem::path& file, std::string_view content);

}  // namespace fsi::io
