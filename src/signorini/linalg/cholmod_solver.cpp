#include "signorini/linalg/cholmod_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>

#include "signorini/linalg/detail/cholmod_matrix.hpp"
#include "signorini/linalg/fill_reducing_ordering.hpp"

namespace signorini {

using detail::check_cholmod;

namespace {
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

struct CholmodSolver::Impl {
  detail::CholmodCommon workspace;  // first member: finished last
  cholmod_common& common = workspace.common;
  detail::CholmodUpper upper;  // upper triangle of H, CHOLMOD's own copy (64-bit indices)
  cholmod_factor* factor = nullptr;
  cholmod_factor* symbolic = nullptr;  // the analysis, kept: an updated factor is simplicial
  // The elimination tree of the permuted matrix, the entries of L on the path from each column
  // to the root, and the inverse permutation, for update_flops() and update(): made by tree()
  // from the first factor that is asked (empty until then; the pattern never changes).
  std::vector<detail::CholmodInt> parent, inverse_perm;
  std::vector<double> path_entries;
  // What predicted_update_seconds() assumes, measured by the last factorisation, conversion and
  // update (the starting values were measured on this project's 2-core machine).
  double factorization_seconds = 0.0;
  double update_flop_rate = 5e9;                // flops of update_flops() per second
  double conversion_seconds_per_entry = 25e-9;  // supernodal L L^T to simplicial L D L^T
  cholmod_dense* x = nullptr;                   // solve2 workspaces, reused between solves
  cholmod_dense* y = nullptr;
  cholmod_dense* e = nullptr;
  Index n = 0;

  Impl() = default;
  ~Impl() { release(); }

  void tree();
  void to_ldl();
  // Throws unless there is a numeric factor (and `row`, when given, is one of its rows).
  void require_factor(const char* call, std::optional<Index> row = {}) const;
  // Before a modification of the factor: the tree for the cost estimates, and L D L^T.
  void prepare_modification() {
    tree();
    to_ldl();
  }
  [[nodiscard]] bool pivots_positive() const;
  // A row modification is a rank-two change along the path from its (permuted) column: twice
  // update_flops() of that column, which sets the rate of the estimates that follow.
  void measured_row_modification(detail::CholmodInt k, double seconds) {
    if (seconds > 1e-3)
      update_flop_rate = 8.0 * path_entries[static_cast<std::size_t>(k)] / seconds;
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void release() {
    cholmod_l_free_dense(&x, &common);
    cholmod_l_free_dense(&y, &common);
    cholmod_l_free_dense(&e, &common);
    cholmod_l_free_factor(&factor, &common);
    cholmod_l_free_factor(&symbolic, &common);
    parent.clear();
    path_entries.clear();
    inverse_perm.clear();
    cholmod_l_free_sparse(&upper.matrix, &common);
  }
};

CholmodSolver::CholmodSolver() : impl_(std::make_unique<Impl>()) {}

CholmodSolver::~CholmodSolver() = default;

void CholmodSolver::analyze(const SparseMatrix& pattern) {
  ScopedTimer timer(timings_, "linear analysis");
  Impl& s = *impl_;
  s.release();
  s.n = pattern.rows();
  s.upper = detail::make_cholmod_upper(pattern, s.common);
  // AMD on the graph of the nodes rather than of the dofs: the same fill for a fraction of the
  // ordering time (and no trial of METIS on the dof graph, which CHOLMOD's default may add).
  const std::vector<Index> order = fill_reducing_ordering(pattern, {});
  std::vector<detail::CholmodInt> perm(order.begin(), order.end());
  s.common.nmethods = 1;
  s.common.method[0].ordering = CHOLMOD_GIVEN;
  s.common.postorder = 1;
  s.factor = cholmod_l_analyze_p(s.upper.matrix, perm.data(), nullptr, 0, &s.common);
  check_cholmod(s.common, "analysis");
  s.symbolic = cholmod_l_copy_factor(s.factor, &s.common);
  check_cholmod(s.common, "analysis");
}

void CholmodSolver::factorize(const SparseMatrix& H) {
  Impl& s = *impl_;
  if (s.upper.matrix == nullptr) analyze(H);
  // The values are copied by position (value_map): a matrix with another pattern, even with the
  // same number of entries, would be factorised with misplaced values.
  if (H.rows() != s.n || H.nonZeros() != s.upper.full_nnz ||
      detail::pattern_hash(H) != s.upper.pattern_hash)
    throw NumericalError("CHOLMOD: factorize() got a matrix whose pattern differs from analyze()");
  ScopedTimer timer(timings_, "linear factorization");
  s.upper.copy_values(H);
  if (s.factor->is_super != s.symbolic->is_super) {
    // Updated since the last factorisation (now simplicial L D L^T): start again from the
    // analysis so that the supernodal (BLAS-3) factorisation runs.
    cholmod_l_free_factor(&s.factor, &s.common);
    s.factor = cholmod_l_copy_factor(s.symbolic, &s.common);
    check_cholmod(s.common, "factorization");
  }
  const auto start = std::chrono::steady_clock::now();
  {
    const detail::SerialOpenMpScope serial;
    cholmod_l_factorize(s.upper.matrix, s.factor, &s.common);
  }
  check_cholmod(s.common, "factorization");
  s.factorization_seconds = seconds_since(start);
}

LinearSolveStats CholmodSolver::solve(const Vector& rhs, Vector& x) {
  ScopedTimer timer(timings_, "linear solve");
  Impl& s = *impl_;
  if (s.factor == nullptr) throw NumericalError("CHOLMOD: solve() before factorize()");
  cholmod_dense b = detail::dense_view(rhs);
  cholmod_l_solve2(CHOLMOD_A, s.factor, &b, nullptr, &s.x, nullptr, &s.y, &s.e, &s.common);
  check_cholmod(s.common, "solve");
  x = Eigen::Map<const Vector>(static_cast<const double*>(s.x->x), s.n);
  return {};
}

void CholmodSolver::Impl::tree() {
  if (!parent.empty()) return;
  // The elimination tree from the factor's structure: within a supernode each column's parent
  // is the next one, the last column's is the first row below the supernode's diagonal block;
  // in a simplicial factor a column's parent is its smallest off-diagonal row.
  const cholmod_factor& L = *factor;
  const auto size = static_cast<std::size_t>(n);
  const auto* perm = static_cast<const detail::CholmodInt*>(L.Perm);
  const auto* count = static_cast<const detail::CholmodInt*>(L.ColCount);
  parent.assign(size, -1);
  inverse_perm.resize(size);
  for (std::size_t k = 0; k < size; ++k)
    inverse_perm[static_cast<std::size_t>(perm[k])] = static_cast<detail::CholmodInt>(k);
  if (L.is_super) {
    const auto* super = static_cast<const detail::CholmodInt*>(L.super);
    const auto* pi = static_cast<const detail::CholmodInt*>(L.pi);
    const auto* ls = static_cast<const detail::CholmodInt*>(L.s);
    for (std::size_t sn = 0; sn < L.nsuper; ++sn) {
      const auto k1 = super[sn], k2 = super[sn + 1];
      for (auto k = k1; k + 1 < k2; ++k) parent[static_cast<std::size_t>(k)] = k + 1;
      const auto below = pi[sn] + (k2 - k1);
      if (below < pi[sn + 1]) parent[static_cast<std::size_t>(k2 - 1)] = ls[below];
    }
  } else {
    const auto* lp = static_cast<const detail::CholmodInt*>(L.p);
    const auto* li = static_cast<const detail::CholmodInt*>(L.i);
    const auto* nz = static_cast<const detail::CholmodInt*>(L.nz);
    for (std::size_t k = 0; k < size; ++k) {
      detail::CholmodInt first = -1;
      for (auto q = lp[k] + 1; q < lp[k] + nz[k]; ++q)
        if (first < 0 || li[q] < first) first = li[q];
      parent[k] = first;
    }
  }
  // A parent comes after its child: one sweep from the root down sums the paths.
  path_entries.assign(size, 0.0);
  for (std::size_t k = size; k-- > 0;)
    path_entries[k] = static_cast<double>(count[k]) +
                      (parent[k] >= 0 ? path_entries[static_cast<std::size_t>(parent[k])] : 0.0);
}

double CholmodSolver::update_flops(const std::vector<Index>& rows) {
  Impl& s = *impl_;
  s.require_factor("update_flops()");
  if (rows.empty()) return 0.0;
  s.tree();
  detail::CholmodInt k = static_cast<detail::CholmodInt>(s.n);
  for (const Index r : rows) k = std::min(k, s.inverse_perm[static_cast<std::size_t>(r)]);
  return 4.0 * s.path_entries[static_cast<std::size_t>(k)];
}

double CholmodSolver::row_modification_flops(Index k) {
  return 2.0 * update_flops({k});
}

double CholmodSolver::predicted_update_seconds(double flops) const {
  return flops / impl_->update_flop_rate;
}

double CholmodSolver::predicted_conversion_seconds() const {
  const Impl& s = *impl_;
  const bool convert = s.factor != nullptr && (s.factor->is_super || s.factor->is_ll);
  return convert ? s.conversion_seconds_per_entry * s.common.lnz : 0.0;
}

double CholmodSolver::last_factorization_seconds() const {
  return impl_->factorization_seconds;
}

void CholmodSolver::Impl::require_factor(const char* call, std::optional<Index> row) const {
  if (factor == nullptr || factor->xtype == CHOLMOD_PATTERN)
    throw NumericalError(fmt::format("CHOLMOD: {} before factorize()", call));
  if (row && (*row < 0 || *row >= n))
    throw NumericalError(fmt::format("CHOLMOD: {} of a row out of range", call));
}

void CholmodSolver::Impl::to_ldl() {
  if (!factor->is_super && !factor->is_ll) return;
  // CHOLMOD modifies simplicial L D L^T factors only. No spare room in the columns (CHOLMOD's
  // default adds 20 % and 5 entries): updates by the node blocks of H add no fill, and a
  // column that does need room is moved by CHOLMOD itself.
  const auto start = std::chrono::steady_clock::now();
  common.grow0 = 1.0;
  common.grow1 = 1.0;
  common.grow2 = 0;
  cholmod_l_change_factor(CHOLMOD_REAL, 0, 0, 0, 1, factor, &common);
  check_cholmod(common, "update");
  conversion_seconds_per_entry =
      seconds_since(start) / std::max(1.0, static_cast<double>(common.lnz));
}

// Every pivot of the L D L^T factor positive: CHOLMOD's modifications can leave a factor
// indefinite without a word where rounding makes the modified matrix so (in exact arithmetic it
// is positive definite), which no later solve would notice.
bool CholmodSolver::Impl::pivots_positive() const {
  const auto* lp = static_cast<const detail::CholmodInt*>(factor->p);
  const auto* lx = static_cast<const double*>(factor->x);
  for (Index k = 0; k < n; ++k)
    if (!(lx[lp[k]] > 0.0)) return false;
  return true;
}

bool CholmodSolver::delete_row(Index k) {
  Impl& s = *impl_;
  s.require_factor("delete_row()", k);
  ScopedTimer timer(timings_, "linear factor update");
  s.prepare_modification();
  const auto kp = s.inverse_perm[static_cast<std::size_t>(k)];
  const auto start = std::chrono::steady_clock::now();
  const int ok = cholmod_l_rowdel(static_cast<std::size_t>(kp), nullptr, s.factor, &s.common);
  s.measured_row_modification(kp, seconds_since(start));
  return ok != 0 && s.common.status >= CHOLMOD_OK && s.pivots_positive();
}

bool CholmodSolver::add_row(Index k, const std::vector<std::pair<Index, double>>& column) {
  Impl& s = *impl_;
  s.require_factor("add_row()", k);
  ScopedTimer timer(timings_, "linear factor update");
  s.prepare_modification();
  // The column in the factor's (permuted) order, sorted, as an n x 1 CHOLMOD matrix.
  std::vector<std::pair<detail::CholmodInt, double>> permuted;
  permuted.reserve(column.size());
  for (const auto& [row, value] : column) {
    if (row < 0 || row >= s.n) throw NumericalError("CHOLMOD: add_row() with a row out of range");
    permuted.emplace_back(s.inverse_perm[static_cast<std::size_t>(row)], value);
  }
  std::sort(permuted.begin(), permuted.end());
  cholmod_sparse* R = cholmod_l_allocate_sparse(static_cast<std::size_t>(s.n), 1, permuted.size(),
                                                1, 1, 0, CHOLMOD_REAL, &s.common);
  check_cholmod(s.common, "update");
  auto* rp = static_cast<detail::CholmodInt*>(R->p);
  auto* ri = static_cast<detail::CholmodInt*>(R->i);
  auto* rx = static_cast<double*>(R->x);
  rp[0] = 0;
  rp[1] = static_cast<detail::CholmodInt>(permuted.size());
  for (std::size_t q = 0; q < permuted.size(); ++q) {
    ri[q] = permuted[q].first;
    rx[q] = permuted[q].second;
  }
  const auto kp = s.inverse_perm[static_cast<std::size_t>(k)];
  const auto start = std::chrono::steady_clock::now();
  const int ok = cholmod_l_rowadd(static_cast<std::size_t>(kp), R, s.factor, &s.common);
  s.measured_row_modification(kp, seconds_since(start));
  cholmod_l_free_sparse(&R, &s.common);
  return ok != 0 && s.common.status >= CHOLMOD_OK && s.pivots_positive();
}

bool CholmodSolver::update(const SparseMatrix& C, bool up) {
  Impl& s = *impl_;
  s.require_factor("update()");
  if (C.rows() != s.n) throw NumericalError("CHOLMOD: update() with a matrix of the wrong size");
  if (C.cols() == 0) return true;
  ScopedTimer timer(timings_, "linear factor update");
  s.prepare_modification();
  // CHOLMOD takes C's rows in the factor's (permuted) order, sorted within each column.
  cholmod_sparse* Cp = cholmod_l_allocate_sparse(
      static_cast<std::size_t>(s.n), static_cast<std::size_t>(C.cols()),
      static_cast<std::size_t>(C.nonZeros()), 1, 1, 0, CHOLMOD_REAL, &s.common);
  check_cholmod(s.common, "update");
  auto* cp = static_cast<detail::CholmodInt*>(Cp->p);
  auto* ci = static_cast<detail::CholmodInt*>(Cp->i);
  auto* cx = static_cast<double*>(Cp->x);
  std::vector<std::pair<detail::CholmodInt, double>> column;
  std::vector<detail::CholmodInt> starts;  // each column's first row: its path starts there
  double flops = 0.0;
  detail::CholmodInt pos = 0;
  for (Index j = 0; j < C.cols(); ++j) {
    cp[j] = pos;
    column.clear();
    for (SparseMatrix::InnerIterator it(C, j); it; ++it)
      column.emplace_back(s.inverse_perm[static_cast<std::size_t>(it.row())], it.value());
    std::sort(column.begin(), column.end());
    for (const auto& [row, value] : column) {
      ci[pos] = row;
      cx[pos++] = value;
    }
    if (!column.empty()) {
      starts.push_back(column.front().first);
      flops += 4.0 * s.path_entries[static_cast<std::size_t>(column.front().first)];
    }
  }
  cp[C.cols()] = pos;
  const auto start = std::chrono::steady_clock::now();
  const int ok = cholmod_l_updown(up ? 1 : 0, Cp, s.factor, &s.common);
  const double dt = seconds_since(start);
  cholmod_l_free_sparse(&Cp, &s.common);
  if (s.common.status == CHOLMOD_NOT_POSDEF || ok == 0 || s.factor->minor < s.factor->n)
    return false;
  check_cholmod(s.common, "update");
  if (!up) {
    // CHOLMOD downdates an L D L^T factor into an indefinite one without a word: a pivot of D
    // that is not positive means the downdated matrix is not positive definite (in exact
    // arithmetic H(P) never is; rounding can make it so), and the caller refactorises. Only
    // the pivots on the columns' paths changed.
    const auto* lp = static_cast<const detail::CholmodInt*>(s.factor->p);
    const auto* lx = static_cast<const double*>(s.factor->x);
    for (detail::CholmodInt k : starts)
      for (; k >= 0; k = s.parent[static_cast<std::size_t>(k)])
        if (!(lx[lp[k]] > 0.0)) return false;
  }
  if (dt > 1e-3) s.update_flop_rate = flops / dt;  // shorter ones say more about the clock
  return true;
}

double CholmodSolver::factor_nonzeros() const {
  return impl_->factor == nullptr ? 0.0 : impl_->common.lnz;
}

std::string cholmod_version() {
  return std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) + "." +
         std::to_string(CHOLMOD_SUBSUB_VERSION);
}

}  // namespace signorini
