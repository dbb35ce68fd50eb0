#pragma once
/// \file contact_sheet.hpp
/// Several frames on one picture: shrunk by area averaging and tiled in reading order
/// (a contact sheet of a run, for the docs or a slide).
#include <cstddef>
#include <vector>

#include "fsi/image.hpp"

namespace fsi::render {

/// `image` resampled to width x height [px], each output pixel the area-weighted mean of
/// the source pixels it covers (a box filter: no aliasing when shrinking). Throws
/// std::invalid_argument for an empty image or a size below 1 px.
Image shrink(const Image& image, int width, int height);

/// `n` indices spread evenly over [0, count), the first and the last included (all of
/// them when count <= n).
std::vector<std::size_t> evenly_spaced(std::size_t count, std::size_t n);

/// The frames shrunk to `tile_width` px wide (heights in proportion, from the first
/// frame) and tiled `columns` per row, `gap` px of white between and around them.
/// Throws std::invalid_argument when there are no frames, they differ in size, or
/// columns / tile_width are below 1.
Image contact_sheet(const std::vector<Image>& frames, int columns, int tile_width, int gap = 8);

}  // namespace fsi::render
