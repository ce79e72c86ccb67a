#pragma once
// The seam between the serial library and a distributed one (docs/distributed.md). The library
// itself passes no messages: a build with PETSc adds the engine of src/signorini/petsc/ (the
// signorini_petsc library, linked by the signorini-mpi tool and its tests), which a program
// makes once and passes to build_model; the model's problem carries it (ContactProblem::engine),
// and the solver asks it whether to take the distributed path; the one Uzawa-GNM loop
// (uzawa_iteration.cpp, generalized_newton.cpp) then runs on the engine's NewtonSpace, whose
// vectors and matrices are PETSc's, spread over the ranks. Every rank runs the loop on the same
// replicated contact-node values (n_c numbers) and the same global reductions, so every rank takes
// the same decisions.

#include <memory>
#include <string>
#include <vector>

#include "signorini/contact/active_set_solver.hpp"
#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/contact/newton_space.hpp"
#include "signorini/contact/solve_summary.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/parallel/communicator.hpp"

namespace signorini {

/// A NewtonSpace whose vectors are distributed.
class DistributedNewtonSpace : public NewtonSpace {
 public:
  /// x as this rank's solution (a collective call): all n unknowns, gathered on every rank, or
  /// on a rank's part of the mesh the values of ContactProblem::solution_unknowns.
  [[nodiscard]] virtual Vector rank_solution() = 0;
  /// How the Newton systems are solved ("CG with GAMG (6 rigid-body modes)").
  [[nodiscard]] virtual std::string linear_solver_description() const = 0;
  /// N H^-1 N^T w on the current Newton matrix H (n_c values on every rank; x unchanged): the
  /// dual operator of classical Uzawa, where H = A. `stats` says how the solve went.
  [[nodiscard]] virtual Vector contact_response(const Vector& w, NewtonSolveStats& stats) = 0;
};

/// The Newton steps of semismooth Newton (active_set_solver.hpp) on distributed objects.
class DistributedActiveSetSolver : public ActiveSetSolver {
 public:
  /// How the steps are solved ("KSP cg with PC gamg (6 rigid-body modes)").
  [[nodiscard]] virtual std::string linear_solver_description() const = 0;
};

/// A Communicator (parallel/communicator.hpp) that also makes the solver's distributed objects.
class DistributedEngine : public Communicator {
 public:
  /// The Newton space of `problem` (partitioned, or held whole by every rank), starting at x0,
  /// this rank's rows of the start (ContactProblem::held_rows; timed in `timings`).
  [[nodiscard]] virtual std::unique_ptr<DistributedNewtonSpace> newton_space(
      const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
      TimingTable& timings) = 0;
  /// The Newton steps of semismooth Newton on `problem` (held whole by every rank), starting at
  /// x0; displacement() gathers x on every rank.
  [[nodiscard]] virtual std::unique_ptr<DistributedActiveSetSolver> active_set_solver(
      const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
      TimingTable& timings) = 0;
};

/// The engine of `problem` (ContactProblem::engine); InputError without one (the distributed
/// path's solvers).
[[nodiscard]] DistributedEngine& required_engine(const ContactProblem& problem);
/// What a distributed solve records in its summary: the ranks, and the engine and the linear
/// solver (`device`).
void record_distributed(SolveSummary& summary, const DistributedEngine& engine,
                        const std::string& linear_solver);

// In these, u is a solution of the problem (ContactResult::u): all n unknowns, or on a rank's
// part of the mesh the values of ContactProblem::solution_unknowns.

/// The rows of A u that this process holds (ContactProblem::first_row to end_row; all of them
/// unless partitioned). No message: a partitioned A holds the columns of these rows, A is
/// symmetric, and a part's solution has the unknowns of their columns.
[[nodiscard]] Vector held_stiffness_rows(const ContactProblem& problem, const Vector& u);
/// 1/2 <A u, u> - <b, u> (a collective call where partitioned: a single number is summed over
/// the ranks).
[[nodiscard]] double quadratic_energy(const ContactProblem& problem, const Vector& u);
/// N u, every row on every rank (a collective call for a part's solution: each row is computed
/// by the rank that owns its unknowns, and the n_c values summed over the ranks).
[[nodiscard]] Vector contact_rows(const ContactProblem& problem, const Vector& u);
/// The length of a solution of the problem: all n, or a part's (ContactProblem::
/// solution_unknowns).
[[nodiscard]] Index solution_size(const ContactProblem& problem);
/// ||u||_inf over all n unknowns (a collective call for a part's solution).
[[nodiscard]] double largest_displacement(const ContactProblem& problem, const Vector& u);
/// The rows of N^T v (v: one value per row of N) that this process holds.
[[nodiscard]] Vector held_contact_transpose_rows(const ContactProblem& problem, const Vector& v);
/// ||b|| over all n unknowns (a collective call where partitioned).
[[nodiscard]] double load_norm(const ContactProblem& problem);
/// Sums values over the ranks where the problem is partitioned (a collective call then).
void sum_over_ranks(const ContactProblem& problem, double* values, Index count);

/// The partition of a distributed solve of `problem` over `ranks` ranks: the one it was
/// assembled for (ContactProblem::row_starts) where it is partitioned, else row_partition
/// (parallel/row_partition.hpp) of its unknowns by their nodes and rows of N. The one rule for
/// the solvers and the result files.
[[nodiscard]] std::vector<Index> partition_of(const ContactProblem& problem, int ranks);

/// Whether a solve with these options on `engine` (null: none, a serial program) takes the
/// distributed path: `distributed` = "petsc", or "auto" with an engine of more than one rank.
/// Throws InputError for "petsc" without an engine and for "off" on more than one rank.
[[nodiscard]] bool distributed_path(const DistributedEngine* engine,
                                    const ContactSolverOptions& options);
/// The same for a solve of `problem` (on ContactProblem::engine).
[[nodiscard]] bool distributed_path(const ContactProblem& problem,
                                    const ContactSolverOptions& options);

}  // namespace signorini
