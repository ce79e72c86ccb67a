#include "problem_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "commands.hpp"
#include "signorini/backend/host_backend.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/linalg/iterative_options.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/output/atomic_file.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::app {

namespace {

// The yardstick: one solve of A x = b with the best linear solver of the path. On the direct
// paths the sparse factorisation (analysis, factorisation, solve); on the CPU backend path (CG
// with multigrid, as the solver plan chooses in 3D) conjugate gradients from x = 0 with the same
// hierarchy, its set-up included, to the same tolerance: CHOLMOD or Jacobi CG would be a
// yardstick far slower than that path's own linear solver.
struct LinearSolveRun {
  double seconds = 0.0;
  int cg_iterations = 0;  // 0 on the direct paths
};

LinearSolveRun linear_solve(const Model& model, const ContactSolverOptions& solver) {
  const SparseMatrix& A = model.problem.A;
  const Index n = A.rows();
  if (uses_backend_path(solver) && solver.device == DeviceKind::Cpu) {
    const auto start = std::chrono::steady_clock::now();
    HostBackend backend;
    // No weights: H = A, held as the contact solve holds it.
    PenalizedOperator H(backend, A, model.problem.contact.N, stiffness_arrays(A));
    const std::unique_ptr<Preconditioner> M =
        make_preconditioner(H, A, model.problem.contact.N, &model.multigrid, solver.linear);
    Pcg pcg(backend, n);
    const DeviceVector b = to_device(backend, model.problem.b);
    DeviceVector x(backend, n);
    const PcgResult r = pcg.solve(H, *M, b, x, pcg_options(solver.linear, n));
    if (!r.converged)
      throw NumericalError(
          fmt::format("bench: the yardstick's CG did not converge ({:.1e})", r.residual));
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
            r.iterations};
  }
  const auto linear = make_linear_solver(solver.linear);
  linear->analyze(A);
  linear->factorize(A);
  Vector x = Vector::Zero(n);
  linear->solve(model.problem.b, x);
  return {linear->timings().total(), 0};
}

}  // namespace

int run_problem_bench(const ProblemBenchOptions& options) {
  const LoadedProblem loaded = read_problem_file(options.file);
  for (const std::string& w : loaded.warnings) fmt::print(stderr, "signorini: warning: {}\n", w);
  const ProblemSpec& spec = loaded.spec;

  // In this process: the model, the contact solve, and the yardstick, one linear solve of the
  // same A and b with the same linear solver (analysis, factorisation, solve: what a solve of
  // the problem without contact costs).
  // At least two rounds: the first pays the page faults of memory touched for the first time
  // (a third of a cold million-unknown solve), which the second reuses; the contact solve and
  // the linear solve are compared warm, the whole process below is cold. Each phase is timed by
  // the library's own timers.
  double best_build = 1e300, best_contact = 1e300, best_linear = 1e300;
  Index dofs = 0, contact_nodes = 0;
  int contact_cg = 0, linear_cg = 0;  // CG iterations of the last round (they do not vary)
  int repeats = std::max(options.repeats, 2);
  bool converged = true;
  std::string path;
  for (int r = 0; r < repeats; ++r) {
    const Model model = build_model(spec);
    best_build = std::min(best_build, model.timings.total());
    dofs = model.dofs.num_dofs();
    contact_nodes = model.problem.contact.size();
    if (dofs > 2000000) repeats = 2;                    // minutes otherwise
    const ContactSolverOptions& solver = model.solver;  // the path planned from the size
    const ContactResult result = solve_contact(model.problem, solver, &model.multigrid);
    best_contact = std::min(best_contact, result.summary.timings.seconds("contact solve"));
    converged = converged && result.summary.converged();
    path = enum_to_string(kSolvePathNames, result.summary.path);
    contact_cg = 0;
    for (const OuterStepRecord& step : result.summary.steps) contact_cg += step.linear_iterations;

    const LinearSolveRun linear = linear_solve(model, solver);
    best_linear = std::min(best_linear, linear.seconds);
    linear_cg = linear.cg_iterations;
  }

  // From the shell: `signorini solve FILE -o SCRATCH -q`, as a child, best of the same number
  // (one only for a problem over a million unknowns).
  const int child_repeats = dofs > 1000000 ? 1 : repeats;
  const ScratchFolder scratch;
  ChildRun best_child;
  best_child.wall_seconds = 1e300;
  for (int r = 0; r < child_repeats; ++r) {
    const ChildRun run = run_child(
        {own_executable(), "solve", options.file, "-o", (scratch.path() / "out").string(), "-q"},
        user_environment());
    if (run.exit_status != 0 && run.exit_status != kNotConverged)
      throw InputError(fmt::format("`signorini solve {}` failed (exit status {}): {}", options.file,
                                   run.exit_status, run.errors));
    converged = converged && run.exit_status == 0;
    if (run.wall_seconds < best_child.wall_seconds) best_child = run;
  }

  fmt::print("{}: {} unknowns, {} contact nodes; {} ({}), best of {} (whole process: {})\n",
             options.file, dofs, contact_nodes,
             enum_to_string(kContactMethodNames, spec.solver.method), path, repeats, child_repeats);
  fmt::print("  {:<44} {:>9}  {:>8}\n", "", "seconds", "ratio");
  // The CG iterations where the path iterates: they do not drift with the machine's moment.
  const auto iterations = [&](int cg) {
    return linear_cg > 0 ? fmt::format("   ({} CG iterations)", cg) : std::string();
  };
  fmt::print("  {:<44} {:>9.3f}  {:>8}{}\n",
             path == "backend" ? "one linear solve (CG, the same multigrid)"
                               : "one linear solve (analyse, factorise, solve)",
             best_linear, "1", iterations(linear_cg));
  fmt::print("  {:<44} {:>9.3f}  {:>8.2f}{}\n", "contact solve (in this process)", best_contact,
             best_contact / best_linear, iterations(contact_cg));
  fmt::print("  {:<44} {:>9.3f}\n", "model: mesh, assembly, loads, contact set", best_build);
  fmt::print("  {:<44} {:>9.3f}  {:>8.2f}   (peak {:.2f} GB)\n",
             "whole process (signorini solve, from outside)", best_child.wall_seconds,
             best_child.wall_seconds / best_linear, best_child.peak_rss_bytes / 1e9);
  if (!options.json_file.empty()) {
    const nlohmann::json j = {
        {"file", options.file},
        {"n_dofs", dofs},
        {"n_contact_nodes", contact_nodes},
        {"method", enum_to_string(kContactMethodNames, spec.solver.method)},
        {"path", path},
        {"repeats", repeats},
        {"converged", converged},
        {"seconds",
         {{"linear_solve", best_linear},
          {"contact_solve", best_contact},
          {"model", best_build},
          {"whole_process", best_child.wall_seconds}}},
        {"cg_iterations", {{"linear_solve", linear_cg}, {"contact_solve", contact_cg}}},
        {"contact_over_linear", best_contact / best_linear},
        {"whole_process_over_linear", best_child.wall_seconds / best_linear},
        {"whole_process_peak_bytes", best_child.peak_rss_bytes}};
    write_file_atomically(options.json_file, j.dump(2) + "\n");
  }
  return converged ? kSuccess : kNotConverged;
}

}  // namespace signorini::app
