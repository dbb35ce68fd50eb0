// Size first, then one read.
#include "io/bounded_file.hpp"

#include <fstream>
#include <system_error>

#include "fsi/error.hpp"

namespace fsi::io {

std::string read_bounded_file(const std::filesystem::path& file, std::size_t max_bytes,
                              const std::string& what) {
  const std::string name = file.string();
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) {
    throw InputError(name, "", "cannot read " + what + ": no such file");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(name, "", "cannot read " + what + ": not a regular file");
  }
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(name, "", "cannot read " + what + ": " + ec.message());
  if (size > max_bytes) {
    throw InputError(name, "",
                     what + " file is " + std::to_string(size) + " bytes, must be at most " +
                         std::to_string(max_bytes) + " bytes");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name, "", "cannot open " + what + " for reading");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  // The file may have changed since file_size(); keep what was read.
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw InputError(name, "", "cannot read " + what + ": read error");
  return bytes;
}

}  // namespace fsi::io
