#pragma once
// Jacobi-preconditioned conjugate gradients on the host: the linear solver the paper used for
// its Newton steps, kept to redo its CPU-vs-GPU comparison. The iteration is the one written for
// every backend (iterative/pcg.hpp), here on the host backend with the Jacobi preconditioner, so
// that `linear.type = "cg"` is one algorithm on the plain path and on the backend path.

#include <memory>

#include "signorini/backend/host_backend.hpp"
#include "signorini/iterative/jacobi_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/iterative/penalized_operator.hpp"
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
  HostBackend backend_;
  // H as an operator (no contact part: the Newton matrix comes assembled), its Jacobi
  // preconditioner, the iteration's work vectors, and b and x on the backend.
  std::unique_ptr<PenalizedOperator> operator_;
  std::unique_ptr<JacobiPreconditioner> jacobi_;
  std::unique_ptr<Pcg> pcg_;
  DeviceVector b_, x_;
};

}  // namespace signorini
