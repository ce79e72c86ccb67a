// Kernels of a contact solve, one at a time, on the paper's problem:
//   build/release/bench/signorini_micro_benchmarks [--benchmark_filter=Assembly]
// For repeatable instruction counts: valgrind --tool=callgrind <binary> --benchmark_filter=...

#include <benchmark/benchmark.h>

#include "signorini/contact/condensed_problem.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/problem/model.hpp"

namespace {

using namespace signorini;

void Assembly(benchmark::State& state) {
  const Index nx = state.range(0);
  const ProblemSpec spec = paper_benchmark(nx, nx / 3);
  const Mesh mesh = make_rectangle_mesh(spec.mesh);
  const DofMap dofs = make_dof_map(mesh, spec.clamps);
  for (auto _ : state) benchmark::DoNotOptimize(assemble_stiffness(mesh, dofs, spec.elasticity));
  state.counters["dofs"] = static_cast<double>(dofs.num_free());
}
BENCHMARK(Assembly)->Arg(120)->Arg(480)->Unit(benchmark::kMillisecond);

void Condensation(benchmark::State& state) {
  const Index nx = state.range(0);
  const Model model = build_model(paper_benchmark(nx, nx / 3));
  for (auto _ : state) benchmark::DoNotOptimize(CondensedProblem(model.problem).reduced().b);
}
BENCHMARK(Condensation)->Arg(120)->Arg(480)->Unit(benchmark::kMillisecond);

void CondensedSolve(benchmark::State& state) {
  // The iterations alone, on the condensed problem (dense Newton systems).
  const Index nx = state.range(0);
  const Model model = build_model(paper_benchmark(nx, nx / 3));
  const CondensedProblem condensed(model.problem);
  ContactSolverOptions o;
  o.method = static_cast<ContactMethod>(state.range(1));
  o.linear.type = LinearSolverType::Dense;
  for (auto _ : state) benchmark::DoNotOptimize(solve_contact(condensed.reduced(), o).l);
}
BENCHMARK(CondensedSolve)
    ->Args({480, static_cast<int>(ContactMethod::UzawaGnm)})
    ->Args({480, static_cast<int>(ContactMethod::SemismoothNewton)})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
