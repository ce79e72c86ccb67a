// Kernels of a contact solve, one at a time, on the paper's problem:
//   build/release/bench/signorini_micro_benchmarks [--benchmark_filter=Assembly]
// For repeatable instruction counts: valgrind --tool=callgrind <binary> --benchmark_filter=...

#include <benchmark/benchmark.h>
#include <sys/mman.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "signorini/backend/host_backend.hpp"
#include "signorini/contact/condensed_problem.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/iterative/galerkin_product.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/rectangle_hierarchy.hpp"

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

// The multigrid preconditioner of the backend path (docs/gpu.md) on the CPU backend: its set-up
// (Galerkin coarse operators on the host, first refresh) and one V-cycle, with every contact node
// active (the stiffest Newton matrix). On a GPU the same set-up runs on the host.
struct MultigridCase {
  Model model;
  std::vector<SparseMatrix> P;
  Vector c;
  explicit MultigridCase(Index nx) : model(build_model(paper_benchmark(nx, nx / 3))) {
    const ProblemSpec spec = paper_benchmark(nx, nx / 3);
    P = make_rectangle_prolongations(spec.mesh, spec.clamps, model.dofs);
    c = 1e8 * model.problem.contact.weights;
  }
};

void MultigridSetup(benchmark::State& state) {
  const MultigridCase m(state.range(0));
  HostBackend be;
  PenalizedOperator op(be, m.model.problem.A, m.model.problem.contact.N);
  op.set_weights(m.c);
  for (auto _ : state) {
    MultigridPreconditioner mg(op, m.model.problem.A, m.model.problem.contact.N, m.P, {});
    benchmark::DoNotOptimize(mg.level_sizes());
  }
  state.counters["dofs"] = static_cast<double>(op.size());
}
BENCHMARK(MultigridSetup)->Arg(480)->Arg(960)->Unit(benchmark::kMillisecond);

void MultigridVCycle(benchmark::State& state) {
  const MultigridCase m(state.range(0));
  HostBackend be;
  PenalizedOperator op(be, m.model.problem.A, m.model.problem.contact.N);
  op.set_weights(m.c);
  MultigridPreconditioner mg(op, m.model.problem.A, m.model.problem.contact.N, m.P, {});
  const DeviceVector r = to_device(be, m.model.problem.b);
  DeviceVector z(be, op.size());
  for (auto _ : state) mg.apply(r, z);
  state.counters["dofs"] = static_cast<double>(op.size());
}
BENCHMARK(MultigridVCycle)->Arg(480)->Arg(960)->Unit(benchmark::kMillisecond);

// The smoothed-aggregation hierarchy (aggregation, tentative and smoothed prolongations, Galerkin
// products) of the nx x nx/3 paper mesh: compare with MultigridSetup, which forms the geometric
// hierarchy's Galerkin products.
void SmoothedAggregationSetup(benchmark::State& state) {
  const Model model = build_model(paper_benchmark(state.range(0), state.range(0) / 3));
  const Matrix B = rigid_body_modes(model.mesh, model.dofs);
  const std::vector<Index> nodes = free_dof_nodes(model.dofs);
  for (auto _ : state) {
    MultigridHierarchy h = smoothed_aggregation_hierarchy(model.problem.A, B, nodes);
    benchmark::DoNotOptimize(h.prolongations.size());
  }
  state.counters["dofs"] = static_cast<double>(model.problem.A.rows());
}
BENCHMARK(SmoothedAggregationSetup)->Arg(480)->Arg(960)->Unit(benchmark::kMillisecond);

// Reading a Gmsh file of format 4.1, binary: an n x n grid of Q1 quadrilaterals ((n + 1)^2
// nodes; n = 1000 gives a million), written here in the layout Gmsh writes (one entity block of
// nodes, one of elements, the four sides as physical curves left out), then read with
// read_gmsh_mesh. The counter MB/s is the file's size over the time of one read (issue target:
// 100 MB/s or more for a million nodes).
std::string gmsh_grid_file(Index n) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("signorini_bench_grid_" + std::to_string(n) + ".msh"))
                               .string();
  if (std::filesystem::exists(path)) return path;
  std::ofstream out(path, std::ios::binary);
  const auto put = [&out](const auto& v) {
    out.write(reinterpret_cast<const char*>(&v), sizeof v);
  };
  const auto nodes = static_cast<std::uint64_t>((n + 1) * (n + 1));
  const auto cells = static_cast<std::uint64_t>(n * n);
  out << "$MeshFormat\n4.1 1 8\n";
  put(std::int32_t{1});
  out << "\n$EndMeshFormat\n$Entities\n";
  for (const std::uint64_t c : {0, 0, 1, 0}) put(c);
  put(std::int32_t{1});
  for (const double v : {0.0, 0.0, 0.0, 1.0, 1.0, 0.0}) put(v);
  put(std::uint64_t{0});  // no physical group
  put(std::uint64_t{0});  // no bounding curves
  out << "\n$EndEntities\n$Nodes\n";
  for (const std::uint64_t v : {std::uint64_t{1}, nodes, std::uint64_t{1}, nodes}) put(v);
  put(std::int32_t{2});
  put(std::int32_t{1});
  put(std::int32_t{0});
  put(nodes);
  for (std::uint64_t k = 1; k <= nodes; ++k) put(k);
  for (Index j = 0; j <= n; ++j)
    for (Index i = 0; i <= n; ++i) {
      put(static_cast<double>(i) / static_cast<double>(n));
      put(static_cast<double>(j) / static_cast<double>(n));
      put(0.0);
    }
  out << "\n$EndNodes\n$Elements\n";
  for (const std::uint64_t v : {std::uint64_t{1}, cells, std::uint64_t{1}, cells}) put(v);
  put(std::int32_t{2});
  put(std::int32_t{1});
  put(std::int32_t{3});
  put(cells);
  std::uint64_t tag = 1;
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i < n; ++i) {
      const auto n0 = static_cast<std::uint64_t>(j * (n + 1) + i + 1);
      put(tag++);
      for (const std::uint64_t v : {n0, n0 + 1, n0 + 2 + static_cast<std::uint64_t>(n),
                                    n0 + 1 + static_cast<std::uint64_t>(n)})
        put(v);
    }
  out << "\n$EndElements\n";
  return path;
}

void GmshRead(benchmark::State& state) {
  const std::string path = gmsh_grid_file(state.range(0));
  const double megabytes = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  Index nodes = 0;
  for (auto _ : state) nodes = read_gmsh_mesh(path).num_nodes();
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["MB"] = megabytes;
  state.counters["MB/s"] = benchmark::Counter(megabytes * static_cast<double>(state.iterations()),
                                              benchmark::Counter::kIsRate);
}
BENCHMARK(GmshRead)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);

// 3D: a rigid ball pressed 0.002 into an n x n x n/2 block of hex8 cells clamped on its top
// (the contact surface is the whole bottom face, (n+1)^2 nodes): the model, then the contact
// solve on the default path (condensed direct) and on the iterative one (CG with
// smoothed-aggregation multigrid on the six rigid modes).
ProblemSpec ball_on_block(Index n) {
  ProblemSpec spec;
  spec.mesh_type = MeshType::Box;
  spec.box.nx = n;
  spec.box.ny = n;
  spec.box.nz = n / 2;
  spec.box.height = 0.5;
  spec.elasticity.material = {1000.0, 0.3};
  spec.clamps = {{"zmax", {true, true, true}}};
  ContactSpec ball;
  ball.boundary = "zmin";
  ball.obstacle.shape = ObstacleShape::Disc;
  ball.obstacle.radius = 2.0;
  ball.obstacle.centre = Eigen::Vector3d(0.5, 0.5, -2.0 + 2e-3);
  spec.contacts = {ball};
  return spec;
}

void BallOnBlock3D(benchmark::State& state) {
  ProblemSpec spec = ball_on_block(state.range(0));
  if (state.range(1) == 1) {
    spec.solver.linear.type = LinearSolverType::ConjugateGradient;
    spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  }
  Index unknowns = 0, contact = 0;
  for (auto _ : state) {
    const Model model = build_model(spec);
    const ContactResult r = solve_contact(model.problem, spec.solver, &model.multigrid);
    if (!r.summary.converged()) state.SkipWithError(r.summary.message.c_str());
    unknowns = model.dofs.num_free();
    contact = model.problem.contact.size();
    benchmark::DoNotOptimize(r.l);
  }
  state.counters["unknowns"] = static_cast<double>(unknowns);
  state.counters["contact_nodes"] = static_cast<double>(contact);
}
BENCHMARK(BallOnBlock3D)
    ->ArgsProduct({{16, 24, 32}, {0, 1}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// One product with the stiffness of ball_on_block(n) on the CPU backend, as the iterative path
// holds it: the CSR arrays in place (0), a copy in node blocks (1), or the upper node blocks of the
// symmetric matrix (2, what upload_symmetric copies). GB/s counts the bytes of the matrix that
// the product streams (12 per entry in CSR, 8.4 in 3 x 3 blocks, about half that in upper ones).
void StiffnessProduct3D(benchmark::State& state) {
  const Model model = build_model(ball_on_block(state.range(0)));
  const SparseMatrix& A = model.problem.A;
  HostBackend be;
  const auto M = state.range(1) == 0   ? be.upload_symmetric(A, HostArrays::Share)
                 : state.range(1) == 1 ? be.upload_transpose(A, HostArrays::Copy)
                                       : be.upload_symmetric(A, HostArrays::Copy);
  const DeviceVector x = to_device(be, Vector::Ones(A.rows()));
  DeviceVector y(be, A.rows());
  for (auto _ : state) {
    be.spmv(*M, x, y);
    benchmark::ClobberMemory();
  }
  const double block_bytes = 8.0 + 4.0 / 9.0;
  const double stored =
      state.range(1) == 2
          ? 0.5 * (1.0 + 3.0 * static_cast<double>(A.rows()) / static_cast<double>(A.nonZeros()))
          : 1.0;  // the upper blocks and the diagonal's
  const double bytes_per_entry = state.range(1) == 0 ? 12.0 : block_bytes * stored;
  state.counters["unknowns"] = static_cast<double>(A.rows());
  state.counters["GB/s"] =
      benchmark::Counter(1e-9 * bytes_per_entry * static_cast<double>(A.nonZeros()) *
                             static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(StiffnessProduct3D)
    ->ArgsProduct({{40, 64, 88}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond);

// The fine level of the smoothed-aggregation hierarchy of ball_on_block(n) (n = 88: 1,045,572
// unknowns, the size of bench/peers/compare_3d.py --n 88), one product at a time: 0, the
// smoothed prolongation P = (I - omega D^-1 A) T; 1, the Galerkin product P^T A P; 2, rho(D^-1 A)
// by Lanczos steps (omega's). These are most of the multigrid set-up at a million unknowns.
void FineLevelProducts3D(benchmark::State& state) {
  const Model model = build_model(ball_on_block(state.range(0)));
  const SparseMatrix& A = model.problem.A;
  const SparseMatrix T =
      aggregate_level(A, rigid_body_modes(model.mesh, model.dofs), free_dof_nodes(model.dofs), {},
                      SmoothedAggregationOptions{}.strength_threshold)
          .tentative;
  const double omega = 4.0 / (3.0 * jacobi_spectral_radius(A));
  const SparseMatrix P = smoothed_prolongation(A, T, omega);
  for (auto _ : state) {
    switch (state.range(1)) {
      case 0:
        benchmark::DoNotOptimize(smoothed_prolongation(A, T, omega).nonZeros());
        break;
      case 1:
        benchmark::DoNotOptimize(galerkin_product(A, P).nonZeros());
        break;
      default:
        benchmark::DoNotOptimize(jacobi_spectral_radius(A));
    }
  }
  state.counters["unknowns"] = static_cast<double>(A.rows());
  state.counters["P_entries"] = static_cast<double>(P.nonZeros());
}
BENCHMARK(FineLevelProducts3D)->ArgsProduct({{88}, {0, 1, 2}})->Unit(benchmark::kMillisecond);

// The first touch of fresh memory (a 1 GiB anonymous mapping with transparent huge pages, one
// write per 4 KiB page), which a large solve pays for every array it makes: 0, the first mapping
// of the run (run this benchmark alone, so that no earlier one freed memory just before); 1, a
// second mapping right after the first was unmapped (the same pages again). On a virtual machine
// the first costs what the host pays to back the pages (docs/performance.md, "P's rows by
// aggregate").
void FirstTouch(benchmark::State& state) {
  constexpr std::size_t bytes = std::size_t{1} << 30;
  const auto touch = [&] {
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return static_cast<char*>(nullptr);
    madvise(p, bytes, MADV_HUGEPAGE);
    auto* c = static_cast<char*>(p);
    for (std::size_t i = 0; i < bytes; i += 4096) c[i] = 1;
    return c;
  };
  for (auto _ : state) {
    if (state.range(0) == 1) {
      state.PauseTiming();
      char* first = touch();
      if (first != nullptr) munmap(first, bytes);
      state.ResumeTiming();
    }
    char* p = touch();
    if (p == nullptr) {
      state.SkipWithError("mmap failed");
      break;
    }
    benchmark::DoNotOptimize(p[bytes / 2]);
    state.PauseTiming();
    munmap(p, bytes);
    state.ResumeTiming();
  }
  state.counters["GB/s"] = benchmark::Counter(
      1e-9 * static_cast<double>(bytes) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(FirstTouch)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
