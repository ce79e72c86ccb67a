#pragma once
// Preconditioned conjugate gradients on a backend (Hestenes–Stiefel with the preconditioned
// residual; Saad, Iterative Methods, Algorithm 9.1). Stops when ||b - H x||_2 <= tolerance
// ||b||_2, measured on the recursively updated residual; per iteration three dot products come
// back to the host, nothing else.

#include "signorini/iterative/linear_operator.hpp"

namespace signorini {

struct PcgOptions {
  double tolerance = 1e-13;  ///< relative to ||b||_2 (the paper's CG tolerance)
  int max_iterations = 10000;
};

struct PcgResult {
  int iterations = 0;
  double residual = 0.0;  ///< ||r|| / ||b|| reached
  bool converged = false;
};

class Pcg {
 public:
  Pcg(Backend& backend, Index n);
  /// Solves H x = b; x holds the initial guess on entry.
  PcgResult solve(LinearOperator& H, Preconditioner& M, const DeviceVector& b, DeviceVector& x,
                  const PcgOptions& options);

 private:
  Backend& backend_;
  DeviceVector r_, z_, p_, q_;
};

}  // namespace signorini
