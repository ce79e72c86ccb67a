#include "signorini/petsc/petsc_active_set_solver.hpp"

#include <tuple>

#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"

namespace signorini {

using petsc::check;

PetscActiveSetSolver::PetscActiveSetSolver(const ContactProblem& problem,
                                           const ContactSolverOptions& options, const Vector& x0,
                                           TimingTable& timings, MPI_Comm comm)
    : p_(problem),
      o_(options),
      external_timings_(timings),
      comm_(comm),
      rotation_(make_normal_rotation(problem.contact, problem.A.rows())) {
  ScopedTimer timer(external_timings_, "distributed set-up");
  n_ = problem.A.rows();
  nc_ = problem.contact.size();
  // The rotation mixes only the dofs of one node, which the partition keeps on one rank.
  std::tie(lo_, hi_) = petsc::owned_rows(problem, comm_);
  for (Index j = 0; j < nc_; ++j) {
    const Index a = rotation_.normal_dof[static_cast<std::size_t>(j)];
    if (a >= lo_ && a < hi_) owned_.push_back(j);
  }
  Ar_ = petsc::distributed_rows(rotate_matrix(problem.A, rotation_, problem.first_row()), lo_, hi_,
                                comm_);
  check(MatDuplicate(Ar_, MAT_COPY_VALUES, &K_), "the Newton matrix");
  // MatZeroRowsColumns keeps K's pattern, so every step's matrix has A_r's.
  check(MatSetOption(K_, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE), "the Newton matrix");
  petsc::mark_spd(K_, "the Newton matrix");
  check(MatCreateVecs(Ar_, &y_, &br_), "vectors");
  for (Vec* v : {&rhs_, &fixed_values_, &reaction_}) check(VecDuplicate(y_, v), "vectors");
  // This rank's rows of b and of the near-null space (petsc::rank_rows), and of x0 (every
  // unknown), rotated: the rotation mixes only one node's unknowns, which are on one rank.
  const auto rotated_rows = [&](const auto& rows) -> Vector {
    Vector whole = Vector::Zero(n_);
    whole.segment(lo_, hi_ - lo_) = rows;
    return rotation_.to_rotated(whole).segment(lo_, hi_ - lo_);
  };
  petsc::set_owned(br_, rotated_rows(petsc::rank_rows(problem, problem.b, lo_, hi_)));
  petsc::set_owned(y_, rotated_rows(x0.segment(lo_, hi_ - lo_)));
  check(MatGetDiagonal(Ar_, reaction_), "the diagonal");
  PetscScalar sum = 0.0;
  check(VecSum(reaction_, &sum), "the diagonal");
  if (n_ > 0 && sum > 0.0) diagonal_ = sum / static_cast<double>(n_);
  // The rigid-body modes in the rotated unknowns, for GAMG.
  Matrix modes;
  if (problem.near_null_space.cols() > 0) {  // (on every rank alike: a collective choice)
    const Matrix rows = petsc::rank_rows(problem, problem.near_null_space, lo_, hi_);
    modes.resize(hi_ - lo_, rows.cols());
    for (Index k = 0; k < modes.cols(); ++k) modes.col(k) = rotated_rows(rows.col(k));
  }
  check(KSPCreate(comm_, &ksp_), "KSP");
  const petsc::KspChoice choice = petsc::configure_ksp(ksp_, K_, o_, modes, false);
  direct_ = choice.direct;
  description_ = choice.description;
}

PetscActiveSetSolver::~PetscActiveSetSolver() {
  KSPDestroy(&ksp_);
  for (Vec* v : {&br_, &y_, &rhs_, &fixed_values_, &reaction_}) VecDestroy(v);
  MatDestroy(&K_);
  MatDestroy(&Ar_);
  petsc::give_back_freed_memory();  // before the results are written (docs/distributed.md)
}

LinearSolveStats PetscActiveSetSolver::solve(const ActiveSet& S, Vector& l, Vector& gap_residual) {
  const ContactSet& c = p_.contact;
  // K: A_r with the rows and columns of the fixed unknowns a_j (j in S) replaced by the
  // diagonal, and the right-hand side b_r - A_r y_fixed with y_fixed on those rows
  // (MatZeroRowsColumns does both); y starts from the last step with the fixed values in.
  std::vector<PetscInt> rows;
  PetscScalar* fixed = nullptr;
  PetscScalar* y = nullptr;
  check(VecSet(fixed_values_, 0.0), "the fixed values");
  check(VecGetArray(fixed_values_, &fixed), "the fixed values");
  check(VecGetArray(y_, &y), "the fixed values");
  for (const Index j : owned_) {
    if (!S[static_cast<std::size_t>(j)]) continue;
    const Index a = rotation_.normal_dof[static_cast<std::size_t>(j)];
    rows.push_back(static_cast<PetscInt>(a));
    fixed[a - lo_] = c.gaps(j) / rotation_.scale(j);
    y[a - lo_] = fixed[a - lo_];
  }
  check(VecRestoreArray(y_, &y), "the fixed values");
  check(VecRestoreArray(fixed_values_, &fixed), "the fixed values");
  check(MatCopy(Ar_, K_, SAME_NONZERO_PATTERN), "the Newton matrix");
  check(VecCopy(br_, rhs_), "the right-hand side");
  check(MatZeroRowsColumns(K_, static_cast<PetscInt>(rows.size()), rows.data(), diagonal_,
                           fixed_values_, rhs_),
        "fixing the active normal displacements");
  check(KSPSetOperators(ksp_, K_, K_), "KSP");
  const double tolerance = tolerance_ > 0.0 ? tolerance_ : o_.linear.cg_tolerance;
  if (!direct_) petsc::set_ksp_tolerance(ksp_, o_, tolerance, n_);
  petsc::KspOutcome k;
  {
    ScopedTimer t(timings_, "linear solve");
    k = petsc::solve(ksp_, rhs_, y_, direct_, workspace_);
  }
  // Multipliers from the reactions: (A_r y)_{a_j} + s_j h_j l_j = (b_r)_{a_j} on S; each rank
  // its own nodes, summed over the ranks (the others add exact zeros).
  check(MatMult(Ar_, y_, reaction_), "the reactions");
  check(VecAYPX(reaction_, -1.0, br_), "the reactions");  // b_r - A_r y
  l = Vector::Zero(nc_);
  gap_residual = Vector::Zero(nc_);
  const PetscScalar* r = nullptr;
  const PetscScalar* yy = nullptr;
  check(VecGetArrayRead(reaction_, &r), "the reactions");
  check(VecGetArrayRead(y_, &yy), "the reactions");
  for (const Index j : owned_) {
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    const Index a = rotation_.normal_dof[static_cast<std::size_t>(j)];
    const double s = rotation_.scale(j);
    if (S[static_cast<std::size_t>(j)]) l(j) = r[a - lo_] / (s * c.weights(j));
    gap_residual(j) = s * yy[a - lo_] - c.gaps(j);
  }
  check(VecRestoreArrayRead(y_, &yy), "the reactions");
  check(VecRestoreArrayRead(reaction_, &r), "the reactions");
  if (nc_ > 0) {
    MPI_Allreduce(MPI_IN_PLACE, l.data(), static_cast<int>(nc_), MPI_DOUBLE, MPI_SUM, comm_);
    MPI_Allreduce(MPI_IN_PLACE, gap_residual.data(), static_cast<int>(nc_), MPI_DOUBLE, MPI_SUM,
                  comm_);
  }
  LinearSolveStats st;
  st.converged = k.converged;
  st.iterations = k.iterations;
  st.residual = k.residual;
  return st;
}

Vector PetscActiveSetSolver::displacement() const {
  // (Gathered whole and rotated back: semismooth Newton's distributed steps still hold the
  // rotation of all n unknowns; a rank's part of the mesh then keeps its part's values.)
  const Vector whole = rotation_.from_rotated(petsc::gather(y_));
  return p_.part_solution() ? Vector(whole(p_.solution_unknowns)) : whole;
}

}  // namespace signorini
