#pragma once
// z = diag(H)^{-1} r: the preconditioner of the paper's conjugate gradients (Section 5), kept as
// the baseline of the GPU comparison.

#include "signorini/iterative/penalized_operator.hpp"

namespace signorini {

/// z = D^{-1} r with D^{-1} given (a diagonal scaling that someone else keeps up to date, as the
/// Chebyshev smoother keeps its own; it must outlive this object).
class DiagonalPreconditioner final : public Preconditioner {
 public:
  explicit DiagonalPreconditioner(const DeviceVector& inverse_diagonal) : dinv_(inverse_diagonal) {}
  void refresh() override {}
  void apply(const DeviceVector& r, DeviceVector& z) override {
    dinv_.backend()->multiply(dinv_, r, z);
  }

 private:
  const DeviceVector& dinv_;
};

class JacobiPreconditioner final : public Preconditioner {
 public:
  explicit JacobiPreconditioner(PenalizedOperator& op);
  /// Recomputes diag(H)^{-1} after the operator's weights changed.
  void refresh() override;
  void apply(const DeviceVector& r, DeviceVector& z) override;
  [[nodiscard]] const DeviceVector& inverse_diagonal() const { return dinv_; }

 private:
  PenalizedOperator& op_;
  DeviceVector dinv_;
};

}  // namespace signorini
