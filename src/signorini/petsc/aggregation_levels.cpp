#include "signorini/petsc/aggregation_levels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <type_traits>
#include <utility>

#include "signorini/core/error.hpp"
#include "signorini/core/types.hpp"
#include "signorini/iterative/galerkin_product.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "signorini/petsc/level_contact_prolongation.hpp"
#include "signorini/petsc/level_numbering.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"

namespace signorini::petsc {

namespace {

// Rows read from PETSc with global column numbers: CSR arrays.
struct GlobalRows {
  std::vector<int> outer{0};
  std::vector<PetscInt> columns;
  std::vector<double> values;
};

void append_rows(Mat M, PetscInt lo, PetscInt hi, GlobalRows& out) {
  for (PetscInt r = lo; r < hi; ++r) {
    PetscInt nc = 0;
    const PetscInt* c = nullptr;
    const PetscScalar* v = nullptr;
    check(MatGetRow(M, r, &nc, &c, &v), "a multigrid level's rows");
    out.columns.insert(out.columns.end(), c, c + nc);
    out.values.insert(out.values.end(), v, v + nc);
    check(MatRestoreRow(M, r, &nc, &c, &v), "a multigrid level's rows");
    out.outer.push_back(static_cast<int>(out.columns.size()));
  }
}

// Global rows into row-major local numbering (each row's columns sorted in it).
RowMatrix local_rows(const GlobalRows& g, Index columns, const ExtNumbering& numbering) {
  const auto rows = static_cast<Index>(g.outer.size()) - 1;
  RowMatrix R(rows, columns);
  R.resizeNonZeros(static_cast<Index>(g.columns.size()));
  std::copy(g.outer.begin(), g.outer.end(), R.outerIndexPtr());
  std::vector<std::pair<int, double>> row;
  for (Index r = 0; r < rows; ++r) {
    const int b = g.outer[static_cast<std::size_t>(r)];
    const int e = g.outer[static_cast<std::size_t>(r) + 1];
    row.clear();
    bool sorted = true;
    for (int k = b; k < e; ++k) {
      const auto c = static_cast<int>(numbering.local(g.columns[static_cast<std::size_t>(k)]));
      sorted = sorted && (row.empty() || row.back().first < c);
      row.emplace_back(c, g.values[static_cast<std::size_t>(k)]);
    }
    if (!sorted) std::sort(row.begin(), row.end());
    for (int k = b; k < e; ++k) {
      R.innerIndexPtr()[k] = row[static_cast<std::size_t>(k - b)].first;
      R.valuePtr()[k] = row[static_cast<std::size_t>(k - b)].second;
    }
  }
  return R;
}

// The rows `rows` (global, ascending; this rank's neighbours') of the distributed M, with
// global column numbers. Collective (every rank calls it, with its own rows).
GlobalRows fetch_rows(Mat M, const std::vector<PetscInt>& rows) {
  PetscInt columns = 0;
  check(MatGetSize(M, nullptr, &columns), "a multigrid level's ghost rows");
  IS row_set = nullptr, column_set = nullptr;
  check(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(rows.size()), rows.data(),
                        PETSC_COPY_VALUES, &row_set),
        "a multigrid level's ghost rows");
  // Every column, in order: the rows come with their global column numbers.
  check(ISCreateStride(PETSC_COMM_SELF, columns, 0, 1, &column_set),
        "a multigrid level's ghost rows");
  Mat* sub = nullptr;
  check(MatCreateSubMatrices(M, 1, &row_set, &column_set, MAT_INITIAL_MATRIX, &sub),
        "a multigrid level's ghost rows");
  GlobalRows out;
  append_rows(sub[0], 0, static_cast<PetscInt>(rows.size()), out);
  check(MatDestroySubMatrices(1, &sub), "a multigrid level's ghost rows");
  ISDestroy(&row_set);
  ISDestroy(&column_set);
  return out;
}

// A prolongation's rows on this rank: its own (R, columns in `numbering`), then those of the
// ghosts fetched from P (on several ranks; collective); `numbering` gains the columns the
// fetched rows bring. Column-major, n_ext x the numbering's size.
SparseMatrix extended_rows(Mat P, const RowMatrix& own, const std::vector<PetscInt>& ghosts,
                           ExtNumbering& numbering) {
  GlobalRows g;
  // Own rows in global columns first, so that the numbering can take the fetched ones in.
  for (Index r = 0; r < own.rows(); ++r) {
    for (RowMatrix::InnerIterator it(own, r); it; ++it) {
      g.columns.push_back(numbering.global(it.col()));
      g.values.push_back(it.value());
    }
    g.outer.push_back(static_cast<int>(g.columns.size()));
  }
  const GlobalRows fetched = fetch_rows(P, ghosts);
  numbering.add_foreign(fetched.columns);
  const int base = g.outer.back();
  for (std::size_t r = 1; r < fetched.outer.size(); ++r) g.outer.push_back(base + fetched.outer[r]);
  g.columns.insert(g.columns.end(), fetched.columns.begin(), fetched.columns.end());
  g.values.insert(g.values.end(), fetched.values.begin(), fetched.values.end());
  return SparseMatrix(local_rows(g, numbering.size(), numbering));
}

// A SeqAIJ matrix's CSR arrays, borrowed from PETSc for the object's life.
class Csr {
 public:
  explicit Csr(Mat M) : M_(M) {
    PetscBool done = PETSC_FALSE;
    check(MatGetRowIJ(M_, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done),
          "a multigrid level's rows");
    if (!done) throw NumericalError("PETSc: a multigrid level's rows are not in CSR");
    check(MatSeqAIJGetArrayRead(M_, &a), "a multigrid level's rows");
  }
  ~Csr() {
    PetscBool done = PETSC_FALSE;
    MatSeqAIJRestoreArrayRead(M_, &a);
    MatRestoreRowIJ(M_, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done);
  }
  Csr(const Csr&) = delete;
  Csr& operator=(const Csr&) = delete;

  PetscInt n = 0;
  const PetscInt* ia = nullptr;
  const PetscInt* ja = nullptr;
  const PetscScalar* a = nullptr;

 private:
  Mat M_;
};

// PETSc's indices are the kernels' (32-bit): its arrays can be read in place.
constexpr bool kSameIndices = std::is_same_v<PetscInt, int>;

// A level's rows on this rank as the columns of its own unknowns (n_ext x n_own, A being
// symmetric). On one rank, PETSc's own CSR arrays read in place (they are A's CSC arrays);
// on several, a copy of its diagonal block (the rank's columns) and its off-diagonal block,
// whose columns PETSc numbers in the ascending order of their global numbers (the ghosts,
// which `fine` takes as its foreign unknowns), so that each row comes out sorted.
class LevelColumns {
 public:
  LevelColumns(Mat level, ExtNumbering& fine) {
    Mat diagonal = level, off = nullptr;
    const PetscInt* ghosts = nullptr;
    PetscBool distributed = PETSC_FALSE;
    check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(level), MATMPIAIJ, &distributed),
          "a multigrid level's rows");
    if (distributed)
      check(MatMPIAIJGetSeqAIJ(level, &diagonal, &off, &ghosts), "a multigrid level's rows");
    in_place_.emplace(diagonal);
    const Csr& d = *in_place_;
    if (kSameIndices && off == nullptr) return;
    std::optional<Csr> o;
    PetscInt off_columns = 0;
    if (off != nullptr) {
      o.emplace(off);
      check(MatGetSize(off, nullptr, &off_columns), "a multigrid level's rows");
      fine.foreign.assign(ghosts, ghosts + off_columns);
    }
    copy_.resize(fine.size(), fine.count);
    Index nonzeros = d.ia[fine.count];
    if (o) nonzeros += o->ia[fine.count];
    copy_.resizeNonZeros(nonzeros);
    int* outer = copy_.outerIndexPtr();
    int* inner = copy_.innerIndexPtr();
    double* values = copy_.valuePtr();
    outer[0] = 0;
    int at = 0;
    for (PetscInt r = 0; r < fine.count; ++r) {
      for (PetscInt k = d.ia[r]; k < d.ia[r + 1]; ++k, ++at) {
        inner[at] = static_cast<int>(d.ja[k]);
        values[at] = d.a[k];
      }
      if (o)
        for (PetscInt k = o->ia[r]; k < o->ia[r + 1]; ++k, ++at) {
          inner[at] = static_cast<int>(fine.count + o->ja[k]);
          values[at] = o->a[k];
        }
      outer[r + 1] = at;
    }
    in_place_.reset();
  }

  [[nodiscard]] SparseView view() const {
    if constexpr (kSameIndices) {
      if (in_place_) {
        const Csr& d = *in_place_;
        return {d.n, d.n, d.ia[d.n], d.ia, d.ja, d.a};
      }
    }
    return view_of(copy_);
  }

 private:
  std::optional<Csr> in_place_;
  SparseMatrix copy_;
};

}  // namespace

CoarseLevels aggregation_levels(Mat A, LevelContactProlongations* contact) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(A));
  int size = 1;
  MPI_Comm_size(comm, &size);
  SmoothedAggregationOptions options;  // the serial tool's, as its hierarchy
  // PETSc's -pc_mg_levels caps the levels, as it caps GAMG's (the PCMG takes it too: levels
  // made beyond it would meet no smoother).
  PetscInt most = 0;
  PetscBool given = PETSC_FALSE;
  check(PetscOptionsGetInt(nullptr, nullptr, "-pc_mg_levels", &most, &given), "-pc_mg_levels");
  if (given && most >= 1) options.max_levels = static_cast<int>(most);
  CoarseLevels out;

  // The fine level's near-null space (this rank's rows) and nodes (A's blocks).
  // Without one attached, the translations, one per unknown of a node (GAMG's default too).
  MatNullSpace space = nullptr;
  check(MatGetNearNullSpace(A, &space), "the near-null space");
  PetscInt lo = 0, hi = 0, block = 1;
  check(MatGetOwnershipRange(A, &lo, &hi), "smoothed aggregation");
  check(MatGetBlockSize(A, &block), "smoothed aggregation");
  Matrix B;
  if (space != nullptr) {
    PetscBool has_constant = PETSC_FALSE;
    PetscInt modes = 0;
    const Vec* vectors = nullptr;
    check(MatNullSpaceGetVecs(space, &has_constant, &modes, &vectors), "the near-null space");
    B.resize(hi - lo, modes);
    for (PetscInt k = 0; k < modes; ++k) {
      const PetscScalar* v = nullptr;
      check(VecGetArrayRead(vectors[k], &v), "the near-null space");
      for (PetscInt i = 0; i < hi - lo; ++i) B(i, k) = v[i];
      check(VecRestoreArrayRead(vectors[k], &v), "the near-null space");
    }
  } else {
    B = Matrix::Zero(hi - lo, block);
    for (PetscInt i = 0; i < hi - lo; ++i) B(i, i % block) = 1.0;
  }
  std::vector<Index> node_of(static_cast<std::size_t>(hi - lo));
  for (PetscInt i = 0; i < hi - lo; ++i) node_of[static_cast<std::size_t>(i)] = i / block;
  std::vector<Index> place_of;

  Mat level = A;
  for (int depth = 0; depth + 1 < options.max_levels; ++depth) {
    PetscInt n = 0;
    check(MatGetSize(level, &n, nullptr), "smoothed aggregation");
    // (The fine level is coarsened once however small: PCMG's coarsest solve is direct, and
    // a single level would be the smoother alone.)
    if (n <= options.max_coarse_unknowns && depth > 0) break;
    check(MatGetOwnershipRange(level, &lo, &hi), "smoothed aggregation");

    // The rank's rows, as the columns of its own unknowns (n_ext x n_own).
    ExtNumbering fine{lo, hi - lo, {}};
    std::optional<LevelColumns> columns(std::in_place, level, fine);
    const SparseView Al = columns->view();

    // The rank's nodes aggregated among themselves; the coarse unknowns numbered rank by rank.
    AggregationLevel t = aggregate_level(Al, B, node_of, place_of, options.strength_threshold);
    const auto own_coarse = static_cast<PetscInt>(t.tentative.cols());
    const PetscInt first_coarse = count_before(own_coarse, comm);
    PetscInt coarse = 0;
    MPI_Allreduce(&own_coarse, &coarse, 1, MPIU_INT, MPI_SUM, comm);
    if (static_cast<double>(coarse) > (1.0 - options.min_reduction) * static_cast<double>(n))
      break;  // no real coarsening left

    // T's rows of the ghosts from their ranks, then this rank's rows of the smoothed P.
    ExtNumbering coarse_numbering{first_coarse, own_coarse, {}};
    // (On one rank the serial tool's estimate, on the rank's threads, where the level is held
    // in place: the serial hierarchy's omega; else PETSc's CG.)
    const SparseMatrix* held = held_matrix(level);
    const double radius =
        held != nullptr ? jacobi_spectral_radius(*held) : jacobi_lambda_max(level);
    out.jacobi_radii.push_back(radius);
    SparseMatrix T_ghosts;  // (on several ranks: T's rows of the ghosts too)
    if (size > 1) {
      const RowMatrix T_own(t.tentative);
      Mat T = distributed_matrix(comm, T_own, coarse_numbering, own_coarse);
      T_ghosts = extended_rows(T, T_own, fine.foreign, coarse_numbering);
      check(MatDestroy(&T), "a tentative prolongation");
    }
    const SparseMatrix& T_ext = size > 1 ? T_ghosts : t.tentative;
    // P = (I - omega D^{-1} A) P_tent, omega = 4 / (3 rho(D^{-1} A)) (Vanek et al., eq. 4.4).
    // (On one rank A_l is square: the serial kernel, by groups of columns, is the faster.)
    const double omega = 4.0 / (3.0 * radius);
    SparseMatrix P_ext;
    Mat P = nullptr;
    if (size == 1) {
      P_ext = smoothed_prolongation(Al, T_ext, omega);  // (P's PETSc form after its last use)
    } else {
      const RowMatrix P_own = smoothed_prolongation_rows(Al, T_ext, omega);
      T_ghosts = SparseMatrix();
      P = distributed_matrix(comm, P_own, coarse_numbering, own_coarse);
      P_ext = extended_rows(P, P_own, fine.foreign, coarse_numbering);
    }

    // The contact prolongation's rows of this level (level_contact_prolongation.hpp): A's
    // diagonal, and P's and T's rows, at the unknowns the contact rows touch.
    if (contact != nullptr && contact->open()) {
      Vector diagonal = Vector::Zero(fine.size());
      for (Index k = 0; k < fine.count; ++k) diagonal(k) = Al.coeff(k, k);
      const SparseMatrix* T = &t.tentative;
      SparseMatrix T_wider;  // (on several ranks: T's own rows in P's sizes)
      if (T->rows() != P_ext.rows() || T->cols() != P_ext.cols()) {
        T_wider = t.tentative;
        T_wider.conservativeResize(P_ext.rows(), P_ext.cols());
        T_wider.makeCompressed();
        T = &T_wider;
      }
      contact->add_level(comm, diagonal, P_ext, *T, omega, fine, coarse_numbering);
    }

    // This rank's share of P^T A P (coarse numbering local), summed into the coarse level by
    // PETSc's COO assembly, which sends the other ranks' rows to them; on one rank, the
    // product itself (symmetric: its columns are its rows).
    SparseMatrix share = galerkin_product(Al, P_ext);
    columns.reset();
    Mat R = nullptr;
    if (size == 1) {
      // On one rank P^T in place from P's column-major arrays (sequential_matrix: no copy),
      // and P its transpose, made by PETSc (at 434,235 unknowns 0.06 s, where P's row-major
      // copy and its copy into PETSc took 0.57 s). P^T is kept for the restriction.
      R = sequential_matrix(std::move(P_ext), comm);
      check(MatTranspose(R, MAT_INITIAL_MATRIX, &P), "a prolongation");
    }
    P_ext = SparseMatrix();
    Mat C = nullptr;
    if (size == 1) {
      C = sequential_matrix(std::move(share), comm);  // (symmetric: in place, no copy)
    } else {
      check(MatCreate(comm, &C), "a coarse level");
      check(MatSetSizes(C, own_coarse, own_coarse, coarse, coarse), "a coarse level");
      check(MatSetType(C, MATAIJ), "a coarse level");
      std::vector<PetscInt> ci, cj;
      ci.reserve(static_cast<std::size_t>(share.nonZeros()));
      cj.reserve(ci.capacity());
      for (Index c = 0; c < share.outerSize(); ++c)
        for (SparseMatrix::InnerIterator it(share, c); it; ++it) {
          ci.push_back(coarse_numbering.global(it.row()));
          cj.push_back(coarse_numbering.global(c));
        }
      check(MatSetPreallocationCOO(C, static_cast<PetscCount>(ci.size()), ci.data(), cj.data()),
            "a coarse level");
      check(MatSetValuesCOO(C, share.valuePtr(), INSERT_VALUES), "a coarse level");
    }
    share = SparseMatrix();
    check(MatSetOption(C, MAT_SYMMETRIC, PETSC_TRUE), "a coarse level");
    out.prolongations.push_back(P);
    out.restrictions.push_back(R);
    out.operators.push_back(C);
    level = C;
    B = std::move(t.coarse_null_space);
    node_of = std::move(t.coarse_node);
    place_of = std::move(t.place_of);
  }
  return out;
}

}  // namespace signorini::petsc
