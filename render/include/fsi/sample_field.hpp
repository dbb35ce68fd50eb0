#pragma once
/// \file sample_field.hpp
/// A synthetic FieldView with analytic fields, for the renderer's tests, benchmarks and
/// examples (the renderer must be testable without running the engine): the rectangle
/// (-1, 1) x (-1, 0.5) m on a (graded) grid of nx x ny nodes cut into triangles, a
/// ball of radius 0.3 m as the interface, and a ball "falling" through still fluid:
/// rigid motion inside, the potential-flow dipole outside, a dipole pressure and a
/// squashing displacement.
#include <fsi/field_view.hpp>

namespace fsi::render {

struct SampleFieldOptions {
  int nx = 33;          ///< nodes in x (>= 2)
  int ny = 25;          ///< nodes in y (>= 2)
  bool graded = false;  ///< refine towards the bottom wall and the centre line
  int interface_segments = 96;
  double time_s = 1.234;                ///< time stamp [s]
  double ball_x = 0.1, ball_y = -0.35;  ///< ball centre [m]
  double radius = 0.3;                  ///< [m]
  double speed = 0.2;                   ///< falling speed [m/s]
};

FieldView sample_field_view(const SampleFieldOptions& options = {});

}  // namespace fsi::render
