#include "signorini/iterative/jacobi_preconditioner.hpp"

namespace signorini {

JacobiPreconditioner::JacobiPreconditioner(PenalizedOperator& op)
    : op_(op), dinv_(op.backend(), op.size()) {
  refresh();
}

void JacobiPreconditioner::refresh() {
  op_.inverse_diagonal(dinv_);
}

void JacobiPreconditioner::apply(const DeviceVector& r, DeviceVector& z) {
  op_.backend().multiply(dinv_, r, z);
}

}  // namespace signorini
