#pragma once
// z = diag(H)^{-1} r: the preconditioner of the paper's conjugate gradients (Section 5), kept as
// the baseline of the GPU comparison.

#include "signorini/iterative/penalized_operator.hpp"

namespace signorini {

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
