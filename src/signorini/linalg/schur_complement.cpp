#include "signorini/linalg/schur_complement.hpp"

#include <Eigen/Cholesky>
#include <exception>
#include <numeric>
#include <thread>

#include "signorini/linalg/dense_storage.hpp"
#include "signorini/linalg/detail/cholmod_matrix.hpp"
#include "signorini/linalg/fill_reducing_ordering.hpp"
#include "signorini/linalg/vertex_separator.hpp"

namespace signorini {

using detail::check_cholmod;
using detail::CholmodInt;

namespace {

/// One sparse Cholesky factorisation P M P^T = L L^T with the trailing unknowns of M (its
/// boundary, `nb` of them) kept last, and the trailing block L_bb of L read out of CHOLMOD's
/// supernodes: L_bb L_bb^T = M_bb - M_bi M_ii^-1 M_ib.
struct PartFactor {
  detail::CholmodCommon workspace;  // first member: finished last
  cholmod_common& common = workspace.common;
  detail::CholmodUpper upper;
  cholmod_factor* factor = nullptr;
  Index n = 0;
  Index nb = 0;
  Eigen::MatrixXd L_bb;
  // Two-part path only: the unknowns of A that M holds (interior, then boundary), and for each
  // boundary unknown of M its position in the interface B.
  std::vector<Index> interior;
  std::vector<Index> boundary_position;

  PartFactor() = default;
  ~PartFactor() {
    cholmod_l_free_factor(&factor, &common);
    cholmod_l_free_sparse(&upper.matrix, &common);
  }
  PartFactor(const PartFactor&) = delete;
  PartFactor& operator=(const PartFactor&) = delete;

  /// Orders (AMD on the node graph, `last` appended: fill_reducing_ordering) and analyses M.
  void analyse(const SparseMatrix& M, SparseMatrix* owned, const std::vector<Index>& last) {
    n = M.rows();
    nb = static_cast<Index>(last.size());
    upper = detail::make_cholmod_upper(M, common, /*keep_value_map=*/false);
    const std::vector<Index> order = fill_reducing_ordering(M, last);
    std::vector<CholmodInt> perm(order.begin(), order.end());
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_GIVEN;
    common.postorder = 0;  // a postorder could move interior columns between the trailing ones
    common.supernodal = CHOLMOD_SUPERNODAL;
    if (owned != nullptr) *owned = SparseMatrix();  // CHOLMOD has its own copy now
    factor = cholmod_l_analyze_p(upper.matrix, perm.data(), nullptr, 0, &common);
    check_cholmod(common, "analysis");
    const auto* p = static_cast<const CholmodInt*>(factor->Perm);
    for (Index k = 0; k < nb; ++k)
      if (p[n - nb + k] != last[static_cast<std::size_t>(k)])
        throw NumericalError("CHOLMOD did not keep the condensed unknowns last");
  }

  /// The numeric factorisation (on the calling thread alone: SerialOpenMpScope) and L_bb.
  void factorise() {
    cholmod_l_factorize(upper.matrix, factor, &common);
    check_cholmod(common, "factorization");
    if (!factor->is_super) throw NumericalError("CHOLMOD: expected a supernodal factor");
    cholmod_l_free_sparse(&upper.matrix, &common);  // only the factor is used from here on
    // Supernode k holds columns super[k] ... super[k+1]-1, its row indices at s[pi[k] ...], its
    // values column-major at x[px[k] ...] with pi[k+1]-pi[k] rows.
    L_bb = Eigen::MatrixXd::Zero(nb, nb);
    const auto* super = static_cast<const CholmodInt*>(factor->super);
    const auto* pi = static_cast<const CholmodInt*>(factor->pi);
    const auto* px = static_cast<const CholmodInt*>(factor->px);
    const auto* rows = static_cast<const CholmodInt*>(factor->s);
    const auto* x = static_cast<const double*>(factor->x);
    const Index first = n - nb;
    for (std::size_t k = 0; k < factor->nsuper; ++k) {
      const CholmodInt c0 = super[k], c1 = super[k + 1];
      if (c1 <= first) continue;
      const CholmodInt nrows = pi[k + 1] - pi[k];
      for (CholmodInt c = std::max<CholmodInt>(c0, first); c < c1; ++c) {
        const double* col = x + px[k] + (c - c0) * nrows;
        for (CholmodInt r = c - c0; r < nrows; ++r)
          L_bb(rows[pi[k] + r] - first, c - first) = col[r];
      }
    }
  }

  /// z = L^-1 P v.
  [[nodiscard]] Vector forward(const Vector& v) {
    return two_solves(v, CHOLMOD_P, "permutation", CHOLMOD_L, "forward substitution");
  }

  /// x = P^T L^-T w.
  [[nodiscard]] Vector backward(const Vector& w) {
    return two_solves(w, CHOLMOD_Lt, "back substitution", CHOLMOD_Pt, "permutation");
  }

  /// CHOLMOD's solve `first`, then `second`, applied to v (the names are for the errors).
  [[nodiscard]] Vector two_solves(const Vector& v, int first, const char* first_name, int second,
                                  const char* second_name) {
    cholmod_dense vd = detail::dense_view(v);
    const detail::OwnedDense y(cholmod_l_solve(first, factor, &vd, &common), common);
    check_cholmod(common, first_name);
    const detail::OwnedDense z(cholmod_l_solve(second, factor, y.get(), &common), common);
    check_cholmod(common, second_name);
    return Eigen::Map<const Vector>(z.values(), n);
  }
};

/// Runs f(0) on a second thread and f(1) on this one; rethrows the first exception of either.
/// CHOLMOD is thread-safe with one workspace per thread; OpenBLAS runs single-threaded here
/// (OPENBLAS_NUM_THREADS=1, app/process_tuning.hpp), in each calling thread.
template <class F>
void on_two_threads(F&& f) {
  const detail::SerialOpenMpScope serial;  // CHOLMOD's own OpenMP loops stay serial (see there)
  std::exception_ptr error0, error1;
  std::thread worker([&] {
#ifdef _OPENMP
    omp_set_max_active_levels(0);  // in case the setting is per thread
#endif
    try {
      f(0);
    } catch (...) {
      error0 = std::current_exception();
    }
  });
  try {
    f(1);
  } catch (...) {
    error1 = std::current_exception();
  }
  worker.join();
  if (error0) std::rethrow_exception(error0);
  if (error1) std::rethrow_exception(error1);
}

/// A(rows, rows) for a list of distinct unknowns: the principal submatrix, so SPD when A is.
SparseMatrix principal_submatrix(const SparseMatrix& A, const std::vector<Index>& unknowns,
                                 std::vector<Index>& local_of) {
  const auto m = static_cast<Index>(unknowns.size());
  for (Index k = 0; k < m; ++k) local_of[static_cast<std::size_t>(unknowns[k])] = k;
  SparseMatrix M(m, m);
  std::vector<int> count(static_cast<std::size_t>(m), 0);
  for (Index k = 0; k < m; ++k) {
    const Index j = unknowns[static_cast<std::size_t>(k)];
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (local_of[static_cast<std::size_t>(it.row())] >= 0) ++count[static_cast<std::size_t>(k)];
  }
  M.reserve(count);
  for (Index k = 0; k < m; ++k) {
    const Index j = unknowns[static_cast<std::size_t>(k)];
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      const Index r = local_of[static_cast<std::size_t>(it.row())];
      if (r >= 0) M.insert(r, k) = it.value();
    }
  }
  M.makeCompressed();
  for (const Index j : unknowns) local_of[static_cast<std::size_t>(j)] = -1;
  return M;
}

}  // namespace

struct SchurComplement::Impl {
  std::vector<Index> last;                         // C, in the caller's order
  std::vector<std::unique_ptr<PartFactor>> parts;  // one: the whole of A; two: build_two_parts
  Eigen::MatrixXd L_cc;                            // S = L_cc L_cc^T
  // Two parts only: B = [separator; C], the separator's unknowns of A, and the dense factor of
  // the interface's Schur complement S_B = L_B L_B^T, L_B = [L_ss 0; L_cs L_cc].
  std::vector<Index> separator;
  Eigen::MatrixXd L_ss, L_cs;
  // What a back substitution needs of the forward one: per part z = L^-1 P (its load), the
  // separator's w_s = L_ss^-1 r_s (two parts), and the condensed load g.
  struct Forward {
    std::vector<Vector> z;
    Vector w_s, g;
  };
  Forward last_forward;  // of the last condensed_load()

  [[nodiscard]] Index nc() const { return static_cast<Index>(last.size()); }
  [[nodiscard]] Index ns() const { return static_cast<Index>(separator.size()); }
  [[nodiscard]] Forward forward(const Vector& b);
  [[nodiscard]] Vector backward(const Forward& fw, const Vector& f);
};

Index SchurComplement::automatic_parts(Index unknowns, int threads) {
  const auto available =
      threads > 0 ? static_cast<unsigned>(threads) : std::thread::hardware_concurrency();
  return unknowns >= kTwoPartUnknowns && available >= 2 ? 2 : 1;
}

SchurComplement::SchurComplement(const SparseMatrix& A, const std::vector<Index>& last, Index parts)
    : impl_(std::make_unique<Impl>()) {
  impl_->last = last;
  build(A, nullptr, parts);
}

SchurComplement::SchurComplement(SparseMatrix&& A, const std::vector<Index>& last, Index parts)
    : impl_(std::make_unique<Impl>()) {
  impl_->last = last;
  build(A, &A, parts);
}

void SchurComplement::build(const SparseMatrix& A, SparseMatrix* owned, Index parts) {
  if (parts <= 0) parts = automatic_parts(A.rows());
  if (parts < 2 || !build_two_parts(A, owned)) build_one_part(A, owned);
  // S = L_cc L_cc^T, formed once in place, exactly symmetric.
  ScopedTimer t(timings_, "condensation Schur complement");
  const Index nc = impl_->nc();
  S_ = dense_stored_matrix(nc);
  Eigen::Map<Eigen::MatrixXd> S(S_.valuePtr(), nc, nc);
  S.noalias() = impl_->L_cc.triangularView<Eigen::Lower>() * impl_->L_cc.transpose();
  S = S.selfadjointView<Eigen::Lower>();
}

void SchurComplement::build_one_part(const SparseMatrix& A, SparseMatrix* owned) {
  Impl& s = *impl_;
  s.parts.clear();
  s.parts.push_back(std::make_unique<PartFactor>());
  PartFactor& f = *s.parts.front();
  {
    ScopedTimer t(timings_, "condensation analysis");
    // Interior ordered by AMD on the node graph (fill_reducing_ordering), C last in the caller's
    // order so that S comes out in it.
    f.analyse(A, owned, s.last);
  }
  ScopedTimer t(timings_, "condensation factorization");
  const detail::SerialOpenMpScope serial;
  f.factorise();
  s.L_cc = std::move(f.L_bb);
}

bool SchurComplement::build_two_parts(const SparseMatrix& A, SparseMatrix* owned) {
  Impl& s = *impl_;
  const Index n = A.rows();
  const Index nc = s.nc();
  // The interface B: the separator's unknowns (those not in C), then C in the caller's order.
  // position[j]: j's place in B, or -1 for the interior of a part.
  std::vector<Index> position(static_cast<std::size_t>(n), -1);
  std::array<std::vector<Index>, 2> interior;
  {
    ScopedTimer t(timings_, "condensation analysis");
    const VertexSeparator split = vertex_separator(A);
    std::vector<char> in_c(static_cast<std::size_t>(n), 0);
    for (const Index j : s.last) in_c[static_cast<std::size_t>(j)] = 1;
    for (Index j = 0; j < n; ++j) {
      if (in_c[static_cast<std::size_t>(j)] != 0) continue;
      const auto p = split.part[static_cast<std::size_t>(j)];
      if (p == 2) {
        position[static_cast<std::size_t>(j)] = s.ns();
        s.separator.push_back(j);
      } else {
        interior[static_cast<std::size_t>(p)].push_back(j);
      }
    }
    if (interior[0].empty() || interior[1].empty()) {
      s.separator.clear();
      return false;
    }
    const Index ns = s.ns();
    for (Index k = 0; k < nc; ++k)
      position[static_cast<std::size_t>(s.last[static_cast<std::size_t>(k)])] = ns + k;
    s.parts.clear();
    s.parts.push_back(std::make_unique<PartFactor>());
    s.parts.push_back(std::make_unique<PartFactor>());
    on_two_threads([&](int k) {
      PartFactor& f = *s.parts[static_cast<std::size_t>(k)];
      f.interior = std::move(interior[static_cast<std::size_t>(k)]);
      // The part's boundary: the unknowns of B that its interior couples to, in B's order.
      std::vector<char> touched(static_cast<std::size_t>(ns + nc), 0);
      for (const Index j : f.interior)
        for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
          const Index b = position[static_cast<std::size_t>(it.row())];
          if (b >= 0) touched[static_cast<std::size_t>(b)] = 1;
        }
      for (Index b = 0; b < ns + nc; ++b)
        if (touched[static_cast<std::size_t>(b)] != 0) f.boundary_position.push_back(b);
      std::vector<Index> unknowns = f.interior;
      for (const Index b : f.boundary_position)
        unknowns.push_back(b < ns ? s.separator[static_cast<std::size_t>(b)]
                                  : s.last[static_cast<std::size_t>(b - ns)]);
      std::vector<Index> local_of(static_cast<std::size_t>(n), -1);
      SparseMatrix M = principal_submatrix(A, unknowns, local_of);
      std::vector<Index> last(f.boundary_position.size());
      std::iota(last.begin(), last.end(), static_cast<Index>(f.interior.size()));
      f.analyse(M, &M, last);
    });
  }
  const Index ns = s.ns();
  const Index nb = ns + nc;
  // The dense step costs nb^3 / 3 flops; when that is not small beside the parts' factorisations
  // (a long separator: a poor cut, or a 3D body), one factorisation is cheaper.
  const double dense_flops =
      static_cast<double>(nb) * static_cast<double>(nb) * static_cast<double>(nb) / 3.0;
  if (dense_flops > 0.25 * (s.parts[0]->common.fl + s.parts[1]->common.fl)) {
    s.parts.clear();
    s.separator.clear();
    return false;
  }
  // S_B = A_BB - sum_k A_Bk A_kk^-1 A_kB, and for part k (its boundary b_k, M_k = A(I_k + b_k)):
  // A_Bk A_kk^-1 A_kB = A(b_k, b_k) - L_bb L_bb^T (the Schur complement of the part's factor).
  // Lower triangles only. A_BB is read before A is released.
  Eigen::MatrixXd S_B = Eigen::MatrixXd::Zero(nb, nb);
  for (Index c = 0; c < nb; ++c) {
    const Index j = c < ns ? s.separator[static_cast<std::size_t>(c)]
                           : s.last[static_cast<std::size_t>(c - ns)];
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      const Index r = position[static_cast<std::size_t>(it.row())];
      if (r >= c) S_B(r, c) = it.value();
    }
  }
  if (owned != nullptr) *owned = SparseMatrix();  // the parts hold their copies
  std::array<Eigen::MatrixXd, 2> update;  // per part: L_bb L_bb^T - A(b_k, b_k), lower triangle
  {
    ScopedTimer t(timings_, "condensation factorization");
    on_two_threads([&](int k) {
      PartFactor& f = *s.parts[static_cast<std::size_t>(k)];
      f.factorise();
      const std::vector<Index>& b = f.boundary_position;
      Eigen::MatrixXd& u = update[static_cast<std::size_t>(k)];
      u = -Eigen::MatrixXd(S_B(b, b).triangularView<Eigen::Lower>());
      u.triangularView<Eigen::Lower>() +=
          f.L_bb.triangularView<Eigen::Lower>() * f.L_bb.transpose();
    });
  }
  ScopedTimer t(timings_, "condensation Schur complement");
  for (std::size_t k = 0; k < 2; ++k) {
    const std::vector<Index>& b = s.parts[k]->boundary_position;
    const Eigen::MatrixXd& u = update[k];
    // b is increasing, so the lower triangle of u lands in the lower triangle of S_B.
    for (std::size_t c = 0; c < b.size(); ++c)
      for (std::size_t r = c; r < b.size(); ++r)
        S_B(b[r], b[c]) += u(static_cast<Index>(r), static_cast<Index>(c));
  }
  // One dense Cholesky factorisation S_B = L_B L_B^T eliminates the separator: its trailing
  // block L_cc gives S = S_cc - S_cs S_ss^-1 S_sc = L_cc L_cc^T, and L_ss, L_cs serve the solves.
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(S_B);
  if (llt.info() != Eigen::Success)
    throw NumericalError("condensation: the interface's Schur complement is not positive definite");
  s.L_ss = S_B.topLeftCorner(ns, ns).triangularView<Eigen::Lower>();
  s.L_cs = S_B.bottomLeftCorner(nc, ns);
  s.L_cc = S_B.bottomRightCorner(nc, nc).triangularView<Eigen::Lower>();
  return true;
}

SchurComplement::~SchurComplement() = default;

Index SchurComplement::parts() const {
  return static_cast<Index>(impl_->parts.size());
}

SchurComplement::Impl::Forward SchurComplement::Impl::forward(const Vector& b) {
  Forward out;
  if (parts.size() == 1) {
    // With z = L^-1 P b, the last rows of L z = P b read L_CI z_I + L_CC z_C = b_C, and
    // L_CI z_I = A_CI A_II^-1 b_I (since L_II z_I = b_I and L_CI = A_CI L_II^-T): g = L_CC z_C.
    out.z = {parts.front()->forward(b)};
    out.g = L_cc.triangularView<Eigen::Lower>() * out.z.front().tail(nc());
    return out;
  }
  // Part k with the load [b_I; 0]: its trailing rows read L_bI z_I + L_bb z_b = 0, so that
  // L_bb z_b = -A_bI A_II^-1 b_I, and the interface load r_B = b_B - sum_k A_Bk A_kk^-1 b_k
  // gathers L_bb z_b from each part.
  out.z.resize(2);
  on_two_threads([&](int k) {
    PartFactor& f = *parts[static_cast<std::size_t>(k)];
    Vector v = Vector::Zero(f.n);
    for (std::size_t i = 0; i < f.interior.size(); ++i) v(static_cast<Index>(i)) = b(f.interior[i]);
    out.z[static_cast<std::size_t>(k)] = f.forward(v);
  });
  Vector r(ns() + nc());
  for (Index i = 0; i < ns(); ++i) r(i) = b(separator[static_cast<std::size_t>(i)]);
  for (Index i = 0; i < nc(); ++i) r(ns() + i) = b(last[static_cast<std::size_t>(i)]);
  for (std::size_t k = 0; k < 2; ++k) {
    const PartFactor& f = *parts[k];
    const Vector y = f.L_bb.triangularView<Eigen::Lower>() * out.z[k].tail(f.nb);
    for (Index i = 0; i < f.nb; ++i) r(f.boundary_position[static_cast<std::size_t>(i)]) += y(i);
  }
  // Forward through L_B: w_s = L_ss^-1 r_s, and g = L_cc w_c = r_c - L_cs w_s.
  out.w_s = L_ss.triangularView<Eigen::Lower>().solve(r.head(ns()));
  out.g = r.tail(nc()) - L_cs * out.w_s;
  return out;
}

Vector SchurComplement::Impl::backward(const Forward& fw, const Vector& f) {
  // x_C = S^-1 (g + f) = L_cc^-T L_cc^-1 (g + f). With one part the forward substitution of
  // E_C f touches the trailing block alone, L^-1 P E_C f = [0; L_cc^-1 f]: one back
  // substitution from z + [0; L_cc^-1 f] gives x.
  if (parts.size() == 1) {
    Vector w = fw.z.front();
    w.tail(nc()) += L_cc.triangularView<Eigen::Lower>().solve(f);
    return parts.front()->backward(w);
  }
  // Two parts: x_s = L_ss^-T (w_s - L_cs^T x_C); then each part's interior by its back
  // substitution with the trailing entries L_bb^T x_b: L_II^T x_I = z_I - L_bI^T x_b.
  Vector x_B(ns() + nc());
  x_B.tail(nc()) = L_cc.transpose().triangularView<Eigen::Upper>().solve(
      L_cc.triangularView<Eigen::Lower>().solve(fw.g + f));
  x_B.head(ns()) = L_ss.transpose().triangularView<Eigen::Upper>().solve(
      fw.w_s - L_cs.transpose() * x_B.tail(nc()));
  Vector x(static_cast<Index>(parts[0]->interior.size() + parts[1]->interior.size()) + ns() + nc());
  on_two_threads([&](int k) {
    PartFactor& p = *parts[static_cast<std::size_t>(k)];
    Vector w = fw.z[static_cast<std::size_t>(k)];
    Vector x_b(p.nb);
    for (Index i = 0; i < p.nb; ++i) x_b(i) = x_B(p.boundary_position[static_cast<std::size_t>(i)]);
    w.tail(p.nb) = p.L_bb.transpose().triangularView<Eigen::Upper>() * x_b;
    const Vector xl = p.backward(w);
    for (std::size_t i = 0; i < p.interior.size(); ++i)
      x(p.interior[i]) = xl(static_cast<Index>(i));
  });
  for (Index i = 0; i < ns(); ++i) x(separator[static_cast<std::size_t>(i)]) = x_B(i);
  for (Index i = 0; i < nc(); ++i) x(last[static_cast<std::size_t>(i)]) = x_B(ns() + i);
  return x;
}

Vector SchurComplement::condensed_load(const Vector& b) {
  ScopedTimer t(timings_, "condensation solve");
  impl_->last_forward = impl_->forward(b);
  return impl_->last_forward.g;
}

Vector SchurComplement::solve_with_condensed_forces(const Vector& f) const {
  ScopedTimer t(timings_, "condensation solve");
  if (impl_->last_forward.z.empty())
    throw NumericalError("SchurComplement: solve_with_condensed_forces() before condensed_load()");
  return impl_->backward(impl_->last_forward, f);
}

Vector SchurComplement::solve(const Vector& rhs) const {
  ScopedTimer t(timings_, "condensation solve");
  return impl_->backward(impl_->forward(rhs), Vector::Zero(impl_->nc()));
}

}  // namespace signorini
