// The .pvd collection: small, so rewriting it whole after each frame is cheap.
#include "fsi/output.hpp"

#include <utility>

#include "io/atomic_file.hpp"
#include "io/number_text.hpp"

namespace fsi::io {

std::string xml_escaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

PvdSeries::PvdSeries(std::filesystem::path pvd_file) : file_(std::move(pvd_file)) {}

void PvdSeries::add(double time_s, const std::filesystem::path& dataset, int part) {
  // generic_string: forward slashes, as ParaView expects on every platform.
  entries_.push_back(Entry{time_s, part, dataset.generic_string()});
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_) {
    xml.append("    <DataSet timestep=\"").append(number_text(e.time_s));
    xml.append("\" group=\"\" part=\"").append(std::to_string(e.part));
    xml.append("\" file=\"").append(xml_escaped(e.dataset)).append("\"/>\n");
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(file_, xml);
}

}  // namespace fsi::io
