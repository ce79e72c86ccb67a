#include "signorini/petsc/petsc_contact_multigrid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <optional>

#include "signorini/core/error.hpp"
#include "signorini/petsc/aggregation_levels.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"

namespace signorini::petsc {

namespace {

// Chebyshev-Jacobi of degree 2 with bounds [0.1, 1.1] x lambda_max(D^-1 H), lambda_max estimated
// by CG from a noisy right-hand side: GAMG's smoother, as the serial one (chebyshev_smoother.hpp).
void make_smoother(KSP k) {
  check(KSPSetType(k, KSPCHEBYSHEV), "the multigrid smoother");
  check(KSPChebyshevEstEigSet(k, 0.0, 0.1, 0.0, 1.1), "the multigrid smoother");
  check(KSPChebyshevEstEigSetUseNoisy(k, PETSC_TRUE), "the multigrid smoother");
  KSP est = nullptr;
  check(KSPChebyshevEstEigGetKSP(k, &est), "the multigrid smoother");
  if (est != nullptr) check(KSPSetType(est, KSPCG), "the multigrid smoother");
  check(KSPSetTolerances(k, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2),
        "the multigrid smoother");
  PC p = nullptr;
  check(KSPGetPC(k, &p), "the multigrid smoother");
  check(PCSetType(p, PCJACOBI), "the multigrid smoother");
}

// A PETSc option in the options database for the life of the object, unless the options hold
// it or its alias already (or `value` is empty): a default of ours that the user's options win
// over.
class ScopedDefaultOption {
 public:
  ScopedDefaultOption(const char* name, const char* value, const char* alias = nullptr)
      : name_(name) {
    PetscBool given = PETSC_FALSE, alias_given = PETSC_FALSE;
    check(PetscOptionsHasName(nullptr, nullptr, name, &given), "PETSc options");
    if (alias != nullptr)
      check(PetscOptionsHasName(nullptr, nullptr, alias, &alias_given), "PETSc options");
    set_ = given == PETSC_FALSE && alias_given == PETSC_FALSE && value[0] != '\0';
    if (set_) check(PetscOptionsSetValue(nullptr, name, value), "PETSc options");
  }
  ~ScopedDefaultOption() {
    if (set_) PetscOptionsClearValue(nullptr, name_);
  }
  ScopedDefaultOption(const ScopedDefaultOption&) = delete;
  ScopedDefaultOption& operator=(const ScopedDefaultOption&) = delete;

 private:
  const char* name_;
  bool set_ = false;
};

// Whether PETSc was built with hypre, whose matrix products MatPtAP can call.
#if defined(PETSC_HAVE_HYPRE)
constexpr bool kHypreProducts = true;
#else
constexpr bool kHypreProducts = false;
#endif

// GAMG's levels of A_setup, fine first (GAMG gives them coarsest first).
CoarseLevels gamg_levels(Mat A_setup) {
  // GAMG once, on A; PETSc's options for GAMG (-pc_gamg_*) apply to it.
  KSP setup = nullptr;
  check(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(A_setup)), &setup), "GAMG");
  check(KSPSetOperators(setup, A_setup, A_setup), "GAMG");
  PC g = nullptr;
  check(KSPGetPC(setup, &g), "GAMG");
  check(PCSetType(g, PCGAMG), "GAMG");
  // Two defaults of ours for GAMG's set-up, where PETSc's options (solver.petsc_options,
  // PETSC_OPTIONS) do not choose otherwise (docs/distributed.md, "The multigrid of the Newton
  // systems"), both measured on Hertz's ball at a million unknowns, one rank of two cores:
  // - aggressive coarsening (the graph squared, MIS-2) on the first two levels, not only the
  //   first: the third level is some 7 times smaller (828 against 6,066 unknowns) and the
  //   Galerkin product that makes it, from the second level's dense 6 x 6 blocks, 1.3 s
  //   instead of 4.5-7.3 s; the levels' refreshes for each active set are cheaper too, for
  //   some 15 % more CG iterations;
  // - the Galerkin products by hypre's, which run on the rank's OpenMP threads (PETSc's own
  //   run on one): the finest level's 5.6 s instead of 8.5 s. Only for GAMG's set-up: the
  //   contact terms' small products below stay PETSc's, cheaper there.
  {
    const ScopedDefaultOption aggressive("-pc_gamg_aggressive_coarsening", "2",
                                         "-pc_gamg_square_graph");
    const ScopedDefaultOption products("-matptap_via", kHypreProducts ? "hypre" : "");
    check(PCSetFromOptions(g), "GAMG options");  // (no -pc_type: keeps_multigrid_levels)
    check(PCSetUp(g), "GAMG's set-up");
  }
  PetscInt np = 0, na = 0;
  Mat* Ps = nullptr;
  Mat* As = nullptr;
  check(PCGetInterpolations(g, &np, &Ps), "GAMG's levels");
  check(PCGetCoarseOperators(g, &na, &As), "GAMG's levels");
  // Both report the number of levels and hold one matrix fewer (PETSc referenced each). One
  // level (a problem of a few dozen unknowns): the smoother alone preconditions.
  if (np != na || np < 1)
    throw NumericalError(fmt::format("PETSc: GAMG made {} prolongators for {} levels", np, na));
  // (np - 1 of each: the levels below the fine one, coarsest first.)
  CoarseLevels out;
  out.prolongations.assign(std::make_reverse_iterator(Ps + np - 1), std::make_reverse_iterator(Ps));
  out.operators.assign(std::make_reverse_iterator(As + na - 1), std::make_reverse_iterator(As));
  check(PetscFree(Ps), "GAMG's levels");
  check(PetscFree(As), "GAMG's levels");
  check(KSPDestroy(&setup), "GAMG");
  return out;
}

// The rows of this rank where Q has entries, if each of them lies in A's pattern (structurally;
// collective: every rank's answer together) and A is AIJ, else nothing. On aggregation's
// levels it does: Q_l = N_l^T diag(c) N_l couples two coarse unknowns only where the
// prolongations of both reach one contact node's unknowns, and A's node block there is
// structurally full, so A_l = P^T A P couples them too (and level by level below).
std::optional<std::vector<PetscInt>> rows_within_pattern(Mat A, Mat Q, MPI_Comm comm) {
  PetscBool aij = PETSC_FALSE;
  check(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(A), &aij, MATSEQAIJ, MATMPIAIJ, ""),
        "a coarse level's pattern");
  PetscInt lo = 0, hi = 0;
  check(MatGetOwnershipRange(Q, &lo, &hi), "a coarse level's pattern");
  std::vector<PetscInt> rows;
  int within = aij ? 1 : 0;
  for (PetscInt r = lo; r < hi && within != 0; ++r) {
    PetscInt nq = 0, na = 0;
    const PetscInt* cq = nullptr;
    const PetscInt* ca = nullptr;
    check(MatGetRow(Q, r, &nq, &cq, nullptr), "a coarse level's pattern");
    if (nq > 0) {
      rows.push_back(r);
      check(MatGetRow(A, r, &na, &ca, nullptr), "a coarse level's pattern");
      // (MatGetRow gives each row's columns ascending.)
      within = std::includes(ca, ca + na, cq, cq + nq) ? 1 : 0;
      check(MatRestoreRow(A, r, &na, &ca, nullptr), "a coarse level's pattern");
    }
    check(MatRestoreRow(Q, r, &nq, &cq, nullptr), "a coarse level's pattern");
  }
  MPI_Allreduce(MPI_IN_PLACE, &within, 1, MPI_INT, MPI_MIN, comm);
  if (within == 0) return std::nullopt;
  return rows;
}

// The values of the AIJ matrix M in its rows `rows` (global, this rank's, ascending): saved
// into `values` (save), or written back from them. Each row's values lie in one piece of
// each of the rank's blocks (its own columns, and the others').
void move_row_values(Mat M, const std::vector<PetscInt>& rows, std::vector<PetscScalar>& values,
                     bool save) {
  PetscBool mpi = PETSC_FALSE;
  check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(M), MATMPIAIJ, &mpi),
        "a coarse level");
  PetscInt lo = 0;
  check(MatGetOwnershipRange(M, &lo, nullptr), "a coarse level");
  Mat parts[2] = {M, nullptr};
  if (mpi) check(MatMPIAIJGetSeqAIJ(M, &parts[0], &parts[1], nullptr), "a coarse level");
  if (save) values.clear();
  std::size_t at = 0;
  for (Mat part : parts) {
    if (part == nullptr) continue;
    PetscInt n = 0;
    const PetscInt* ia = nullptr;
    const PetscInt* ja = nullptr;
    PetscBool done = PETSC_FALSE;
    check(MatGetRowIJ(part, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done), "a coarse level");
    PetscScalar* a = nullptr;
    check(MatSeqAIJGetArray(part, &a), "a coarse level");
    for (const PetscInt r : rows) {
      const PetscInt b = ia[r - lo], e = ia[r - lo + 1];
      if (save) {
        values.insert(values.end(), a + b, a + e);
      } else {
        std::copy(
            values.begin() + static_cast<std::ptrdiff_t>(at),
            values.begin() + static_cast<std::ptrdiff_t>(at + static_cast<std::size_t>(e - b)),
            a + b);
        at += static_cast<std::size_t>(e - b);
      }
    }
    check(MatSeqAIJRestoreArray(part, &a), "a coarse level");
    check(MatRestoreRowIJ(part, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done),
          "a coarse level");
  }
  if (!save) {  // (the blocks' states changed; an assembly, with nothing to send, marks M's)
    check(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY), "a coarse level");
    check(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY), "a coarse level");
  }
}

}  // namespace

ContactMultigrid::ContactMultigrid(PC pc, Mat A_setup, const std::vector<ContactRow>& rows,
                                   MPI_Comm comm, Levels levels, bool contact_prolongation)
    : pc_(pc), comm_(comm) {
  // On our own levels, the contact prolongation's rows come with them (of this rank's contact
  // rows, in the rank's own unknowns of the fine level).
  if (levels == Levels::Aggregation && contact_prolongation) {
    PetscInt lo = 0, hi = 0;
    check(MatGetOwnershipRange(A_setup, &lo, &hi), "the contact matrix");
    std::vector<Eigen::Triplet<double, int>> entries;
    for (std::size_t k = 0; k < rows.size(); ++k)
      for (std::size_t q = 0; q < rows[k].dofs.size(); ++q)
        if (rows[k].normal[q] != 0.0)
          entries.emplace_back(static_cast<int>(k), static_cast<int>(rows[k].dofs[q] - lo),
                               rows[k].normal[q]);
    RowMatrix N(static_cast<Index>(rows.size()), hi - lo);
    N.setFromTriplets(entries.begin(), entries.end());
    contact_ = std::make_unique<LevelContactProlongations>(std::move(N));
  }
  // The levels, fine first; PCMG numbers them coarsest first.
  CoarseLevels made = levels == Levels::Aggregation ? aggregation_levels(A_setup, contact_.get())
                                                    : gamg_levels(A_setup);
  if (contact_ && contact_->levels() == 0) contact_.reset();
  P_.assign(made.prolongations.rbegin(), made.prolongations.rend());
  levels_.resize(made.operators.size());
  const auto radius = [&made](std::size_t depth) {  // (fine first, where the maker has it)
    return depth < made.jacobi_radii.size() ? made.jacobi_radii[depth] : 0.0;
  };
  for (std::size_t l = 0; l < made.operators.size(); ++l) {
    levels_[l].A = made.operators[made.operators.size() - 1 - l];
    levels_[l].lambda_a = radius(made.operators.size() - l);
  }
  fine_lambda_a_ = radius(0);

  // N on the finest level: this rank's contact rows, numbered after the lower ranks' ones.
  const auto m = static_cast<PetscInt>(rows.size());
  const PetscInt first = count_before(m, comm_);
  first_row_ = first;
  PetscInt local_cols = 0, cols = 0;
  check(MatGetLocalSize(A_setup, &local_cols, nullptr), "the contact matrix");
  check(MatGetSize(A_setup, &cols, nullptr), "the contact matrix");
  std::size_t widest = 1;
  for (const ContactRow& row : rows) widest = std::max(widest, row.dofs.size());
  Mat N = nullptr;
  check(MatCreateAIJ(comm_, m, local_cols, PETSC_DETERMINE, cols, static_cast<PetscInt>(widest),
                     nullptr, 0, nullptr, &N),
        "the contact matrix");
  for (PetscInt k = 0; k < m; ++k) {
    const ContactRow& row = rows[static_cast<std::size_t>(k)];
    const PetscInt i = first + k;
    check(MatSetValues(N, 1, &i, static_cast<PetscInt>(row.dofs.size()), row.dofs.data(),
                       row.normal.data(), INSERT_VALUES),
          "the contact matrix");
    row_j_.push_back(row.j);
    row_entries_.push_back(static_cast<int>(
        std::count_if(row.normal.begin(), row.normal.end(), [](double v) { return v != 0.0; })));
  }
  check(MatAssemblyBegin(N, MAT_FINAL_ASSEMBLY), "the contact matrix");
  check(MatAssemblyEnd(N, MAT_FINAL_ASSEMBLY), "the contact matrix");

  // diag(c), every diagonal entry stored, so that the products' patterns hold for every c.
  check(MatCreateAIJ(comm_, m, m, PETSC_DETERMINE, PETSC_DETERMINE, 1, nullptr, 0, nullptr, &C_),
        "diag(c)");
  check(MatCreateVecs(C_, &c_, nullptr), "diag(c)");
  check(VecSet(c_, 1.0), "diag(c)");
  check(MatDiagonalSet(C_, c_, INSERT_VALUES), "diag(c)");

  // N_l = N_{l+1} P_l, Q_l = N_l^T diag(c) N_l, and H_l's pattern: that of A_l + Q_l.
  Mat finer = N;
  for (std::size_t l = levels_.size(); l-- > 0;) {
    Coarse& c = levels_[l];
    check(MatMatMult(finer, P_[l], MAT_INITIAL_MATRIX, PETSC_DEFAULT, &c.N),
          "the contact rows on a coarse level");
    check(MatPtAP(C_, c.N, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &c.Q),
          "the contact term on a coarse level");
    // Where Q's pattern lies in A's (as on aggregation's levels), H is on A's pattern, and a
    // refresh writes back A's values in Q's rows alone, saved here. On our own levels H is A
    // itself, changed in place; GAMG's coarse operators are objects of its own solvers (on one
    // rank the coarsest is its coarse solver's, and changed in place it left CG with an
    // indefinite preconditioner), so H is a copy there. At a million unknowns, one rank, the
    // first coarse level has 24 million entries: H on the union of both patterns took 2.0 s
    // to make (two copies of the level, and the union), and each refresh copied the whole
    // level. Else H is a copy on the union, and A_in_H A on it.
    // (Every level but the coarsest is smoothed: A_l's lambda_max once, where GAMG made it.)
    if (l > 0 && c.lambda_a <= 0.0) c.lambda_a = jacobi_lambda_max(c.A);
    std::optional<std::vector<PetscInt>> q_rows = rows_within_pattern(c.A, c.Q, comm_);
    if (q_rows) {
      if (levels == Levels::Aggregation)
        std::swap(c.H, c.A);
      else
        check(MatDuplicate(c.A, MAT_COPY_VALUES, &c.H), "a coarse level");
      check(MatDestroy(&c.A), "a coarse level");
      c.q_rows = std::move(*q_rows);
      move_row_values(c.H, c.q_rows, c.q_row_values, true);
      check(MatAXPY(c.H, 1.0, c.Q, SUBSET_NONZERO_PATTERN), "a coarse level");
      mark_spd(c.H, "a coarse level");
    } else {
      check(MatDuplicate(c.A, MAT_COPY_VALUES, &c.H), "a coarse level");
      check(MatAXPY(c.H, 1.0, c.Q, DIFFERENT_NONZERO_PATTERN), "a coarse level");
      mark_spd(c.H, "a coarse level");
      check(MatDuplicate(c.H, MAT_DO_NOT_COPY_VALUES, &c.A_in_H), "a coarse level");
      check(MatAXPY(c.A_in_H, 1.0, c.A, SUBSET_NONZERO_PATTERN), "a coarse level");
      check(MatDestroy(&c.A), "a coarse level");  // A_in_H holds it from here on
    }
    finer = c.N;
  }
  check(MatDestroy(&N), "the contact matrix");

  // On a rank with several threads, the transfers and the products of the coarse levels but
  // the coarsest run on them too (threaded_product.hpp; docs/distributed.md, "Threads per
  // rank"): on Hertz's ball at a million unknowns, one rank, the transfers between the two
  // finest levels and the smoothing of the second took half of a V-cycle's time on one
  // thread. Levels of a few thousand rows per rank stay PETSc's.
  const auto threaded_pays = [](Mat M) {
    PetscInt local_rows = 0;
    check(MatGetLocalSize(M, &local_rows, nullptr), "multigrid");
    return local_rows >= 5000 && ThreadedProduct::worthwhile(M);
  };
  transfers_.resize(P_.size());
  made.restrictions.resize(P_.size(), nullptr);  // (fine first; P_ and transfers_ too)
  for (std::size_t l = 0; l < P_.size(); ++l) {
    Mat& R = made.restrictions[P_.size() - 1 - l];
    if (!threaded_pays(P_[l])) {
      check(MatDestroy(&R), "a restriction");
      continue;
    }
    Transfer& t = transfers_[l];
    if (R != nullptr)
      std::swap(t.R, R);  // (the maker's P^T)
    else
      check(MatTranspose(P_[l], MAT_INITIAL_MATRIX, &t.R), "a restriction");
    t.prolongation = std::make_unique<ThreadedProduct>(P_[l]);
    t.restriction = std::make_unique<ThreadedProduct>(t.R);
  }
  for (std::size_t l = 1; l < levels_.size(); ++l)  // (levels_[0]: the coarsest, factorised)
    if (threaded_pays(levels_[l].H))
      levels_[l].threaded = std::make_unique<ThreadedProduct>(levels_[l].H);

  // The PCMG: GAMG's prolongators, the coarse levels' H_l, the finest from the KSP.
  const auto L = static_cast<PetscInt>(levels_.size() + 1);
  check(PCSetType(pc_, PCMG), "multigrid");
  check(PCMGSetLevels(pc_, L, nullptr), "multigrid");
  check(PCMGSetGalerkin(pc_, PC_MG_GALERKIN_NONE), "multigrid");
  // (The contact prolongation's levels, finest first: depth d is PCMG's level L - 1 - d.)
  const std::size_t corrected = contact_ ? contact_->levels() : 0;
  corrected_.resize(corrected);
  changes_.assign(corrected, nullptr);
  for (PetscInt l = 1; l < L; ++l) {
    const Transfer& t = transfers_[static_cast<std::size_t>(l) - 1];
    const auto depth = static_cast<std::size_t>(L - 1 - l);
    if (depth < corrected) {
      auto& c = corrected_[depth];
      c = t.prolongation
              ? std::make_unique<CorrectedTransfer>(t.prolongation->shell(), t.restriction->shell())
              : std::make_unique<CorrectedTransfer>(P_[static_cast<std::size_t>(l) - 1], nullptr);
      check(PCMGSetInterpolation(pc_, l, c->interpolation()), "multigrid");
      check(PCMGSetRestriction(pc_, l, c->restriction()), "multigrid");
    } else if (t.prolongation) {
      check(PCMGSetInterpolation(pc_, l, t.prolongation->shell()), "multigrid");
      check(PCMGSetRestriction(pc_, l, t.restriction->shell()), "multigrid");
    } else {
      check(PCMGSetInterpolation(pc_, l, P_[static_cast<std::size_t>(l) - 1]), "multigrid");
    }
  }
  for (PetscInt l = 0; l < L; ++l) {
    KSP k = nullptr;
    check(PCMGGetSmoother(pc_, l, &k), "multigrid");
    if (l + 1 < L) {
      const Mat H = levels_[static_cast<std::size_t>(l)].op();
      check(KSPSetOperators(k, H, H), "multigrid");
    }
    if (l > 0 || L == 1) make_smoother(k);
  }
  if (fine_lambda_a_ <= 0.0) fine_lambda_a_ = jacobi_lambda_max(A_setup);
  sizes_.push_back(cols);
  for (std::size_t l = levels_.size(); l-- > 0;) {
    PetscInt n = 0;
    check(MatGetSize(levels_[l].H, &n, nullptr), "multigrid");
    sizes_.push_back(n);
  }
}

ContactMultigrid::~ContactMultigrid() {
  // (The PC, the shells' user, is gone: the KSP that holds it is destroyed first.)
  corrected_.clear();
  for (Mat& dP : changes_) MatDestroy(&dP);
  for (Transfer& t : transfers_) {
    t.prolongation.reset();
    t.restriction.reset();
    MatDestroy(&t.R);
  }
  for (Coarse& c : levels_) {
    c.threaded.reset();
    for (Mat* M : {&c.A, &c.N, &c.Q, &c.H, &c.A_in_H}) MatDestroy(M);  // (A: null once used)
  }
  for (Mat& P : P_) MatDestroy(&P);
  MatDestroy(&C_);
  VecDestroy(&c_);
}

void ContactMultigrid::set_weights(const Vector& c, int block_unknowns) {
  PetscScalar* a = nullptr;
  check(VecGetArray(c_, &a), "diag(c)");
  for (std::size_t k = 0; k < row_j_.size(); ++k) a[k] = c(row_j_[k]);
  check(VecRestoreArray(c_, &a), "diag(c)");
  check(MatDiagonalSet(C_, c_, INSERT_VALUES), "diag(c)");
  if (contact_) {
    // The transfers P_l + dP_l and the coarse contact rows they carry, for this c (scalar
    // weights only: with friction's blocks, A's prolongations, as serially).
    Vector own(static_cast<Index>(row_j_.size()));
    for (std::size_t k = 0; k < row_j_.size(); ++k)
      own(static_cast<Index>(k)) = block_unknowns == 0 ? c(row_j_[k]) : 0.0;
    std::vector<Mat> rows(contact_->levels() + 1, nullptr);
    for (std::size_t d = 1; d < rows.size(); ++d) rows[d] = levels_[levels_.size() - d].N;
    contact_->update(comm_, own, first_row_, rows, changes_);
    for (std::size_t d = 0; d < corrected_.size(); ++d) corrected_[d]->set_change(changes_[d]);
  }
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Coarse& lev = levels_[l];
    check(MatPtAP(C_, lev.N, MAT_REUSE_MATRIX, PETSC_DEFAULT, &lev.Q),
          "the contact term on a coarse level");
    if (lev.A_in_H == nullptr)  // (H on A's pattern: Q's rows alone differ from A's)
      move_row_values(lev.H, lev.q_rows, lev.q_row_values, false);
    else
      check(MatCopy(lev.A_in_H, lev.H, SAME_NONZERO_PATTERN), "a coarse level");
    check(MatAXPY(lev.H, 1.0, lev.Q, SUBSET_NONZERO_PATTERN), "a coarse level");
    if (lev.threaded) lev.threaded->refresh();
    // The smoothers' diagonals and the coarsest factorisation are set up again. The smoothers'
    // intervals: the larger of A_l's lambda_max and the contact zone's, instead of 10 CG steps
    // on the whole level, each time (at 434,235 unknowns on one rank, the refreshes' time).
    KSP k = nullptr;
    check(PCMGGetSmoother(pc_, static_cast<PetscInt>(l), &k), "multigrid");
    check(KSPSetOperators(k, lev.op(), lev.op()), "multigrid");
    if (l == 0) continue;  // (the coarsest: factorised)
    const double lambda = std::max(lev.lambda_a, zone_lambda_max(lev));
    check(KSPChebyshevSetEigenvalues(k, 1.1 * lambda, 0.1 * lambda), "a smoother");
  }
  // The fine level: instead of 10 products with H, the bound of multigrid_preconditioner.cpp
  // (refresh()): lambda_max(D_H^-1 H) <= max(lambda_A, the most nonzero components of an active
  // n_j, or with friction's blocks the unknowns that a node's rows touch together: a positive
  // semidefinite k x k block E has lambda_max(diag(E)^-1 E) <= k); with GAMG's interval
  // [0.1, 1.1] x lambda_max.
  int entries = block_unknowns;
  if (block_unknowns == 0)
    for (std::size_t k = 0; k < row_j_.size(); ++k)
      if (c(row_j_[k]) > 0.0) entries = std::max(entries, row_entries_[k]);
  MPI_Allreduce(MPI_IN_PLACE, &entries, 1, MPI_INT, MPI_MAX, comm_);
  const double bound = std::max(fine_lambda_a_, static_cast<double>(entries));
  KSP fine = nullptr;
  check(PCMGGetSmoother(pc_, static_cast<PetscInt>(levels_.size()), &fine), "multigrid");
  check(KSPChebyshevSetEigenvalues(fine, 1.1 * bound, 0.1 * bound), "the fine smoother");
}

double ContactMultigrid::zone_lambda_max(const Coarse& level) const {
  Vec d = nullptr;
  check(MatCreateVecs(level.Q, &d, nullptr), "the contact zone");
  check(MatGetDiagonal(level.Q, d), "the contact zone");
  PetscInt lo = 0, hi = 0;
  check(VecGetOwnershipRange(d, &lo, &hi), "the contact zone");
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(d, &a), "the contact zone");
  std::vector<PetscInt> zone;
  for (PetscInt i = lo; i < hi; ++i)
    if (PetscRealPart(a[i - lo]) > 0.0) zone.push_back(i);
  check(VecRestoreArrayRead(d, &a), "the contact zone");
  check(VecDestroy(&d), "the contact zone");
  IS is = nullptr;
  check(ISCreateGeneral(comm_, static_cast<PetscInt>(zone.size()), zone.data(), PETSC_COPY_VALUES,
                        &is),
        "the contact zone");
  PetscInt size = 0;
  check(ISGetSize(is, &size), "the contact zone");
  double lambda = 0.0;
  if (size > 0) {
    Mat Z = nullptr;
    check(MatCreateSubMatrix(level.H, is, is, MAT_INITIAL_MATRIX, &Z), "the contact zone");
    lambda = jacobi_lambda_max(Z);
    check(MatDestroy(&Z), "the contact zone");
  }
  check(ISDestroy(&is), "the contact zone");
  return lambda;
}

}  // namespace signorini::petsc
