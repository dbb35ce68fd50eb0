#pragma once
/// \file vtu_writer.hpp
/// FieldView -> VTK XML files for ParaView/VisIt (ASCII, values in shortest round-trip
/// form, so they read back bit-identically):
///   .vtu  UnstructuredGrid: the sub-triangles; point data vx, vy, p, ux, uy and the
///         3-component vectors velocity and displacement; cell data phase (0 fluid,
///         1 solid); field data TimeValue.
///   .vtp  PolyData lines: the discrete interface (or any set of segments).
/// Files are replaced atomically. A view whose arrays disagree in size, or whose
/// triangles point past the nodes, is a programming error: std::invalid_argument.
#include <filesystem>
#include <string>
#include <vector>

#include "fsi/field_view.hpp"
#include "io/pvd_series.hpp"

namespace fsi::io {

/// Writes the mesh and nodal fields of `view` as a .vtu file.
void write_vtu(const std::filesystem::path& file, const FieldView& view);

/// Writes `segments` (e.g. view.interface) as a .vtp file of lines, time `time_s` [s].
void write_vtp_segments(const std::filesystem::path& file, const std::vector<Segment2>& segments,
                        double time_s);

/// One frame of a time series: writes `<folder>/<stem>_<step>.vtu` and
/// `<folder>/<stem>_interface_<step>.vtp` (step zero-padded to 6 digits) and adds them
/// to `series` (parts 0 and 1), whose .pvd should live in `folder`.
void write_vtk_frame(const std::filesystem::path& folder, const std::string& stem,
                     const FieldView& view, PvdSeries& series);

}  // namespace fsi::io
