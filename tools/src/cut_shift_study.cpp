#include "cut_shift_study.hpp"

#include <cmath>

#include "study_meshes.hpp"

namespace fsi::study {

std::vector<ShiftCase> run_shift_study() {
  const mesh::PatchMesh mesh = square_mesh(Grading::uniform, 2);
  const double h = 2.0 / 32.0;
  struct Family {
    std::string name;
    Circle base;
  };
  const std::vector<Family> families{
      {"generic", Circle{mesh::Vec2(0.0123, -0.0231), 0.6}},
      {"vertex", Circle{mesh::Vec2(0.0, 0.0), 10 * h}},
      {"tangent", Circle{mesh::Vec2(0.5 * h, 0.0), 10 * h}},
  };
  struct Shift {
    std::string name;
    mesh::Vec2 move;
    double dr;
  };
  const std::vector<Shift> shifts{
      {"base", mesh::Vec2(0, 0), 0.0},
      {"x+1e-5h", mesh::Vec2(1e-5 * h, 0), 0.0},
      {"y-1e-5h", mesh::Vec2(0, -1e-5 * h), 0.0},
      {"xy+1e-5h", mesh::Vec2(1e-5 * h, 1e-5 * h), 0.0},
      {"r+1e-5h", mesh::Vec2(0, 0), 1e-5 * h},
      {"r-1e-8h", mesh::Vec2(0, 0), -1e-8 * h},
      {"r+1e-8h", mesh::Vec2(0, 0), 1e-8 * h},
      {"r+1e-10h", mesh::Vec2(0, 0), 1e-10 * h},
      {"r-1e-12h", mesh::Vec2(0, 0), -1e-12 * h},
      {"r+1e-12h", mesh::Vec2(0, 0), 1e-12 * h},
  };
  std::vector<ShiftCase> cases;
  for (const Family& f : families) {
    double base_error = 0.0;
    for (const Shift& s : shifts) {
      ShiftCase c;
      c.family = f.name;
      c.name = s.name;
      c.circle = Circle{f.base.centre + s.move, f.base.radius + s.dr};
      c.result = solve_interface_poisson(mesh, c.circle);
      if (s.name == "base") base_error = c.result.l2_error;
      c.relative_change = std::abs(c.result.l2_error - base_error) / base_error;
      cases.push_back(c);
    }
  }
  return cases;
}

}  // namespace fsi::study
