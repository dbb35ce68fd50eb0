#pragma once
// The two kinds of picture, each drawn on a Canvas by its own source file.
#include "canvas.hpp"
#include "fsi/plot.hpp"
#include "fsi/renderer.hpp"

namespace fsi::render::detail {

/// field_frame.cpp
void draw_field_frame(Canvas& canvas, const FieldView& view, const FrameSpec& spec, Image& out);
/// plot_drawing.cpp
Image draw_plot(Canvas& canvas, const PlotSpec& spec);

/// Throws std::invalid_argument when the view's arrays do not fit together.
void validate(const FieldView& view);

}  // namespace fsi::render::detail
