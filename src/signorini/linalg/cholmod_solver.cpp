#include "signorini/linalg/cholmod_solver.hpp"

#include <string>

#include "signorini/linalg/detail/cholmod_matrix.hpp"
#include "signorini/linalg/fill_reducing_ordering.hpp"

namespace signorini {

using detail::check_cholmod;

struct CholmodSolver::Impl {
  detail::CholmodCommon workspace;  // first member: finished last
  cholmod_common& common = workspace.common;
  detail::CholmodUpper upper;  // upper triangle of H, CHOLMOD's own copy (64-bit indices)
  cholmod_factor* factor = nullptr;
  cholmod_dense* x = nullptr;  // solve2 workspaces, reused between solves
  cholmod_dense* y = nullptr;
  cholmod_dense* e = nullptr;
  Index n = 0;

  Impl() = default;
  ~Impl() { release(); }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void release() {
    cholmod_l_free_dense(&x, &common);
    cholmod_l_free_dense(&y, &common);
    cholmod_l_free_dense(&e, &common);
    cholmod_l_free_factor(&factor, &common);
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
  {
    const detail::SerialOpenMpScope serial;
    cholmod_l_factorize(s.upper.matrix, s.factor, &s.common);
  }
  check_cholmod(s.common, "factorization");
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

double CholmodSolver::factor_nonzeros() const {
  return impl_->factor == nullptr ? 0.0 : impl_->common.lnz;
}

std::string cholmod_version() {
  return std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) + "." +
         std::to_string(CHOLMOD_SUBSUB_VERSION);
}

}  // namespace signorini
