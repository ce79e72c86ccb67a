#pragma once
// The PETSc objects that both distributed solvers build (petsc_newton_space.hpp for Uzawa-GNM,
// petsc_active_set_solver.hpp for semismooth Newton): a rank's rows of a matrix that every rank
// holds whole, vectors filled from and gathered into whole vectors, and the KSP that the serial
// options choose (docs/distributed.md, "Which path, and options").

#include <petscksp.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/core/types.hpp"

namespace signorini::petsc {

/// The range [first, second) of unknowns that this rank of `comm` owns (partition_of).
[[nodiscard]] std::pair<Index, Index> owned_rows(const ContactProblem& problem, MPI_Comm comm);

/// Marks M symmetric for good, and positive definite where its type takes the option.
void mark_spd(Mat M, const char* what);

/// Rows [lo, hi) of the symmetric, column-major A (row i of A is its column i) as an MPIAIJ
/// matrix of block size `block`, marked symmetric positive definite. A holds either all its
/// columns (n x n) or only these (n x (hi - lo), column i at i - lo: a partitioned problem's A,
/// ContactProblem::column_of).
[[nodiscard]] Mat distributed_rows(const SparseMatrix& A, Index lo, Index hi, MPI_Comm comm,
                                   PetscInt block = 1);

/// S^T as a SeqAIJ matrix on `comm` (of one process) in blocks of `block`: S itself where it is
/// symmetric, such as A or a Galerkin product, and a prolongation's restriction from the
/// prolongation. The matrix takes S and reads its arrays in place (S's column pointers are the
/// row pointers of S^T), freeing them with itself: no copy, where a copy into PETSc took a
/// third of a second per 18 million entries (a level's matrix is made once and only read).
/// S's entries are sorted in each column here where they are not. (A copy where PETSc's
/// indices are not 32-bit.)
[[nodiscard]] Mat sequential_matrix(SparseMatrix&& S, MPI_Comm comm, PetscInt block = 1);

/// The same on S's arrays without taking them: S must outlive M and keep its values (PETSc never
/// writes them). A copy, as sequential_matrix, where S is not compressed with each column's
/// entries ascending (or PETSc's indices are not 32-bit). One rank's A for the set-up, which
/// the model holds through the solve (instead of a copy of 1 GB at a million hex8 unknowns).
[[nodiscard]] Mat sequential_view(const SparseMatrix& S, MPI_Comm comm, PetscInt block = 1);

/// The matrix S that sequential_matrix made M from (read-only, alive as long as M), or null
/// where M was made otherwise.
[[nodiscard]] const SparseMatrix* held_matrix(Mat M);

/// As distributed_rows, in node blocks of `block` rows (MPIBAIJ) where `block` is above 1: a
/// product with a 3 x 3 block matrix reads a ninth of the column indices (12 ms against AIJ's
/// 14 ms at 100,860 unknowns). GAMG's set-up needs AIJ; the products of the CG and the smoothers
/// take either.
[[nodiscard]] Mat block_rows(const SparseMatrix& A, Index lo, Index hi, MPI_Comm comm,
                             PetscInt block);

/// Attaches the columns of `near_null_space` (this rank's rows of M; made orthonormal over the
/// ranks) to M as its near-null space, for GAMG; returns how many were kept.
std::size_t attach_near_null_space(Mat M, const Matrix& near_null_space);

/// The sum of `mine` over the ranks before this one (0 on the first): where this rank's share
/// starts in a numbering rank by rank. Collective.
[[nodiscard]] PetscInt count_before(PetscInt mine, MPI_Comm comm);

/// lambda_max(D^-1 A) estimated by 10 steps of Jacobi-preconditioned CG from a random right-hand
/// side (the Lanczos values of CG), as GAMG's smoothers estimate theirs.
[[nodiscard]] double jacobi_lambda_max(Mat A);

/// Returns the memory that the process has freed to the system (glibc keeps freed blocks in the
/// process's heap, where later allocations fit only in part, and its resident size stays): after
/// GAMG's set-up and when a Newton space is destroyed, so that neither the node-block matrices
/// made next nor the results written after a solve raise the peak (docs/distributed.md, "Memory
/// per rank"). A no-op without glibc.
void give_back_freed_memory();

/// The rows [first, last) of this rank of `v`, a vector (or the columns of a matrix) of the
/// problem's rows, such as b or the near-null space: v itself for a partitioned problem, which
/// holds only these (ContactProblem), else those rows of the whole.
[[nodiscard]] Vector rank_rows(const ContactProblem& problem, const Vector& v, Index first,
                               Index last);
[[nodiscard]] Matrix rank_rows(const ContactProblem& problem, const Matrix& m, Index first,
                               Index last);

/// v's entries on this rank from `rows`, as many as the rank holds.
void set_owned(Vec v, const Vector& rows);

/// The whole vector on every rank.
[[nodiscard]] Vector gather(Vec v);
/// The entries `at` (global indices, any rank's) of the distributed v on this rank, from their
/// owners by one scatter (a collective call).
[[nodiscard]] Vector values_at(Vec v, const std::vector<PetscInt>& at);
/// The ranks' entries `own` (each rank's, in the order of the ranks) put together on every rank:
/// one MPI_Allgatherv into the result, with no whole copy beside it.
[[nodiscard]] Vector allgather(const Vector& own, MPI_Comm comm);

/// What configure_ksp chose.
struct KspChoice {
  bool direct = false;      ///< KSP preonly with a factorisation
  std::string description;  ///< "KSP cg with PC gamg (6 rigid-body modes)"
};

/// solver.petsc_options into PETSc's options database.
void insert_petsc_options(const ContactSolverOptions& options);
/// The same for an option string alone (solver.petsc_options; empty: nothing).
void insert_petsc_options(const std::string& petsc_options);

/// Whether Uzawa-GNM's CG keeps its multigrid levels (ContactMultigrid): "cg" with "multigrid"
/// on "gamg" or "aggregation", and no -pc_type among the PETSc options.
[[nodiscard]] bool keeps_multigrid_levels(const ContactSolverOptions& options);

/// Makes `pc` the multigrid of CG for "cg" with "multigrid" on GAMG (ContactMultigrid); returns
/// what it made, for the description.
using MultigridBuilder = std::function<std::string(PC pc)>;

/// Sets `ksp` up for the operator H from the serial options: "cg" with "multigrid" -> CG with GAMG
/// on the columns of `near_null_space` (this rank's rows, made orthonormal; none when it is
/// empty), "cg" with "jacobi" -> CG with Jacobi, a direct solver -> MUMPS's Cholesky
/// factorisation; CG measures the unpreconditioned residual and starts from the given x. Then
/// solver.petsc_options. `reuse_interpolation`: GAMG keeps its prolongators when H's values
/// change. `multigrid`, where given (the caller asks keeps_multigrid_levels), makes the multigrid
/// of "cg" with "multigrid"; H may then be null, the caller giving the KSP its operator later (the
/// multigrid's levels do not need it).
KspChoice configure_ksp(KSP ksp, Mat H, const ContactSolverOptions& options,
                        const Matrix& near_null_space, bool reuse_interpolation,
                        const MultigridBuilder& multigrid = {});

/// Relative residual, iterations and convergence of the last KSPSolve with right-hand side rhs.
struct KspOutcome {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;
  std::string reason;  ///< PETSc's name of the reason, e.g. "DIVERGED_ITS"
  /// MUMPS's factorisation failed for a work array smaller than it needed (INFOG(1) one of
  /// -8, -9, -11, -12, -14, -15, -17, -20): more work space (ICNTL(14)) may let it through.
  bool short_workspace = false;
};
[[nodiscard]] KspOutcome ksp_outcome(KSP ksp, Vec rhs, bool direct);

/// KSPSolve(ksp, rhs, x), and where MUMPS's factorisation failed for a work space estimated short
/// (KspOutcome::short_workspace), the factorisation again with ICNTL(14) raised, at most three
/// times. `raised` becomes the last ICNTL(14) set (unchanged where none was needed).
[[nodiscard]] KspOutcome solve(KSP ksp, Vec rhs, Vec x, bool direct,
                               std::optional<PetscInt>& raised);
/// A solver's description, with the ICNTL(14) that solve() raised MUMPS's work space to, if any.
[[nodiscard]] std::string with_workspace_note(const std::string& description,
                                              const std::optional<PetscInt>& raised);

/// Sets the relative tolerance and iteration limit of an iterative KSP.
void set_ksp_tolerance(KSP ksp, const ContactSolverOptions& options, double tolerance, Index n);

}  // namespace signorini::petsc
