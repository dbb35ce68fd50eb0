// Temp file + rename; the temp sits next to the target so the rename cannot cross devices.
#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "fsi/error.hpp"

namespace fsi::io {

void write_file_atomically(const std::filesystem::path& file, std::string_view content) {
  std::filesystem::path temp = file;
  temp += ".tmp";
  std::string failure;
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) failure = std::strerror(errno);
  }
  if (failure.empty()) {
    std::error_code ec;
    std::filesystem::rename(temp, file, ec);
    if (!ec) return;
    failure = ec.message();
  }
  std::error_code ignored;
  std::filesystem::remove(temp, ignored);
  throw InputError(file.string(), "", "cannot write: " + failure);
}

}  // namespace fsi::io
