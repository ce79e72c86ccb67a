#include "signorini/petsc/level_contact_prolongation.hpp"

#include <fmt/format.h>

#include <utility>

#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_check.hpp"

namespace signorini::petsc {

namespace {

// The rows of `full` where `keep[r]`, each with D's row added on `full`'s pattern where
// `add[r]` (D: the same numbering; its entries off that pattern are left out, so that a level's
// rows keep the pattern of PETSc's contact matrix); the other rows empty.
RowMatrix rows_with(const RowMatrix& full, const RowMatrix* D, const std::vector<char>& keep,
                    const std::vector<char>& add) {
  const Index m = full.rows();
  RowMatrix out(m, full.cols());
  Index count = 0;
  for (Index r = 0; r < m; ++r)
    if (keep[static_cast<std::size_t>(r)] != 0)
      count += full.outerIndexPtr()[r + 1] - full.outerIndexPtr()[r];
  out.resizeNonZeros(count);
  int* outer = out.outerIndexPtr();
  int* inner = out.innerIndexPtr();
  double* values = out.valuePtr();
  int at = 0;
  outer[0] = 0;
  for (Index r = 0; r < m; ++r) {
    if (keep[static_cast<std::size_t>(r)] != 0) {
      const int b = full.outerIndexPtr()[r], e = full.outerIndexPtr()[r + 1];
      for (int k = b; k < e; ++k, ++at) {
        inner[at] = full.innerIndexPtr()[k];
        values[at] = full.valuePtr()[k];
      }
      if (D != nullptr && add[static_cast<std::size_t>(r)] != 0) {
        // (Both rows' columns ascending: one merge.)
        int q = at - (e - b);
        for (int k = D->outerIndexPtr()[r]; k < D->outerIndexPtr()[r + 1]; ++k) {
          const int column = D->innerIndexPtr()[k];
          while (q < at && inner[q] < column) ++q;
          if (q < at && inner[q] == column) values[q] += D->valuePtr()[k];
        }
      }
    }
    outer[r + 1] = at;
  }
  return out;
}

}  // namespace

LevelContactProlongations::LevelContactProlongations(RowMatrix N) : N_(std::move(N)) {
  N_.makeCompressed();
}

void LevelContactProlongations::add_level(MPI_Comm comm, const Vector& diagonal,
                                          const SparseMatrix& P, const SparseMatrix& T,
                                          double omega, const ExtNumbering& fine,
                                          const ExtNumbering& coarse) {
  if (!open_) throw NumericalError("contact prolongation: a level after the list was closed");
  const RowMatrix& rows = levels_.empty() ? N_ : coarse_N_.back();
  SparseMatrix N(rows);  // (the rank's own columns; the ghosts' follow, empty)
  N.conservativeResize(rows.rows(), fine.size());
  int ok = 1;
  std::unique_ptr<ContactProlongation> prolongation;
  try {
    prolongation = std::make_unique<ContactProlongation>(diagonal, N, P, T, omega);
  } catch (const NumericalError&) {
    ok = 0;  // (T has no row where a contact row reaches: A's prolongation from here down)
  }
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_MIN, comm);
  if (ok == 0) {
    open_ = false;
    return;
  }
  // The next level's rows N_l P_l, from P's rows at N_l's unknowns; they stay on this rank if
  // every column is one of the next level's own unknowns.
  RowMatrix next(prolongation->carry(N));
  int local = 1;
  for (Index k = 0; k < next.nonZeros() && local != 0; ++k)
    if (next.innerIndexPtr()[k] >= coarse.count) local = 0;
  MPI_Allreduce(MPI_IN_PLACE, &local, 1, MPI_INT, MPI_MIN, comm);
  if (local != 0) {
    next.conservativeResize(next.rows(), coarse.count);
    next.makeCompressed();  // (a narrower row-major matrix comes back uncompressed)
  }
  levels_.push_back(Level{std::move(prolongation), fine.count, fine.size(), coarse});
  coarse_N_.push_back(std::move(next));
  open_ = local != 0;
}

void LevelContactProlongations::write_rows(Mat M, const RowMatrix& current,
                                           const ExtNumbering& numbering, PetscInt first_row,
                                           const std::vector<char>& write) {
  // (Entries outside M's pattern, if rounding ever made one, are dropped, not added.)
  check(MatSetOption(M, MAT_NEW_NONZERO_LOCATIONS, PETSC_FALSE), "a level's contact rows");
  check(MatSetOption(M, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE), "a level's contact rows");
  std::vector<PetscInt> columns;
  for (Index r = 0; r < current.rows(); ++r) {
    if (write[static_cast<std::size_t>(r)] == 0) continue;
    const int b = current.outerIndexPtr()[r], e = current.outerIndexPtr()[r + 1];
    columns.clear();
    for (int k = b; k < e; ++k) columns.push_back(numbering.global(current.innerIndexPtr()[k]));
    const PetscInt row = first_row + static_cast<PetscInt>(r);
    check(MatSetValues(M, 1, &row, static_cast<PetscInt>(columns.size()), columns.data(),
                       current.valuePtr() + b, INSERT_VALUES),
          "a level's contact rows");
  }
  check(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY), "a level's contact rows");
  check(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY), "a level's contact rows");
}

void LevelContactProlongations::update(MPI_Comm comm, const Vector& c, PetscInt first_row,
                                       const std::vector<Mat>& rows, std::vector<Mat>& changes) {
  const Index m = N_.rows();
  if (c.size() != m || rows.size() < levels_.size() + 1 || changes.size() < levels_.size())
    throw NumericalError(fmt::format("contact prolongation: {} weights for {} rows", c.size(), m));
  std::vector<char> active(static_cast<std::size_t>(m)), write(static_cast<std::size_t>(m));
  if (was_active_.size() != active.size()) was_active_.assign(active.size(), 0);
  for (Index r = 0; r < m; ++r) {
    const auto s = static_cast<std::size_t>(r);
    active[s] = c(r) > 0.0 ? 1 : 0;
    write[s] = active[s] != 0 || was_active_[s] != 0 ? 1 : 0;
  }
  // Level by level, finest first, as MultigridPreconditioner::update_contact_prolongation: the
  // current rows N_l,cur = N P_H,0 ... P_H,l-1 (the active ones) give the change P_H,l - P_l,
  // and N_l+1,cur = N_l+1 + D_l+1 with D_l+1 = D_l P_l + N_l,cur (P_H,l - P_l), D_0 = 0.
  RowMatrix current = rows_with(N_, nullptr, active, active);
  RowMatrix D;
  for (std::size_t l = 0;; ++l) {
    if (l > 0) {
      // Active rows with D, rows no longer active back to A's prolongations' (N_l).
      current = rows_with(coarse_N_[l - 1], D.nonZeros() > 0 ? &D : nullptr, write, active);
      write_rows(rows[l], current, levels_[l - 1].coarse, first_row, write);
    }
    if (l == levels_.size()) break;
    const Level& lev = levels_[l];
    SparseMatrix Nt(current.transpose());
    Nt.conservativeResize(lev.extended, m);
    const SparseMatrix change = lev.prolongation->change(c, &Nt);
    int any = change.nonZeros() > 0 ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, comm);
    check(MatDestroy(&changes[l]), "a prolongation's change");
    if (any != 0) {
      const RowMatrix own_rows(change.topRows(lev.own));
      changes[l] = distributed_matrix(comm, own_rows, lev.coarse, lev.coarse.count);
    }
    RowMatrix next;
    if (D.nonZeros() > 0) {
      SparseMatrix Dp(D);
      Dp.conservativeResize(m, lev.extended);
      next = RowMatrix(lev.prolongation->carry(Dp));
    }
    if (change.nonZeros() > 0) {
      RowMatrix extended = current;
      extended.conservativeResize(m, lev.extended);
      RowMatrix term = extended * change;
      next = next.nonZeros() > 0 ? RowMatrix(next + term) : std::move(term);
    }
    if (next.nonZeros() > 0) {
      next.conservativeResize(m, coarse_N_[l].cols());
      next.makeCompressed();
    }
    D = std::move(next);
  }
  was_active_ = std::move(active);
}

}  // namespace signorini::petsc
