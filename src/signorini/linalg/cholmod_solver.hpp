#pragma once
// Supernodal sparse Cholesky by SuiteSparse CHOLMOD (64-bit index interface, so factors beyond
// 2^31 entries work). The fill-reducing ordering and symbolic factorisation are computed once in
// analyze() and reused by every factorize() of a matrix with that pattern.

#include <memory>
#include <vector>

#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver();
  ~CholmodSolver() override;
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  void analyze(const SparseMatrix& pattern) override;
  void factorize(const SparseMatrix& H) override;
  LinearSolveStats solve(const Vector& rhs, Vector& x) override;
  [[nodiscard]] std::string_view name() const override { return "cholmod"; }

  /// Nonzeros of the Cholesky factor after the last factorisation (0 before).
  [[nodiscard]] double factor_nonzeros() const;

 private:
  struct Impl;  // CHOLMOD's state, freed by its destructor
  std::unique_ptr<Impl> impl_;
};

/// CHOLMOD's version, e.g. "3.0.14".
std::string cholmod_version();

}  // namespace signorini
