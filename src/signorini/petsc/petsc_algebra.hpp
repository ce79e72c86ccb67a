#pragma once
// The PETSc objects that both distributed solvers build (petsc_newton_space.hpp for Uzawa-GNM,
// petsc_active_set_solver.hpp for semismooth Newton): a rank's rows of a matrix that every rank
// holds whole, vectors filled from and gathered into whole vectors, and the KSP that the serial
// options choose (docs/distributed.md, "Which path, and options").

#include <petscksp.h>

#include <string>
#include <utility>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/core/types.hpp"

namespace signorini::petsc {

/// The range [first, second) of unknowns that this rank of `comm` owns (partition_of).
[[nodiscard]] std::pair<Index, Index> owned_rows(const ContactProblem& problem, MPI_Comm comm);

/// Rows [lo, hi) of the symmetric, column-major A (row i of A is its column i) as an MPIAIJ
/// matrix, marked symmetric positive definite.
[[nodiscard]] Mat distributed_rows(const SparseMatrix& A, Index lo, Index hi, MPI_Comm comm);

/// v's entries [lo, hi) (this rank's) from the whole vector `whole`.
void set_local(Vec v, const Vector& whole, Index lo, Index hi);

/// The whole vector on every rank.
[[nodiscard]] Vector gather(Vec v);

/// What configure_ksp chose.
struct KspChoice {
  bool direct = false;      ///< KSP preonly with a factorisation
  std::string description;  ///< "KSP cg with PC gamg (6 rigid-body modes)"
};

/// Sets `ksp` up for the operator H from the serial options: "cg" with "multigrid" -> CG with GAMG
/// on the columns of `near_null_space` (whole, made orthonormal; none when it is empty), "cg"
/// with "jacobi" -> CG with Jacobi, a direct solver -> MUMPS's Cholesky factorisation; CG measures
/// the unpreconditioned residual and starts from the given x. Then solver.petsc_options.
/// `reuse_interpolation`: GAMG keeps its prolongators when H's values change.
KspChoice configure_ksp(KSP ksp, Mat H, const ContactSolverOptions& options,
                        const Matrix& near_null_space, Index lo, Index hi,
                        bool reuse_interpolation);

/// Relative residual, iterations and convergence of the last KSPSolve with right-hand side rhs.
struct KspOutcome {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;
  std::string reason;  ///< PETSc's name of the reason, e.g. "DIVERGED_ITS"
};
[[nodiscard]] KspOutcome ksp_outcome(KSP ksp, Vec rhs, bool direct);

/// Sets the relative tolerance and iteration limit of an iterative KSP.
void set_ksp_tolerance(KSP ksp, const ContactSolverOptions& options, double tolerance, Index n);

}  // namespace signorini::petsc
