#include "signorini/contact/newton_system.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

#include "signorini/linalg/cholmod_solver.hpp"
#include "signorini/linalg/dense_cholesky_solver.hpp"
#include "signorini/linalg/dense_storage.hpp"

namespace signorini {

namespace {

class SparseNewtonSystem final : public NewtonSystem {
 public:
  SparseNewtonSystem(const ContactProblem& problem, const ModifiedLagrangian& phi,
                     const LinearSolverOptions& options)
      : p_(problem),
        phi_(phi),
        solver_(make_linear_solver(options)),
        H_(phi.hessian_pattern()),
        Nt_(problem.contact.N.transpose()) {
    solver_->analyze(H_);  // one symbolic analysis: every H(P) has this pattern
    if (options.factor_updates != FactorUpdates::Never)
      cholmod_ = dynamic_cast<CholmodSolver*>(solver_.get());
    always_update_ = options.factor_updates == FactorUpdates::Always;
  }
  void set_active(const ActiveSet& active) override {
    if (has_factor_ && active == current_) return;
    if (!(has_factor_ && cholmod_ != nullptr && update_to(active))) {
      phi_.hessian(active, H_);
      solver_->factorize(H_);
      ++factorizations_;
      updates_since_factorization_ = 0;
    }
    current_ = active;
    has_factor_ = true;
    has_linearization_ = false;  // the factor is of this active set now
  }
  LinearSolveStats solve(const Vector& rhs, Vector& x) override { return solver_->solve(rhs, x); }
  [[nodiscard]] const TimingTable& timings() const override { return solver_->timings(); }

 protected:
  // No rank-one updates: the blocks change on every sliding node.
  void set_blocks(const Linearization& lin) override {
    if (has_linearization_ && lin == current_linearization_) return;
    phi_.hessian(lin, H_);
    solver_->factorize(H_);
    ++factorizations_;
    current_linearization_ = lin;
    has_linearization_ = true;
    // The factor is no longer that of an active set: a step whose blocks are all 0 and 1 (no
    // node sliding, set_active above) must factorise again, not reuse it.
    has_factor_ = false;
  }

 private:
  Linearization current_linearization_;  // friction's, where it was set
  bool has_linearization_ = false;
  // Updates and downdates accumulate rounding: refactorise after this many since the last
  // factorisation, however cheap they are.
  static constexpr std::size_t kMaxUpdates = 2000;

  // H(P') = H(P) + sum_{j in P' \ P} v_j v_j^T - sum_{j in P \ P'} v_j v_j^T with
  // v_j = sqrt(r h_j) n_j, the terms of (17): the nodes that enter update the factor, those that
  // leave downdate it (entering first, so that no intermediate matrix loses definiteness).
  // False where a factorisation is cheaper, or a downdate failed (then the caller refactorises).
  bool update_to(const ActiveSet& active) {
    std::vector<Index> entering, leaving;
    double flops = 0.0;
    for (std::size_t j = 0; j < active.size(); ++j) {
      if (active[j] == current_[j]) continue;
      (active[j] ? entering : leaving).push_back(static_cast<Index>(j));
      flops += cholmod_->update_flops(node_rows(static_cast<Index>(j)));
    }
    const std::size_t changed = entering.size() + leaving.size();
    // Update where that is expected to take less time than the factorisation it replaces. The
    // first update after a factorisation also converts the factor (to L D L^T, about 25 ns per
    // entry here, more than a 2D factorisation); that serves the updates that follow as well,
    // so it counts half.
    if (updates_since_factorization_ + changed > kMaxUpdates ||
        (!always_update_ && cholmod_->predicted_update_seconds(flops) +
                                    0.5 * cholmod_->predicted_conversion_seconds() >
                                cholmod_->last_factorization_seconds()))
      return false;
    if (!cholmod_->update(node_columns(entering), true) ||
        !cholmod_->update(node_columns(leaving), false))
      return false;
    updates_ += static_cast<int>(changed);
    updates_since_factorization_ += changed;
    return true;
  }

  // The columns v_j of the given nodes as an n x k sparse matrix.
  SparseMatrix node_columns(const std::vector<Index>& nodes) const {
    SparseMatrix C(p_.A.rows(), static_cast<Index>(nodes.size()));
    std::vector<Eigen::Triplet<double, Index>> entries;
    for (std::size_t c = 0; c < nodes.size(); ++c) {
      const Index j = nodes[c];
      // Row j of N is node j / components' (friction: several rows per node).
      const double scale = std::sqrt(phi_.r() * p_.contact.weights(j / p_.contact.components));
      for (SparseMatrix::InnerIterator it(Nt_, j); it; ++it)
        entries.emplace_back(it.row(), static_cast<Index>(c), scale * it.value());
    }
    C.setFromTriplets(entries.begin(), entries.end());
    return C;
  }

  // The dofs of node j's normal (its rank-one term's rows).
  std::vector<Index> node_rows(Index j) const {
    std::vector<Index> rows;
    for (SparseMatrix::InnerIterator it(Nt_, j); it; ++it) rows.push_back(it.row());
    return rows;
  }

  const ContactProblem& p_;
  const ModifiedLagrangian& phi_;
  std::unique_ptr<LinearSolver> solver_;
  CholmodSolver* cholmod_ = nullptr;  // solver_, where it can update its factor
  bool always_update_ = false;        // factor_updates = "always"
  SparseMatrix H_;
  SparseMatrix Nt_;  // column j = row j of N
  ActiveSet current_;
  bool has_factor_ = false;
  std::size_t updates_since_factorization_ = 0;
};

class DenseNewtonSystem final : public NewtonSystem {
 public:
  // A condensed problem's matrix (every entry stored) is read where it is; any other is copied
  // to a dense array once.
  DenseNewtonSystem(const ContactProblem& problem, double r)
      : p_(problem),
        r_(r),
        A_(dense_data(problem.A, owned_), problem.A.rows(), problem.A.cols()),
        Nt_(problem.contact.N.transpose()) {}

  void set_blocks(const Linearization& lin) override {
    if (has_linearization_ && lin == current_linearization_) return;
    const Index m = p_.contact.components;
    Eigen::MatrixXd& H = solver_.workspace(A_.rows());
    H.triangularView<Eigen::Lower>() = A_;
    for (Index j = 0; j < p_.contact.size(); ++j) {
      const double* D = &lin.blocks[static_cast<std::size_t>(m * m * j)];
      const double scale = r_ * p_.contact.weights(j);
      for (Index a = 0; a < m; ++a)
        for (Index b = 0; b < m; ++b) {
          const double d = D[a + m * b];
          if (d == 0.0) continue;
          for (SparseMatrix::InnerIterator ia(Nt_, m * j + a); ia; ++ia)
            for (SparseMatrix::InnerIterator ib(Nt_, m * j + b); ib; ++ib)
              if (ia.row() >= ib.row())
                H(ia.row(), ib.row()) += scale * d * ia.value() * ib.value();
        }
    }
    solver_.factorize_in_place();
    ++factorizations_;
    current_linearization_ = lin;
    has_linearization_ = true;
    has_factor_ = false;  // not the factor of an active set (SparseNewtonSystem says why)
  }

  void set_active(const ActiveSet& active) override {
    if (has_factor_ && active == current_) return;
    std::vector<Index> changed;
    if (has_factor_)
      for (std::size_t j = 0; j < active.size(); ++j)
        if (active[j] != current_[j]) changed.push_back(static_cast<Index>(j));
    // A rank-one update costs about 2 n^2 flops, a factorisation n^3 / 3; updates also
    // accumulate round-off, so refactorise after many.
    const auto n = static_cast<double>(A_.rows());
    const auto max_updates = std::max<std::size_t>(200, static_cast<std::size_t>(n / 3.0));
    const bool update = has_factor_ && 6.0 * static_cast<double>(changed.size()) < n &&
                        updates_since_factorization_ + changed.size() < max_updates;
    bool ok = update;
    if (update) {
      for (const Index j : changed) {
        const bool on = active[static_cast<std::size_t>(j)];
        if (!solver_.rank_update(node_vector(j), on ? 1.0 : -1.0)) {
          ok = false;
          break;
        }
        ++updates_;
        ++updates_since_factorization_;
      }
    }
    if (!ok) {
      // H = A + sum_{j in P} v_j v_j^T, written into the solver's array and factorised there.
      Eigen::MatrixXd& H = solver_.workspace(A_.rows());
      H.triangularView<Eigen::Lower>() = A_;
      for (std::size_t j = 0; j < active.size(); ++j)
        if (active[j]) {
          const Vector v = node_vector(static_cast<Index>(j));
          H.selfadjointView<Eigen::Lower>().rankUpdate(v);
        }
      solver_.factorize_in_place();  // LLT reads the lower triangle
      ++factorizations_;
      updates_since_factorization_ = 0;
    }
    current_ = active;
    has_factor_ = true;
  }
  LinearSolveStats solve(const Vector& rhs, Vector& x) override { return solver_.solve(rhs, x); }
  [[nodiscard]] const TimingTable& timings() const override { return solver_.timings(); }

 private:
  // sqrt(r h_j) n_j: H(P) = A + sum_{j in P} v_j v_j^T (row j of N, of node j / components).
  Vector node_vector(Index j) const {
    Vector v = Vector::Zero(A_.rows());
    const double scale = std::sqrt(r_ * p_.contact.weights(j / p_.contact.components));
    for (SparseMatrix::InnerIterator it(Nt_, j); it; ++it) v(it.row()) = scale * it.value();
    return v;
  }

  static const double* dense_data(const SparseMatrix& A, Eigen::MatrixXd& owned) {
    if (is_dense_stored(A)) return A.valuePtr();
    owned = Eigen::MatrixXd(A);
    return owned.data();
  }

  const ContactProblem& p_;
  double r_;
  Eigen::MatrixXd owned_;  // only for a matrix that is not dense-stored
  Eigen::Map<const Eigen::MatrixXd> A_;
  SparseMatrix Nt_;
  DenseCholeskySolver solver_;
  ActiveSet current_;
  bool has_factor_ = false;
  Linearization current_linearization_;  // friction's in 3D, where it was set
  bool has_linearization_ = false;
  std::size_t updates_since_factorization_ = 0;
};

}  // namespace

std::unique_ptr<NewtonSystem> make_newton_system(const ContactProblem& problem,
                                                 const ModifiedLagrangian& phi,
                                                 const LinearSolverOptions& options) {
  if (options.type == LinearSolverType::Dense)
    return std::make_unique<DenseNewtonSystem>(problem, phi.r());
  return std::make_unique<SparseNewtonSystem>(problem, phi, options);
}

}  // namespace signorini
