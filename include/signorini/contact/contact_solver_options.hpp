#pragma once
// Options of the contact solvers. Defaults are the paper's (Section 5 and method.md section 4):
// GNM tolerance 1e-10, Uzawa tolerance 1e-8, Armijo sigma = 1e-4, l^0 = 0, except r, which is
// chosen from the problem unless given (the paper's r = 1e8 suits only metres and MPa; method.md
// section 7), and the KKT test that every "converged" must pass. Each field name is also the key
// of the [solver] table in a problem file, declared once with its range and doc in
// contact_solver_option_table() (src/signorini/contact/contact_solver_option_table.hpp), which
// the file reader, validate(), the reports and docs/problem-format.md all use.

#include <functional>
#include <optional>
#include <string>

#include "signorini/backend/device_kind.hpp"
#include "signorini/core/enum_names.hpp"
#include "signorini/core/types.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

enum class ContactMethod { UzawaGnm, ClassicalUzawa, SemismoothNewton };

inline constexpr EnumNames<ContactMethod, 3> kContactMethodNames{{
    {ContactMethod::UzawaGnm, "uzawa_gnm"},
    {ContactMethod::ClassicalUzawa, "classical_uzawa"},
    {ContactMethod::SemismoothNewton, "semismooth_newton"},
}};

/// How accurately each Uzawa step is minimised (ContactSolverOptions::inner_tolerance).
enum class InnerTolerance { Auto, Fixed, Adaptive };

inline constexpr EnumNames<InnerTolerance, 3> kInnerToleranceNames{{
    {InnerTolerance::Auto, "auto"},
    {InnerTolerance::Fixed, "fixed"},
    {InnerTolerance::Adaptive, "adaptive"},
}};

/// Whether the solve runs distributed over MPI ranks through PETSc
/// (ContactSolverOptions::distributed, docs/distributed.md).
enum class DistributedMode { Auto, Petsc, Off };

inline constexpr EnumNames<DistributedMode, 3> kDistributedModeNames{{
    {DistributedMode::Auto, "auto"},
    {DistributedMode::Petsc, "petsc"},
    {DistributedMode::Off, "off"},
}};

/// How a distributed run shares the mesh among the ranks (docs/distributed.md).
enum class PartitionMode { Auto, Graph };
inline constexpr EnumNames<PartitionMode, 2> kPartitionModeNames{{
    {PartitionMode::Auto, "auto"},
    {PartitionMode::Graph, "graph"},
}};

/// The algebraic multigrid of the distributed path (ContactSolverOptions::petsc_multigrid).
enum class PetscMultigrid { Auto, Gamg, Aggregation, Hypre };

inline constexpr EnumNames<PetscMultigrid, 4> kPetscMultigridNames{{
    {PetscMultigrid::Auto, "auto"},
    {PetscMultigrid::Gamg, "gamg"},
    {PetscMultigrid::Aggregation, "aggregation"},
    {PetscMultigrid::Hypre, "hypre"},
}};

/// What petsc_multigrid = Auto is on `ranks` ranks: on one, the serial tool's own smoothed
/// aggregation (the serial path's hierarchy, made in 0.5-0.7 times GAMG's set-up time on hex8
/// cells); on several, GAMG, whose aggregates cross the ranks' borders, so that its coarsest
/// level does not grow with the number of ranks (docs/distributed.md, "Our own levels").
[[nodiscard]] constexpr PetscMultigrid resolved_petsc_multigrid(PetscMultigrid chosen, int ranks) {
  if (chosen != PetscMultigrid::Auto) return chosen;
  return ranks == 1 ? PetscMultigrid::Aggregation : PetscMultigrid::Gamg;
}

/// Reported to ContactSolverOptions::observer as the solver goes, for progress logs.
struct IterationEvent {
  enum class Kind { Inner, Outer };
  Kind kind = Kind::Inner;
  int outer = 0;          ///< Uzawa step k (or Newton iteration of the semismooth method)
  int inner = 0;          ///< GNM iteration m within step k (Inner events)
  Index active = 0;       ///< size of the active set
  double residual = 0.0;  ///< Inner: max(||G||/f, ||dx||/||x||); Outer: ||l^k - l^{k-1}|| / ||l^k||
  int armijo = 0;         ///< Armijo halvings in this GNM iteration
  int linear_iterations = 0;
};

/// What a callback (ContactSolverOptions::callback) wants after an iteration.
enum class CallbackAction { Continue, Stop };

struct ContactSolverOptions {
  /// "uzawa_gnm": the paper's modified-Lagrangian Uzawa method (13) with the generalised Newton
  /// method (17) for step (i); "classical_uzawa": Uzawa on the ordinary Lagrangian (the baseline);
  /// "semismooth_newton": primal-dual active set method on the KKT system.
  ContactMethod method = ContactMethod::UzawaGnm;
  /// Augmentation parameter r > 0 of the modified Lagrangian (10). The solution does not depend
  /// on it; it changes the iteration path only. Empty: automatic, r = auto_r_factor times the
  /// median over the contact nodes of (N A N^T)_jj / h_j, a stiffness per area of the problem
  /// itself, so that the same physical problem takes the same iterations in any consistent units
  /// (method.md section 7). The paper's examples give r = 1e8 (metres and MPa).
  std::optional<double> r;
  /// The dimensionless factor of the automatic r (ignored when r is given).
  double auto_r_factor = 10.0;
  /// "Converged" also requires every relative KKT residual of the result (equilibrium,
  /// penetration, sign, complementarity; KktResiduals) to be below this, whatever the method's
  /// own rule says (method.md section 7).
  double kkt_tolerance = 1e-6;
  /// Uzawa (both variants) stops when ||l^k - l^{k-1}||_2 / ||l^k||_2 < uzawa_tolerance.
  double uzawa_tolerance = 1e-8;
  int max_uzawa_iterations = 1000;
  /// GNM stops when max(||G(x_m)||_2 / f, ||x_m - x_{m-1}||_2 / ||x_m||_2) < gnm_tolerance, with
  /// the force scale f = max(||b||_2, ||A x_m - b||_2) (the paper's rule with the gradient made
  /// relative, method.md section 7), or when the active set repeats after a full Newton step (the
  /// minimiser is then exact).
  double gnm_tolerance = 1e-10;
  /// GNM iteration limit per Uzawa step; 0: automatic, gnm_iteration_limit().
  int max_gnm_iterations = 0;
  /// Armijo rule: Phi(x + a d) <= Phi(x) + armijo_sigma a <G(x), d>, a = 1/2, 1/4, ...
  double armijo_sigma = 1e-4;
  int max_armijo_halvings = 60;
  /// Step rho of the classical Uzawa method; 0 chooses 1.5 / lambda_max of the dual operator.
  double classical_step = 0.0;
  int max_classical_iterations = 200000;
  /// Iteration limit of the semismooth Newton (primal-dual active set) method; 0: automatic,
  /// newton_iteration_limit().
  int max_newton_iterations = 0;
  /// Seconds a solve may take (each ContactSolver::solve); 0: no limit. Past it the solve stops
  /// at the next iteration with termination "time_limit" and the current iterate, its KKT
  /// residuals reported (the tool writes it and exits with status 3).
  double time_limit = 0.0;
  LinearSolverOptions linear;
  /// Where the solve runs: "cpu" or "cuda" (an NVIDIA GPU, docs/gpu.md). "cuda" runs the whole
  /// Uzawa-GNM loop with its vectors on the GPU and needs linear.type = "cg"; the "cg" solver
  /// with the "multigrid" preconditioner runs on that same backend path on the CPU too.
  DeviceKind device = DeviceKind::Cpu;
  /// With the "cholmod" linear solver: condense the problem onto the normal displacements of the
  /// contact nodes by one sparse factorisation (a Schur complement) and iterate on that small
  /// dense problem (docs/performance.md). The solution is the same; only the cost changes.
  /// Ignored for "cg" (the paper's configuration) and "dense".
  bool schur_complement = true;
  /// Threads the solver may use; 0: as many as the machine runs at once. Today only the
  /// condensation uses them: from 100,000 unknowns on, it factorises two parts of the problem at
  /// once (linalg/schur_complement.hpp). 1: one thread, one factorisation.
  int threads = 0;
  /// Adaptive: inexact Uzawa-GNM, each Uzawa step k minimised only as accurately as its
  /// multipliers warrant, GNM to tau_k = min(0.001 x the previous step's relative dual change,
  /// tau_(k-1) / 10) (at least 10 x linear.cg_tolerance), and on the iterative (backend) path each
  /// Newton system solved by CG to a tenth of that (uzawa_iteration.cpp). The last steps are
  /// solved more tightly than gnm_tolerance; the KKT check is unchanged. Fewer CG iterations for
  /// the same solution to the solver's tolerances; the counts differ from the exact method's.
  /// Fixed: every step to gnm_tolerance and cg_tolerance (the paper's method).
  /// Auto: adaptive where build_model plans the iterative path (problem/solver_plan.hpp), fixed
  /// otherwise.
  InnerTolerance inner_tolerance = InnerTolerance::Auto;
  /// With inexact Uzawa-GNM (adaptive inner tolerance) on the iterative and distributed paths:
  /// from step 2 on, once the multipliers change by less than 0.2, finish by semismooth Newton's
  /// steps from Uzawa's state (the energy minimised with the nodes in contact fixed, by
  /// projected CG, the set corrected by the primal-dual rule) and take the result as the answer
  /// where the KKT conditions hold (uzawa_iteration.cpp, docs/solvers.md). The same solution to
  /// the solver's tolerances in fewer CG iterations. false: Uzawa's steps to the end.
  bool active_set_finish = true;

  /// True when the Uzawa steps are minimised inexactly (inner_tolerance = Adaptive).
  [[nodiscard]] bool adaptive_inner_tolerance() const {
    return inner_tolerance == InnerTolerance::Adaptive;
  }
  /// Let build_model() choose the path from the problem's size and the machine's memory
  /// (problem/solver_plan.hpp): with the default "cholmod" solver on the CPU, CG with multigrid
  /// for 3D problems above 15,000 free unknowns or a factor that would not fit, and the sparse
  /// direct path when the condensed matrix would not fit. false: exactly as configured.
  bool automatic_path = true;
  /// Auto: the PETSc path (docs/distributed.md) where the tool runs on more than one MPI rank
  /// (a build with PETSc, started by mpirun), the serial paths otherwise. Petsc: the PETSc path
  /// even on one rank (an InputError where the model was built without a PETSc engine). Off:
  /// never (an InputError on more than one rank).
  DistributedMode distributed = DistributedMode::Auto;
  /// Auto: on more than one rank a generated box is made in blocks, each rank its own
  /// (problem/box_model_in_parts.hpp); any other mesh is read by rank 0, its nodes partitioned
  /// by PETSc's graph partitioner and sent in parts; each rank builds its part of the model
  /// (problem/model_in_parts.hpp). Graph: rank 0 builds
  /// the whole model from a partition by the graph partitioner, for a box too.
  PartitionMode partition = PartitionMode::Auto;
  /// Options for PETSc's database on the PETSc path ("-ksp_monitor -pc_gamg_threshold 0.02"):
  /// they apply to the Newton systems' KSP after signorini's own choices, for experts.
  std::string petsc_options;
  /// The multigrid of linear.preconditioner = "multigrid" on the distributed path: PETSc's GAMG
  /// (smoothed aggregation on the rigid-body modes), the serial tool's smoothed aggregation on
  /// each rank's nodes, or hypre's BoomerAMG; Auto: resolved_petsc_multigrid().
  PetscMultigrid petsc_multigrid = PetscMultigrid::Auto;
  /// Called after every inner and outer iteration; may be empty.
  std::function<void(const IterationEvent&)> observer;
  /// Called after the observer at every event; returning CallbackAction::Stop ends the solve at
  /// once with termination "stopped_by_callback" and the current iterate (a user abort, a time
  /// limit). May be empty.
  std::function<CallbackAction(const IterationEvent&)> callback;
};

/// Reports `event` to the observer and the callback of `options`; true when the callback asks to
/// stop.
[[nodiscard]] bool notify(const ContactSolverOptions& options, const IterationEvent& event);

/// True when the solve runs on the backend path (docs/gpu.md): on a GPU, or with the multigrid
/// preconditioner of conjugate gradients.
[[nodiscard]] bool uses_backend_path(const ContactSolverOptions& options);

/// Throws InputError naming the first bad field ("solver.r = -1: expected ...").
void validate(const ContactSolverOptions& options);

struct ContactProblem;

/// The automatic r of a problem: auto_r_factor * median_j (N A N^T)_jj / h_j over the movable
/// contact nodes (method.md section 7). Units of stress per length, like r.
[[nodiscard]] double automatic_r(const ContactProblem& problem, double factor);

/// The GNM iteration limit per Uzawa step for a contact set of `contact_nodes` nodes:
/// max_gnm_iterations where given, else (0) a quarter of the contact nodes, at least 100 and at
/// most 2000. An active-set step may add or release only a few nodes where the contact zone's
/// edge moves little per step (a thin strip of cells 500 times longer than high: 3 nodes a
/// step, 133 steps for 3,001 contact nodes), so a fixed limit would stop large problems that
/// converge.
[[nodiscard]] int gnm_iteration_limit(const ContactSolverOptions& options, Index contact_nodes);
/// The same for semismooth Newton: max_newton_iterations, else a quarter of the contact nodes,
/// at least 200 and at most 2000. Its active set never returns to an earlier one (that ends the
/// run as active_set_cycling), so a run stopped by the limit would end if given more steps.
[[nodiscard]] int newton_iteration_limit(const ContactSolverOptions& options, Index contact_nodes);

/// options.r if given, else automatic_r(problem, options.auto_r_factor).
[[nodiscard]] double augmentation_parameter(const ContactProblem& problem,
                                            const ContactSolverOptions& options);

}  // namespace signorini
