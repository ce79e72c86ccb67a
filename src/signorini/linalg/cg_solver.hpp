#pragma once
// Jacobi-preconditioned conjugate gradients (Eigen's ConjugateGradient): the linear solver the
// paper used for its Newton steps, kept to redo its CPU-vs-GPU comparison.

#include <Eigen/IterativeLinearSolvers>

#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

class CgSolver final : public LinearSolver {
 public:
  explicit CgSolver(const LinearSolverOptions& options) : options_(options) {}
  void analyze(const SparseMatrix& /*pattern*/) override {}
  void factorize(const SparseMatrix& H) override;
  LinearSolveStats solve(const Vector& rhs, Vector& x) override;
  [[nodiscard]] std::string_view name() const override { return "cg"; }

 private:
  LinearSolverOptions options_;
  SparseMatrix matrix_;  // Eigen's CG keeps a reference: own the matrix here.
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper,
                           Eigen::DiagonalPreconditioner<double>>
      cg_;
};

}  // namespace signorini
