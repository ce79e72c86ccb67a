#pragma once
// Dense Cholesky (Eigen's blocked LLT) behind the LinearSolver interface, for small matrices: the
// contact problems condensed onto their contact boundary (contact/condensed_problem.hpp) are dense.
// Besides full factorisations it supports rank-one updates and downdates, O(n^2) each, used when
// only a few contact nodes change state between Newton steps. The factor overwrites the matrix
// it is computed from (one n x n array, written by the caller through workspace()).

#include <Eigen/Cholesky>
#include <optional>

#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

class DenseCholeskySolver final : public LinearSolver {
 public:
  void analyze(const SparseMatrix& /*pattern*/) override {}
  void factorize(const SparseMatrix& H) override;
  /// Factorises a dense SPD matrix (a copy of it, into the workspace).
  void factorize_dense(const Eigen::MatrixXd& H);
  /// The n x n array that factorize_in_place() factorises: write H into its lower triangle.
  Eigen::MatrixXd& workspace(Index n);
  /// Factorises the workspace in place (its lower triangle becomes L).
  void factorize_in_place();
  /// Replaces the factorised H by H + sigma v v^T (sigma = +1 or -1). Returns false if the result
  /// is not numerically positive definite; the caller should then factorise again.
  bool rank_update(const Vector& v, double sigma);
  LinearSolveStats solve(const Vector& rhs, Vector& x) override;
  [[nodiscard]] std::string_view name() const override { return "dense"; }

 private:
  Eigen::MatrixXd storage_;  // H, then its factor
  // Made by each factorisation over storage_ (Eigen's in-place decomposition).
  std::optional<Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>>> llt_;
  bool factorized_ = false;
};

}  // namespace signorini
