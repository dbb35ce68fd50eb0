#pragma once
/// \file pvd_series.hpp
/// A ParaView time series: a .pvd collection file listing one dataset (or several
/// "parts") per time. It is rewritten, atomically, after every added frame, so it is a
/// valid file listing every frame written so far even if the run stops.
#include <filesystem>
#include <string>
#include <vector>

namespace fsi::io {

class PvdSeries {
 public:
  /// Starts an empty series in `pvd_file` (written at the first add()).
  explicit PvdSeries(std::filesystem::path pvd_file);

  /// Registers `dataset` (a path relative to the .pvd's folder) at `time_s` [s].
  /// `part` tells datasets of the same time apart (e.g. 0: fields, 1: interface).
  void add(double time_s, const std::filesystem::path& dataset, int part = 0);

  const std::filesystem::path& file() const { return file_; }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    double time_s;
    int part;
    std::string dataset;
  };
  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

/// `text` with the five XML special characters escaped (for attribute values).
std::string xml_escaped(const std::string& text);

}  // namespace fsi::io
