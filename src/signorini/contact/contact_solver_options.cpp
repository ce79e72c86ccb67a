#include "signorini/contact/contact_solver_options.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver_option_table.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"
#include "signorini/linalg/linear_solver_option_table.hpp"

namespace signorini {

const OptionTable<ContactSolverOptions>& contact_solver_option_table() {
  using O = ContactSolverOptions;
  static const OptionTable<O> table = [] {
    OptionTable<O> t("solver");
    t.choice(
        "method", &O::method, kContactMethodNames,
        "`uzawa_gnm`: the paper's Uzawa method on the modified Lagrangian with generalised "
        "Newton steps; `classical_uzawa`: Uzawa on the ordinary Lagrangian (the baseline the "
        "paper improves on, slow; not with `multigrid` or a GPU); `semismooth_newton`: primal-dual "
        "active set method on the KKT system, on every path (on the iterative one by "
        "projected conjugate gradients: [solvers.md](solvers.md))");
    t.number_or_auto(
        "r", &O::r, positive(),
        "augmentation parameter of the modified Lagrangian (a stress per length). The solution "
        "does not depend on it, only the iteration path does. `\"auto\"` (or no `r`): chosen "
        "from the problem, `auto_r_factor` times the median over the contact nodes of the "
        "normal stiffness per boundary area, so that the same physical problem takes the same "
        "iterations in any units ([method.md](method.md) section 7). The paper's examples give "
        "`r = 1e8` (metres and MPa) to reproduce Table 1");
    t.number("auto_r_factor", &O::auto_r_factor, positive(),
             "the dimensionless factor of the automatic r: larger takes fewer Uzawa steps (7 on "
             "every Table 1 mesh at 10) and harder Newton steps");
    t.number("kkt_tolerance", &O::kkt_tolerance, open_interval(0.0, 1.0),
             "a run is reported converged only when the method's own rule holds and every "
             "relative KKT residual (equilibrium, penetration, sign, complementarity; "
             "[solvers.md](solvers.md)) is below this; otherwise it ends with "
             "`kkt_residuals_too_large`, exit status 3");
    t.number("uzawa_tolerance", &O::uzawa_tolerance, positive(),
             "Uzawa stops when ||l^k - l^(k-1)|| / ||l^k|| is below it");
    t.integer("max_uzawa_iterations", &O::max_uzawa_iterations, at_least(1),
              "Uzawa iteration limit");
    t.number("gnm_tolerance", &O::gnm_tolerance, positive(),
             "GNM stops when max(||G(x_m)|| / f, ||x_m - x_(m-1)|| / ||x_m||) is below it, "
             "f = max(||b||, ||A x_m - b||) (the paper's rule, with the gradient made relative "
             "so that it means the same in any units)");
    t.integer("max_gnm_iterations", &O::max_gnm_iterations, at_least(0),
              "GNM iteration limit per Uzawa step; 0: a quarter of the contact nodes, at least "
              "100 and at most 2000 (an active-set step may move the contact zone's edge by a "
              "few nodes only)")
        .range_note("(0: automatic)");
    t.number("armijo_sigma", &O::armijo_sigma, open_interval(0.0, 0.5),
             "sufficient-decrease constant of the Armijo rule");
    t.integer("max_armijo_halvings", &O::max_armijo_halvings, at_least(1),
              "step halvings before a line search counts as failed");
    t.number("classical_step", &O::classical_step, at_least(0.0),
             "step rho of `classical_uzawa`; 0 chooses 1.5 / lambda_max of the dual operator")
        .range_note("(0: automatic)");
    t.integer("max_classical_iterations", &O::max_classical_iterations, at_least(1),
              "iteration limit of `classical_uzawa`");
    t.integer("max_newton_iterations", &O::max_newton_iterations, at_least(0),
              "iteration limit of `semismooth_newton`; 0: a quarter of the contact nodes, at "
              "least 200 and at most 2000")
        .range_note("(0: automatic)");
    t.number("time_limit", &O::time_limit, at_least(0.0),
             "seconds a solve may take; past it the solve stops at the next iteration with "
             "termination `time_limit` and the current iterate, which the tool writes (exit "
             "status 3). In seconds; 0: no limit")
        .range_note("(0: none)");
    t.boolean("schur_complement", &O::schur_complement,
              "with the `cholmod` linear solver: condense the problem onto the contact nodes by "
              "one sparse factorisation (a Schur complement) and iterate on that small dense "
              "problem (docs/solvers.md). Same solution, lower cost. Ignored for `cg` and "
              "`dense`");
    t.integer("threads", &O::threads, at_least(0),
              "threads the solver may use; 0: as many as the machine runs at once. Today the "
              "condensation (`schur_complement`) uses two from 100,000 unknowns on, factorising "
              "two parts of the problem at once; 1: one factorisation on one thread. The "
              "solution differs by rounding only")
        .range_note("(0: automatic)");
    t.choice("inner_tolerance", &O::inner_tolerance, kInnerToleranceNames,
             "how accurately each Uzawa step is minimised. `\"adaptive\"`: inexact Uzawa-GNM, "
             "step k to min(0.001 x the previous step's relative dual change, a tenth of step "
             "k-1's tolerance) (at least 10 x `cg_tolerance`), and with `cg` each Newton "
             "system to a tenth of that: fewer CG "
             "iterations, the same solution to the solver's tolerances, other counts; "
             "`semismooth_newton` on the iterative path solves its Newton steps to 1e-6 until "
             "the active set repeats, then to `cg_tolerance`. "
             "`\"fixed\"`: every step to `gnm_tolerance` and `cg_tolerance` (the paper's "
             "method). `\"auto\"`: adaptive where `automatic_path` chooses the iterative path, "
             "fixed otherwise ([solvers.md](solvers.md))");
    t.boolean("active_set_finish", &O::active_set_finish,
              "with inexact Uzawa-GNM (`inner_tolerance` adaptive, the iterative and distributed "
              "paths): from step 2 on, once the multipliers change by less than 0.2, finish by "
              "semismooth Newton's steps from Uzawa's state (the problem with the nodes in "
              "contact fixed, by projected CG, the set corrected until it repeats) and take the "
              "result as the answer where its multipliers are nonnegative and no other node "
              "penetrates; the same solution to the solver's tolerances in fewer CG iterations "
              "([solvers.md](solvers.md)). `false`: Uzawa's steps to the end");
    t.boolean("automatic_path", &O::automatic_path,
              "choose the solver path from the problem's size and this machine's memory: with "
              "the default `cholmod` solver on the CPU, `cg` with `multigrid` for 3D problems "
              "above 15,000 free unknowns or a sparse factor that would not fit, and the sparse "
              "direct path when the condensed matrix would not fit; the summary says which and "
              "why ([solvers.md](solvers.md)). `false`: exactly as configured");
    t.choice("distributed", &O::distributed, kDistributedModeNames,
             "`\"auto\"`: solve through PETSc on every MPI rank when the tool runs on more than "
             "one (`mpirun -n N signorini solve ...`), serially otherwise; `\"petsc\"`: the "
             "PETSc path even on one rank; `\"off\"`: never (an error under mpirun with more "
             "than one rank). Needs a build with PETSc ([distributed.md](distributed.md))");
    t.choice("partition", &O::partition, kPartitionModeNames,
             "how a run on several MPI ranks shares the mesh and builds the model: "
             "`\"auto\"`, a generated box in blocks of cubes that each rank makes itself (no "
             "rank holds the whole mesh), any other mesh read by rank 0, its nodes partitioned "
             "by PETSc's graph partitioner (PT-Scotch) and sent in parts, from which each rank "
             "builds its part of the model; `\"graph\"`: rank 0 makes or reads the mesh, "
             "partitions it "
             "with PT-Scotch and builds the whole model, for a box too "
             "([distributed.md](distributed.md))");
    t.text("petsc_options", &O::petsc_options,
           "options for PETSc's database on the PETSc path, applied to the Newton systems' "
           "solver after signorini's own (`\"-ksp_monitor -pc_gamg_threshold 0.02\"`); empty: "
           "none");
    t.choice("petsc_multigrid", &O::petsc_multigrid, kPetscMultigridNames,
             "on the distributed path, the multigrid of `[solver.linear] preconditioner = "
             "\"multigrid\"`: `\"auto\"`, `\"aggregation\"` on one rank and `\"gamg\"` on "
             "several; `\"gamg\"`, PETSc's smoothed aggregation on the rigid-body "
             "modes, its levels formed once and kept for every active set of Uzawa-GNM (a "
             "`-pc_type` in `petsc_options` replaces them); `\"aggregation\"`, the serial "
             "tool's smoothed aggregation made on each rank's own nodes, with its own Galerkin "
             "products on the rank's threads, kept likewise (semismooth Newton takes GAMG); "
             "`\"hypre\"`, hypre's BoomerAMG "
             "(classical AMG, without the modes: slower "
             "on elastic bodies) ([distributed.md](distributed.md))");
    t.choice("device", &O::device, kDeviceKindNames,
             "where the solve runs; `\"cuda\"`: the whole Uzawa–GNM loop on an NVIDIA GPU, with "
             "`[solver.linear] type = \"cg\"` ([gpu.md](gpu.md))");
    return t;
  }();
  return table;
}

bool notify(const ContactSolverOptions& options, const IterationEvent& event) {
  if (options.observer) options.observer(event);
  return options.callback && options.callback(event) == CallbackAction::Stop;
}

bool uses_backend_path(const ContactSolverOptions& o) {
  return o.device == DeviceKind::Cuda || (o.linear.type == LinearSolverType::ConjugateGradient &&
                                          o.linear.preconditioner == PreconditionerType::Multigrid);
}

void validate(const ContactSolverOptions& o) {
  // Key names and ranges from the tables ("solver.r = -1: expected a positive number or
  // \"auto\""), then linalg's own check of its options, then what no single option says.
  check_ranges(contact_solver_option_table(), o);
  check_ranges(linear_solver_option_table(), o.linear);
  validate(o.linear);
  // The backend path (docs/gpu.md) runs the paper's method with conjugate gradients only.
  if (o.device == DeviceKind::Cuda && o.linear.type != LinearSolverType::ConjugateGradient)
    throw InputError(fmt::format(
        "solver.device = \"cuda\" with solver.linear.type = \"{}\": the GPU solver is "
        "iterative; set solver.linear.type = \"cg\" (and solver.linear.preconditioner = "
        "\"multigrid\" for speed)",
        enum_to_string(kLinearSolverTypeNames, o.linear.type)));
}

double automatic_r(const ContactProblem& p, double factor) {
  // (N A N^T)_jj = nu_j^T A_jj nu_j over node j's free dofs is the normal stiffness of contact
  // node j (force per length); divided by the node's share h_j of the boundary it is a stiffness
  // per area, the units of r (stress per length). So r scales with E / h in every consistent set
  // of units, and r h_j / (N A N^T)_jj = factor: the penalty is as stiff as the body at the node,
  // whatever the units and the mesh size (method.md section 7).
  const ContactSet& c = p.contact;
  const SparseMatrix Nt = c.N.transpose();  // column j = row j of N
  // A partitioned A has node j's block only on the rank that owns the node: the others add 0.
  // With friction the normal row of node j is row components * j.
  Vector stiffness = Vector::Zero(c.size());
  for (Index j = 0; j < c.size(); ++j)
    for (SparseMatrix::InnerIterator a(Nt, c.components * j); a; ++a)
      for (SparseMatrix::InnerIterator b(Nt, c.components * j); b; ++b)
        if (b.row() >= p.first_row() && b.row() < p.end_row())  // (A's columns: column_of)
          stiffness(j) += a.value() * p.A.coeff(a.row(), p.column_of(b.row())) * b.value();
  sum_over_ranks(p, stiffness.data(), stiffness.size());
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(c.size()));
  for (Index j = 0; j < c.size(); ++j) {
    if (!c.movable[static_cast<std::size_t>(j)] || !(c.weights(j) > 0.0)) continue;
    if (stiffness(j) > 0.0) values.push_back(stiffness(j) / c.weights(j));
  }
  if (values.empty())
    throw InputError(
        "solver.r: no contact node has a free normal displacement, so r cannot be chosen "
        "automatically; give solver.r");
  // The median: corner nodes (half weights) and nodes beside a clamp do not decide it.
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return factor * *mid;
}

namespace {
int quarter_of(Index contact_nodes, int floor) {
  return static_cast<int>(std::clamp<Index>(contact_nodes / 4, floor, 2000));
}
}  // namespace

int gnm_iteration_limit(const ContactSolverOptions& options, Index contact_nodes) {
  return options.max_gnm_iterations > 0 ? options.max_gnm_iterations
                                        : quarter_of(contact_nodes, 100);
}

int newton_iteration_limit(const ContactSolverOptions& options, Index contact_nodes) {
  return options.max_newton_iterations > 0 ? options.max_newton_iterations
                                           : quarter_of(contact_nodes, 200);
}

double augmentation_parameter(const ContactProblem& problem, const ContactSolverOptions& options) {
  return options.r ? *options.r : automatic_r(problem, options.auto_r_factor);
}

}  // namespace signorini
