#pragma once
/// \file bounded_file.hpp
/// Reading a whole input file whose size is checked first, so a huge or special file
/// (a 100 GB log, /dev/zero) gives an error instead of exhausting memory.
#include <cstddef>
#include <filesystem>
#include <string>

namespace fsi::io {

/// The file's bytes. Throws InputError(file, "", why) if it is missing, not a regular
/// file, unreadable or larger than `max_bytes`; `what` names it in messages ("scenario").
std::string read_bounded_file(const std::filesystem::path& file, std::size_t max_bytes,
                              const std::string& what);

}  // namespace fsi::io
