#include "signorini/contact/newton_system.hpp"

#include <cmath>

#include "signorini/linalg/dense_cholesky_solver.hpp"
#include "signorini/linalg/dense_storage.hpp"

namespace signorini {

namespace {

class SparseNewtonSystem final : public NewtonSystem {
 public:
  SparseNewtonSystem(const ContactProblem& problem, const ModifiedLagrangian& phi,
                     const LinearSolverOptions& options)
      : phi_(phi), solver_(make_linear_solver(options)), H_(problem.A) {
    solver_->analyze(problem.A);  // one symbolic analysis: every H(P) has A's pattern
  }
  void set_active(const ActiveSet& active) override {
    if (has_factor_ && active == current_) return;
    phi_.hessian(active, H_);
    solver_->factorize(H_);
    current_ = active;
    has_factor_ = true;
    ++factorizations_;
  }
  LinearSolveStats solve(const Vector& rhs, Vector& x) override { return solver_->solve(rhs, x); }
  [[nodiscard]] const TimingTable& timings() const override { return solver_->timings(); }

 private:
  const ModifiedLagrangian& phi_;
  std::unique_ptr<LinearSolver> solver_;
  SparseMatrix H_;
  ActiveSet current_;
  bool has_factor_ = false;
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
  // sqrt(r h_j) n_j: H(P) = A + sum_{j in P} v_j v_j^T.
  Vector node_vector(Index j) const {
    Vector v = Vector::Zero(A_.rows());
    const double scale = std::sqrt(r_ * p_.contact.weights(j));
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
