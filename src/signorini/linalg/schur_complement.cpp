#include "signorini/linalg/schur_complement.hpp"

#include <numeric>

#include "signorini/linalg/dense_storage.hpp"
#include "signorini/linalg/detail/cholmod_matrix.hpp"
#include "signorini/linalg/fill_reducing_ordering.hpp"

namespace signorini {

using detail::check_cholmod;
using detail::CholmodInt;

struct SchurComplement::Impl {
  detail::CholmodCommon workspace;  // first member: finished last
  cholmod_common& common = workspace.common;
  detail::CholmodUpper upper;
  cholmod_factor* factor = nullptr;
  Index n = 0;

  Impl() = default;
  ~Impl() {
    cholmod_l_free_factor(&factor, &common);
    cholmod_l_free_sparse(&upper.matrix, &common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

SchurComplement::SchurComplement(const SparseMatrix& A, const std::vector<Index>& last)
    : impl_(std::make_unique<Impl>()), last_(last) {
  build(A, nullptr);
}

SchurComplement::SchurComplement(SparseMatrix&& A, const std::vector<Index>& last)
    : impl_(std::make_unique<Impl>()), last_(last) {
  build(A, &A);
}

void SchurComplement::build(const SparseMatrix& A, SparseMatrix* owned) {
  const std::vector<Index>& last = last_;
  Impl& s = *impl_;
  s.n = A.rows();
  const Index n = s.n;
  const auto nc = static_cast<Index>(last.size());
  {
    ScopedTimer t(timings_, "condensation analysis");
    s.upper = detail::make_cholmod_upper(A, s.common, /*keep_value_map=*/false);
    // Interior ordered by AMD on the node graph (fill_reducing_ordering), C last in the caller's
    // order so that S comes out in it.
    const std::vector<Index> order = fill_reducing_ordering(A, last);
    std::vector<CholmodInt> perm(order.begin(), order.end());
    s.common.nmethods = 1;
    s.common.method[0].ordering = CHOLMOD_GIVEN;
    s.common.postorder = 0;  // a postorder could move interior columns between those of C
    s.common.supernodal = CHOLMOD_SUPERNODAL;
    if (owned != nullptr) *owned = SparseMatrix();  // CHOLMOD has its own copy now
    s.factor = cholmod_l_analyze_p(s.upper.matrix, perm.data(), nullptr, 0, &s.common);
    check_cholmod(s.common, "analysis");
    const auto* p = static_cast<const CholmodInt*>(s.factor->Perm);
    for (Index k = 0; k < nc; ++k)
      if (p[n - nc + k] != last[static_cast<std::size_t>(k)])
        throw NumericalError("CHOLMOD did not keep the condensed unknowns last");
  }
  {
    ScopedTimer t(timings_, "condensation factorization");
    {
      const detail::SerialOpenMpScope serial;
      cholmod_l_factorize(s.upper.matrix, s.factor, &s.common);
    }
    check_cholmod(s.common, "factorization");
    if (!s.factor->is_super) throw NumericalError("CHOLMOD: expected a supernodal factor");
    cholmod_l_free_sparse(&s.upper.matrix, &s.common);  // only the factor is used from here on
  }
  {
    ScopedTimer t(timings_, "condensation Schur complement");
    // L_CC from the supernodes that hold columns n - nc ... n - 1. Supernode k holds columns
    // super[k] ... super[k+1]-1, its row indices at s[pi[k] ...], its values column-major at
    // x[px[k] ...] with pi[k+1]-pi[k] rows.
    L_cc_ = Eigen::MatrixXd::Zero(nc, nc);
    Eigen::MatrixXd& Lcc = L_cc_;
    const auto* super = static_cast<const CholmodInt*>(s.factor->super);
    const auto* pi = static_cast<const CholmodInt*>(s.factor->pi);
    const auto* px = static_cast<const CholmodInt*>(s.factor->px);
    const auto* rows = static_cast<const CholmodInt*>(s.factor->s);
    const auto* x = static_cast<const double*>(s.factor->x);
    const Index first = n - nc;
    for (std::size_t k = 0; k < s.factor->nsuper; ++k) {
      const CholmodInt c0 = super[k], c1 = super[k + 1];
      if (c1 <= first) continue;
      const CholmodInt nrows = pi[k + 1] - pi[k];
      for (CholmodInt c = std::max<CholmodInt>(c0, first); c < c1; ++c) {
        const double* col = x + px[k] + (c - c0) * nrows;
        for (CholmodInt r = c - c0; r < nrows; ++r) {
          const CholmodInt row = rows[pi[k] + r];
          Lcc(row - first, c - first) = col[r];
        }
      }
    }
    S_ = dense_stored_matrix(nc);
    Eigen::Map<Eigen::MatrixXd> S(S_.valuePtr(), nc, nc);
    S.noalias() = Lcc.triangularView<Eigen::Lower>() * Lcc.transpose();
    S = S.selfadjointView<Eigen::Lower>();  // exactly symmetric
  }
}

SchurComplement::~SchurComplement() = default;

Vector SchurComplement::condensed_load(const Vector& b) {
  ScopedTimer t(timings_, "condensation solve");
  Impl& s = *impl_;
  const auto nc = static_cast<Index>(last_.size());
  // With z = L^-1 P b, the last rows of L z = P b read L_CI z_I + L_CC z_C = b_C, and
  // L_CI z_I = A_CI A_II^-1 b_I (since L_II z_I = b_I and L_CI = A_CI L_II^-T): so g = L_CC z_C.
  cholmod_dense bd = detail::dense_view(b);
  const detail::OwnedDense pb(cholmod_l_solve(CHOLMOD_P, s.factor, &bd, &s.common), s.common);
  check_cholmod(s.common, "permutation");
  const detail::OwnedDense z(cholmod_l_solve(CHOLMOD_L, s.factor, pb.get(), &s.common), s.common);
  check_cholmod(s.common, "forward substitution");
  forward_load_ = Eigen::Map<const Vector>(z.values(), s.n);
  return L_cc_.triangularView<Eigen::Lower>() * forward_load_.tail(nc);
}

Vector SchurComplement::solve_with_condensed_forces(const Vector& f) const {
  ScopedTimer t(timings_, "condensation solve");
  Impl& s = *impl_;
  const auto nc = static_cast<Index>(last_.size());
  if (forward_load_.size() != s.n)
    throw NumericalError("SchurComplement: solve_with_condensed_forces() before condensed_load()");
  Vector w = forward_load_;
  w.tail(nc) += L_cc_.triangularView<Eigen::Lower>().solve(f);
  cholmod_dense wd = detail::dense_view(w);
  const detail::OwnedDense y(cholmod_l_solve(CHOLMOD_Lt, s.factor, &wd, &s.common), s.common);
  check_cholmod(s.common, "back substitution");
  const detail::OwnedDense x(cholmod_l_solve(CHOLMOD_Pt, s.factor, y.get(), &s.common), s.common);
  check_cholmod(s.common, "permutation");
  return Eigen::Map<const Vector>(x.values(), s.n);
}

Vector SchurComplement::solve(const Vector& rhs) const {
  ScopedTimer t(timings_, "condensation solve");
  Impl& s = *impl_;
  cholmod_dense bd = detail::dense_view(rhs);
  const detail::OwnedDense x(cholmod_l_solve(CHOLMOD_A, s.factor, &bd, &s.common), s.common);
  check_cholmod(s.common, "solve");
  return Eigen::Map<const Vector>(x.values(), s.n);
}

}  // namespace signorini
