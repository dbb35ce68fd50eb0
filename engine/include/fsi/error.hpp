#pragma once
/// \file error.hpp
/// Errors that cross the engine boundary.
///
/// Three kinds of failure (see README, "Failure policy"):
///  - programming errors: debug asserts, never exceptions;
///  - bad input (scenario files, checkpoints, commands): fsi::InputError, which names
///    the file, the key path and what was allowed, so a user can fix it;
///  - numerical trouble (no convergence, real contact, NaN): reported in StepReport,
///    never thrown.
#include <stdexcept>
#include <string>

namespace fsi {

/// Bad input: a scenario, checkpoint or command that cannot be used.
class InputError : public std::runtime_error {
 public:
  /// \param file   the file (or "<string>", "<command>") the input came from
  /// \param key    JSON-pointer-like path of the offending field, e.g. "/numerics/k"
  /// \param why    what is wrong and what is allowed, e.g. "must be in (0, 1], got -2"
  InputError(std::string file, std::string key, std::string why)
      : std::runtime_error(file + ": " + (key.empty() ? std::string() : key + ": ") + why),
        file_(std::move(file)), key_(std::move(key)), why_(std::move(why)) {}
  const std::string& file() const noexcept { return file_; }
  const std::string& key() const noexcept { return key_; }
  const std::string& why() const noexcept { return why_; }

 private:
  std::string file_, key_, why_;
};

}  // namespace fsi
