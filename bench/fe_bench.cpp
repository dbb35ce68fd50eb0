// FE core benchmark (not a test): assembly time vs. UMFPACK factorization and solve time
// for a 5-field-per-node system (vx, vy, ux, uy, p) with the FSI solver's sparsity
// pattern, on 65^2 and 129^2 nodes with a cut circle:
//   v and u: vector Laplacian + mass, p: Laplacian + mass + anisotropic CIP.
// Compare the ratios assemble / factorize and solve / factorize, not absolute times.
//
//   build/bench/fsi-bench-fe                       # all
//   build/bench/fsi-bench-fe --benchmark_filter=129
#include <benchmark/benchmark.h>

#include "fe/cut_mesh.hpp"
#include "fe/element.hpp"
#include "fe/stabilization_edges.hpp"
#include "forms/pressure_stabilization.hpp"
#include "solve/sparse_lu.hpp"
#include "solve/sparsity.hpp"

namespace {

using fsi::mesh::Vec2;
constexpr int kFields = 5;

struct System {
  fsi::mesh::PatchMesh mesh;
  fsi::fe::CutMesh cut;
  fsi::solve::SparseMatrix a;

  explicit System(int refinements) {
    fsi::BlockSpec b;
    b.x = {fsi::AxisPiece{-1.0, 1.0, 8, 0.1, 0.4}};
    b.y = {fsi::AxisPiece{-1.0, 1.0, 8, 0.4, 0.1}};
    fsi::MeshSpec spec;
    spec.blocks = {b};
    spec.refinements = refinements;
    mesh = fsi::mesh::build_patch_mesh(spec, {});
    cut = fsi::fe::build_cut_mesh(mesh, [](const Vec2& x) { return (x - Vec2(0.0123, -0.0231)).norm() - 0.5; });
    // Rows v -> {v, u, p}; u -> {v, u}; p -> {v, p}; neighbouring patches: p-p only.
    const fsi::solve::FieldCoupling coupling{{1, 1, 1, 1, 1}, {1, 1, 1, 1, 1}, {1, 1, 1, 1, 0},
                                             {1, 1, 1, 1, 0}, {1, 1, 0, 0, 1}};
    fsi::solve::FieldCoupling neighbor(kFields, std::vector<char>(kFields, 0));
    neighbor[4][4] = 1;
    a = fsi::solve::build_pattern(mesh, kFields, coupling, neighbor);
  }

  /// Element loop (quadrature recomputed, as after every interface move) + CIP edges.
  void assemble() {
    std::fill(a.valuePtr(), a.valuePtr() + a.nonZeros(), 0.0);
    std::vector<fsi::fe::QuadraturePoint> points;
    for (const auto& e : cut.elements) {
      points.clear();
      fsi::fe::append_quadrature(cut, e, points);
      std::array<std::array<double, 4>, 4> lap{}, mass{};
      for (const auto& q : points)
        for (int i = 0; i < q.n; ++i)
          for (int j = 0; j < q.n; ++j) {
            lap[i][j] += q.weight * q.grad[i].dot(q.grad[j]);
            mass[i][j] += q.weight * q.value[i] * q.value[j];
          }
      for (int i = 0; i < e.vertices; ++i)
        for (int j = 0; j < e.vertices; ++j)
          for (int f = 0; f < kFields; ++f) {
            const int k = fsi::solve::value_index(a, kFields * e.node[i] + f, kFields * e.node[j] + f);
            a.valuePtr()[k] += lap[i][j] + mass[i][j];
          }
    }
    const auto edges = fsi::fe::build_stabilization_edges(cut);
    fsi::forms::add_pressure_stabilization(mesh, cut, edges, 0.05, kFields, 4, a);
  }
};

void set_counters(benchmark::State& state, const System& s) {
  state.counters["nodes"] = s.mesh.num_nodes();
  state.counters["per_node"] = benchmark::Counter(
      static_cast<double>(s.mesh.num_nodes()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Assemble(benchmark::State& state) {
  System s(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    s.assemble();
    benchmark::DoNotOptimize(s.a.valuePtr());
  }
  set_counters(state, s);
}

void BM_Factorize(benchmark::State& state) {
  System s(static_cast<int>(state.range(0)));
  s.assemble();
  fsi::solve::SparseLU lu;
  if (!lu.factorize(s.a)) state.SkipWithError("singular");  // symbolic analysis once, outside
  for (auto _ : state) benchmark::DoNotOptimize(lu.factorize(s.a));
  set_counters(state, s);
}

void BM_Solve(benchmark::State& state) {
  System s(static_cast<int>(state.range(0)));
  s.assemble();
  fsi::solve::SparseLU lu;
  if (!lu.factorize(s.a)) state.SkipWithError("singular");
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(s.a.rows());
  for (auto _ : state) benchmark::DoNotOptimize(lu.solve(b));
  set_counters(state, s);
}

// Argument: global refinements of the 8 x 8 base mesh (2: 65^2 nodes, 3: 129^2 nodes).
BENCHMARK(BM_Assemble)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Factorize)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Solve)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
