#include "signorini/petsc/petsc_algebra.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>  // malloc_trim
#endif

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_check.hpp"

namespace signorini::petsc {

std::pair<Index, Index> owned_rows(const ContactProblem& problem, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::vector<Index> starts = partition_of(problem, size);
  return {starts[static_cast<std::size_t>(rank)], starts[static_cast<std::size_t>(rank) + 1]};
}

void mark_spd(Mat M, const char* what) {
  check(MatSetOption(M, MAT_SYMMETRIC, PETSC_TRUE), what);
  check(MatSetOption(M, MAT_SYMMETRY_ETERNAL, PETSC_TRUE), what);
  // (MPIBAIJ takes no MAT_SPD in PETSc 3.18; CG and the smoothers do not need it.)
  PetscBool block = PETSC_FALSE;
  check(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(M), &block, MATSEQBAIJ, MATMPIBAIJ,
                                  ""),
        what);
  if (!block) check(MatSetOption(M, MAT_SPD, PETSC_TRUE), what);
}

namespace {

// An empty matrix of `type` with this rank's m rows of n, in blocks of `block`.
Mat new_matrix(MPI_Comm comm, PetscInt m, PetscInt n, PetscInt block, MatType type,
               const char* what) {
  Mat M = nullptr;
  check(MatCreate(comm, &M), what);
  check(MatSetSizes(M, m, m, n, n), what);
  check(MatSetBlockSize(M, block), what);
  check(MatSetType(M, type), what);
  return M;
}

// Where A's column of unknown i is: i - offset (A holds all n columns, offset 0, or only the
// rank's [lo, hi), offset lo: a partitioned problem's A, ContactProblem::column_of).
Index held_column_offset(const SparseMatrix& A, Index lo, Index hi) {
  if (A.cols() == A.rows()) return 0;
  if (A.cols() != hi - lo)
    throw NumericalError("a distributed matrix: A holds neither all its columns nor this rank's");
  return lo;
}

}  // namespace

Mat distributed_rows(const SparseMatrix& A, Index lo, Index hi, MPI_Comm comm, PetscInt block) {
  const auto m = static_cast<PetscInt>(hi - lo);
  const Index offset = held_column_offset(A, lo, hi);  // column i of A at i - offset
  // Preallocated exactly (the entries of each row in this rank's columns and elsewhere), then
  // filled a row at a time: no CSR copy of the rank's rows beside A and PETSc's own (at 405,600
  // unknowns that copy was 0.39 GB of the process's peak).
  std::vector<PetscInt> d_nnz(static_cast<std::size_t>(m), 0), o_nnz(d_nnz);
  for (Index i = lo; i < hi; ++i)
    for (SparseMatrix::InnerIterator it(A, i - offset); it; ++it)
      ++(it.row() >= lo && it.row() < hi ? d_nnz : o_nnz)[static_cast<std::size_t>(i - lo)];
  const auto n = static_cast<PetscInt>(A.rows());
  Mat M = new_matrix(comm, m, n, block, MATAIJ, "a distributed matrix");
  // (Each call is a no-op on a matrix of the other type; on one rank every column is this
  // rank's. MatXAIJSetPreallocation would reset the block size that GAMG reads.)
  check(MatSeqAIJSetPreallocation(M, 0, d_nnz.data()), "a distributed matrix");
  check(MatMPIAIJSetPreallocation(M, 0, d_nnz.data(), 0, o_nnz.data()), "a distributed matrix");
  // Each row whole, in one call, its columns ascending, the preallocation exact: PETSc copies
  // the row instead of searching its place for each entry (3.9 s -> 1.8 s at a million
  // hex8 unknowns, one rank).
  check(MatSetOption(M, MAT_SORTED_FULL, PETSC_TRUE), "a distributed matrix");
  std::vector<PetscInt> columns;
  std::vector<PetscScalar> values;
  for (Index i = lo; i < hi; ++i) {
    // Column i of A is row i (A is symmetric, both triangles stored), its entries sorted.
    columns.clear();
    values.clear();
    for (SparseMatrix::InnerIterator it(A, i - offset); it; ++it) {
      columns.push_back(static_cast<PetscInt>(it.row()));
      values.push_back(it.value());
    }
    const auto row = static_cast<PetscInt>(i);
    check(MatSetValues(M, 1, &row, static_cast<PetscInt>(columns.size()), columns.data(),
                       values.data(), INSERT_VALUES),
          "a distributed matrix");
  }
  check(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY), "a distributed matrix");
  check(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY), "a distributed matrix");
  mark_spd(M, "a distributed matrix");
  return M;
}

namespace {
PetscErrorCode free_held_matrix(void* held) {
  delete static_cast<SparseMatrix*>(held);
  return 0;
}

// M made on S's arrays in place (PETSc's indices 32-bit; S compressed, each column's entries
// ascending), with S composed on it for held_matrix(); `destroy` frees S with M, or null where
// S is the caller's.
Mat matrix_on_arrays(const SparseMatrix& S, MPI_Comm comm, PetscInt block,
                     PetscErrorCode (*destroy)(void*)) {
  const char* what = "a matrix";
  const auto rows = static_cast<PetscInt>(S.cols());
  const auto cols = static_cast<PetscInt>(S.rows());
  // (PETSc reads them through non-const pointers; no value of M is ever set.)
  auto* outer = const_cast<PetscInt*>(reinterpret_cast<const PetscInt*>(S.outerIndexPtr()));
  auto* inner = const_cast<PetscInt*>(reinterpret_cast<const PetscInt*>(S.innerIndexPtr()));
  auto* values = const_cast<double*>(S.valuePtr());
  Mat M = nullptr;
  check(MatCreateSeqAIJWithArrays(comm, rows, cols, outer, inner, values, &M), what);
  PetscContainer container = nullptr;
  check(PetscContainerCreate(comm, &container), what);
  check(PetscContainerSetPointer(container, const_cast<SparseMatrix*>(&S)), what);
  if (destroy != nullptr) check(PetscContainerSetUserDestroy(container, destroy), what);
  check(PetscObjectCompose(reinterpret_cast<PetscObject>(M), "signorini_arrays",
                           reinterpret_cast<PetscObject>(container)),
        what);
  check(PetscContainerDestroy(&container), what);  // (M holds it)
  if (block > 1) check(MatSetBlockSize(M, block), what);
  return M;
}

bool columns_sorted(const SparseMatrix& S) {
  if (!S.isCompressed()) return false;
  for (Index c = 0; c < S.cols(); ++c)
    if (!std::is_sorted(S.innerIndexPtr() + S.outerIndexPtr()[c],
                        S.innerIndexPtr() + S.outerIndexPtr()[c + 1]))
      return false;
  return true;
}

}  // namespace

Mat sequential_matrix(SparseMatrix&& S, MPI_Comm comm, PetscInt block) {
  const char* what = "a matrix";
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (size != 1) throw std::logic_error("sequential_matrix: a communicator of several processes");
  auto held = std::make_unique<SparseMatrix>(std::move(S));
  held->makeCompressed();
  // PETSc's rows need their columns ascending.
  const Index m = held->cols();
  int* outer = held->outerIndexPtr();
  int* inner = held->innerIndexPtr();
  double* values = held->valuePtr();
  std::vector<std::pair<int, double>> column;
  for (Index c = 0; c < m; ++c) {
    const int b = outer[c], e = outer[c + 1];
    if (std::is_sorted(inner + b, inner + e)) continue;
    column.clear();
    for (int k = b; k < e; ++k) column.emplace_back(inner[k], values[k]);
    std::sort(column.begin(), column.end());
    for (int k = b; k < e; ++k)
      std::tie(inner[k], values[k]) = column[static_cast<std::size_t>(k - b)];
  }
  if constexpr (std::is_same_v<PetscInt, int>) {
    // The arrays go with M: the container composed on it frees them when M goes.
    Mat M = matrix_on_arrays(*held, comm, block, &free_held_matrix);
    held.release();
    return M;
  }
  const auto rows = static_cast<PetscInt>(m);
  const auto cols = static_cast<PetscInt>(held->rows());
  const std::vector<PetscInt> o(outer, outer + m + 1), i(inner, inner + outer[m]);
  Mat M = nullptr;
  check(MatCreate(comm, &M), what);
  check(MatSetSizes(M, rows, cols, rows, cols), what);
  check(MatSetType(M, MATSEQAIJ), what);
  check(MatSetOption(M, MAT_SORTED_FULL, PETSC_TRUE), what);
  check(MatSeqAIJSetPreallocationCSR(M, o.data(), i.data(), values), what);
  if (block > 1) check(MatSetBlockSize(M, block), what);
  return M;
}

Mat sequential_view(const SparseMatrix& S, MPI_Comm comm, PetscInt block) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (size != 1) throw std::logic_error("sequential_view: a communicator of several processes");
  if constexpr (std::is_same_v<PetscInt, int>) {
    if (columns_sorted(S)) return matrix_on_arrays(S, comm, block, nullptr);
  }
  return sequential_matrix(SparseMatrix(S), comm, block);
}

const SparseMatrix* held_matrix(Mat M) {
  PetscObject container = nullptr;
  check(PetscObjectQuery(reinterpret_cast<PetscObject>(M), "signorini_arrays", &container),
        "a matrix");
  if (container == nullptr) return nullptr;
  void* held = nullptr;
  check(PetscContainerGetPointer(reinterpret_cast<PetscContainer>(container), &held), "a matrix");
  return static_cast<const SparseMatrix*>(held);
}

Mat block_rows(const SparseMatrix& A, Index lo, Index hi, MPI_Comm comm, PetscInt block) {
  if (block <= 1) return distributed_rows(A, lo, hi, comm);
  // Block row ib holds the rows lo + bs ib ... of one node, which all have the same columns (the
  // nodes that share a cell with it): their block columns are those of its first row.
  const Index bs = block;
  const Index rows = (hi - lo) / bs;
  const Index offset = held_column_offset(A, lo, hi);  // column i of A at i - offset
  std::vector<PetscInt> d_blocks(static_cast<std::size_t>(rows), 0), o_blocks(d_blocks);
  for (Index ib = 0; ib < rows; ++ib)
    for (SparseMatrix::InnerIterator it(A, lo - offset + ib * bs); it; ++it)
      if (it.row() % bs == 0) {
        const bool own = it.row() >= lo && it.row() < hi;
        ++(own ? d_blocks : o_blocks)[static_cast<std::size_t>(ib)];
      }
  Mat M = new_matrix(comm, static_cast<PetscInt>(hi - lo), static_cast<PetscInt>(A.rows()), block,
                     MATBAIJ, "a block matrix");
  check(MatXAIJSetPreallocation(M, block, d_blocks.data(), o_blocks.data(), nullptr, nullptr),
        "a block matrix");
  // One block row at a time: a bs x (bs * blocks) row-major array (MatSetValuesBlocked).
  std::vector<PetscInt> columns;
  std::vector<PetscScalar> values;
  for (Index ib = 0; ib < rows; ++ib) {
    columns.clear();
    for (SparseMatrix::InnerIterator it(A, lo - offset + ib * bs); it; ++it)
      if (it.row() % bs == 0) columns.push_back(static_cast<PetscInt>(it.row() / bs));
    const std::size_t width = columns.size() * static_cast<std::size_t>(bs);
    values.assign(width * static_cast<std::size_t>(bs), 0.0);
    for (Index k = 0; k < bs; ++k) {
      std::size_t c = 0;  // the position of the entry's block among `columns`
      for (SparseMatrix::InnerIterator it(A, lo - offset + ib * bs + k); it; ++it) {
        const auto b = static_cast<PetscInt>(it.row() / bs);
        while (columns[c] != b) ++c;
        values[static_cast<std::size_t>(k) * width + c * static_cast<std::size_t>(bs) +
               static_cast<std::size_t>(it.row() % bs)] = it.value();
      }
    }
    const auto row = static_cast<PetscInt>(lo / bs + ib);
    check(MatSetValuesBlocked(M, 1, &row, static_cast<PetscInt>(columns.size()), columns.data(),
                              values.data(), INSERT_VALUES),
          "a block matrix");
  }
  check(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY), "a block matrix");
  check(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY), "a block matrix");
  mark_spd(M, "a block matrix");
  return M;
}

void give_back_freed_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

Vector rank_rows(const ContactProblem& problem, const Vector& v, Index first, Index last) {
  return problem.partitioned() ? v : Vector(v.segment(first, last - first));
}

Matrix rank_rows(const ContactProblem& problem, const Matrix& m, Index first, Index last) {
  return problem.partitioned() || m.size() == 0 ? m : Matrix(m.middleRows(first, last - first));
}

void set_owned(Vec v, const Vector& rows) {
  PetscInt m = 0;
  check(VecGetLocalSize(v, &m), "a distributed vector");
  if (m != rows.size())
    throw NumericalError(
        fmt::format("PETSc: {} values for a rank's {} entries of a vector", rows.size(), m));
  PetscScalar* a = nullptr;
  check(VecGetArray(v, &a), "a distributed vector");
  for (PetscInt i = 0; i < m; ++i) a[i] = rows(i);
  check(VecRestoreArray(v, &a), "a distributed vector");
}

Vector gather(Vec v) {
  PetscInt m = 0;
  check(VecGetLocalSize(v, &m), "gathering a vector");
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(v, &a), "gathering a vector");
  const Vector own = Eigen::Map<const Vector>(a, m);
  check(VecRestoreArrayRead(v, &a), "gathering a vector");
  return allgather(own, PetscObjectComm(reinterpret_cast<PetscObject>(v)));
}

Vector values_at(Vec v, const std::vector<PetscInt>& at) {
  const auto count = static_cast<PetscInt>(at.size());
  IS from = nullptr;
  Vec got = nullptr;
  VecScatter scatter = nullptr;
  check(ISCreateGeneral(PETSC_COMM_SELF, count, at.data(), PETSC_USE_POINTER, &from),
        "reading a distributed vector");
  check(VecCreateSeq(PETSC_COMM_SELF, count, &got), "reading a distributed vector");
  check(VecScatterCreate(v, from, got, nullptr, &scatter), "reading a distributed vector");
  check(VecScatterBegin(scatter, v, got, INSERT_VALUES, SCATTER_FORWARD),
        "reading a distributed vector");
  check(VecScatterEnd(scatter, v, got, INSERT_VALUES, SCATTER_FORWARD),
        "reading a distributed vector");
  Vector out(count);
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(got, &a), "reading a distributed vector");
  std::copy(a, a + count, out.data());
  check(VecRestoreArrayRead(got, &a), "reading a distributed vector");
  VecScatterDestroy(&scatter);
  VecDestroy(&got);
  ISDestroy(&from);
  return out;
}

Vector allgather(const Vector& own, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  // (MPI's counts are ints: a vector of more than 2^31 - 1 entries would need MPI 4's.)
  if (own.size() > std::numeric_limits<int>::max())
    throw NumericalError("gathering a vector: more entries on one rank than MPI counts");
  const int mine = static_cast<int>(own.size());
  std::vector<int> counts(static_cast<std::size_t>(size)), starts(static_cast<std::size_t>(size));
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  long long total = 0;
  for (int r = 0; r < size; ++r) {
    if (total > std::numeric_limits<int>::max())
      throw NumericalError("gathering a vector: more entries than MPI counts");
    starts[static_cast<std::size_t>(r)] = static_cast<int>(total);
    total += counts[static_cast<std::size_t>(r)];
  }
  Vector whole(static_cast<Index>(total));
  MPI_Allgatherv(own.data(), mine, MPI_DOUBLE, whole.data(), counts.data(), starts.data(),
                 MPI_DOUBLE, comm);
  return whole;
}

namespace {

// The columns of the near-null space on this rank's rows, made orthonormal (MatNullSpaceCreate
// wants them so) by modified Gram-Schmidt with global dot products; a mode that is (nearly) a
// combination of the others, as a rotation about an axis on which every free dof is held, is
// dropped.
std::vector<Vec> near_null_vectors(const Matrix& modes, Mat like) {
  std::vector<Vec> out;
  for (Index k = 0; k < modes.cols(); ++k) {
    Vec v = nullptr;
    check(MatCreateVecs(like, &v, nullptr), "near-null space");
    set_owned(v, modes.col(k));
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

PetscInt count_before(PetscInt mine, MPI_Comm comm) {
  PetscInt before = 0;
  MPI_Exscan(&mine, &before, 1, MPIU_INT, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank == 0 ? 0 : before;  // (MPI_Exscan leaves the first rank's undefined)
}

double jacobi_lambda_max(Mat A) {
  KSP k = nullptr;
  check(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &k), "an estimate");
  check(KSPSetOperators(k, A, A), "an estimate");
  check(KSPSetType(k, KSPCG), "an estimate");
  PC p = nullptr;
  check(KSPGetPC(k, &p), "an estimate");
  check(PCSetType(p, PCJACOBI), "an estimate");
  check(KSPSetComputeSingularValues(k, PETSC_TRUE), "an estimate");
  check(KSPSetNormType(k, KSP_NORM_NONE), "an estimate");
  check(KSPSetConvergenceTest(k, KSPConvergedSkip, nullptr, nullptr), "an estimate");
  check(KSPSetTolerances(k, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 10), "an estimate");
  Vec b = nullptr, x = nullptr;
  check(MatCreateVecs(A, &x, &b), "an estimate");
  PetscRandom random = nullptr;
  check(PetscRandomCreate(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &random),
        "an estimate");
  check(PetscRandomSetFromOptions(random), "an estimate");
  check(VecSetRandom(b, random), "an estimate");
  check(KSPSolve(k, b, x), "an estimate");
  PetscReal emax = 0.0, emin = 0.0;
  check(KSPComputeExtremeSingularValues(k, &emax, &emin), "an estimate");
  PetscRandomDestroy(&random);
  VecDestroy(&b);
  VecDestroy(&x);
  KSPDestroy(&k);
  return emax;
}

std::size_t attach_near_null_space(Mat M, const Matrix& near_null_space) {
  PetscInt rows = 0;
  check(MatGetLocalSize(M, &rows, nullptr), "near-null space");
  if (near_null_space.rows() != rows)
    throw NumericalError(fmt::format("PETSc: a near-null space of {} rows for a rank's {} rows",
                                     near_null_space.rows(), rows));
  std::vector<Vec> vecs = near_null_vectors(near_null_space, M);
  MatNullSpace space = nullptr;
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(M));
  check(MatNullSpaceCreate(comm, PETSC_FALSE, static_cast<PetscInt>(vecs.size()), vecs.data(),
                           &space),
        "near-null space");
  check(MatSetNearNullSpace(M, space), "near-null space");
  check(MatNullSpaceDestroy(&space), "near-null space");
  const std::size_t modes = vecs.size();
  for (Vec& v : vecs) check(VecDestroy(&v), "near-null space");
  return modes;
}

void insert_petsc_options(const ContactSolverOptions& o) {
  insert_petsc_options(o.petsc_options);
}

void insert_petsc_options(const std::string& petsc_options) {
  if (!petsc_options.empty())
    check(PetscOptionsInsertString(nullptr, petsc_options.c_str()),
          fmt::format("solver.petsc_options = \"{}\"", petsc_options).c_str());
}

bool keeps_multigrid_levels(const ContactSolverOptions& o) {
  insert_petsc_options(o);
  PetscBool pc_type_given = PETSC_FALSE;
  check(PetscOptionsHasName(nullptr, nullptr, "-pc_type", &pc_type_given), "PETSc options");
  return o.linear.type == LinearSolverType::ConjugateGradient &&
         o.linear.preconditioner == PreconditionerType::Multigrid &&
         o.petsc_multigrid != PetscMultigrid::Hypre && !pc_type_given;
}

KspChoice configure_ksp(KSP ksp, Mat H, const ContactSolverOptions& o,
                        const Matrix& near_null_space, bool reuse_interpolation,
                        const MultigridBuilder& multigrid) {
  KspChoice choice;
  std::string built;
  if (H != nullptr) check(KSPSetOperators(ksp, H, H), "KSP");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "KSP");
  std::size_t modes = 0;
  if (o.linear.type == LinearSolverType::ConjugateGradient) {
    check(KSPSetType(ksp, KSPCG), "KSP");
    // ||b - H x|| / ||b||, as the serial PCG measures it (not the preconditioned norm).
    check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSP");
    check(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE), "KSP");
    if (o.linear.preconditioner == PreconditionerType::Multigrid &&
        o.petsc_multigrid == PetscMultigrid::Hypre) {
      check(PCSetType(pc, PCHYPRE), "hypre");
      check(PCHYPRESetType(pc, "boomeramg"), "hypre");
    } else if (multigrid) {
      built = multigrid(pc);
    } else if (o.linear.preconditioner == PreconditionerType::Multigrid) {
      check(PCSetType(pc, PCGAMG), "GAMG");
      // A new active set changes H only on the contact nodes' blocks: the levels' prolongators
      // can be kept and only the Galerkin products redone, as the serial refresh does.
      check(PCGAMGSetReuseInterpolation(pc, reuse_interpolation ? PETSC_TRUE : PETSC_FALSE),
            "GAMG");
      // The smoothers' Chebyshev bounds estimated anew at each set-up: by default GAMG takes
      // them from its first smoothed-aggregation estimate, that of A, which the penalty of a new
      // active set exceeds, and the smoother diverges (CG stops with DIVERGED_INDEFINITE_PC).
      check(PCGAMGSetUseSAEstEig(pc, PETSC_FALSE), "GAMG");
      if (near_null_space.cols() > 0) modes = attach_near_null_space(H, near_null_space);
    } else {
      check(PCSetType(pc, PCJACOBI), "Jacobi");
    }
  } else {
    choice.direct = true;
    check(KSPSetType(ksp, KSPPREONLY), "KSP");
    check(PCSetType(pc, PCCHOLESKY), "Cholesky");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "MUMPS");
  }
  insert_petsc_options(o);
  check(KSPSetFromOptions(ksp), "KSP options");
  KSPType ksp_type = nullptr;
  PCType pc_type = nullptr;
  check(KSPGetType(ksp, &ksp_type), "KSP");
  check(PCGetType(pc, &pc_type), "KSP");
  choice.description = fmt::format("KSP {} with PC {}", ksp_type != nullptr ? ksp_type : "?",
                                   pc_type != nullptr ? pc_type : "?");
  if (choice.direct) choice.description += " (MUMPS)";
  if (!built.empty()) choice.description += " (" + built + ")";
  // (The modes only where the PC in the end is GAMG: petsc_options may have changed it.)
  if (modes > 0 && pc_type != nullptr && std::string(pc_type) == PCGAMG)
    choice.description += fmt::format(" ({} rigid-body modes)", modes);
  return choice;
}

KspOutcome ksp_outcome(KSP ksp, Vec rhs, bool direct) {
  KspOutcome out;
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  check(KSPGetConvergedReason(ksp, &reason), "KSP");
  out.converged = reason > 0;
  out.reason = KSPConvergedReasons[reason];
  if (direct && reason == KSP_DIVERGED_PC_FAILED) {
    // MUMPS's own account (its manual, INFOG(1) < 0: -9 a work array too small, -10 a
    // numerically singular matrix, -13 an allocation that failed, -19 the memory limit
    // ICNTL(23)), so that a failed factorisation says why.
    PC pc = nullptr;
    Mat F = nullptr;
    MatSolverType type = nullptr;
    PetscInt infog1 = 0, infog2 = 0;
    if (KSPGetPC(ksp, &pc) == 0 && PCFactorGetMatSolverType(pc, &type) == 0 && type != nullptr &&
        std::string(type) == MATSOLVERMUMPS && PCFactorGetMatrix(pc, &F) == 0 && F != nullptr &&
        MatMumpsGetInfog(F, 1, &infog1) == 0 && MatMumpsGetInfog(F, 2, &infog2) == 0) {
      out.reason += fmt::format(", MUMPS INFOG(1) = {}, INFOG(2) = {}", infog1, infog2);
      // A work array smaller than the factorisation needed (MUMPS's manual, INFOG(1)): the
      // analysis's estimate plus ICNTL(14) percent was short, as it may be when MUMPS's dynamic
      // scheduling on many ranks differs from the estimate's.
      constexpr PetscInt short_workspace[] = {-8, -9, -11, -12, -14, -15, -17, -20};
      out.short_workspace = std::find(std::begin(short_workspace), std::end(short_workspace),
                                      infog1) != std::end(short_workspace);
    }
  }
  if (!direct) {
    PetscInt its = 0;
    PetscReal rnorm = 0.0, bnorm = 0.0;
    check(KSPGetIterationNumber(ksp, &its), "KSP");
    check(KSPGetResidualNorm(ksp, &rnorm), "KSP");
    check(VecNorm(rhs, NORM_2, &bnorm), "KSP");
    out.iterations = static_cast<int>(its);
    out.residual = bnorm > 0.0 ? rnorm / bnorm : rnorm;
  }
  return out;
}

KspOutcome solve(KSP ksp, Vec rhs, Vec x, bool direct, std::optional<PetscInt>& raised) {
  check(KSPSolve(ksp, rhs, x), "KSPSolve");
  KspOutcome out = ksp_outcome(ksp, rhs, direct);
  // MUMPS sizes its work arrays from the analysis's estimate plus ICNTL(14) percent; where the
  // factorisation needed more (on many ranks MUMPS shares out parts of the work at run time,
  // which the estimate cannot foresee), its manual's remedy is a larger ICNTL(14) and the
  // factorisation again. Each rank sees the same failure (MUMPS's INFOG is global), so all
  // retry together.
  for (int attempt = 0; attempt < 3 && out.short_workspace; ++attempt) {
    PC pc = nullptr;
    Mat F = nullptr, H = nullptr;
    PetscInt percent = 0;
    check(KSPGetPC(ksp, &pc), "MUMPS's work space");
    check(PCFactorGetMatrix(pc, &F), "MUMPS's work space");
    check(MatMumpsGetIcntl(F, 14, &percent), "MUMPS's work space");
    raised = std::max(percent + 50, 2 * percent);
    // A failed factorisation cannot be repeated numerically (PETSc's MUMPS interface keeps the
    // failure): the PC starts afresh, analysis included, which reads ICNTL(14) from the options
    // database, where the raised value goes (over any that petsc_options gave; it stays there for
    // the process's later factorisations, which the same estimate would fail alike).
    const char* prefix = nullptr;
    check(KSPGetOptionsPrefix(ksp, &prefix), "MUMPS's work space");
    const std::string key = fmt::format("-{}mat_mumps_icntl_14", prefix != nullptr ? prefix : "");
    check(PetscOptionsSetValue(nullptr, key.c_str(), std::to_string(*raised).c_str()),
          "MUMPS's work space");
    check(KSPGetOperators(ksp, &H, nullptr), "MUMPS's work space");
    check(PetscObjectReference(reinterpret_cast<PetscObject>(H)), "MUMPS's work space");
    check(PCReset(pc), "MUMPS's work space");
    check(KSPSetOperators(ksp, H, H), "MUMPS's work space");
    check(MatDestroy(&H), "MUMPS's work space");  // (the reference taken above)
    check(KSPSolve(ksp, rhs, x), "KSPSolve");
    out = ksp_outcome(ksp, rhs, direct);
  }
  if (out.short_workspace)
    out.reason +=
        ": its work space was estimated short, also with ICNTL(14) raised three times; "
        "solver.petsc_options = \"-mat_mumps_icntl_14 400\" gives it 400 % more";
  return out;
}

std::string with_workspace_note(const std::string& description,
                                const std::optional<PetscInt>& raised) {
  if (!raised) return description;
  return fmt::format(
      "{} (MUMPS's work space raised to ICNTL(14) = {} after a factorisation "
      "that needed more)",
      description, *raised);
}

void set_ksp_tolerance(KSP ksp, const ContactSolverOptions& o, double tolerance, Index n) {
  check(KSPSetTolerances(ksp, tolerance, 0.0, PETSC_DEFAULT,
                         static_cast<PetscInt>(o.linear.cg_iteration_limit(n))),
        "KSP tolerances");
}

}  // namespace signorini::petsc
