// Uses the installed public headers and library: builds the default scenario and
// prints a number that comes from the library, not from the headers.
#include <fsi/scenario.hpp>

#include <cstdio>

int main() {
  const fsi::Scenario s = fsi::example1_scenario();
  std::printf("embedded fsi: scenario '%s', %zu mesh block(s), ball radius %.2f m\n",
              s.name.c_str(), s.mesh.blocks.size(), s.body.radius_m);
  return s.mesh.blocks.size() == 1 ? 0 : 1;
}
