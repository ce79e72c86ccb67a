#pragma once
// Supernodal sparse Cholesky by SuiteSparse CHOLMOD (64-bit index interface, so factors beyond
// 2^31 entries work). The fill-reducing ordering and symbolic factorisation are computed once in
// analyze() and reused by every factorize() of a matrix with that pattern.

#include <memory>
#include <utility>
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

  /// Estimated flops of a rank-one update or downdate by a column whose nonzeros lie in the
  /// given rows: about 4 per entry of L on the elimination-tree path from the first of them to
  /// the root, the columns that the update changes (Davis and Hager's row-modification cost).
  /// Needs a factorisation; 0 for no rows.
  [[nodiscard]] double update_flops(const std::vector<Index>& rows);

  /// Replaces the factor of H by that of H + C C^T (up = true) or H - C C^T (down), C an n x k
  /// sparse matrix in H's own row order, by CHOLMOD's update/downdate (cholmod_updown). The
  /// first update converts the supernodal L L^T factor to a simplicial L D L^T one (CHOLMOD
  /// updates only those); the next factorize() starts from the supernodal analysis again.
  /// Returns false, leaving no usable factor, when a downdate meets a matrix that is not
  /// numerically positive definite: the caller refactorises.
  bool update(const SparseMatrix& C, bool up);

  /// Replaces the factor of H by that of H with row and column k set to the identity's (the
  /// unknown k fixed: H x = b then gives x_k = b_k and couples it to nothing), by CHOLMOD's row
  /// deletion (cholmod_rowdel, a rank-two modification; Davis and Hager's row modifications).
  /// Converts the factor to L D L^T as update() does. Returns false, leaving no usable factor,
  /// where the factor becomes indefinite (then the caller refactorises).
  bool delete_row(Index k);
  /// The reverse of delete_row(): row and column k of the factored matrix must be the
  /// identity's; they become `column` (the entries (i, H_ik) of the new column k, in H's own
  /// order, the diagonal included; rows that are the identity's must have no entry), by
  /// cholmod_rowadd. Returns false as update() does.
  bool add_row(Index k, const std::vector<std::pair<Index, double>>& column);

  /// Estimated flops of delete_row(k) or add_row(k, ...): a rank-two change, twice
  /// update_flops({k}).
  [[nodiscard]] double row_modification_flops(Index k);

  /// Seconds that update() is expected to take for updates of these estimated flops, at the
  /// rate of this solver's last update (or this project's machine's before any).
  [[nodiscard]] double predicted_update_seconds(double flops) const;
  /// Seconds that the next update() is expected to spend converting the factor to L D L^T: 0
  /// where it is already, else at the rate of the last conversion (or this machine's).
  [[nodiscard]] double predicted_conversion_seconds() const;
  /// Seconds of the last numeric factorisation (0 before any).
  [[nodiscard]] double last_factorization_seconds() const;

 private:
  struct Impl;  // CHOLMOD's state, freed by its destructor
  std::unique_ptr<Impl> impl_;
};

/// CHOLMOD's version, e.g. "3.0.14".
std::string cholmod_version();

}  // namespace signorini
