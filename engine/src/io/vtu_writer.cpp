// VTK XML writers. ASCII keeps them dependency-free and easy to check in tests;
// a 66049-node frame is about 10 MB, which is fine for the studies' frame rates.
#include "fsi/output.hpp"

#include <cstdio>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/number_text.hpp"

namespace fsi::io {
namespace {

constexpr int kVtkTriangle = 5;

/// Appends `<DataArray ...>values</DataArray>`; `values(out)` writes the numbers.
template <class WriteValues>
void data_array(std::string& out, const char* type, const std::string& name, int components,
                WriteValues&& values) {
  out.append("        <DataArray type=\"").append(type).append("\"");
  if (!name.empty()) out.append(" Name=\"").append(name).append("\"");
  if (components > 1)
    out.append(" NumberOfComponents=\"").append(std::to_string(components)).append("\"");
  out += " format=\"ascii\">\n";
  values(out);
  out += "\n        </DataArray>\n";
}

void append_number(std::string& out, double value, bool& first) {
  if (!first) out += ' ';
  first = false;
  out += number_text(value);
}

void scalars(std::string& out, const std::string& name, const std::vector<double>& values) {
  data_array(out, "Float64", name, 1, [&](std::string& o) {
    bool first = true;
    for (double v : values) append_number(o, v, first);
  });
}

void vectors(std::string& out, const std::string& name, const std::vector<double>& x,
             const std::vector<double>& y) {
  data_array(out, "Float64", name, 3, [&](std::string& o) {
    bool first = true;
    for (std::size_t i = 0; i < x.size(); ++i) {
      append_number(o, x[i], first);
      append_number(o, y[i], first);
      append_number(o, 0.0, first);
    }
  });
}

void points(std::string& out, const std::vector<Point2>& nodes) {
  out += "      <Points>\n";
  data_array(out, "Float64", "", 3, [&](std::string& o) {
    bool first = true;
    for (const Point2& p : nodes) {
      append_number(o, p.x, first);
      append_number(o, p.y, first);
      append_number(o, 0.0, first);
    }
  });
  out += "      </Points>\n";
}

void time_value(std::string& out, double time_s) {
  out += "    <FieldData>\n";
  out +=
      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
      "format=\"ascii\">";
  out.append(number_text(time_s)).append("</DataArray>\n    </FieldData>\n");
}

void check_view(const FieldView& view) {
  const std::size_t n = view.nodes.size();
  for (const auto* field : {&view.vx, &view.vy, &view.p, &view.ux, &view.uy}) {
    if (field->size() != n) {
      throw std::invalid_argument("write_vtu: a nodal field has " + std::to_string(field->size()) +
                                  " values for " + std::to_string(n) + " nodes");
    }
  }
  if (view.triangle_phase.size() != view.triangles.size()) {
    throw std::invalid_argument("write_vtu: triangle_phase and triangles differ in size");
  }
  for (const auto& t : view.triangles) {
    for (int i : t) {
      if (i < 0 || static_cast<std::size_t>(i) >= n) {
        throw std::invalid_argument("write_vtu: triangle node index " + std::to_string(i) +
                                    " outside [0, " + std::to_string(n) + ")");
      }
    }
  }
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const FieldView& view) {
  check_view(view);
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n";
  time_value(out, view.time_s);
  out.append("    <Piece NumberOfPoints=\"").append(std::to_string(view.nodes.size()));
  out.append("\" NumberOfCells=\"").append(std::to_string(view.triangles.size())).append("\">\n");

  out += "      <PointData Scalars=\"p\" Vectors=\"velocity\">\n";
  scalars(out, "vx", view.vx);
  scalars(out, "vy", view.vy);
  scalars(out, "p", view.p);
  scalars(out, "ux", view.ux);
  scalars(out, "uy", view.uy);
  vectors(out, "velocity", view.vx, view.vy);
  vectors(out, "displacement", view.ux, view.uy);
  out += "      </PointData>\n";

  out += "      <CellData Scalars=\"phase\">\n";
  data_array(out, "UInt8", "phase", 1, [&](std::string& o) {
    for (std::size_t i = 0; i < view.triangle_phase.size(); ++i) {
      if (i > 0) o += ' ';
      o += view.triangle_phase[i] == Phase::solid ? '1' : '0';
    }
  });
  // The body of each solid cell (0 = body1, ...; -1 fluid): one filter in ParaView picks a body.
  if (view.triangle_body.size() == view.triangles.size())
    data_array(out, "Int32", "body_id", 1, [&](std::string& o) {
      for (std::size_t i = 0; i < view.triangle_body.size(); ++i) {
        if (i > 0) o += ' ';
        o += std::to_string(view.triangle_body[i]);
      }
    });
  out += "      </CellData>\n";

  points(out, view.nodes);
  out += "      <Cells>\n";
  data_array(out, "Int64", "connectivity", 1, [&](std::string& o) {
    for (std::size_t i = 0; i < view.triangles.size(); ++i) {
      const auto& t = view.triangles[i];
      if (i > 0) o += ' ';
      o.append(std::to_string(t[0])).append(" ").append(std::to_string(t[1]));
      o.append(" ").append(std::to_string(t[2]));
    }
  });
  data_array(out, "Int64", "offsets", 1, [&](std::string& o) {
    for (std::size_t i = 0; i < view.triangles.size(); ++i) {
      if (i > 0) o += ' ';
      o += std::to_string(3 * (i + 1));
    }
  });
  data_array(out, "UInt8", "types", 1, [&](std::string& o) {
    for (std::size_t i = 0; i < view.triangles.size(); ++i) {
      if (i > 0) o += ' ';
      o += std::to_string(kVtkTriangle);
    }
  });
  out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(file, out);
}

void write_vtp_segments(const std::filesystem::path& file, const std::vector<Segment2>& segments,
                        double time_s) {
  std::vector<Point2> ends;
  ends.reserve(2 * segments.size());
  for (const Segment2& s : segments) {
    ends.push_back(s.a);
    ends.push_back(s.b);
  }
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PolyData>\n";
  time_value(out, time_s);
  out.append("    <Piece NumberOfPoints=\"").append(std::to_string(ends.size()));
  out.append("\" NumberOfVerts=\"0\" NumberOfLines=\"").append(std::to_string(segments.size()));
  out += "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  points(out, ends);
  out += "      <Lines>\n";
  data_array(out, "Int64", "connectivity", 1, [&](std::string& o) {
    for (std::size_t i = 0; i < ends.size(); ++i) {
      if (i > 0) o += ' ';
      o += std::to_string(i);
    }
  });
  data_array(out, "Int64", "offsets", 1, [&](std::string& o) {
    for (std::size_t i = 0; i < segments.size(); ++i) {
      if (i > 0) o += ' ';
      o += std::to_string(2 * (i + 1));
    }
  });
  out += "      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  write_file_atomically(file, out);
}

void write_vtk_frame(const std::filesystem::path& folder, const std::string& stem,
                     const FieldView& view, PvdSeries& series) {
  char step[32];
  std::snprintf(step, sizeof step, "%06ld", view.step);
  const std::string fields = stem + "_" + step + ".vtu";
  const std::string interface = stem + "_interface_" + step + ".vtp";
  write_vtu(folder / fields, view);
  write_vtp_segments(folder / interface, view.interface, view.time_s);
  series.add(view.time_s, fields, 0);
  series.add(view.time_s, interface, 1);
}

}  // namespace fsi::io
