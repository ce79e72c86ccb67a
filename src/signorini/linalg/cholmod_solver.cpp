#include "signorini/linalg/cholmod_solver.hpp"

#include <cholmod.h>

#include <cstring>
#include <string>

#include "signorini/core/error.hpp"

namespace signorini {

using CholmodInt = SuiteSparse_long;

struct CholmodSolver::Impl {
  cholmod_common common{};
  cholmod_sparse* upper = nullptr;  // upper triangle of H, CHOLMOD's own copy (64-bit indices)
  cholmod_factor* factor = nullptr;
  cholmod_dense* x = nullptr;  // solve2 workspaces, reused between solves
  cholmod_dense* y = nullptr;
  cholmod_dense* e = nullptr;
  std::vector<CholmodInt> value_map;  // entry k of `upper` is H.valuePtr()[value_map[k]]
  Index n = 0;
  Index full_nnz = 0;

  void check(const char* what) const {
    if (common.status == CHOLMOD_NOT_POSDEF)
      throw NumericalError(std::string("CHOLMOD ") + what +
                           ": matrix is not positive definite (is the body held by clamped "
                           "boundaries?)");
    if (common.status == CHOLMOD_OUT_OF_MEMORY)
      throw NumericalError(std::string("CHOLMOD ") + what + ": out of memory");
    if (common.status < CHOLMOD_OK)
      throw NumericalError(std::string("CHOLMOD ") + what + " failed with status " +
                           std::to_string(common.status));
  }
  void release() {
    cholmod_l_free_dense(&x, &common);
    cholmod_l_free_dense(&y, &common);
    cholmod_l_free_dense(&e, &common);
    cholmod_l_free_factor(&factor, &common);
    cholmod_l_free_sparse(&upper, &common);
  }
};

CholmodSolver::CholmodSolver() : impl_(new Impl) {
  cholmod_l_start(&impl_->common);
  impl_->common.print = 0;  // errors are reported through exceptions, not printed
  impl_->common.error_handler = nullptr;
}

CholmodSolver::~CholmodSolver() {
  impl_->release();
  cholmod_l_finish(&impl_->common);
  delete impl_;
}

void CholmodSolver::analyze(const SparseMatrix& pattern) {
  ScopedTimer timer(timings_, "linear analysis");
  Impl& s = *impl_;
  s.release();
  if (pattern.rows() != pattern.cols()) throw NumericalError("CHOLMOD: matrix is not square");
  s.n = pattern.rows();
  s.full_nnz = pattern.nonZeros();
  // Keep the upper triangle (stype = 1) and remember where each kept value sits in the full
  // matrix, so that factorize() only copies values.
  s.value_map.clear();
  s.value_map.reserve(static_cast<std::size_t>(s.full_nnz / 2 + s.n));
  std::vector<CholmodInt> colptr(static_cast<std::size_t>(s.n + 1), 0);
  std::vector<CholmodInt> rows;
  rows.reserve(s.value_map.capacity());
  for (Index j = 0; j < s.n; ++j) {
    for (int k = pattern.outerIndexPtr()[j]; k < pattern.outerIndexPtr()[j + 1]; ++k) {
      const Index i = pattern.innerIndexPtr()[k];
      if (i <= j) {
        rows.push_back(i);
        s.value_map.push_back(k);
      }
    }
    colptr[static_cast<std::size_t>(j + 1)] = static_cast<CholmodInt>(rows.size());
  }
  const auto nnz = rows.size();
  s.upper = cholmod_l_allocate_sparse(static_cast<std::size_t>(s.n), static_cast<std::size_t>(s.n),
                                      nnz, /*sorted=*/1, /*packed=*/1, /*stype=*/1, CHOLMOD_REAL,
                                      &s.common);
  s.check("allocate");
  std::memcpy(s.upper->p, colptr.data(), colptr.size() * sizeof(CholmodInt));
  std::memcpy(s.upper->i, rows.data(), nnz * sizeof(CholmodInt));
  std::memset(s.upper->x, 0, nnz * sizeof(double));
  s.factor = cholmod_l_analyze(s.upper, &s.common);
  s.check("analysis");
}

void CholmodSolver::factorize(const SparseMatrix& H) {
  Impl& s = *impl_;
  if (s.upper == nullptr) analyze(H);
  if (H.rows() != s.n || H.nonZeros() != s.full_nnz)
    throw NumericalError("CHOLMOD: factorize() got a matrix whose pattern differs from analyze()");
  ScopedTimer timer(timings_, "linear factorization");
  auto* vals = static_cast<double*>(s.upper->x);
  const double* hv = H.valuePtr();
  for (std::size_t k = 0; k < s.value_map.size(); ++k) vals[k] = hv[s.value_map[k]];
  cholmod_l_factorize(s.upper, s.factor, &s.common);
  s.check("factorization");
}

LinearSolveStats CholmodSolver::solve(const Vector& rhs, Vector& x) {
  ScopedTimer timer(timings_, "linear solve");
  Impl& s = *impl_;
  if (s.factor == nullptr) throw NumericalError("CHOLMOD: solve() before factorize()");
  cholmod_dense b{};
  b.nrow = static_cast<std::size_t>(s.n);
  b.ncol = 1;
  b.nzmax = b.nrow;
  b.d = b.nrow;
  b.x = const_cast<double*>(rhs.data());  // read only: CHOLMOD does not write to B
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_l_solve2(CHOLMOD_A, s.factor, &b, nullptr, &s.x, nullptr, &s.y, &s.e, &s.common);
  s.check("solve");
  x = Eigen::Map<const Vector>(static_cast<const double*>(s.x->x), s.n);
  return {};
}

double CholmodSolver::factor_nonzeros() const {
  return impl_->factor == nullptr ? 0.0 : impl_->common.lnz;
}

std::string_view CholmodSolver::ordering_name() const {
  if (impl_->factor == nullptr) return "none";
  switch (impl_->factor->ordering) {
    case CHOLMOD_NATURAL: return "natural";
    case CHOLMOD_GIVEN: return "given";
    case CHOLMOD_AMD: return "AMD";
    case CHOLMOD_METIS: return "METIS";
    case CHOLMOD_NESDIS: return "NESDIS";
    case CHOLMOD_COLAMD: return "COLAMD";
    default: return "other";
  }
}

std::string cholmod_version() {
  return std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) + "." +
         std::to_string(CHOLMOD_SUBSUB_VERSION);
}

}  // namespace signorini
