#include "signorini/iterative/multigrid_preconditioner.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <algorithm>

#include "signorini/backend/host_backend.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/contact_zone_estimate.hpp"
#include "signorini/iterative/galerkin_product.hpp"

namespace signorini {

struct MultigridPreconditioner::Level {
  SparseMatrix A;                            // the Galerkin product, where formed here
  std::unique_ptr<PenalizedOperator> owned;  // coarse levels own their operator
  PenalizedOperator* op = nullptr;
  std::unique_ptr<ChebyshevSmoother> smoother;
  // To this level from the next coarser one: P^T always (P's CSC arrays, shared on the CPU), P
  // only where the backend has no transposed product (a GPU).
  std::unique_ptr<DeviceSparseMatrix> P, Pt;
  DeviceVector b, x, r;                              // right-hand side, correction, residual
  std::unique_ptr<PenalizedOperator> on_host;        // host copy for the eigenvalue estimate
  std::unique_ptr<ChebyshevSmoother> host_smoother;  // its smoother: only estimates
  const SparseMatrix* host_A = nullptr;              // A_l on the host (the caller's, or `A` above)
  double lambda_without_contact = 0.0;               // lambda_max(D^-1 A_l) once estimated (c = 0)
  // N_l = N P_0 ... P_l-1 as formed (coarse levels; on the fine level N itself where the
  // contact prolongation needs it)
  SparseMatrix N;
  const SparseMatrix* P_host = nullptr;  // the prolongation from the next level, on the host
  // The change P_H - P of the prolongation from the next level (contact_prolongation.hpp): its
  // maker (null: none), its host matrix (whose arrays dPt may share), P_H - P and its transpose
  // on the backend (null: none).
  std::unique_ptr<ContactProlongation> contact_prolongation;
  SparseMatrix dP_host;
  std::unique_ptr<DeviceSparseMatrix> dP, dPt;
};

MultigridPreconditioner::MultigridPreconditioner(PenalizedOperator& fine, const SparseMatrix& A,
                                                 const SparseMatrix& N,
                                                 const std::vector<SparseMatrix>& prolongations,
                                                 MultigridOptions options,
                                                 const std::vector<SparseMatrix>& coarse_operators)
    : backend_(fine.backend()), options_(options) {
  if (A.rows() != fine.size() || N.cols() != fine.size())
    throw NumericalError("multigrid: A and N do not match the fine operator");
  if (!coarse_operators.empty() && coarse_operators.size() != prolongations.size())
    throw NumericalError(fmt::format("multigrid: {} coarse operators for {} prolongations",
                                     coarse_operators.size(), prolongations.size()));
  // The current level's matrices: the fine A is used in place (no copy of the largest matrix).
  // On the CPU each coarse level's matrix is copied (in node blocks) where memory allows, and
  // multiplied in place otherwise (stiffness_arrays), and each restriction is multiplied in place
  // (HostArrays::Share): the hierarchy's matrices, or the ones formed here, which their Level
  // keeps.
  const SparseMatrix* current = &A;
  SparseMatrix Nl = N;
  fine_row_columns_.assign(static_cast<std::size_t>(N.rows()), {});
  for (Index j = 0; j < N.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(N, j); it; ++it)
      if (it.value() != 0.0) fine_row_columns_[static_cast<std::size_t>(it.row())].push_back(j);
  auto first = std::make_unique<Level>();
  first->op = &fine;
  first->host_A = &A;
  levels_.push_back(std::move(first));
  for (const SparseMatrix& P : prolongations) {
    if (P.rows() != current->rows())
      throw NumericalError(fmt::format("multigrid: prolongation {} has {} rows, level has {}",
                                       levels_.size(), P.rows(), current->rows()));
    // Galerkin coarse operators (the hierarchy of docs/gpu.md), unless given.
    const std::size_t index = levels_.size() - 1;
    auto level = std::make_unique<Level>();
    ScopedTimer products(setup_timings_, "multigrid: coarse operators");
    if (coarse_operators.empty()) {
      level->A = galerkin_product(*current, P);
      current = &level->A;
    } else {
      current = &coarse_operators[index];
      if (current->rows() != P.cols())
        throw NumericalError(fmt::format("multigrid: coarse operator {} has {} rows, not {}",
                                         index + 1, current->rows(), P.cols()));
    }
    Nl = Nl * P;
    level->host_A = current;
    level->N = Nl;
    products.stop();
    ScopedTimer uploads(setup_timings_, "multigrid: level uploads");
    Level& finer = *levels_.back();
    finer.P_host = &P;
    finer.Pt = backend_.upload_transpose(P, HostArrays::Share);  // P's CSC arrays: P^T's CSR
    if (!backend_.has_transposed_product()) finer.P = backend_.upload(P);
    level->owned =
        std::make_unique<PenalizedOperator>(backend_, *current, Nl, stiffness_arrays(*current));
    level->op = level->owned.get();
    if (current->rows() < options_.host_estimate_below) {
      if (!host_) host_ = std::make_unique<HostBackend>();
      level->on_host = std::make_unique<PenalizedOperator>(*host_, *current, Nl, HostArrays::Share);
    }
    backend_.synchronize();
    uploads.stop();
    levels_.push_back(std::move(level));
  }
  ScopedTimer first_refresh(setup_timings_, "multigrid: first refresh");
  // The coarsest level on the host, for its dense factorisation (only if it is solved so).
  if (current->rows() <= options_.max_dense_coarse) {
    coarse_A_ = *current;
    coarse_Nt_ = Nl.transpose();
  }
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Level& lev = *levels_[l];
    const Index n = lev.op->size();
    if (l > 0) {
      lev.b = DeviceVector(backend_, n);
      lev.x = DeviceVector(backend_, n);
    }
    lev.r = DeviceVector(backend_, n);
    const bool coarsest = l + 1 == levels_.size();
    if (!coarsest || n > options_.max_dense_coarse) {
      ChebyshevOptions o = options_.smoother;
      if (coarsest) o.degree *= 10;
      lev.smoother = std::make_unique<ChebyshevSmoother>(*lev.op, o);
      if (lev.on_host) lev.host_smoother = std::make_unique<ChebyshevSmoother>(*lev.on_host, o);
    }
  }
  for (std::size_t l = 0; l < levels_.size() && l < options_.lambda_max.size(); ++l)
    if (levels_[l]->smoother) levels_[l]->lambda_without_contact = options_.lambda_max[l];
  // Each level's prolongation smoothed with its H_l at the contact unknowns where smoothed
  // aggregation kept its tentative prolongation: set up at the first refresh with contact
  // (make_contact_prolongations), so that a linear solve does not pay for it.
  contact_prolongation_ = options_.tentatives != nullptr && !options_.tentatives->empty() &&
                          !prolongations.empty() && N.rows() > 0;
  if (contact_prolongation_) levels_.front()->N = N;
  refresh();
  backend_.synchronize();
}

MultigridPreconditioner::~MultigridPreconditioner() = default;

std::vector<Index> MultigridPreconditioner::level_sizes() const {
  std::vector<Index> sizes;
  for (const auto& l : levels_) sizes.push_back(l->op->size());
  return sizes;
}

double MultigridPreconditioner::lambda_max(std::size_t level) const {
  if (level >= levels_.size())
    throw NumericalError(fmt::format("multigrid: no level {} of {}", level, levels_.size()));
  const Level& l = *levels_[level];
  return l.smoother ? l.smoother->lambda_max() : 0.0;
}

double MultigridPreconditioner::block_unknowns_bound(Index block) {
  if (block == block_bound_size_) return block_bound_;
  block_bound_ = 0.0;
  for (std::size_t first = 0; first < fine_row_columns_.size();
       first += static_cast<std::size_t>(block)) {
    std::vector<Index> columns;
    for (std::size_t a = first; a < first + static_cast<std::size_t>(block); ++a)
      for (const Index col : fine_row_columns_[a])
        if (std::find(columns.begin(), columns.end(), col) == columns.end()) columns.push_back(col);
    block_bound_ = std::max(block_bound_, static_cast<double>(columns.size()));
  }
  block_bound_size_ = block;
  return block_bound_;
}

const SparseMatrix& MultigridPreconditioner::prolongation_change(std::size_t level) const {
  if (level >= levels_.size())
    throw NumericalError(fmt::format("multigrid: no level {} of {}", level, levels_.size()));
  return levels_[level]->dP_host;
}

SparseMatrix MultigridPreconditioner::contact_rows(std::size_t level) const {
  if (level >= levels_.size())
    throw NumericalError(fmt::format("multigrid: no level {} of {}", level, levels_.size()));
  return levels_[level]->op->contact_transpose().transpose();
}

void MultigridPreconditioner::make_contact_prolongations() {
  // The pattern of level l's contact rows is that of N P_0 ... P_l-1, which holds that of
  // N P_H,0 ... P_H,l-1 (contact_prolongation.hpp).
  const std::vector<SparseMatrix>& tentatives = *options_.tentatives;
  for (std::size_t l = 0;
       l + 1 < levels_.size() && l < tentatives.size() && l < options_.omegas.size(); ++l) {
    const SparseMatrix& T = tentatives[l];
    if (T.nonZeros() == 0 || !(options_.omegas[l] > 0.0)) break;
    Level& lev = *levels_[l];
    try {
      lev.contact_prolongation = std::make_unique<ContactProlongation>(
          *lev.host_A, lev.N, *lev.P_host, T, options_.omegas[l]);
    } catch (const NumericalError&) {
      // T kept for other contact rows than these (keep_contact_rows with another N): A's
      // prolongation from here down, as without T.
      break;
    }
  }
  contact_prolongations_made_ = true;
}

void MultigridPreconditioner::update_contact_prolongation(const Vector& c) {
  // Scalar weights only: friction's block weights keep A's prolongations.
  const bool scalar = levels_.front()->op->block_size() == 1;
  const bool any_active = scalar && (c.array() > 0.0).any();
  if (!any_active && !prolongation_changed_) return;  // (A's prolongations, and they are in place)
  if (!contact_prolongations_made_) {
    make_contact_prolongations();
    // (No level could: A's prolongations, and the levels as they are.)
    contact_prolongation_ = levels_.front()->contact_prolongation != nullptr;
    if (!contact_prolongation_) return;
  }
  // Level by level, finest first: the current contact rows N_l,cur = N P_H,0 ... P_H,l-1 (the
  // active rows only: c_j = 0 elsewhere) give level l's change P_H,l - P_l, and then
  //   N_l+1,cur = N_l,cur (P_l + dP_l) = N_l+1 (pruned to the active rows) + D_l+1,
  //   D_l+1 = D_l P_l + N_l,cur dP_l,   D_0 = 0,
  // so that the coarse contact terms are those of the P_H (the coarse A_l stay A's). Without an
  // active row, N_l again. The pruning keeps, at 434,235 unknowns on Hertz's ball, about 1,000
  // of 7,366 rows, each a few hundred coarse columns, whose copies and uploads per refresh are
  // then a seventh (and so are the products per V-cycle).
  const auto active_row = [&c](Index row, Index, double) { return c(row) != 0.0; };
  SparseMatrix D;  // D_l (empty on the fine level)
  bool changed = false;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Level& lev = *levels_[l];
    // N_l,cur: the fine level's N itself, a coarse level's formed here.
    SparseMatrix Nl;
    const SparseMatrix* current = &lev.N;
    if (l > 0) {
      Nl = lev.N;
      if (any_active) {
        Nl.prune(active_row);
        if (D.nonZeros() > 0) Nl += D;
      }
      lev.op->set_contact_matrix(Nl);
      current = &Nl;
    }
    if (l + 1 == levels_.size()) {
      if (!lev.smoother) coarse_Nt_ = current->transpose();  // (the dense coarsest level's factor)
      break;
    }
    // (Level l's current rows as set just above, transposed there; the fine level's N.)
    SparseMatrix change;
    if (any_active && lev.contact_prolongation)
      change = lev.contact_prolongation->change(c, &lev.op->contact_transpose());
    lev.dP.reset();
    lev.dPt.reset();
    lev.dP_host = std::move(change);
    const bool level_changed = lev.dP_host.nonZeros() > 0;
    if (level_changed) {
      // The transfers P + (P_H - P): the restriction by (P_H - P)^T's rows (its CSC arrays
      // shared on the CPU, as P's are for P^T), the prolongation by P_H - P's own rows.
      lev.dPt = backend_.upload_transpose(lev.dP_host, HostArrays::Share);
      lev.dP = backend_.upload(lev.dP_host);
      changed = true;
    }
    // D_l+1 (nonzero only below a level with a change).
    SparseMatrix next;
    if (D.nonZeros() > 0) next = D * *lev.P_host;
    if (level_changed) {
      SparseMatrix term = *current * lev.dP_host;
      if (next.nonZeros() > 0)
        next += term;
      else
        next = std::move(term);
    }
    D = std::move(next);
  }
  prolongation_changed_ = changed;
}

void MultigridPreconditioner::refresh() {
  recorded_.reset();
  const Vector& c = levels_.front()->op->weights();
  const bool without_contact = (c.array() == 0.0).all();
  if (contact_prolongation_) update_contact_prolongation(c);
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Level& lev = *levels_[l];
    if (l > 0) lev.op->set_weights(c);  // the same c on every level: N_l = N P_H P_1 ... P_l
    if (!lev.smoother) continue;
    const double known = lambda_max_without_lanczos(lev, without_contact);
    if (known > 0.0) {
      lev.smoother->refresh(known);
      continue;
    }
    if (lev.host_smoother) {  // (the host copy is read by its estimate alone)
      lev.on_host->set_weights(c);
      if (contact_prolongation_)  // (the level's contact rows as the V-cycle has them)
        lev.on_host->set_contact_matrix(SparseMatrix(lev.op->contact_transpose().transpose()));
      lev.host_smoother->refresh();
      lev.smoother->refresh(lev.host_smoother->lambda_max());
    } else {
      lev.smoother->refresh();
    }
    if (without_contact) lev.lambda_without_contact = lev.smoother->lambda_max();
  }
  if (!levels_.back()->smoother) factor_coarsest();
}

double MultigridPreconditioner::lambda_max_without_lanczos(Level& lev, bool without_contact) {
  // lambda_max(D_H^-1 H) for the smoother, once lambda_A = lambda_max(D_A^-1 A) of the level is
  // known (estimated at the first refresh, for c = 0, or given for the fine level), without the
  // Lanczos steps on the whole level that each new active set cost before (12 products with
  // H_l: on Hertz's ball at 434,235 unknowns 85 % of a refresh, on the first coarse level).
  const double lambda_a = lev.lambda_without_contact;
  if (lambda_a == 0.0) return 0.0;
  if (without_contact) return lambda_a;
  // With block weights (friction in 3D; only the fine level has them, the coarse ones take
  // their diagonal) a bound: with H = A + E and D_H = D_A + diag(E),
  //   x^T H x / x^T D_H x <= max(x^T A x / x^T D_A x, x^T E x / x^T diag(E) x)
  // (a mediant), and for a positive semidefinite k x k block lambda_max(diag(E)^-1 E) <= its
  // trace = k, the unknowns that the node's rows touch together.
  const Index block = lev.op->block_size();
  if (block > 1) return std::max(lambda_a, block_unknowns_bound(block));
  // Else the larger of A's and the contact zone's (contact_zone_estimate.hpp). The bound above
  // with k = the nonzero components of n_j is 3 in 3D, where the fine level's true value on
  // Hertz's ball is A's 2.40; on the coarse levels, whose rows N_l = N P overlap, it is 8-12
  // against a true 2.5-3.0, which the zone's estimate finds within 0.5 %.
  return std::max(
      lambda_a, contact_zone_lambda_max(*lev.host_A, lev.op->contact_transpose(), lev.op->weights(),
                                        options_.smoother.lanczos_steps));
}

void MultigridPreconditioner::factor_coarsest() {
  // H_L = A_L + N_L^T diag(c) N_L, dense, inverted once per active set.
  const Vector& c = levels_.front()->op->weights();
  // The contact terms from the active rows alone (c_j = 0 elsewhere), each row's outer product
  // added in place: a sparse product over all the contact rows was half of every refresh of
  // this level (5 ms of 9 at 7,366 contact rows, of which about 1,000 active).
  Matrix H = Matrix(coarse_A_);
  for (Index j = 0; j < coarse_Nt_.outerSize(); ++j) {
    if (c(j) == 0.0) continue;
    for (SparseMatrix::InnerIterator a(coarse_Nt_, j); a; ++a)
      for (SparseMatrix::InnerIterator b(coarse_Nt_, j); b; ++b)
        H(a.row(), b.row()) += c(j) * a.value() * b.value();
  }
  auto llt = std::make_unique<Eigen::LLT<Matrix>>(H);
  if (llt->info() != Eigen::Success)
    throw NumericalError(fmt::format(
        "multigrid: the coarsest operator ({} unknowns) is not positive definite", H.rows()));
  if (backend_.kind() == DeviceKind::Cpu) {
    // The vectors are in the host's memory: the factor itself, no inverse (at 990 unknowns the
    // inverse was two thirds of every refresh, 0.2 s of CPU time, 15 times in a solve of Hertz's
    // ball at 940,094 unknowns).
    coarse_factor_ = std::move(llt);
    return;
  }
  coarse_inverse_ = backend_.upload(Matrix(llt->solve(Matrix::Identity(H.rows(), H.cols()))));
}

void MultigridPreconditioner::apply(const DeviceVector& r, DeviceVector& z) {
  // The cycle has no host synchronisation (no dot products), so it can be recorded once per
  // refresh and replayed by every CG iteration.
  if (!recorded_ || recorded_r_ != &r || recorded_z_ != &z || recorded_r_data_ != r.data() ||
      recorded_z_data_ != z.data()) {
    recorded_ = backend_.record([this, &r, &z] { cycle(0, r, z); });
    recorded_r_ = &r;
    recorded_z_ = &z;
    recorded_r_data_ = r.data();
    recorded_z_data_ = z.data();
    if (recorded_->ran_while_recording()) return;  // z = M r already (one cycle saved)
  }
  recorded_->replay();
}

void MultigridPreconditioner::coarse_solve(const DeviceVector& b, DeviceVector& x) {
  if (coarse_factor_) {
    const Eigen::Map<const Vector> rhs(b.data(), b.size());
    Eigen::Map<Vector> solution(x.data(), x.size());
    solution = coarse_factor_->solve(rhs);
    return;
  }
  backend_.gemv(*coarse_inverse_, b, x);
}

void MultigridPreconditioner::cycle(std::size_t l, const DeviceVector& b, DeviceVector& x) {
  Level& lev = *levels_[l];
  if (l + 1 == levels_.size()) {
    if (lev.smoother)
      lev.smoother->smooth(b, x, true);
    else
      coarse_solve(b, x);
    return;
  }
  Level& next = *levels_[l + 1];
  lev.smoother->smooth(b, x, true);  // pre-smoothing from x = 0
  lev.op->apply(x, lev.r);
  backend_.axpby(1.0, b, -1.0, lev.r);                            // r = b - H x
  backend_.spmv(*lev.Pt, lev.r, next.b);                          // restriction P^T r
  if (lev.dPt) backend_.spmv(*lev.dPt, lev.r, next.b, 1.0, 1.0);  // + (P_H - P)^T r
  cycle(l + 1, next.b, next.x);                                   // coarse correction
  if (lev.P)
    backend_.spmv(*lev.P, next.x, x, 1.0, 1.0);  // x += P e
  else
    backend_.spmv_transpose(*lev.Pt, next.x, x, 1.0, 1.0);
  if (lev.dP) backend_.spmv(*lev.dP, next.x, x, 1.0, 1.0);  // + (P_H - P) e
  lev.smoother->smooth(b, x, false);  // post-smoothing (same polynomial: symmetric cycle)
}

}  // namespace signorini
