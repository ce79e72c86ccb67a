#include "signorini/petsc/petsc_newton_space.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/row_partition.hpp"

namespace signorini {

using petsc::check;

namespace {

// The columns of the near-null space on this rank's rows, made orthonormal (MatNullSpaceCreate
// wants them so) by modified Gram-Schmidt with global dot products; a mode that is (nearly) a
// combination of the others, as a rotation about an axis on which every free dof is held, is
// dropped.
std::vector<Vec> near_null_vectors(const Matrix& modes, Index lo, Index hi, Vec like) {
  std::vector<Vec> out;
  for (Index k = 0; k < modes.cols(); ++k) {
    Vec v = nullptr;
    check(VecDuplicate(like, &v), "near-null space");
    PetscScalar* a = nullptr;
    check(VecGetArray(v, &a), "near-null space");
    for (Index i = lo; i < hi; ++i) a[i - lo] = modes(i, k);
    check(VecRestoreArray(v, &a), "near-null space");
    PetscReal before = 0.0, after = 0.0;
    check(VecNorm(v, NORM_2, &before), "near-null space");
    for (Vec u : out) {
      PetscScalar dot = 0.0;
      check(VecDot(v, u, &dot), "near-null space");
      check(VecAXPY(v, -dot, u), "near-null space");
    }
    check(VecNorm(v, NORM_2, &after), "near-null space");
    if (!(after > 1e-10 * before)) {
      check(VecDestroy(&v), "near-null space");
      continue;
    }
    check(VecScale(v, 1.0 / after), "near-null space");
    out.push_back(v);
  }
  return out;
}

}  // namespace

PetscNewtonSpace::PetscNewtonSpace(const ContactProblem& problem,
                                   const ContactSolverOptions& options, const Vector& x0,
                                   TimingTable& timings, MPI_Comm comm)
    : p_(problem), o_(options), timings_(timings), comm_(comm) {
  ScopedTimer timer(timings_, "distributed set-up");
  int rank = 0, size = 1;
  MPI_Comm_rank(comm_, &rank);
  MPI_Comm_size(comm_, &size);
  n_ = problem.A.rows();
  nc_ = problem.contact.size();
  starts_ = row_partition(n_, size, problem.node_of_unknown, problem.contact.N);
  lo_ = starts_[static_cast<std::size_t>(rank)];
  hi_ = starts_[static_cast<std::size_t>(rank) + 1];
  const auto m = static_cast<PetscInt>(hi_ - lo_);

  // This rank's rows of A in CSR form: row i of the symmetric A is its column i, which the
  // column-major A holds with sorted row numbers.
  const SparseMatrix& A = problem.A;
  std::vector<PetscInt> ia(static_cast<std::size_t>(m) + 1, 0), ja;
  std::vector<PetscScalar> va;
  ja.reserve(static_cast<std::size_t>(A.outerIndexPtr()[hi_] - A.outerIndexPtr()[lo_]));
  va.reserve(ja.capacity());
  for (Index i = lo_; i < hi_; ++i) {
    for (SparseMatrix::InnerIterator it(A, i); it; ++it) {
      ja.push_back(static_cast<PetscInt>(it.row()));
      va.push_back(it.value());
    }
    ia[static_cast<std::size_t>(i - lo_) + 1] = static_cast<PetscInt>(ja.size());
  }
  const auto N = static_cast<PetscInt>(n_);
  check(MatCreateMPIAIJWithArrays(comm_, m, m, N, N, ia.data(), ja.data(), va.data(), &A_),
        "the stiffness matrix");
  check(MatSetOption(A_, MAT_SYMMETRIC, PETSC_TRUE), "the stiffness matrix");
  check(MatSetOption(A_, MAT_SYMMETRY_ETERNAL, PETSC_TRUE), "the stiffness matrix");
  check(MatSetOption(A_, MAT_SPD, PETSC_TRUE), "the stiffness matrix");
  check(MatDuplicate(A_, MAT_COPY_VALUES, &H_), "the Newton matrix");
  check(MatSetOption(H_, MAT_SYMMETRIC, PETSC_TRUE), "the Newton matrix");
  check(MatSetOption(H_, MAT_SYMMETRY_ETERNAL, PETSC_TRUE), "the Newton matrix");
  check(MatSetOption(H_, MAT_SPD, PETSC_TRUE), "the Newton matrix");

  check(MatCreateVecs(A_, &x_, &b_), "vectors");
  for (Vec* v : {&x_new_, &residual_, &d_, &Ad_, &work_}) check(VecDuplicate(x_, v), "vectors");
  PetscScalar* a = nullptr;
  check(VecGetArray(b_, &a), "vectors");
  for (Index i = lo_; i < hi_; ++i) a[i - lo_] = problem.b(i);
  check(VecRestoreArray(b_, &a), "vectors");
  check(VecGetArray(x_, &a), "vectors");
  for (Index i = lo_; i < hi_; ++i) a[i - lo_] = x0(i);
  check(VecRestoreArray(x_, &a), "vectors");
  check(MatMult(A_, x_, residual_), "A x");  // A x - b at x0
  check(VecAXPY(residual_, -1.0, b_), "A x - b");

  // The contact rows of this rank: all the dofs of a row lie in one range (row_partition).
  const SparseMatrix Nt = problem.contact.N.transpose();
  for (Index j = 0; j < nc_; ++j) {
    ContactRow row{j, {}, {}};
    for (SparseMatrix::InnerIterator it(Nt, j); it; ++it) {
      row.dofs.push_back(static_cast<PetscInt>(it.row()));
      row.normal.push_back(it.value());
    }
    if (!row.dofs.empty() && row.dofs.front() >= lo_ && row.dofs.front() < hi_)
      rows_.push_back(std::move(row));
  }
  set_up_solver();
  active_.assign(static_cast<std::size_t>(nc_), false);
  Nx_ = contact_values_of(x_);
}

PetscNewtonSpace::~PetscNewtonSpace() {
  KSPDestroy(&ksp_);
  for (Vec* v : {&b_, &x_, &x_new_, &residual_, &d_, &Ad_, &work_}) VecDestroy(v);
  MatDestroy(&H_);
  MatDestroy(&A_);
}

// The KSP from the serial options (docs/distributed.md): "cg" with "multigrid" -> CG with PETSc's
// smoothed-aggregation GAMG on the rigid-body modes; "cg" with "jacobi" -> CG with Jacobi; a
// direct solver ("cholmod", "dense") -> MUMPS's distributed Cholesky factorisation. Then
// solver.petsc_options, which may change any of it.
void PetscNewtonSpace::set_up_solver() {
  check(KSPCreate(comm_, &ksp_), "KSP");
  check(KSPSetOperators(ksp_, H_, H_), "KSP");
  PC pc = nullptr;
  check(KSPGetPC(ksp_, &pc), "KSP");
  std::size_t modes = 0;
  if (o_.linear.type == LinearSolverType::ConjugateGradient) {
    check(KSPSetType(ksp_, KSPCG), "KSP");
    // ||b - H x|| / ||b||, as the serial PCG measures it (not the preconditioned norm).
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSP");
    check(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE), "KSP");
    if (o_.linear.preconditioner == PreconditionerType::Multigrid) {
      check(PCSetType(pc, PCGAMG), "GAMG");
      // A new active set changes H only on the contact nodes' blocks: the levels' prolongators
      // are kept and only the Galerkin products redone, as the serial refresh does.
      check(PCGAMGSetReuseInterpolation(pc, PETSC_TRUE), "GAMG");
      // The smoothers' Chebyshev bounds estimated anew at each set-up: by default GAMG takes
      // them from its first smoothed-aggregation estimate, that of A, which the penalty of a new
      // active set exceeds, and the smoother diverges (CG stops with DIVERGED_INDEFINITE_PC).
      check(PCGAMGSetUseSAEstEig(pc, PETSC_FALSE), "GAMG");
      if (p_.near_null_space.rows() == n_) {
        std::vector<Vec> vecs = near_null_vectors(p_.near_null_space, lo_, hi_, x_);
        MatNullSpace space = nullptr;
        check(MatNullSpaceCreate(comm_, PETSC_FALSE, static_cast<PetscInt>(vecs.size()),
                                 vecs.data(), &space),
              "near-null space");
        check(MatSetNearNullSpace(H_, space), "near-null space");
        check(MatNullSpaceDestroy(&space), "near-null space");
        modes = vecs.size();
        for (Vec& v : vecs) check(VecDestroy(&v), "near-null space");
      }
    } else {
      check(PCSetType(pc, PCJACOBI), "Jacobi");
    }
  } else {
    direct_ = true;
    check(KSPSetType(ksp_, KSPPREONLY), "KSP");
    check(PCSetType(pc, PCCHOLESKY), "Cholesky");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "MUMPS");
  }
  if (!o_.petsc_options.empty())
    check(PetscOptionsInsertString(nullptr, o_.petsc_options.c_str()),
          fmt::format("solver.petsc_options = \"{}\"", o_.petsc_options).c_str());
  check(KSPSetFromOptions(ksp_), "KSP options");
  KSPType ksp_type = nullptr;
  PCType pc_type = nullptr;
  check(KSPGetType(ksp_, &ksp_type), "KSP");
  check(PCGetType(pc, &pc_type), "KSP");
  description_ = fmt::format("KSP {} with PC {}", ksp_type != nullptr ? ksp_type : "?",
                             pc_type != nullptr ? pc_type : "?");
  if (direct_) description_ += " (MUMPS)";
  if (modes > 0) description_ += fmt::format(" ({} rigid-body modes)", modes);
}

// H(P) = A + sum_{j in P} r h_j n_j n_j^T (17): A's values again, then each active node's block
// on its own rows. Every rank calls this with the same P (the loop is replicated), so the
// collective assembly is met by all.
void PetscNewtonSpace::set_active(const ActiveSet& active, double r) {
  if (has_active_ && active == active_) return;
  ScopedTimer t(timings_, "preconditioner setup");
  check(MatCopy(A_, H_, SAME_NONZERO_PATTERN), "the Newton matrix");
  std::vector<PetscScalar> block;
  for (const ContactRow& row : rows_) {
    if (!active[static_cast<std::size_t>(row.j)]) continue;
    const double c = r * p_.contact.weights(row.j);
    const std::size_t k = row.dofs.size();
    block.assign(k * k, 0.0);
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t b = 0; b < k; ++b) block[a * k + b] = c * row.normal[a] * row.normal[b];
    check(MatSetValues(H_, static_cast<PetscInt>(k), row.dofs.data(), static_cast<PetscInt>(k),
                       row.dofs.data(), block.data(), ADD_VALUES),
          "the Newton matrix");
  }
  check(MatAssemblyBegin(H_, MAT_FINAL_ASSEMBLY), "the Newton matrix");
  check(MatAssemblyEnd(H_, MAT_FINAL_ASSEMBLY), "the Newton matrix");
  check(KSPSetOperators(ksp_, H_, H_), "KSP");  // the preconditioner is set up again
  active_ = active;
  has_active_ = true;
  ++refreshes_;
}

NewtonSolveStats PetscNewtonSpace::solve(const Vector& terms) {
  // Newton right-hand side b - N^T terms, then H x_new = rhs from x_new = x (17).
  check(VecCopy(b_, work_), "the right-hand side");
  add_contact_transpose(-terms, work_);
  check(VecCopy(x_, x_new_), "the initial guess");
  const double tolerance = linear_tolerance_ > 0.0 ? linear_tolerance_ : o_.linear.cg_tolerance;
  NewtonSolveStats out;
  if (!direct_) {
    check(KSPSetTolerances(ksp_, tolerance, 0.0, PETSC_DEFAULT,
                           static_cast<PetscInt>(o_.linear.cg_iteration_limit(n_))),
          "KSP tolerances");
    out.tolerance = tolerance;
  }
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  PetscInt its = 0;
  PetscReal rnorm = 0.0, bnorm = 0.0;
  {
    ScopedTimer t(timings_, "linear solve");
    check(KSPSolve(ksp_, work_, x_new_), "KSPSolve");
  }
  check(KSPGetConvergedReason(ksp_, &reason), "KSP");
  check(KSPGetIterationNumber(ksp_, &its), "KSP");
  out.iterations = direct_ ? 0 : static_cast<int>(its);
  out.converged = reason > 0;
  if (!direct_) {
    check(KSPGetResidualNorm(ksp_, &rnorm), "KSP");
    check(VecNorm(work_, NORM_2, &bnorm), "KSP");
    out.residual = bnorm > 0.0 ? rnorm / bnorm : rnorm;
  }
  out.solver = direct_ ? "MUMPS" : "PETSc CG";
  if (!out.converged) out.solver += fmt::format(" ({})", KSPConvergedReasons[reason]);
  return out;
}

void PetscNewtonSpace::direction(ModifiedLagrangian::Direction& dir) {
  check(VecWAXPY(d_, -1.0, x_, x_new_), "the Newton direction");
  check(MatMult(A_, d_, Ad_), "A d");
  PetscScalar rd = 0.0, dAd = 0.0;
  check(VecDot(residual_, d_, &rd), "dot product");
  check(VecDot(Ad_, d_, &dAd), "dot product");
  dir.residual_dot_d = rd;
  dir.d_A_d = dAd;
  dir.Nd = contact_values_of(d_);
}

void PetscNewtonSpace::step(double t) {
  check(VecAXPY(x_, t, d_), "step");
  check(VecAXPY(residual_, t, Ad_), "step");
  Nx_ = contact_values_of(x_);
  last_t_ = t;
}

NewtonStepNorms PetscNewtonSpace::norms(const Vector& contact_forces) {
  // G = (A x - b) + N^T (h z_+)
  check(VecCopy(residual_, work_), "norms");
  add_contact_transpose(contact_forces, work_);
  PetscReal g = 0.0, r = 0.0, x = 0.0, d = 0.0;
  check(VecNorm(work_, NORM_2, &g), "norms");
  check(VecNorm(residual_, NORM_2, &r), "norms");
  check(VecNorm(x_, NORM_2, &x), "norms");
  check(VecNorm(d_, NORM_2, &d), "norms");
  return {g, r, x, last_t_ * d};
}

Vector PetscNewtonSpace::gathered_solution() {
  VecScatter scatter = nullptr;
  Vec all = nullptr;
  check(VecScatterCreateToAll(x_, &scatter, &all), "gathering u");
  check(VecScatterBegin(scatter, x_, all, INSERT_VALUES, SCATTER_FORWARD), "gathering u");
  check(VecScatterEnd(scatter, x_, all, INSERT_VALUES, SCATTER_FORWARD), "gathering u");
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(all, &a), "gathering u");
  Vector u = Eigen::Map<const Vector>(a, n_);
  check(VecRestoreArrayRead(all, &a), "gathering u");
  VecScatterDestroy(&scatter);
  VecDestroy(&all);
  return u;
}

// (N v)_j for every contact node on every rank: each rank its own rows, summed over the ranks
// (every other rank adds an exact zero, so the values are those of a serial product).
Vector PetscNewtonSpace::contact_values_of(Vec v) {
  Vector values = Vector::Zero(nc_);
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(v, &a), "N x");
  for (const ContactRow& row : rows_) {
    double s = 0.0;
    for (std::size_t k = 0; k < row.dofs.size(); ++k) s += row.normal[k] * a[row.dofs[k] - lo_];
    values(row.j) = s;
  }
  check(VecRestoreArrayRead(v, &a), "N x");
  if (nc_ > 0)
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(nc_), MPI_DOUBLE, MPI_SUM, comm_);
  return values;
}

void PetscNewtonSpace::add_contact_transpose(const Vector& values, Vec v) {
  PetscScalar* a = nullptr;
  check(VecGetArray(v, &a), "N^T l");
  for (const ContactRow& row : rows_)
    for (std::size_t k = 0; k < row.dofs.size(); ++k)
      a[row.dofs[k] - lo_] += row.normal[k] * values(row.j);
  check(VecRestoreArray(v, &a), "N^T l");
}

}  // namespace signorini
